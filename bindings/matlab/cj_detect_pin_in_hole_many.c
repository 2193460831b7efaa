/* SPDX-License-Identifier: BSD-3-Clause */
/* MEX gateway: contact detection in a pin-in-hole joint over many poses, answered as one struct
 * of arrays (mex_columns.h), over the C API's cj_detect_pin_in_hole_many. The same source builds
 * with MATLAB's `mex` and Octave's `mkoctfile --mex`.
 *
 *   r = cj_detect_pin_in_hole_many(dims, holes, pins)
 *   r = cj_detect_pin_in_hole_many(dims, holes, pins, options)
 *
 * Arguments as for cj_detect_pin_in_hole (cj_detect_pin_in_hole.c): N x 6 rows [p_WP, axis_W], a
 * single row repeats. The answer is cj_detect_many's struct of arrays, scenario_code a
 * cj_pin_in_hole_scenario code. Errors: "clearjoint:invalidInput" with the C API's message, the
 * pose named by its index from 0 ("poses[k]: pin.axis_W = ..."). */

#include "mex.h"

#include "clearjoint/clearjoint.h"
#include "mex_batch.h"
#include "mex_columns.h"
#include "mex_inputs.h"

static void store(void* context, size_t index, const cj_pin_in_hole_result* r) {
  mex_columns_store((mex_columns*)context, index, r->scenario, r->aligned, &r->certificate, r->contact_count,
                    r->contacts);
}

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  static const char usage[] = "r = cj_detect_pin_in_hole_many(dims, holes, pins [, options])";
  cj_pin_in_hole_dimensions dims;
  cj_pose_array holes, pins;
  cj_options options;
  size_t hole_rows = 0, pin_rows = 0, count;
  mex_columns columns;
  if (nlhs > 1) mexErrMsgIdAndTxt("clearjoint:invalidInput", "cj_detect_pin_in_hole_many returns one value");
  if (nrhs < 3 || nrhs > 4) mexErrMsgIdAndTxt("clearjoint:invalidInput", "usage: %s", usage);
  dims = mex_pin_in_hole_dimensions(prhs[0]);
  holes = mex_poses(prhs[1], "holes", &hole_rows);
  pins = mex_poses(prhs[2], "pins", &pin_rows);
  options = nrhs == 4 ? mex_options(prhs[3]) : cj_default_options();
  if (hole_rows != pin_rows && hole_rows != 1 && pin_rows != 1) {
    mexErrMsgIdAndTxt("clearjoint:invalidInput", "holes (%d rows) and pins (%d rows): must have as many rows, or one of them 1",
                      (int)hole_rows, (int)pin_rows);
  }
  count = hole_rows > pin_rows ? hole_rows : pin_rows;
  if (hole_rows == 1) holes.stride = 0;
  if (pin_rows == 1) pins.stride = 0;
  mex_columns_create(&columns, count);
  mex_detect_pin_in_hole_all(&dims, &holes, &pins, count, &options, store, &columns);
  plhs[0] = mex_columns_finish(&columns);
}
