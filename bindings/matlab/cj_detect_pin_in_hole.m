% CJ_DETECT_PIN_IN_HOLE  Contacts of a pin in its hole, certified (clearjoint MEX file).
%
%   result = cj_detect_pin_in_hole(dims, hole, pin)
%   result = cj_detect_pin_in_hole(dims, hole, pin, options)
%
%   dims     struct with hole_radius, hole_length (between the link's two faces), pin_radius
%            and, optionally, stops: a K x 2 matrix [position, outer_radius] of the pin's axial
%            stops (K = 0, 1 or 2; absent or empty: a free sliding pin). A stop's position is
%            measured along the pin's axis from the pin's point P (any one length unit).
%   hole, pin
%            [p_WP, axis_W]: the hole's centre (midway between the link's faces) and axis, the
%            pin's point P (at the hole's centre when centred) and axis, in the world frame;
%            a 1 x 6 row or N x 6 rows; a single row serves every pose of the other argument.
%   options  struct with any of certify (logical, default true), exact_fallback (logical,
%            default true), parallel_angle_tolerance (radians, default 0).
%
%   result   N x 1 struct array with fields scenario ("none", "one_edge",
%            "both_edges_opposite", "both_edges_same_side", "line", "one_stop", "both_stops",
%            "face", "edges_and_stops", "line_and_face", "beyond_model"), scenario_code,
%            aligned, certificate (level, level_code, reason, reason_code), contact_count and
%            contacts. contacts is a contact_count x 1 struct array: type ("radial": an edge or
%            the line contact, "axial": a stop), base ("a"/"b": at link face A or B, "mid": the
%            line contact), depth, depth_error_bound, p_WCj (on the pin), p_WCj_error_bound,
%            p_WCi (on the link), p_WCi_error_bound, normal_W, crossings (angle,
%            angle_error_bound, point, point_error_bound, multiplicity) and certificate.
%            "No bound known" is Inf.
%
%   Bad input raises "clearjoint:invalidInput" with a message that names the field and value
%   ("dimensions.pin_radius = 10: must be smaller than hole_radius = 10 ...").
%
%   Example:
%     dims = struct('hole_radius', 10, 'hole_length', 20, 'pin_radius', 9.9, ...
%                   'stops', [-10.5 16; 10.5 16]);
%     r = cj_detect_pin_in_hole(dims, [0 0 0 0 0 1], [0 0 0 0 0.0125 1]);
%     r.scenario, r.contacts(1).depth
%
%   This file holds only the help text; the function is the MEX file cj_detect_pin_in_hole.mex
%   beside it. See also CJ_DETECT. Documentation: docs/languages.md (installed in
%   share/doc/clearjoint/docs).

% SPDX-License-Identifier: BSD-3-Clause
% MATLAB and Octave show a file's first comment block as its help text: the licence comes last.
