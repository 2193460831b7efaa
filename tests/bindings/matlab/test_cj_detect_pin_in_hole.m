% SPDX-License-Identifier: BSD-3-Clause
% Tests of the MEX gateway cj_detect_pin_in_hole under Octave (run by ctest through octave-cli;
% errors fail the run). The pin-in-hole equivalence test compares every double with the C++ API;
% this one checks what a MATLAB user sees: scenarios, contacts, stops, several poses and errors.
function test_cj_detect_pin_in_hole()
  % Hole radius 10, length 20, pin radius 9.9, heads at -10.5 and +10.5 of outer radius 16.
  dims = struct('hole_radius', 10, 'hole_length', 20, 'pin_radius', 9.9, 'stops', [-10.5 16; 10.5 16]);
  hole = [0 0 0 0 0 1];
  tilt = 0.0125;

  % A pin tilted about the hole's centre bears on both edges at opposite sides, at the depth of
  % the closed form 9.9 - 10 sqrt(1 - sin 2t) (tests/geometry/joint/test_detect_pin_in_hole_contacts.cpp).
  r = cj_detect_pin_in_hole(dims, hole, [0 0 0 0 sin(tilt) cos(tilt)]);
  assert(strcmp(r.scenario, 'both_edges_opposite') && r.scenario_code == 2 && ~r.aligned);
  assert(r.contact_count == 2 && strcmp(r.certificate.level, 'certified'));
  assert(strcmp(r.contacts(1).type, 'radial') && strcmp(r.contacts(1).base, 'a'));
  assert(strcmp(r.contacts(2).base, 'b'));
  assert(abs(r.contacts(1).depth - (9.9 - 10 * sqrt(1 - sin(2 * tilt)))) < 1e-12);
  c = r.contacts(1);
  assert(norm(c.p_WCj - c.p_WCi - c.depth * c.normal_W) < 1e-12);

  % Aligned, offset radially by 0.15: the line contact along the bore, depth 0.05.
  r = cj_detect_pin_in_hole(dims, hole, [0.15 0 0 0 0 1]);
  assert(strcmp(r.scenario, 'line') && r.aligned && strcmp(r.contacts(1).base, 'mid'));
  assert(abs(r.contacts(1).depth - 0.05) < 1e-12);
  % Pushed axially past the play of 0.5: a stop flush on its link face.
  r = cj_detect_pin_in_hole(dims, hole, [0 0 0.6 0 0 1]);
  assert(strcmp(r.scenario, 'face') && strcmp(r.contacts(1).type, 'axial'));
  % Without stops the same pin slides freely.
  free = rmfield(dims, 'stops');
  r = cj_detect_pin_in_hole(free, hole, [0 0 0.6 0 0 1]);
  assert(strcmp(r.scenario, 'none') && r.contact_count == 0 && isempty(r.contacts));
  free.stops = zeros(0, 2);
  assert(strcmp(cj_detect_pin_in_hole(free, hole, [0 0 0.6 0 0 1]).scenario, 'none'));

  % Options: certificates off make the answer uncertain, with the reason.
  r = cj_detect_pin_in_hole(dims, hole, [0 0 0 0 sin(tilt) cos(tilt)], struct('certify', false));
  assert(strcmp(r.certificate.level, 'uncertain') && ~isempty(r.certificate.reason));

  % N poses: an N x 1 struct array, each element the single call's answer.
  pins = [0 0 0 0 sin(tilt) cos(tilt); 0.15 0 0 0 0 1; 0 0 0.6 0 0 1; 0 0 0 0 0 1];
  many = cj_detect_pin_in_hole(dims, hole, pins);
  assert(isequal(size(many), [4 1]));
  for i = 1:4
    assert(isequal(many(i), cj_detect_pin_in_hole(dims, hole, pins(i, :))));
  end

  % Errors name the field and the value; with several poses, the pose (counted from 0).
  thick = dims;
  thick.pin_radius = 10;
  expect_error(@() cj_detect_pin_in_hole(thick, hole, pins(1, :)), 'dimensions.pin_radius = 10');
  inside = dims;
  inside.stops(2, 1) = 5;
  expect_error(@() cj_detect_pin_in_hole(inside, hole, pins(1, :)), 'dimensions.stops[1].position = 5');
  three = dims;
  three.stops = [-10.5 16; 10.5 16; 11 16];
  expect_error(@() cj_detect_pin_in_hole(three, hole, pins(1, :)), 'dims.stops: must be a real double K x 2');
  expect_error(@() cj_detect_pin_in_hole(rmfield(dims, 'hole_length'), hole, pins(1, :)), ...
               'dims.hole_length: missing');
  expect_error(@() cj_detect_pin_in_hole(dims, hole, [0 0 0 0 0 0]), 'pin.axis_W = [0, 0, 0]');
  bad = pins;
  bad(3, 4:6) = 0;
  expect_error(@() cj_detect_pin_in_hole(dims, hole, bad), 'poses[2]: pin.axis_W = [0, 0, 0]');
  expect_error(@() cj_detect_pin_in_hole(dims, [hole; hole], pins), 'hole (2 rows) and pin (4 rows)');
  disp('test_cj_detect_pin_in_hole: all assertions passed');
end

function expect_error(call, expected_text)
  try
    call();
  catch err
    assert(strcmp(err.identifier, 'clearjoint:invalidInput'), 'identifier %s', err.identifier);
    assert(~isempty(strfind(err.message, expected_text)), 'message "%s" lacks "%s"', err.message, ...
           expected_text);
    return;
  end
  error('no error raised; expected "%s"', expected_text);
end
