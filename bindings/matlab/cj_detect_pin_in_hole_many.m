% CJ_DETECT_PIN_IN_HOLE_MANY  Contacts of a pin in its hole over many poses, as arrays
% (clearjoint MEX file).
%
%   r = cj_detect_pin_in_hole_many(dims, holes, pins)
%   r = cj_detect_pin_in_hole_many(dims, holes, pins, options)
%
%   Arguments as for cj_detect_pin_in_hole: dims a struct with hole_radius, hole_length,
%   pin_radius and optionally stops (K x 2 [position, outer_radius], K <= 2); holes and pins
%   N x 6 rows [p_WP, axis_W] (a single row repeats); options certify, exact_fallback,
%   parallel_angle_tolerance.
%
%   r is one struct of arrays, whatever N is, as cj_detect_many's, with K = max(contact_count)
%   over the batch (at most 6; 0 when no pose has a contact):
%     scenario_code, aligned, certificate_level, certificate_reason, contact_count: N x 1
%     type, base, depth, depth_error_bound, p_WCj_error_bound, p_WCi_error_bound,
%       crossing_count, certificate_level_of_contact, certificate_reason_of_contact: N x K
%     p_WCj, p_WCi, normal_W: N x 3 x K (r.p_WCj(i, :, k) is pose i's contact k)
%     crossing_angle, crossing_angle_error_bound, crossing_point_error_bound,
%       crossing_multiplicity: N x 2 x K
%     crossing_point: N x 3 x 2 x K
%   scenario_code is a cj_pin_in_hole_scenario code (0 none, 1 one_edge,
%   2 both_edges_opposite, 3 both_edges_same_side, 4 line, 5 one_stop, 6 both_stops, 7 face,
%   8 edges_and_stops, 9 line_and_face, 10 beyond_model); the other codes are the C API's
%   (cj_certainty, cj_reason, cj_contact_type: 0 radial, an edge or the line contact, 1 axial,
%   a stop; cj_base: 0 a, 1 b, the link face, 2 mid, the line contact). p_WCj is on the pin,
%   p_WCi on the link. Slots past a pose's contact_count, or a contact's crossing_count, are
%   NaN. Each pose's numbers are those cj_detect_pin_in_hole gives for it, bit for bit.
%
%   Bad input raises "clearjoint:invalidInput" naming the field and value, and the pose counted
%   from 0 ("poses[17]: pin.axis_W = [0, 0, 0]: must not be the zero vector").
%
%   Example:
%     dims = struct('hole_radius', 10, 'hole_length', 20, 'pin_radius', 9.9, ...
%                   'stops', [-10.5 16; 10.5 16]);
%     pins = [0.2 * rand(1000, 3) - 0.1, repmat([0 0 1], 1000, 1)];
%     r = cj_detect_pin_in_hole_many(dims, [0 0 0 0 0 1], pins);
%     histc(r.scenario_code, 0:10)
%
%   This file holds only the help text; the function is the MEX file
%   cj_detect_pin_in_hole_many.mex beside it. See also CJ_DETECT_PIN_IN_HOLE, CJ_DETECT_MANY.
%   Documentation: docs/languages.md (installed in share/doc/clearjoint/docs).

% SPDX-License-Identifier: BSD-3-Clause
% MATLAB and Octave show a file's first comment block as its help text: the licence comes last.
