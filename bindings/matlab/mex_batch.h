/* SPDX-License-Identifier: BSD-3-Clause */
#ifndef CLEARJOINT_MEX_BATCH_H
#define CLEARJOINT_MEX_BATCH_H
/* The gateways' batch loops: cj_detect_many and cj_detect_pin_in_hole_many over the caller's
 * arrays, a chunk at a time. */

#include "mex.h"

#include "clearjoint/clearjoint.h"

/* Receives the answer for pose `index` (from 0). */
typedef void (*mex_result_sink)(void* context, size_t index, const cj_result* result);

/* Detect poses 0 .. count-1 and hand each answer to `sink`. On failure raises the MATLAB error
 * "clearjoint:invalidInput" (or "clearjoint:failed") with the C API's message, the pose named by
 * its index from 0. Arrays and memory the gateway made are freed by MATLAB/Octave when the error
 * unwinds the MEX call. */
void mex_detect_all(const cj_dimensions* dims, const cj_pose_array* bearings,
                    const cj_pose_array* journals, size_t count, const cj_options* options,
                    mex_result_sink sink, void* context);

/* Receives the pin-in-hole answer for pose `index` (from 0). */
typedef void (*mex_pin_in_hole_sink)(void* context, size_t index, const cj_pin_in_hole_result* result);

/* mex_detect_all for the pin-in-hole joint (cj_detect_pin_in_hole_many), the same errors. */
void mex_detect_pin_in_hole_all(const cj_pin_in_hole_dimensions* dims, const cj_pose_array* holes,
                                const cj_pose_array* pins, size_t count, const cj_options* options,
                                mex_pin_in_hole_sink sink, void* context);

/* Raise the MATLAB error for a failed C API call. */
void mex_raise(int status, const char* message);

#endif
