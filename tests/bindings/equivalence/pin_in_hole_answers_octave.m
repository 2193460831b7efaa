% SPDX-License-Identifier: BSD-3-Clause
% The MEX gateway's answers for the pin-in-hole equivalence test (README.md), run by octave-cli:
% cj_detect_pin_in_hole on every record.
%
% usage: pin_in_hole_answers_octave(INPUT, OUTPUT), with the MEX files on the path.
function pin_in_hole_answers_octave(input_path, output_path)
  fid = fopen(input_path, 'r');
  data = fread(fid, Inf, 'double');
  fclose(fid);
  records = reshape(data, 23, [])';
  count = records(1, 1);
  records = records(2:end, :);
  assert(rows(records) == count);
  out = fopen(output_path, 'w');
  for i = 0:count - 1
    r = records(i + 1, :);
    options = struct('certify', r(21), 'parallel_angle_tolerance', r(22), 'exact_fallback', r(23));
    try
      found = cj_detect_pin_in_hole(dimensions_of(r), r(9:14), r(15:20), options);
      fprintf(out, '%s\n', single_line(i, found));
    catch err
      % Octave puts the function's name before a MEX error's text; MATLAB does not.
      text = regexprep(err.message, '^cj_detect_pin_in_hole: ', '');
      fprintf(out, 'S %d error %d %s\n', i, status_of(err), text);
    end_try_catch
  end
  fclose(out);
end

function d = dimensions_of(r)
  % stops[0, stop_count) as the rows of dims.stops (the inputs' counts are 0, 1 or 2).
  d = struct('hole_radius', r(1), 'hole_length', r(2), 'pin_radius', r(3), ...
             'stops', reshape(r(5:8), 2, 2)'(1:r(4), :));
end

function s = status_of(err)
  if strcmp(err.identifier, 'clearjoint:invalidInput')
    s = 1;  % CJ_INVALID_INPUT
  else
    s = 3;  % CJ_INTERNAL_ERROR
  end
end

function t = hex(x)
  % IEEE bits of each double, 16 upper-case hex digits after a space.
  h = upper(num2hex(x(:)));
  t = reshape([repmat(' ', rows(h), 1), h]', 1, []);
end

function line = single_line(i, r)
  line = sprintf('S %d ok %d %d %d %d "%s" %d', i, r.scenario_code, r.aligned, ...
                 r.certificate.level_code, r.certificate.reason_code, r.certificate.reason, ...
                 r.contact_count);
  for k = 1:r.contact_count
    c = r.contacts(k);
    line = [line, sprintf(' | %d %d', type_code(c.type), base_code(c.base)), hex(c.depth), ...
            hex(c.p_WCj), hex(c.p_WCi), hex(c.normal_W), hex(c.depth_error_bound), ...
            hex(c.p_WCj_error_bound), hex(c.p_WCi_error_bound), sprintf(' %d', numel(c.crossings))];
    for m = 1:numel(c.crossings)
      x = c.crossings(m);
      line = [line, hex(x.angle), hex(x.angle_error_bound), hex(x.point), ...
              hex(x.point_error_bound), sprintf(' %d', x.multiplicity)];
    end
    line = [line, sprintf(' %d %d "%s"', c.certificate.level_code, c.certificate.reason_code, ...
                          c.certificate.reason)];
  end
end

function code = type_code(name)
  code = find(strcmp(name, {'radial', 'axial'})) - 1;
end

function code = base_code(name)
  code = find(strcmp(name, {'a', 'b', 'mid'})) - 1;
end
