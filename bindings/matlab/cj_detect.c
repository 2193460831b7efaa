/* SPDX-License-Identifier: BSD-3-Clause */
/* MEX gateway: contact detection from MATLAB and Octave, over the C API (clearjoint.h).
 * Written against the MEX API only, so the same source builds with MATLAB's `mex` and with
 * Octave's `mkoctfile --mex`.
 *
 *   result = cj_detect(dims, bearing, journal)
 *   result = cj_detect(dims, bearing, journal, options)
 *
 * dims: struct (bearing_radius, bearing_length, journal_radius, journal_length).
 * bearing, journal: [p_WP, axis_W] rows, 1 x 6 or N x 6; a single row serves every pose of the
 * other argument. options: struct with any of certify, exact_fallback, parallel_angle_tolerance.
 * result: N x 1 struct array (mex_results.h lists the fields). For large N, cj_detect_many
 * answers the same as arrays, much faster. Errors: "clearjoint:invalidInput" with the C API's
 * message, which names the field and value ("journal.axis_W = [0, 0, 0]: must not be the zero
 * vector"; with N > 1, "poses[k]: ..." with k counted from 0). */

#include "mex.h"

#include "clearjoint/clearjoint.h"
#include "mex_batch.h"
#include "mex_inputs.h"
#include "mex_results.h"

static void set_result(void* results, size_t index, const cj_result* result) {
  mex_set_result((mxArray*)results, index, result);
}

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  const mex_detection_inputs in = mex_detection_arguments(
      nrhs, prhs, "result = cj_detect(dims, bearing, journal [, options])", "bearing", "journal");
  mxArray* results;
  if (nlhs > 1) mexErrMsgIdAndTxt("clearjoint:invalidInput", "cj_detect returns one value");
  results = mex_create_results(in.count);
  if (in.count == 1) {
    /* One pose: cj_detect, whose messages name the field without a pose index. */
    cj_pose bearing, journal;
    cj_result result;
    char message[1024];
    int c, status;
    for (c = 0; c < 3; ++c) {
      bearing.p_WP[c] = *in.bearings.component[c];
      bearing.axis_W[c] = *in.bearings.component[c + 3];
      journal.p_WP[c] = *in.journals.component[c];
      journal.axis_W[c] = *in.journals.component[c + 3];
    }
    status = cj_detect(&in.dims, &bearing, &journal, &in.options, &result, message, sizeof message);
    if (status != CJ_OK) mex_raise(status, message);
    mex_set_result(results, 0, &result);
  } else {
    mex_detect_all(&in.dims, &in.bearings, &in.journals, in.count, &in.options, set_result, results);
  }
  plhs[0] = results;
}
