/* SPDX-License-Identifier: BSD-3-Clause */
#ifndef CLEARJOINT_MEX_INPUTS_H
#define CLEARJOINT_MEX_INPUTS_H
/* The MEX gateway's inputs: MATLAB/Octave values read into the C API's structs. Every function
 * raises a MATLAB error ("clearjoint:invalidInput") naming the argument and field it rejects. */

#include "mex.h"

#include "clearjoint/clearjoint.h"

/* dims: a struct with the scalar double fields bearing_radius, bearing_length, journal_radius,
 * journal_length. The values themselves are the C API's to check. */
cj_dimensions mex_dimensions(const mxArray* dims);

/* dims: a struct with the scalar double fields hole_radius, hole_length, pin_radius and an
 * optional field stops, a K x 2 real double matrix [position, outer_radius] with K <= 2 (absent or
 * empty: a free sliding pin). The values themselves are the C API's to check. */
cj_pin_in_hole_dimensions mex_pin_in_hole_dimensions(const mxArray* dims);

/* An N x 6 real double matrix [p_WP, axis_W] (one pose per row), read in place: MATLAB stores it
 * column-major, which cj_pose_array_columns() describes. *rows receives N. */
cj_pose_array mex_poses(const mxArray* poses, const char* name, size_t* rows);

/* options: a struct whose fields certify, exact_fallback, parallel_angle_tolerance (each
 * optional, scalar) override cj_default_options(); any other field is an error. */
cj_options mex_options(const mxArray* options);

/* The arguments both gateways take: (dims, bearings, journals [, options]), poses N x 6 or 1 x 6
 * (a single row serves every pose: stride 0). `usage` is raised for a wrong argument count. */
typedef struct mex_detection_inputs {
  cj_dimensions dims;
  cj_pose_array bearings;
  cj_pose_array journals;
  size_t count;
  cj_options options;
} mex_detection_inputs;

mex_detection_inputs mex_detection_arguments(int nrhs, const mxArray* prhs[], const char* usage,
                                             const char* bearing_name, const char* journal_name);

#endif
