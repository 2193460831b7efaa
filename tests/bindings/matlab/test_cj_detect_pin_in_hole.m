% SPDX-License-Identifier: BSD-3-Clause
% Tests of the MEX gateways cj_detect_pin_in_hole and cj_detect_pin_in_hole_many under Octave (run
% by ctest through octave-cli; errors fail the run). The pin-in-hole equivalence test compares every
% double with the C++ API; this one checks what a MATLAB user sees: scenarios, contacts, stops,
% several poses, the batch's arrays and errors.
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

  % The batch gateway: one struct of arrays, each pose's numbers the single call's, bit for bit.
  soa = cj_detect_pin_in_hole_many(dims, hole, pins);
  assert(isequal(size(soa.contact_count), [4 1]) && islogical(soa.aligned));
  assert(isequal(soa.scenario_code, [2; 4; 7; 0]));
  assert(isequal(soa.contact_count, [many.contact_count]') && isequal(soa.aligned, [many.aligned]'));
  assert(size(soa.depth, 2) == 2);  % K: the most contacts of any pose
  for i = 1:4
    assert(soa.certificate_level(i) == many(i).certificate.level_code);
    assert(soa.certificate_reason(i) == many(i).certificate.reason_code);
    for k = 1:many(i).contact_count
      c = many(i).contacts(k);
      assert(isequal(typecast(soa.depth(i, k), 'uint64'), typecast(c.depth, 'uint64')));
      assert(isequal(soa.p_WCj(i, :, k), c.p_WCj) && isequal(soa.p_WCi(i, :, k), c.p_WCi));
      assert(isequal(soa.normal_W(i, :, k), c.normal_W));
      assert(soa.type(i, k) == strcmp(c.type, 'axial') && soa.crossing_count(i, k) == numel(c.crossings));
      for m = 1:numel(c.crossings)
        assert(isequal(soa.crossing_angle(i, m, k), c.crossings(m).angle));
        assert(isequal(soa.crossing_point(i, :, m, k), c.crossings(m).point));
      end
    end
    assert(all(isnan(soa.depth(i, many(i).contact_count + 1:end))));
  end
  % Options reach every pose; a single pin row serves many holes.
  plain = cj_detect_pin_in_hole_many(dims, hole, pins, struct('certify', false));
  assert(all(plain.certificate_level == 2) && isequal(plain.contact_count, soa.contact_count));
  moved = cj_detect_pin_in_hole_many(dims, [hole; hole], pins(1, :));
  assert(isequal(moved.depth(1, :), moved.depth(2, :)) && isequal(moved.scenario_code, [2; 2]));
  % No contact anywhere: the contact arrays are empty (K = 0).
  none = cj_detect_pin_in_hole_many(dims, hole, [0 0 0 0 0 1; 0 0 0.1 0 0 1]);
  assert(isequal(none.scenario_code, [0; 0]) && isequal(size(none.depth), [2 0]));

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
  % The batch gateway counts poses from 0 across its chunks of 256; NaN in a pose is named too.
  batch = repmat(pins(1, :), 300, 1);
  batch(290, 4:6) = 0;
  expect_error(@() cj_detect_pin_in_hole_many(dims, hole, batch), ...
               'poses[289]: pin.axis_W = [0, 0, 0]: must not be the zero vector');
  batch = repmat(pins(1, :), 3, 1);
  batch(2, 2) = NaN;
  expect_error(@() cj_detect_pin_in_hole_many(dims, hole, batch), 'poses[1]: pin.p_WP = [0, nan, 0]');
  expect_error(@() cj_detect_pin_in_hole_many(thick, hole, pins), 'dimensions.pin_radius = 10');
  expect_error(@() cj_detect_pin_in_hole_many(dims, hole, pins(:, 1:5)), 'pins: must be a real double N x 6 matrix');
  expect_error(@() cj_detect_pin_in_hole_many(dims, [hole; hole], pins), 'holes (2 rows) and pins (4 rows)');
  expect_error(@() cj_detect_pin_in_hole_many(dims, hole, pins, struct('parallel_angle_tolerance', -1)), ...
               'options.parallel_angle_tolerance = -1');
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
