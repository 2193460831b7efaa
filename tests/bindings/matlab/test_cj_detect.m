% SPDX-License-Identifier: BSD-3-Clause
% Tests of the MEX gateways cj_detect and cj_detect_many under Octave (run by ctest through
% octave-cli; errors fail the run). The equivalence test compares every double with the C++ API;
% this one checks what a MATLAB user sees: scenarios, contacts, layouts and errors.
function test_cj_detect()
  table2 = struct('bearing_radius', 10, 'bearing_length', 20, 'journal_radius', 9.9, ...
                  'journal_length', 19.8);
  bearing = [0 0 0 0 0 1];
  tilted = @(y0, z0, tilt) [0 y0 z0 0 sin(tilt) cos(tilt)];

  % Scenario (e) of Fig. 2: a radial and an axial contact at base A, as in the C++ tests.
  r = cj_detect(table2, bearing, tilted(0.08, 0.08, 0.005));
  assert(strcmp(r.scenario, 'e'));
  assert(r.scenario_code == 5 && ~r.aligned && r.contact_count == 2);
  assert(strcmp(r.certificate.level, 'certified') && strcmp(r.certificate.reason, ''));
  assert(strcmp(r.contacts(1).type, 'radial') && strcmp(r.contacts(1).base, 'a'));
  assert(strcmp(r.contacts(2).type, 'axial') && strcmp(r.contacts(2).base, 'a'));
  assert(numel(r.contacts(1).crossings) == 2 && r.contacts(1).crossings(1).multiplicity == 1);
  c = r.contacts(1);
  % p_WCj - p_WCi = depth * normal_W (eqs. 22-23), up to rounding of O(10) mm coordinates.
  assert(norm(c.p_WCj - c.p_WCi - c.depth * c.normal_W) < 1e-12);

  % Aligned journal pushed along +y: the line contact (j), depth e - cr = 0.05.
  r = cj_detect(table2, bearing, [0 0.15 0.02 0 0 1]);
  assert(strcmp(r.scenario, 'j') && r.aligned && strcmp(r.contacts(1).base, 'mid'));
  assert(abs(r.contacts(1).depth - 0.05) < 1e-12);
  % Free flight: an empty contact array.
  r = cj_detect(table2, bearing, tilted(0, 0, 0.005));
  assert(strcmp(r.scenario, 'none') && r.contact_count == 0 && isempty(r.contacts));

  % Options: certificates off make every answer uncertain, with the reason.
  r = cj_detect(table2, bearing, tilted(0.08, 0.08, 0.005), struct('certify', false));
  assert(strcmp(r.certificate.level, 'uncertain') && ~isempty(r.certificate.reason));

  % N poses: a struct array from cj_detect and arrays from cj_detect_many, the same numbers.
  journals = [tilted(0.08, 0.08, 0.005); tilted(0, 0, 0.005); tilted(0, 0, 0.013); ...
              tilted(0.08, -0.08, 0.005); [0 0.15 -0.13 0 0 -1]];
  many = cj_detect(table2, bearing, journals);
  soa = cj_detect_many(table2, bearing, journals);
  assert(isequal(size(many), [5 1]) && isequal(size(soa.contact_count), [5 1]));
  assert(isequal([many.scenario_code]', soa.scenario_code));
  assert(isequal([many.contact_count]', soa.contact_count));
  for i = 1:5
    for k = 1:many(i).contact_count
      assert(isequal(many(i).contacts(k).depth, soa.depth(i, k)));
      assert(isequal(many(i).contacts(k).p_WCj, soa.p_WCj(i, :, k)));
      assert(isequal(many(i).contacts(k).normal_W, soa.normal_W(i, :, k)));
    end
    % Slots past the contacts are NaN.
    assert(all(isnan(soa.depth(i, many(i).contact_count + 1:end))));
  end
  assert(all(soa.scenario_code == [5; 0; 9; 6; 12]));
  % One journal against many bearings broadcasts the same way.
  moved = cj_detect_many(table2, [bearing; bearing], journals(1, :));
  assert(isequaln(moved.depth(1, :), moved.depth(2, :)) && moved.contact_count(1) == 2);

  % Errors name the field and the value; in a batch, the pose (counted from 0).
  expect_error(@() cj_detect(table2, bearing, [0 0 0 0 0 0]), ...
               'journal.axis_W = [0, 0, 0]: must not be the zero vector');
  bad_dims = table2;
  bad_dims.journal_radius = 10;
  expect_error(@() cj_detect(bad_dims, bearing, tilted(0, 0, 0)), 'dimensions.journal_radius = 10');
  expect_error(@() cj_detect(rmfield(table2, 'journal_length'), bearing, tilted(0, 0, 0)), ...
               'dims.journal_length: missing');
  expect_error(@() cj_detect(table2, bearing, [0 0 0 0 1]), 'journal: must be a real double N x 6 matrix');
  expect_error(@() cj_detect(table2, bearing, tilted(0, 0, 0), struct('tolerance', 1)), ...
               'options.tolerance: unknown field');
  expect_error(@() cj_detect(table2, bearing, tilted(0, 0, 0), struct('parallel_angle_tolerance', -1)), ...
               'options.parallel_angle_tolerance = -1');
  batch = repmat(tilted(0, 0, 0.005), 300, 1);
  batch(290, 4:6) = 0;  % pose 289 counted from 0, in the second chunk of 256
  expect_error(@() cj_detect_many(table2, bearing, batch), ...
               'poses[289]: journal.axis_W = [0, 0, 0]: must not be the zero vector');
  expect_error(@() cj_detect(table2, bearing, batch), 'poses[289]: journal.axis_W');
  expect_error(@() cj_detect_many(table2, [bearing; bearing], journals), ...
               'bearings (2 rows) and journals (5 rows)');
  disp('test_cj_detect: all assertions passed');
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
