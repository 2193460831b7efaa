/* SPDX-License-Identifier: BSD-3-Clause */
#ifndef CLEARJOINT_MEX_RESULTS_H
#define CLEARJOINT_MEX_RESULTS_H
/* The MEX gateway's output: C API results written as MATLAB structs.
 *
 * One result is a struct with fields
 *   scenario (char, "none", "a" ... "l", "beyond_model"), scenario_code (cj_scenario), aligned (logical),
 *   certificate (struct: level, level_code, reason, reason_code), contact_count, contacts;
 * contacts is a contact_count x 1 struct array with fields
 *   type ("radial"/"axial"), base ("a"/"b"/"mid"), depth, depth_error_bound,
 *   p_WCj, p_WCj_error_bound, p_WCi, p_WCi_error_bound, normal_W (1 x 3 each point),
 *   crossings (crossing_count x 1 struct array: angle, angle_error_bound, point, point_error_bound,
 *   multiplicity) and certificate.
 * Numbers are doubles; "no bound known" is Inf. */

#include "mex.h"

#include "clearjoint/clearjoint.h"

/* An N x 1 struct array with the result fields, to be filled by mex_set_result. */
mxArray* mex_create_results(size_t count);

/* Write `result` into element `index` of an array from mex_create_results. */
void mex_set_result(mxArray* results, size_t index, const cj_result* result);

/* The same fields for a pin-in-hole answer, scenario a cj_pin_in_hole_scenario key ("none",
 * "one_edge", ..., "beyond_model"). */
void mex_set_pin_in_hole_result(mxArray* results, size_t index, const cj_pin_in_hole_result* result);

#endif
