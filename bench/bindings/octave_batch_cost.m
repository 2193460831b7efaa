% SPDX-License-Identifier: BSD-3-Clause
% The cost of detection from Octave, per pose: cj_detect_many on a batch of 1e5 random realistic
% poses of the paper's joint (Table 2, metres; journal off the axis by up to 1.5 cr, along it by
% up to 1.5 ca, tilted by up to 2 cr / Lj, from a fixed seed), and cj_detect's struct array on
% the first 1e4 of them. Each time is the median of `runs` calls, in CPU time (cputime: the
% process's user and system time, like bench_c_api's CPU column) and in wall-clock time (tic/toc).
% Writes a JSON object to `output`.
%
% usage: octave_batch_cost(OUTPUT [, RUNS]), with the MEX files on the path.
function octave_batch_cost(output, runs)
  if nargin < 2
    runs = 5;
  end
  dims = struct('bearing_radius', 10e-3, 'bearing_length', 20e-3, 'journal_radius', 9.9e-3, ...
                'journal_length', 19.8e-3);
  cr = dims.bearing_radius - dims.journal_radius;
  ca = (dims.bearing_length - dims.journal_length) / 2;
  n = 1e5;
  rand('twister', 20170824);
  offset = 1.5 * cr * sqrt(rand(n, 1));
  azimuth = 2 * pi * rand(n, 1);
  shift = 1.5 * ca * (2 * rand(n, 1) - 1);
  tilt = 2 * cr / dims.journal_length * rand(n, 1);
  tilt_azimuth = 2 * pi * rand(n, 1);
  journals = [offset .* cos(azimuth), offset .* sin(azimuth), shift, ...
              sin(tilt) .* cos(tilt_azimuth), sin(tilt) .* sin(tilt_azimuth), cos(tilt)];
  bearing = [0 0 0 0 0 1];

  [many, many_cpu] = deal(zeros(runs, 1));
  for k = 1:runs
    [start_cpu, start] = deal(cputime, tic);
    r = cj_detect_many(dims, bearing, journals);
    [many(k), many_cpu(k)] = deal(toc(start), cputime - start_cpu);
  end
  in_contact = mean(r.contact_count > 0);
  m = 1e4;
  [structs, structs_cpu] = deal(zeros(runs, 1));
  for k = 1:runs
    [start_cpu, start] = deal(cputime, tic);
    s = cj_detect(dims, bearing, journals(1:m, :));
    [structs(k), structs_cpu(k)] = deal(toc(start), cputime - start_cpu);
  end
  fid = fopen(output, 'w');
  fprintf(fid, ['{"poses": %d, "in_contact_share": %.4f, "cj_detect_many_cpu_ns_per_pose": %.1f, ', ...
                '"cj_detect_many_wall_ns_per_pose": %.1f, "struct_array_poses": %d, ', ...
                '"cj_detect_struct_array_cpu_ns_per_pose": %.1f, ', ...
                '"cj_detect_struct_array_wall_ns_per_pose": %.1f, "runs": %d, "octave_version": "%s"}\n'], ...
          n, in_contact, median(many_cpu) / n * 1e9, median(many) / n * 1e9, m, ...
          median(structs_cpu) / m * 1e9, median(structs) / m * 1e9, runs, OCTAVE_VERSION);
  fclose(fid);
end
