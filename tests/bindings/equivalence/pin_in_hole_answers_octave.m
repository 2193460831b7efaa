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
      fprintf(out, '%s\n', equivalence_single_line(i, found));
    catch err
      % Octave puts the function's name before a MEX error's text; MATLAB does not.
      text = regexprep(err.message, '^cj_detect_pin_in_hole: ', '');
      fprintf(out, 'S %d error %d %s\n', i, equivalence_status(err), text);
    end_try_catch
  end
  fclose(out);
end

function d = dimensions_of(r)
  % stops[0, stop_count) as the rows of dims.stops (the inputs' counts are 0, 1 or 2).
  d = struct('hole_radius', r(1), 'hole_length', r(2), 'pin_radius', r(3), ...
             'stops', reshape(r(5:8), 2, 2)'(1:r(4), :));
end

