% CJ_DETECT  Contacts of a revolute joint with clearance, certified (clearjoint MEX file).
%
%   result = cj_detect(dims, bearing, journal)
%   result = cj_detect(dims, bearing, journal, options)
%
%   dims     struct with bearing_radius, bearing_length, journal_radius, journal_length
%            (any one length unit).
%   bearing, journal
%            [p_WP, axis_W]: the cylinder's centre and axis in the world frame, a 1 x 6 row or
%            N x 6 rows; a single row serves every pose of the other argument.
%   options  struct with any of certify (logical, default true), exact_fallback (logical,
%            default true), parallel_angle_tolerance (radians, default 0).
%
%   result   N x 1 struct array with fields scenario ("none", "a" ... "l", "beyond_model"),
%            scenario_code, aligned, certificate (level, level_code, reason, reason_code),
%            contact_count and contacts. contacts is a contact_count x 1 struct array: type
%            ("radial"/"axial"), base ("a"/"b"/"mid"), depth, depth_error_bound, p_WCj,
%            p_WCj_error_bound, p_WCi, p_WCi_error_bound, normal_W, crossings (angle,
%            angle_error_bound, point, point_error_bound, multiplicity) and certificate.
%            "No bound known" is Inf.
%
%   Bad input raises "clearjoint:invalidInput" with a message that names the field and value.
%   For large N, cj_detect_many gives the same answers as arrays, much faster.
%
%   Example:
%     dims = struct('bearing_radius', 10, 'bearing_length', 20, ...
%                   'journal_radius', 9.9, 'journal_length', 19.8);
%     r = cj_detect(dims, [0 0 0 0 0 1], [0 0.15 0.02 0 0 1]);
%     r.scenario, r.contacts(1).depth
%
%   This file holds only the help text; the function is the MEX file cj_detect.mex beside it.
%   See also CJ_DETECT_MANY. Documentation: docs/languages.md (installed in share/doc/clearjoint/docs).

% SPDX-License-Identifier: BSD-3-Clause
% MATLAB and Octave show a file's first comment block as its help text: the licence comes last.
