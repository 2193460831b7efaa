% SPDX-License-Identifier: BSD-3-Clause
% The MEX gateways' answers for the pin-in-hole equivalence test (README.md), run by octave-cli:
% cj_detect_pin_in_hole on every record, and cj_detect_pin_in_hole_many on the random poses (the
% records from the header's double 1 on), whose arrays must hold each pose's single answer bit
% for bit (an error otherwise: the batch's arrays carry codes, not the reason texts the lines
% need, so the lines are the single calls').
%
% usage: pin_in_hole_answers_octave(INPUT, OUTPUT), with the MEX files on the path.
function pin_in_hole_answers_octave(input_path, output_path)
  fid = fopen(input_path, 'r');
  data = fread(fid, Inf, 'double');
  fclose(fid);
  records = reshape(data, 23, [])';
  count = records(1, 1);
  singles = records(1, 2);
  records = records(2:end, :);
  assert(rows(records) == count);
  out = fopen(output_path, 'w');
  batch_answers = cell(count - singles, 1);
  for i = 0:count - 1
    r = records(i + 1, :);
    options = struct('certify', r(21), 'parallel_angle_tolerance', r(22), 'exact_fallback', r(23));
    try
      found = cj_detect_pin_in_hole(dimensions_of(r), r(9:14), r(15:20), options);
      fprintf(out, '%s\n', equivalence_single_line(i, found));
      if i >= singles
        batch_answers{i - singles + 1} = found;
      end
    catch err
      % Octave puts the function's name before a MEX error's text; MATLAB does not.
      text = regexprep(err.message, '^cj_detect_pin_in_hole: ', '');
      fprintf(out, 'S %d error %d %s\n', i, equivalence_status(err), text);
    end_try_catch
  end
  fclose(out);
  if count > singles
    batch = records(singles + 1:end, :);
    % One joint and the default options (README.md).
    assert(all(all(batch(:, 1:8) == batch(1, 1:8))) && all(batch(:, 21) == 1) && all(batch(:, 22) == 0) ...
           && all(batch(:, 23) == 1));
    soa = cj_detect_pin_in_hole_many(dimensions_of(batch(1, :)), batch(:, 9:14), batch(:, 15:20));
    for n = 1:rows(batch)
      expect_same_row(soa, n, batch_answers{n}, singles + n - 1);
    end
    printf('%d batch poses: cj_detect_pin_in_hole_many gives the single answers bit for bit\n', rows(batch));
  end
end

% Row n of the batch's arrays holds the single answer `r`, every double compared as its bits.
function expect_same_row(soa, n, r, index)
  same = @(a, b) isequal(typecast(double(a(:)'), 'uint64'), typecast(double(b(:)'), 'uint64'));
  ok = soa.scenario_code(n) == r.scenario_code && soa.aligned(n) == r.aligned ...
       && soa.certificate_level(n) == r.certificate.level_code ...
       && soa.certificate_reason(n) == r.certificate.reason_code && soa.contact_count(n) == r.contact_count;
  for k = 1:r.contact_count
    c = r.contacts(k);
    ok = ok && same(soa.depth(n, k), c.depth) && same(soa.depth_error_bound(n, k), c.depth_error_bound) ...
         && same(soa.p_WCj(n, :, k), c.p_WCj) && same(soa.p_WCi(n, :, k), c.p_WCi) ...
         && same(soa.normal_W(n, :, k), c.normal_W) && same(soa.p_WCj_error_bound(n, k), c.p_WCj_error_bound) ...
         && same(soa.p_WCi_error_bound(n, k), c.p_WCi_error_bound) ...
         && soa.type(n, k) == find(strcmp(c.type, {'radial', 'axial'})) - 1 ...
         && soa.base(n, k) == find(strcmp(c.base, {'a', 'b', 'mid'})) - 1 ...
         && soa.certificate_level_of_contact(n, k) == c.certificate.level_code ...
         && soa.certificate_reason_of_contact(n, k) == c.certificate.reason_code ...
         && soa.crossing_count(n, k) == numel(c.crossings);
    for m = 1:numel(c.crossings)
      x = c.crossings(m);
      ok = ok && same(soa.crossing_angle(n, m, k), x.angle) ...
           && same(soa.crossing_angle_error_bound(n, m, k), x.angle_error_bound) ...
           && same(soa.crossing_point(n, :, m, k), x.point) ...
           && same(soa.crossing_point_error_bound(n, m, k), x.point_error_bound) ...
           && soa.crossing_multiplicity(n, m, k) == x.multiplicity;
    end
  end
  if ~ok
    error('pose %d: cj_detect_pin_in_hole_many and cj_detect_pin_in_hole differ', index);
  end
end

function d = dimensions_of(r)
  % stops[0, stop_count) as the rows of dims.stops (the inputs' counts are 0, 1 or 2).
  d = struct('hole_radius', r(1), 'hole_length', r(2), 'pin_radius', r(3), ...
             'stops', reshape(r(5:8), 2, 2)'(1:r(4), :));
end

