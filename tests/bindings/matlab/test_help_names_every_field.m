% SPDX-License-Identifier: BSD-3-Clause
% The help texts of cj_detect, cj_detect_many, cj_detect_pin_in_hole and cj_detect_pin_in_hole_many
% (the comments-only .m files beside the MEX files) name every field of the answers the MEX files
% give. The MEX writers are held to the library's
% result field lists by the equivalence test (every field must reach the Octave lines); their
% help is a hand-written list, and this test fails naming a field it lacks.
function test_help_names_every_field()
  table2 = struct('bearing_radius', 10, 'bearing_length', 20, 'journal_radius', 9.9, ...
                  'journal_length', 19.8);
  % Scenario (e) of Fig. 2: two contacts, each with two crossings, so that every nested struct
  % of the answer is present.
  journal = [0 0.08 0.08 0 sin(0.005) cos(0.005)];
  r = cj_detect(table2, [0 0 0 0 0 1], journal);
  assert(r.contact_count == 2 && numel(r.contacts(1).crossings) == 2);
  fields = [fieldnames(r); fieldnames(r.certificate); fieldnames(r.contacts); ...
            fieldnames(r.contacts(1).crossings); fieldnames(r.contacts(1).certificate)];
  expect_named('cj_detect', unique(fields));
  expect_named('cj_detect_many', fieldnames(cj_detect_many(table2, [0 0 0 0 0 1], journal)));
  % A pin tilted about the hole's centre: both edges, each with its crossings.
  pin_dims = struct('hole_radius', 10, 'hole_length', 20, 'pin_radius', 9.9, 'stops', [-10.5 16; 10.5 16]);
  p = cj_detect_pin_in_hole(pin_dims, [0 0 0 0 0 1], [0 0 0 0 sin(0.0125) cos(0.0125)]);
  assert(p.contact_count == 2 && numel(p.contacts(1).crossings) == 2);
  fields = [fieldnames(p); fieldnames(p.certificate); fieldnames(p.contacts); ...
            fieldnames(p.contacts(1).crossings); fieldnames(p.contacts(1).certificate)];
  expect_named('cj_detect_pin_in_hole', unique(fields));
  expect_named('cj_detect_pin_in_hole_many', fieldnames(cj_detect_pin_in_hole_many(pin_dims, [0 0 0 0 0 1], ...
                                                                               [0 0 0 0 sin(0.0125) cos(0.0125)])));
end

function expect_named(name, fields)
  text = evalc(['help ' name]);
  missing = {};
  for k = 1:numel(fields)
    if isempty(regexp(text, ['\<' fields{k} '\>'], 'once'))
      missing{end + 1} = fields{k};
    end
  end
  if !isempty(missing)
    error('help %s does not name the field(s) %s of its answer', name, strjoin(missing, ', '));
  end
  printf('help %s names all %d fields of its answer\n', name, numel(fields));
end
