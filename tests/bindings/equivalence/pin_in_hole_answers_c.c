/* SPDX-License-Identifier: BSD-3-Clause */
/* The C API's answers for the pin-in-hole equivalence test (README.md): cj_detect_pin_in_hole on
 * the test cases, cj_detect_pin_in_hole_many on the random poses, read in place from the input
 * file's 23-double records through byte strides. Also checks that the batch answers equal those
 * of cj_detect_pin_in_hole and of cj_detect_pin_in_hole_many on a column-major copy, pose by
 * pose (exit status 1 otherwise). Compiled as strict C99, as answers_c.c is.
 *
 * usage: pin_in_hole_answers_c INPUT OUTPUT */

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clearjoint/clearjoint.h"
#include "contact_line.h"

#define RECORD 23

/* One answer line (README.md), with reason texts. */
static void format_result(char* line, size_t index, const cj_pin_in_hole_result* r) {
  int k;
  line[0] = '\0';
  add(line, "S %zu ok %d %d %d %d \"%s\" %d", index, r->scenario, r->aligned, r->certificate.level,
      r->certificate.reason, r->certificate.reason_text, r->contact_count);
  for (k = 0; k < r->contact_count; ++k) {
    add_contact(line, 1, &r->contacts[k]);
  }
}

static double* read_all(const char* path, size_t* doubles) {
  FILE* file = fopen(path, "rb");
  long bytes;
  double* data;
  if (file == NULL || fseek(file, 0, SEEK_END) != 0 || (bytes = ftell(file)) < 0) return NULL;
  rewind(file);
  *doubles = (size_t)bytes / sizeof(double);
  data = (double*)malloc((size_t)bytes);
  if (data == NULL || fread(data, sizeof(double), *doubles, file) != *doubles) return NULL;
  fclose(file);
  return data;
}

/* The dimensions of record r; the reserved members zero. */
static cj_pin_in_hole_dimensions dimensions_of(const double* r) {
  cj_pin_in_hole_dimensions dims;
  memset(&dims, 0, sizeof dims);
  dims.hole_radius = r[0];
  dims.hole_length = r[1];
  dims.pin_radius = r[2];
  dims.stop_count = (int32_t)r[3];
  dims.stops[0].position = r[4];
  dims.stops[0].outer_radius = r[5];
  dims.stops[1].position = r[6];
  dims.stops[1].outer_radius = r[7];
  return dims;
}

static void poses_of(const double* r, cj_pose* hole, cj_pose* pin) {
  memcpy(hole->p_WP, r + 8, sizeof hole->p_WP);
  memcpy(hole->axis_W, r + 11, sizeof hole->axis_W);
  memcpy(pin->p_WP, r + 14, sizeof pin->p_WP);
  memcpy(pin->axis_W, r + 17, sizeof pin->axis_W);
}

/* The batch records share the first one's joint and the default options (README.md). */
static int one_joint_default_options(const double* first, size_t batch) {
  size_t i;
  int c;
  for (i = 0; i < batch; ++i) {
    const double* r = first + i * RECORD;
    for (c = 0; c < 8; ++c) {
      if (r[c] != first[c]) return 0;
    }
    if (r[20] != 1.0 || r[21] != 0.0 || r[22] != 1.0) return 0;
  }
  return 1;
}

/* Answers the batch records, writes their lines and compares them with the other C routes. */
static int answer_batch(FILE* out, const double* first, size_t singles, size_t batch) {
  const cj_pin_in_hole_dimensions dims = dimensions_of(first);
  cj_pin_in_hole_result *results, *column_results, single;
  double* columns;
  cj_pose_array holes, pins;
  char line[LINE_CAPACITY], other[LINE_CAPACITY], message[1024];
  size_t processed = 0, i;
  int c, failures = 0;
  if (!one_joint_default_options(first, batch)) {
    fprintf(stderr, "the batch records do not share one joint and the default options\n");
    return -1;
  }
  /* In place: pose k's component c at first + k * RECORD + offset + c. */
  for (c = 0; c < 6; ++c) {
    holes.component[c] = first + 8 + c;
    pins.component[c] = first + 14 + c;
  }
  holes.stride = pins.stride = RECORD * (ptrdiff_t)sizeof(double);
  results = (cj_pin_in_hole_result*)calloc(batch, sizeof(cj_pin_in_hole_result));
  column_results = (cj_pin_in_hole_result*)calloc(batch, sizeof(cj_pin_in_hole_result));
  columns = (double*)malloc(2 * 6 * batch * sizeof(double));
  if (results == NULL || column_results == NULL || columns == NULL) return -1;
  if (cj_detect_pin_in_hole_many(&dims, &holes, &pins, batch, NULL, results, &processed, message,
                                 sizeof message) != CJ_OK || processed != batch) {
    fprintf(stderr, "cj_detect_pin_in_hole_many failed after %zu poses: %s\n", processed, message);
    return -1;
  }
  /* The same poses column-major (MATLAB's layout): holes then pins, batch x 6 each. */
  for (i = 0; i < batch; ++i) {
    for (c = 0; c < 6; ++c) {
      columns[i + c * batch] = first[i * RECORD + 8 + c];
      columns[6 * batch + i + c * batch] = first[i * RECORD + 14 + c];
    }
  }
  holes = cj_pose_array_columns(columns, batch);
  pins = cj_pose_array_columns(columns + 6 * batch, batch);
  if (cj_detect_pin_in_hole_many(&dims, &holes, &pins, batch, NULL, column_results, NULL, message,
                                 sizeof message) != CJ_OK) {
    fprintf(stderr, "cj_detect_pin_in_hole_many (column-major) failed: %s\n", message);
    return -1;
  }
  for (i = 0; i < batch; ++i) {
    cj_pose hole, pin;
    poses_of(first + i * RECORD, &hole, &pin);
    format_result(line, singles + i, &results[i]);
    fprintf(out, "%s\n", line);
    format_result(other, singles + i, &column_results[i]);
    if (strcmp(line, other) != 0) {
      fprintf(stderr, "pose %zu: row-major and column-major batches differ\n", singles + i);
      ++failures;
    }
    if (cj_detect_pin_in_hole(&dims, &hole, &pin, NULL, &single, message, sizeof message) != CJ_OK) {
      fprintf(stderr, "pose %zu: cj_detect_pin_in_hole failed: %s\n", singles + i, message);
      ++failures;
      continue;
    }
    format_result(other, singles + i, &single);
    if (strcmp(line, other) != 0) {
      fprintf(stderr, "pose %zu: cj_detect_pin_in_hole and cj_detect_pin_in_hole_many differ\n", singles + i);
      ++failures;
    }
  }
  /* Freed, so that LeakSanitizer (scripts/run-sanitizers.sh) has nothing to report. */
  free(columns);
  free(column_results);
  free(results);
  return failures;
}

int main(int argc, char** argv) {
  size_t doubles = 0, count, singles, i;
  double* data;
  FILE* out;
  char line[LINE_CAPACITY], message[1024];
  cj_pin_in_hole_result result;
  int failures = 0;
  if (argc != 3) {
    fprintf(stderr, "usage: %s INPUT OUTPUT\n", argv[0]);
    return 2;
  }
  data = read_all(argv[1], &doubles);
  out = fopen(argv[2], "w");
  if (data == NULL || doubles < RECORD || out == NULL) {
    fprintf(stderr, "%s: cannot read %s or write %s\n", argv[0], argv[1], argv[2]);
    return 2;
  }
  count = (size_t)data[0];
  singles = (size_t)data[1];
  if (singles > count || doubles < (count + 1) * RECORD) {
    fprintf(stderr, "%s: %s holds no header and %zu records\n", argv[0], argv[1], count);
    return 2;
  }
  for (i = 0; i < singles; ++i) {
    const double* r = data + (i + 1) * RECORD;
    const cj_pin_in_hole_dimensions dims = dimensions_of(r);
    cj_pose hole, pin;
    cj_options options = cj_default_options();
    int status;
    poses_of(r, &hole, &pin);
    options.certify = r[20] != 0.0;
    options.parallel_angle_tolerance = r[21];
    options.exact_fallback = r[22] != 0.0;
    status = cj_detect_pin_in_hole(&dims, &hole, &pin, &options, &result, message, sizeof message);
    if (status == CJ_OK) {
      format_result(line, i, &result);
    } else {
      line[0] = '\0';
      add(line, "S %zu error %d %s", i, status, message);
    }
    fprintf(out, "%s\n", line);
  }
  if (count > singles) {
    failures = answer_batch(out, data + (singles + 1) * RECORD, singles, count - singles);
    if (failures < 0) return 1;
  }
  free(data);
  if (fclose(out) != 0) return 2;
  printf("%zu single-call and %zu batch answers written; %d differences between C calls\n", singles,
         count - singles, failures);
  return failures == 0 ? 0 : 1;
}
