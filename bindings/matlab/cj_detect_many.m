% CJ_DETECT_MANY  Contacts of a revolute joint with clearance over many poses, as arrays
% (clearjoint MEX file).
%
%   r = cj_detect_many(dims, bearings, journals)
%   r = cj_detect_many(dims, bearings, journals, options)
%
%   Arguments as for cj_detect: dims a struct of the four lengths; bearings and journals
%   N x 6 rows [p_WP, axis_W] (a single row repeats); options certify, exact_fallback,
%   parallel_angle_tolerance.
%
%   r is one struct of arrays, whatever N is, with K = max(contact_count) over the batch
%   (at most 6; 0 when no pose has a contact):
%     scenario_code, aligned, certificate_level, certificate_reason, contact_count: N x 1
%     type, base, depth, depth_error_bound, p_WCj_error_bound, p_WCi_error_bound,
%       crossing_count, certificate_level_of_contact, certificate_reason_of_contact: N x K
%     p_WCj, p_WCi, normal_W: N x 3 x K (r.p_WCj(i, :, k) is pose i's contact k)
%     crossing_angle, crossing_angle_error_bound, crossing_point_error_bound,
%       crossing_multiplicity: N x 2 x K
%     crossing_point: N x 3 x 2 x K
%   Codes are the C API's enum values (cj_scenario, cj_certainty, cj_reason,
%   cj_contact_type, cj_base); slots past a pose's contact_count, or a contact's
%   crossing_count, are NaN.
%
%   Example:
%     dims = struct('bearing_radius', 10, 'bearing_length', 20, ...
%                   'journal_radius', 9.9, 'journal_length', 19.8);
%     journals = [0.2 * rand(1000, 3) - 0.1, repmat([0 0 1], 1000, 1)];
%     r = cj_detect_many(dims, [0 0 0 0 0 1], journals);
%     histc(r.scenario_code, 0:13)
%
%   This file holds only the help text; the function is the MEX file cj_detect_many.mex
%   beside it. See also CJ_DETECT. Documentation: docs/languages.md (installed in share/doc/clearjoint/docs).

% SPDX-License-Identifier: BSD-3-Clause
% MATLAB and Octave show a file's first comment block as its help text: the licence comes last.
