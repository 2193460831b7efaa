/* SPDX-License-Identifier: BSD-3-Clause */
#include "mex_inputs.h"

#include <string.h>

static const char* const kInvalidInput = "clearjoint:invalidInput";

/* The scalar double in field `field` of struct `s` (argument `name`). */
static double scalar_field(const mxArray* s, const char* name, const char* field) {
  const mxArray* value = mxGetField(s, 0, field);
  if (value == NULL) {
    mexErrMsgIdAndTxt(kInvalidInput, "%s.%s: missing (the struct needs this field)", name, field);
  }
  if (!mxIsDouble(value) && !mxIsLogical(value)) {
    mexErrMsgIdAndTxt(kInvalidInput, "%s.%s: must be a double scalar, not %s", name, field,
                      mxGetClassName(value));
  }
  if (mxIsComplex(value) || mxGetNumberOfElements(value) != 1) {
    mexErrMsgIdAndTxt(kInvalidInput, "%s.%s: must be a real scalar (%d x %d given)", name, field,
                      (int)mxGetM(value), (int)mxGetN(value));
  }
  return mxGetScalar(value);
}

static void require_scalar_struct(const mxArray* s, const char* name) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1) {
    mexErrMsgIdAndTxt(kInvalidInput, "%s: must be a 1 x 1 struct", name);
  }
}

cj_dimensions mex_dimensions(const mxArray* dims) {
  cj_dimensions d;
  require_scalar_struct(dims, "dims");
  d.bearing_radius = scalar_field(dims, "dims", "bearing_radius");
  d.bearing_length = scalar_field(dims, "dims", "bearing_length");
  d.journal_radius = scalar_field(dims, "dims", "journal_radius");
  d.journal_length = scalar_field(dims, "dims", "journal_length");
  return d;
}

cj_pin_in_hole_dimensions mex_pin_in_hole_dimensions(const mxArray* dims) {
  cj_pin_in_hole_dimensions d;
  const mxArray* stops;
  memset(&d, 0, sizeof d); /* the reserved members */
  require_scalar_struct(dims, "dims");
  d.hole_radius = scalar_field(dims, "dims", "hole_radius");
  d.hole_length = scalar_field(dims, "dims", "hole_length");
  d.pin_radius = scalar_field(dims, "dims", "pin_radius");
  stops = mxGetField(dims, 0, "stops");
  if (stops != NULL && !mxIsEmpty(stops)) {
    size_t k, count = mxGetM(stops);
    const double* values;
    if (!mxIsDouble(stops) || mxIsComplex(stops) || mxIsSparse(stops) || mxGetNumberOfDimensions(stops) != 2 ||
        mxGetN(stops) != 2 || count > CJ_MAX_AXIAL_STOPS) {
      mexErrMsgIdAndTxt(kInvalidInput,
                        "dims.stops: must be a real double K x 2 matrix [position, outer_radius] with K <= %d "
                        "(%s %d x %d given)",
                        CJ_MAX_AXIAL_STOPS, mxGetClassName(stops), (int)mxGetM(stops), (int)mxGetN(stops));
    }
    values = mxGetPr(stops);
    for (k = 0; k < count; ++k) {
      d.stops[k].position = values[k];
      d.stops[k].outer_radius = values[k + count];
    }
    d.stop_count = (int32_t)count;
  }
  return d;
}

cj_pose_array mex_poses(const mxArray* poses, const char* name, size_t* rows) {
  if (!mxIsDouble(poses) || mxIsComplex(poses) || mxIsSparse(poses) ||
      mxGetNumberOfDimensions(poses) != 2 || mxGetN(poses) != 6 || mxGetM(poses) == 0) {
    mexErrMsgIdAndTxt(kInvalidInput,
                      "%s: must be a real double N x 6 matrix [p_WP, axis_W] with N >= 1 (%s %d x %d given)",
                      name, mxGetClassName(poses), (int)mxGetM(poses), (int)mxGetN(poses));
  }
  *rows = mxGetM(poses);
  return cj_pose_array_columns(mxGetPr(poses), *rows);
}

cj_options mex_options(const mxArray* options) {
  cj_options o = cj_default_options();
  int k;
  require_scalar_struct(options, "options");
  for (k = 0; k < mxGetNumberOfFields(options); ++k) {
    const char* field = mxGetFieldNameByNumber(options, k);
    if (strcmp(field, "certify") == 0) {
      o.certify = scalar_field(options, "options", field) != 0.0;
    } else if (strcmp(field, "exact_fallback") == 0) {
      o.exact_fallback = scalar_field(options, "options", field) != 0.0;
    } else if (strcmp(field, "parallel_angle_tolerance") == 0) {
      o.parallel_angle_tolerance = scalar_field(options, "options", field);
    } else {
      mexErrMsgIdAndTxt(kInvalidInput,
                        "options.%s: unknown field (known: certify, exact_fallback, parallel_angle_tolerance)",
                        field);
    }
  }
  return o;
}

mex_detection_inputs mex_detection_arguments(int nrhs, const mxArray* prhs[], const char* usage,
                                             const char* bearing_name, const char* journal_name) {
  mex_detection_inputs in;
  size_t bearing_rows = 0, journal_rows = 0;
  if (nrhs < 3 || nrhs > 4) mexErrMsgIdAndTxt(kInvalidInput, "usage: %s", usage);
  in.dims = mex_dimensions(prhs[0]);
  in.bearings = mex_poses(prhs[1], bearing_name, &bearing_rows);
  in.journals = mex_poses(prhs[2], journal_name, &journal_rows);
  in.options = nrhs == 4 ? mex_options(prhs[3]) : cj_default_options();
  if (bearing_rows != journal_rows && bearing_rows != 1 && journal_rows != 1) {
    mexErrMsgIdAndTxt(kInvalidInput, "%s (%d rows) and %s (%d rows): must have as many rows, or one of them 1",
                      bearing_name, (int)bearing_rows, journal_name, (int)journal_rows);
  }
  in.count = bearing_rows > journal_rows ? bearing_rows : journal_rows;
  if (bearing_rows == 1) in.bearings.stride = 0;
  if (journal_rows == 1) in.journals.stride = 0;
  return in;
}
