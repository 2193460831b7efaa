/* SPDX-License-Identifier: BSD-3-Clause */
#ifndef CLEARJOINT_MEX_COLUMNS_H
#define CLEARJOINT_MEX_COLUMNS_H
/* The batch gateways' answer (cj_detect_many, cj_detect_pin_in_hole_many): one struct of arrays,
 * a fixed set of fields whatever N is (MATLAB values are costly to create one by one):
 *   scenario_code, aligned, certificate_level, certificate_reason, contact_count: N x 1
 *   type, base, depth, depth_error_bound, p_WCj_error_bound, p_WCi_error_bound,
 *     crossing_count, certificate_level_of_contact, certificate_reason_of_contact: N x K
 *   p_WCj, p_WCi, normal_W: N x 3 x K (r.p_WCj(i, :, k) is pose i's contact k)
 *   crossing_angle, crossing_angle_error_bound, crossing_point_error_bound,
 *     crossing_multiplicity: N x 2 x K
 *   crossing_point: N x 3 x 2 x K
 * with K = max(contact_count) over the batch (at most 6; 0 when no pose has a contact, so the
 * arrays are empty). Codes are the C API's enum values; slots past a pose's contact_count (or a
 * contact's crossing_count) are NaN. */

#include "mex.h"

#include "clearjoint/clearjoint.h"

enum mex_column {
  MEX_SCENARIO_CODE, MEX_ALIGNED, MEX_CERTIFICATE_LEVEL, MEX_CERTIFICATE_REASON, MEX_CONTACT_COUNT,
  MEX_TYPE, MEX_BASE, MEX_DEPTH, MEX_DEPTH_ERROR_BOUND, MEX_P_WCJ_ERROR_BOUND, MEX_P_WCI_ERROR_BOUND,
  MEX_CROSSING_COUNT, MEX_CONTACT_CERTIFICATE_LEVEL, MEX_CONTACT_CERTIFICATE_REASON,
  MEX_P_WCJ, MEX_P_WCI, MEX_NORMAL_W,
  MEX_CROSSING_ANGLE, MEX_CROSSING_ANGLE_ERROR_BOUND, MEX_CROSSING_POINT_ERROR_BOUND,
  MEX_CROSSING_MULTIPLICITY, MEX_CROSSING_POINT,
  MEX_COLUMN_COUNT
};

/* The answer being filled: its struct and each field's data (column-major, first index the pose). */
typedef struct mex_columns {
  mxArray* result;
  double* out[MEX_COLUMN_COUNT];
  mwSize n;
  int most_contacts; /* over the poses so far */
} mex_columns;

/* The struct of arrays for n poses, every slot NaN. */
void mex_columns_create(mex_columns* columns, size_t n);

/* Pose `index`'s answer: the members cj_result and cj_pin_in_hole_result share. */
void mex_columns_store(mex_columns* columns, size_t index, int32_t scenario, int32_t aligned,
                       const cj_certificate* certificate, int32_t contact_count, const cj_contact* contacts);

/* The finished answer: the contact slots no pose uses dropped, aligned as logicals. */
mxArray* mex_columns_finish(mex_columns* columns);

#endif
