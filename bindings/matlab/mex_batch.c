/* SPDX-License-Identifier: BSD-3-Clause */
#include "mex_batch.h"

#include <stdlib.h>
#include <stdio.h>
#include <string.h>

/* Poses per call of cj_detect_many (cj_detect_pin_in_hole_many): the results buffer stays small
 * (1.5 KB a result) whatever the batch's size. */
#define CHUNK 256
#define MESSAGE_CAPACITY 1024

void mex_raise(int status, const char* message) {
  mexErrMsgIdAndTxt(status == CJ_INVALID_INPUT ? "clearjoint:invalidInput" : "clearjoint:failed", "%s",
                    message);
}

/* The batch calls number the failing pose within its chunk; the caller counts from pose 0. */
static void raise_in_chunk(int status, const char* message, size_t chunk_start) {
  static const char prefix[] = "poses[";
  char renumbered[MESSAGE_CAPACITY + 32];
  if (strncmp(message, prefix, sizeof prefix - 1) == 0) {
    char* end = NULL;
    const unsigned long local = strtoul(message + sizeof prefix - 1, &end, 10);
    if (end != NULL && end[0] == ']') {
      snprintf(renumbered, sizeof renumbered, "poses[%lu]%s", (unsigned long)chunk_start + local, end + 1);
      mex_raise(status, renumbered);
    }
  }
  mex_raise(status, message);
}

/* The same array, starting at pose `start`. */
static cj_pose_array from(const cj_pose_array* poses, size_t start) {
  cj_pose_array out = *poses;
  int c;
  for (c = 0; c < 6; ++c) {
    out.component[c] = (const double*)((const char*)poses->component[c] + (ptrdiff_t)start * poses->stride);
  }
  return out;
}

void mex_detect_all(const cj_dimensions* dims, const cj_pose_array* bearings,
                    const cj_pose_array* journals, size_t count, const cj_options* options,
                    mex_result_sink sink, void* context) {
  cj_result* chunk = (cj_result*)mxMalloc(CHUNK * sizeof(cj_result));
  char message[MESSAGE_CAPACITY];
  size_t start, k;
  for (start = 0; start < count; start += CHUNK) {
    const size_t n = count - start < CHUNK ? count - start : CHUNK;
    const cj_pose_array b = from(bearings, start), j = from(journals, start);
    const int status = cj_detect_many(dims, &b, &j, n, options, chunk, NULL, message, sizeof message);
    if (status != CJ_OK) raise_in_chunk(status, message, start);
    for (k = 0; k < n; ++k) sink(context, start + k, &chunk[k]);
  }
  mxFree(chunk);
}

void mex_detect_pin_in_hole_all(const cj_pin_in_hole_dimensions* dims, const cj_pose_array* holes,
                                const cj_pose_array* pins, size_t count, const cj_options* options,
                                mex_pin_in_hole_sink sink, void* context) {
  cj_pin_in_hole_result* chunk = (cj_pin_in_hole_result*)mxMalloc(CHUNK * sizeof(cj_pin_in_hole_result));
  char message[MESSAGE_CAPACITY];
  size_t start, k;
  for (start = 0; start < count; start += CHUNK) {
    const size_t n = count - start < CHUNK ? count - start : CHUNK;
    const cj_pose_array h = from(holes, start), p = from(pins, start);
    const int status = cj_detect_pin_in_hole_many(dims, &h, &p, n, options, chunk, NULL, message, sizeof message);
    if (status != CJ_OK) raise_in_chunk(status, message, start);
    for (k = 0; k < n; ++k) sink(context, start + k, &chunk[k]);
  }
  mxFree(chunk);
}
