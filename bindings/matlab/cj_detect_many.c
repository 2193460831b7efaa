/* SPDX-License-Identifier: BSD-3-Clause */
/* MEX gateway: contact detection over many poses, answered as one struct of arrays, over the C
 * API's cj_detect_many. The same source builds with MATLAB's `mex` and Octave's `mkoctfile --mex`.
 *
 *   r = cj_detect_many(dims, bearings, journals)
 *   r = cj_detect_many(dims, bearings, journals, options)
 *
 * Arguments as for cj_detect (cj_detect.c): N x 6 rows [p_WP, axis_W], a single row repeats.
 * cj_detect answers with a struct per pose (convenient, but MATLAB values are costly to create
 * one by one); this answers with a fixed set of arrays whatever N is, for large batches:
 *   scenario_code, aligned, certificate_level, certificate_reason, contact_count: N x 1
 *   type, base, depth, depth_error_bound, p_WCj_error_bound, p_WCi_error_bound,
 *     crossing_count, certificate_level_of_contact, certificate_reason_of_contact: N x K
 *   p_WCj, p_WCi, normal_W: N x 3 x K (r.p_WCj(i, :, k) is pose i's contact k)
 *   crossing_angle, crossing_angle_error_bound, crossing_point_error_bound,
 *     crossing_multiplicity: N x 2 x K
 *   crossing_point: N x 3 x 2 x K
 * with K = max(contact_count) over the batch (at most 6; 0 when no pose has a contact, so the
 * arrays are empty).
 * Codes are the C API's enum values (cj_scenario, cj_certainty, cj_reason, cj_contact_type,
 * cj_base); slots past a pose's contact_count (or a contact's crossing_count) are NaN. */

#include <math.h>

#include "mex.h"

#include "clearjoint/clearjoint.h"
#include "mex_batch.h"
#include "mex_inputs.h"

enum field {
  SCENARIO_CODE, ALIGNED, CERTIFICATE_LEVEL, CERTIFICATE_REASON, CONTACT_COUNT,
  TYPE, BASE, DEPTH, DEPTH_ERROR_BOUND, P_WCJ_ERROR_BOUND, P_WCI_ERROR_BOUND, CROSSING_COUNT,
  CONTACT_CERTIFICATE_LEVEL, CONTACT_CERTIFICATE_REASON,
  P_WCJ, P_WCI, NORMAL_W,
  CROSSING_ANGLE, CROSSING_ANGLE_ERROR_BOUND, CROSSING_POINT_ERROR_BOUND, CROSSING_MULTIPLICITY,
  CROSSING_POINT,
  FIELD_COUNT
};

static const char* const kFieldNames[FIELD_COUNT] = {
    "scenario_code", "aligned", "certificate_level", "certificate_reason", "contact_count",
    "type", "base", "depth", "depth_error_bound", "p_WCj_error_bound", "p_WCi_error_bound",
    "crossing_count", "certificate_level_of_contact", "certificate_reason_of_contact",
    "p_WCj", "p_WCi", "normal_W",
    "crossing_angle", "crossing_angle_error_bound", "crossing_point_error_bound",
    "crossing_multiplicity", "crossing_point"};

/* The shape of each field: N, then the field's own dimensions. */
static void field_shape(int f, mwSize n, mwSize* dims, mwSize* ndims) {
  dims[0] = n;
  if (f <= CONTACT_COUNT) {
    dims[1] = 1;
    *ndims = 2;
  } else if (f <= CONTACT_CERTIFICATE_REASON) {
    dims[1] = CJ_MAX_CONTACTS;
    *ndims = 2;
  } else if (f <= NORMAL_W) {
    dims[1] = 3;
    dims[2] = CJ_MAX_CONTACTS;
    *ndims = 3;
  } else if (f <= CROSSING_MULTIPLICITY) {
    dims[1] = 2;
    dims[2] = CJ_MAX_CONTACTS;
    *ndims = 3;
  } else {
    dims[1] = 3;
    dims[2] = 2;
    dims[3] = CJ_MAX_CONTACTS;
    *ndims = 4;
  }
}

/* Write pose i's answer into the arrays (column-major, first index the pose). */
struct arrays {
  double* out[FIELD_COUNT];
  mwSize n;
  int most_contacts; /* over the poses so far */
};

static void store(void* context, size_t index, const cj_result* r) {
  double* const* out = ((struct arrays*)context)->out;
  const mwSize n = ((struct arrays*)context)->n, i = (mwSize)index;
  int k, m, c;
  if (r->contact_count > ((struct arrays*)context)->most_contacts) {
    ((struct arrays*)context)->most_contacts = r->contact_count;
  }
  out[SCENARIO_CODE][i] = r->scenario;
  out[ALIGNED][i] = r->aligned;
  out[CERTIFICATE_LEVEL][i] = r->certificate.level;
  out[CERTIFICATE_REASON][i] = r->certificate.reason;
  out[CONTACT_COUNT][i] = r->contact_count;
  for (k = 0; k < r->contact_count; ++k) {
    const cj_contact* x = &r->contacts[k];
    const mwSize ik = i + n * k;
    out[TYPE][ik] = x->type;
    out[BASE][ik] = x->base;
    out[DEPTH][ik] = x->depth;
    out[DEPTH_ERROR_BOUND][ik] = x->depth_error_bound;
    out[P_WCJ_ERROR_BOUND][ik] = x->p_WCj_error_bound;
    out[P_WCI_ERROR_BOUND][ik] = x->p_WCi_error_bound;
    out[CROSSING_COUNT][ik] = x->crossing_count;
    out[CONTACT_CERTIFICATE_LEVEL][ik] = x->certificate.level;
    out[CONTACT_CERTIFICATE_REASON][ik] = x->certificate.reason;
    for (c = 0; c < 3; ++c) {
      const mwSize ick = i + n * (c + 3 * k);
      out[P_WCJ][ick] = x->p_WCj[c];
      out[P_WCI][ick] = x->p_WCi[c];
      out[NORMAL_W][ick] = x->normal_W[c];
    }
    for (m = 0; m < x->crossing_count; ++m) {
      const cj_crossing* s = &x->crossings[m];
      const mwSize imk = i + n * (m + 2 * k);
      out[CROSSING_ANGLE][imk] = s->angle;
      out[CROSSING_ANGLE_ERROR_BOUND][imk] = s->angle_error_bound;
      out[CROSSING_POINT_ERROR_BOUND][imk] = s->point_error_bound;
      out[CROSSING_MULTIPLICITY][imk] = s->multiplicity;
      for (c = 0; c < 3; ++c) out[CROSSING_POINT][i + n * (c + 3 * (m + 2 * k))] = s->point[c];
    }
  }
}

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[]) {
  const mex_detection_inputs in = mex_detection_arguments(
      nrhs, prhs, "r = cj_detect_many(dims, bearings, journals [, options])", "bearings", "journals");
  mxArray *result, *logicals;
  mxLogical* aligned;
  struct arrays arrays;
  size_t k;
  int f;
  if (nlhs > 1) mexErrMsgIdAndTxt("clearjoint:invalidInput", "cj_detect_many returns one value");
  arrays.n = (mwSize)in.count;
  result = mxCreateStructMatrix(1, 1, FIELD_COUNT, (const char**)kFieldNames);
  for (f = 0; f < FIELD_COUNT; ++f) {
    mwSize shape[4], ndims, total = 1, d;
    mxArray* array;
    field_shape(f, arrays.n, shape, &ndims);
    array = mxCreateNumericArray(ndims, shape, mxDOUBLE_CLASS, mxREAL);
    arrays.out[f] = mxGetPr(array);
    for (d = 0; d < ndims; ++d) total *= shape[d];
    for (d = 0; d < total; ++d) arrays.out[f][d] = NAN;
    mxSetFieldByNumber(result, 0, f, array);
  }
  arrays.most_contacts = 0;
  mex_detect_all(&in.dims, &in.bearings, &in.journals, in.count, &in.options, store, &arrays);
  /* The contact slot is every field's last dimension: dropping the slots no pose uses keeps the
   * data as it is and spares Octave/MATLAB copying them (a batch rarely has more than two
   * contacts a pose, and 6 slots are ~1.6 KB a pose). */
  for (f = TYPE; f < FIELD_COUNT; ++f) {
    mxArray* array = mxGetFieldByNumber(result, 0, f);
    mwSize shape[4];
    const mwSize ndims = mxGetNumberOfDimensions(array);
    mwSize d;
    for (d = 0; d < ndims; ++d) shape[d] = mxGetDimensions(array)[d];
    shape[ndims - 1] = arrays.most_contacts;
    mxSetDimensions(array, shape, ndims);
  }
  /* The aligned flags as logicals, as in cj_detect. */
  logicals = mxCreateLogicalMatrix(arrays.n, 1);
  aligned = mxGetLogicals(logicals);
  for (k = 0; k < in.count; ++k) aligned[k] = arrays.out[ALIGNED][k] != 0.0;
  mxDestroyArray(mxGetFieldByNumber(result, 0, ALIGNED));
  mxSetFieldByNumber(result, 0, ALIGNED, logicals);
  plhs[0] = result;
}
