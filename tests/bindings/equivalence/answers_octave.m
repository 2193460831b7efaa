% SPDX-License-Identifier: BSD-3-Clause
% The MEX gateways' answers for the equivalence test (README.md), run by octave-cli:
% cj_detect on the single-call records, cj_detect_many on the batch records (N x 6 matrices).
%
% usage: answers_octave(INPUT, OUTPUT), with the MEX files on the path.
function answers_octave(input_path, output_path)
  fid = fopen(input_path, 'r');
  data = fread(fid, Inf, 'double');
  fclose(fid);
  records = reshape(data, 19, [])';
  count = records(1, 1);
  singles = records(1, 2);
  records = records(2:end, :);
  assert(rows(records) == count);
  out = fopen(output_path, 'w');
  for i = 0:singles - 1
    r = records(i + 1, :);
    options = struct('certify', r(17), 'parallel_angle_tolerance', r(18), 'exact_fallback', r(19));
    try
      found = cj_detect(dimensions_of(r), r(5:10), r(11:16), options);
      fprintf(out, '%s\n', equivalence_single_line(i, found));
    catch err
      % Octave puts the function's name before a MEX error's text; MATLAB does not.
      text = regexprep(err.message, '^cj_detect: ', '');
      fprintf(out, 'S %d error %d %s\n', i, equivalence_status(err), text);
    end_try_catch
  end
  if count > singles
    b = records(singles + 1:end, :);
    found = cj_detect_many(dimensions_of(b(1, :)), b(:, 5:10), b(:, 11:16));
    write_batch_lines(out, singles, found);
  end
  fclose(out);
end

function d = dimensions_of(r)
  d = struct('bearing_radius', r(1), 'bearing_length', r(2), 'journal_radius', r(3), ...
             'journal_length', r(4));
end

function write_batch_lines(out, first_index, r)
  % The hex digits of every field at once (num2hex per value costs more than the detection).
  n = numel(r.scenario_code);
  h = struct();
  for name = {'depth', 'p_WCj', 'p_WCi', 'normal_W', 'depth_error_bound', 'p_WCj_error_bound', ...
              'p_WCi_error_bound', 'crossing_angle', ...
              'crossing_angle_error_bound', 'crossing_point', 'crossing_point_error_bound'}
    h.(name{1}) = [repmat(' ', numel(r.(name{1})), 1), upper(num2hex(r.(name{1})(:)))];
  end
  % Rows of a point's three coordinates: pose i, coordinate c, slot s (contact, or crossing and
  % contact) at i + n (c - 1) + 3 n (s - 1).
  xyz = @(i, s) i + n * (0:2) + 3 * n * (s - 1);
  for i = 1:n
    line = sprintf('B %d ok %d %d %d %d %d', first_index + i - 1, r.scenario_code(i), r.aligned(i), ...
                   r.certificate_level(i), r.certificate_reason(i), r.contact_count(i));
    for k = 1:r.contact_count(i)
      ik = i + n * (k - 1);
      line = [line, sprintf(' | %d %d', r.type(ik), r.base(ik)), h.depth(ik, :), ...
              reshape(h.p_WCj(xyz(i, k), :)', 1, []), reshape(h.p_WCi(xyz(i, k), :)', 1, []), ...
              reshape(h.normal_W(xyz(i, k), :)', 1, []), h.depth_error_bound(ik, :), ...
              h.p_WCj_error_bound(ik, :), h.p_WCi_error_bound(ik, :), sprintf(' %d', r.crossing_count(ik))];
      for m = 1:r.crossing_count(ik)
        imk = i + n * (m - 1) + 2 * n * (k - 1);
        line = [line, h.crossing_angle(imk, :), h.crossing_angle_error_bound(imk, :), ...
                reshape(h.crossing_point(xyz(i, m + 2 * (k - 1)), :)', 1, []), ...
                h.crossing_point_error_bound(imk, :), sprintf(' %d', r.crossing_multiplicity(imk))];
      end
      line = [line, sprintf(' %d %d', r.certificate_level_of_contact(ik), ...
                            r.certificate_reason_of_contact(ik))];
    end
    fprintf(out, '%s\n', line);
  end
end
