/* SPDX-License-Identifier: BSD-3-Clause */
/* The batch gateways' struct of arrays (mex_columns.h). */
#include "mex_columns.h"

#include <math.h>

static const char* const kFieldNames[MEX_COLUMN_COUNT] = {
    "scenario_code", "aligned", "certificate_level", "certificate_reason", "contact_count",
    "type", "base", "depth", "depth_error_bound", "p_WCj_error_bound", "p_WCi_error_bound",
    "crossing_count", "certificate_level_of_contact", "certificate_reason_of_contact",
    "p_WCj", "p_WCi", "normal_W",
    "crossing_angle", "crossing_angle_error_bound", "crossing_point_error_bound",
    "crossing_multiplicity", "crossing_point"};

/* The shape of each field: N, then the field's own dimensions. */
static void field_shape(int f, mwSize n, mwSize* dims, mwSize* ndims) {
  dims[0] = n;
  if (f <= MEX_CONTACT_COUNT) {
    dims[1] = 1;
    *ndims = 2;
  } else if (f <= MEX_CONTACT_CERTIFICATE_REASON) {
    dims[1] = CJ_MAX_CONTACTS;
    *ndims = 2;
  } else if (f <= MEX_NORMAL_W) {
    dims[1] = 3;
    dims[2] = CJ_MAX_CONTACTS;
    *ndims = 3;
  } else if (f <= MEX_CROSSING_MULTIPLICITY) {
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

void mex_columns_create(mex_columns* columns, size_t n) {
  int f;
  columns->n = (mwSize)n;
  columns->most_contacts = 0;
  columns->result = mxCreateStructMatrix(1, 1, MEX_COLUMN_COUNT, (const char**)kFieldNames);
  for (f = 0; f < MEX_COLUMN_COUNT; ++f) {
    mwSize shape[4], ndims, total = 1, d;
    mxArray* array;
    field_shape(f, columns->n, shape, &ndims);
    array = mxCreateNumericArray(ndims, shape, mxDOUBLE_CLASS, mxREAL);
    columns->out[f] = mxGetPr(array);
    for (d = 0; d < ndims; ++d) total *= shape[d];
    for (d = 0; d < total; ++d) columns->out[f][d] = NAN;
    mxSetFieldByNumber(columns->result, 0, f, array);
  }
}

void mex_columns_store(mex_columns* columns, size_t index, int32_t scenario, int32_t aligned,
                       const cj_certificate* certificate, int32_t contact_count, const cj_contact* contacts) {
  double* const* out = columns->out;
  const mwSize n = columns->n, i = (mwSize)index;
  int k, m, c;
  if (contact_count > columns->most_contacts) columns->most_contacts = contact_count;
  out[MEX_SCENARIO_CODE][i] = scenario;
  out[MEX_ALIGNED][i] = aligned;
  out[MEX_CERTIFICATE_LEVEL][i] = certificate->level;
  out[MEX_CERTIFICATE_REASON][i] = certificate->reason;
  out[MEX_CONTACT_COUNT][i] = contact_count;
  for (k = 0; k < contact_count; ++k) {
    const cj_contact* x = &contacts[k];
    const mwSize ik = i + n * k;
    out[MEX_TYPE][ik] = x->type;
    out[MEX_BASE][ik] = x->base;
    out[MEX_DEPTH][ik] = x->depth;
    out[MEX_DEPTH_ERROR_BOUND][ik] = x->depth_error_bound;
    out[MEX_P_WCJ_ERROR_BOUND][ik] = x->p_WCj_error_bound;
    out[MEX_P_WCI_ERROR_BOUND][ik] = x->p_WCi_error_bound;
    out[MEX_CROSSING_COUNT][ik] = x->crossing_count;
    out[MEX_CONTACT_CERTIFICATE_LEVEL][ik] = x->certificate.level;
    out[MEX_CONTACT_CERTIFICATE_REASON][ik] = x->certificate.reason;
    for (c = 0; c < 3; ++c) {
      const mwSize ick = i + n * (c + 3 * k);
      out[MEX_P_WCJ][ick] = x->p_WCj[c];
      out[MEX_P_WCI][ick] = x->p_WCi[c];
      out[MEX_NORMAL_W][ick] = x->normal_W[c];
    }
    for (m = 0; m < x->crossing_count; ++m) {
      const cj_crossing* s = &x->crossings[m];
      const mwSize imk = i + n * (m + 2 * k);
      out[MEX_CROSSING_ANGLE][imk] = s->angle;
      out[MEX_CROSSING_ANGLE_ERROR_BOUND][imk] = s->angle_error_bound;
      out[MEX_CROSSING_POINT_ERROR_BOUND][imk] = s->point_error_bound;
      out[MEX_CROSSING_MULTIPLICITY][imk] = s->multiplicity;
      for (c = 0; c < 3; ++c) out[MEX_CROSSING_POINT][i + n * (c + 3 * (m + 2 * k))] = s->point[c];
    }
  }
}

mxArray* mex_columns_finish(mex_columns* columns) {
  mxArray* logicals;
  mxLogical* aligned;
  mwSize k;
  int f;
  /* The contact slot is every field's last dimension: dropping the slots no pose uses keeps the
   * data as it is and spares Octave/MATLAB copying them (a batch rarely has more than two
   * contacts a pose, and 6 slots are ~1.6 KB a pose). */
  for (f = MEX_TYPE; f < MEX_COLUMN_COUNT; ++f) {
    mxArray* array = mxGetFieldByNumber(columns->result, 0, f);
    mwSize shape[4];
    const mwSize ndims = mxGetNumberOfDimensions(array);
    mwSize d;
    for (d = 0; d < ndims; ++d) shape[d] = mxGetDimensions(array)[d];
    shape[ndims - 1] = columns->most_contacts;
    mxSetDimensions(array, shape, ndims);
  }
  /* The aligned flags as logicals, as in cj_detect. */
  logicals = mxCreateLogicalMatrix(columns->n, 1);
  aligned = mxGetLogicals(logicals);
  for (k = 0; k < columns->n; ++k) aligned[k] = columns->out[MEX_ALIGNED][k] != 0.0;
  mxDestroyArray(mxGetFieldByNumber(columns->result, 0, MEX_ALIGNED));
  mxSetFieldByNumber(columns->result, 0, MEX_ALIGNED, logicals);
  return columns->result;
}
