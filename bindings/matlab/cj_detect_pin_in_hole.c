/* SPDX-License-Identifier: BSD-3-Clause */
/* MEX gateway: contact detection in a pin-in-hole joint from MATLAB and Octave, over the C API
 * (cj_detect_pin_in_hole in clearjoint.h). Written against the MEX API only, as cj_detect.c.
 *
 *   result = cj_detect_pin_in_hole(dims, hole, pin)
 *   result = cj_detect_pin_in_hole(dims, hole, pin, options)
 *
 * dims: struct (hole_radius, hole_length, pin_radius, optional stops: K x 2 [position,
 * outer_radius], K <= 2). hole, pin: [p_WP, axis_W] rows, 1 x 6 or N x 6; a single row serves
 * every pose of the other argument. options: as cj_detect's. result: N x 1 struct array with
 * cj_detect's fields (mex_results.h), the scenario a pin-in-hole key. Errors:
 * "clearjoint:invalidInput" with the C API's message, which names the field and value (with
 * N > 1, "poses[k]: ..." with k counted from 0). */

#include <stdio.h>

#include "mex.h"

#include "clearjoint/clearjoint.h"
#include "mex_batch.h"
#include "mex_inputs.h"
#include "mex_results.h"

#define MESSAGE_CAPACITY 1024

/* Pose k of `poses` (stride 0: the same pose for every k). */
static cj_pose pose_at(const cj_pose_array* poses, size_t k) {
  cj_pose pose;
  int c;
  for (c = 0; c < 3; ++c) {
    pose.p_WP[c] = *(const double*)((const char*)poses->component[c] + (ptrdiff_t)k * poses->stride);
    pose.axis_W[c] = *(const double*)((const char*)poses->component[c + 3] + (ptrdiff_t)k * poses->stride);
  }
  return pose;
}

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  static const char usage[] = "result = cj_detect_pin_in_hole(dims, hole, pin [, options])";
  cj_pin_in_hole_dimensions dims;
  cj_pose_array holes, pins;
  cj_options options;
  size_t hole_rows = 0, pin_rows = 0, count, k;
  mxArray* results;
  if (nlhs > 1) mexErrMsgIdAndTxt("clearjoint:invalidInput", "cj_detect_pin_in_hole returns one value");
  if (nrhs < 3 || nrhs > 4) mexErrMsgIdAndTxt("clearjoint:invalidInput", "usage: %s", usage);
  dims = mex_pin_in_hole_dimensions(prhs[0]);
  holes = mex_poses(prhs[1], "hole", &hole_rows);
  pins = mex_poses(prhs[2], "pin", &pin_rows);
  options = nrhs == 4 ? mex_options(prhs[3]) : cj_default_options();
  if (hole_rows != pin_rows && hole_rows != 1 && pin_rows != 1) {
    mexErrMsgIdAndTxt("clearjoint:invalidInput", "hole (%d rows) and pin (%d rows): must have as many rows, or one of them 1",
                      (int)hole_rows, (int)pin_rows);
  }
  count = hole_rows > pin_rows ? hole_rows : pin_rows;
  if (hole_rows == 1) holes.stride = 0;
  if (pin_rows == 1) pins.stride = 0;
  results = mex_create_results(count);
  for (k = 0; k < count; ++k) {
    const cj_pose hole = pose_at(&holes, k), pin = pose_at(&pins, k);
    cj_pin_in_hole_result result;
    char message[MESSAGE_CAPACITY];
    const int status = cj_detect_pin_in_hole(&dims, &hole, &pin, &options, &result, message, sizeof message);
    if (status != CJ_OK) {
      /* One pose: the message names the field alone, as cj_detect's does; more: the pose too. */
      char numbered[MESSAGE_CAPACITY + 32];
      if (count > 1) {
        snprintf(numbered, sizeof numbered, "poses[%lu]: %s", (unsigned long)k, message);
        mex_raise(status, numbered);
      }
      mex_raise(status, message);
    }
    mex_set_pin_in_hole_result(results, k, &result);
  }
  plhs[0] = results;
}
