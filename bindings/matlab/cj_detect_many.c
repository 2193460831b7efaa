/* SPDX-License-Identifier: BSD-3-Clause */
/* MEX gateway: contact detection over many poses, answered as one struct of arrays, over the C
 * API's cj_detect_many. The same source builds with MATLAB's `mex` and Octave's `mkoctfile --mex`.
 *
 *   r = cj_detect_many(dims, bearings, journals)
 *   r = cj_detect_many(dims, bearings, journals, options)
 *
 * Arguments as for cj_detect (cj_detect.c): N x 6 rows [p_WP, axis_W], a single row repeats.
 * cj_detect answers with a struct per pose (convenient, but MATLAB values are costly to create
 * one by one); this answers with the struct of arrays of mex_columns.h, for large batches. Codes
 * are the C API's enum values (cj_scenario, cj_certainty, cj_reason, cj_contact_type, cj_base). */

#include "mex.h"

#include "clearjoint/clearjoint.h"
#include "mex_batch.h"
#include "mex_columns.h"
#include "mex_inputs.h"

static void store(void* context, size_t index, const cj_result* r) {
  mex_columns_store((mex_columns*)context, index, r->scenario, r->aligned, &r->certificate, r->contact_count,
                    r->contacts);
}

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  const mex_detection_inputs in = mex_detection_arguments(
      nrhs, prhs, "r = cj_detect_many(dims, bearings, journals [, options])", "bearings", "journals");
  mex_columns columns;
  if (nlhs > 1) mexErrMsgIdAndTxt("clearjoint:invalidInput", "cj_detect_many returns one value");
  mex_columns_create(&columns, in.count);
  mex_detect_all(&in.dims, &in.bearings, &in.journals, in.count, &in.options, store, &columns);
  plhs[0] = mex_columns_finish(&columns);
}
