/* SPDX-License-Identifier: BSD-3-Clause */
/* The C API's answers for the equivalence test (README.md): cj_detect on the single-call records,
 * cj_detect_many on the batch records, read in place from the input file's 19-double records
 * through byte strides. Also checks that the batch answers equal cj_detect's and those of
 * cj_detect_many on a column-major copy, pose by pose (exit status 1 otherwise).
 * Compiled as strict C99: it is also the test that the header is valid C.
 *
 * usage: answers_c INPUT OUTPUT */

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clearjoint/clearjoint.h"
#include "contact_line.h"

#define RECORD 19

/* One answer line (README.md); `tag` is 'S' (with reason texts) or 'B'. */
static void format_result(char* line, char tag, size_t index, const cj_result* r) {
  int k;
  line[0] = '\0';
  add(line, "%c %zu ok %d %d %d %d", tag, index, r->scenario, r->aligned, r->certificate.level,
      r->certificate.reason);
  if (tag == 'S') add(line, " \"%s\"", r->certificate.reason_text);
  add(line, " %d", r->contact_count);
  for (k = 0; k < r->contact_count; ++k) {
    add_contact(line, tag == 'S', &r->contacts[k]);
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

int main(int argc, char** argv) {
  size_t doubles = 0, count, singles, batch, i;
  double *file_data, *data;
  FILE* out;
  char line[LINE_CAPACITY], other[LINE_CAPACITY], message[1024];
  cj_result *results = NULL, *column_results = NULL, single;
  double* columns = NULL;
  cj_pose_array bearings, journals;
  int c, failures = 0;
  if (argc != 3) {
    fprintf(stderr, "usage: %s INPUT OUTPUT\n", argv[0]);
    return 2;
  }
  file_data = read_all(argv[1], &doubles);
  out = fopen(argv[2], "w");
  if (file_data == NULL || doubles < RECORD || out == NULL) {
    fprintf(stderr, "%s: cannot read %s or write %s\n", argv[0], argv[1], argv[2]);
    return 2;
  }
  count = (size_t)file_data[0];
  singles = (size_t)file_data[1];
  batch = count - singles;
  data = file_data + RECORD; /* past the header */

  for (i = 0; i < singles; ++i) {
    const double* r = data + i * RECORD;
    cj_dimensions dims;
    cj_pose bearing, journal;
    cj_options options = cj_default_options();
    int status;
    dims.bearing_radius = r[0];
    dims.bearing_length = r[1];
    dims.journal_radius = r[2];
    dims.journal_length = r[3];
    memcpy(bearing.p_WP, r + 4, sizeof bearing.p_WP);
    memcpy(bearing.axis_W, r + 7, sizeof bearing.axis_W);
    memcpy(journal.p_WP, r + 10, sizeof journal.p_WP);
    memcpy(journal.axis_W, r + 13, sizeof journal.axis_W);
    options.certify = r[16] != 0.0;
    options.parallel_angle_tolerance = r[17];
    options.exact_fallback = r[18] != 0.0;
    status = cj_detect(&dims, &bearing, &journal, &options, &single, message, sizeof message);
    if (status == CJ_OK) {
      format_result(line, 'S', i, &single);
    } else {
      line[0] = '\0';
      add(line, "S %zu error %d %s", i, status, message);
    }
    fprintf(out, "%s\n", line);
  }

  if (batch > 0) {
    const double* first = data + singles * RECORD;
    const cj_dimensions dims = {first[0], first[1], first[2], first[3]};
    size_t processed = 0;
    /* In place: pose k's component c at first + k * RECORD + offset + c. */
    for (c = 0; c < 6; ++c) {
      bearings.component[c] = first + 4 + c;
      journals.component[c] = first + 10 + c;
    }
    bearings.stride = journals.stride = RECORD * (ptrdiff_t)sizeof(double);
    results = (cj_result*)malloc(batch * sizeof(cj_result));
    column_results = (cj_result*)malloc(batch * sizeof(cj_result));
    columns = (double*)malloc(2 * 6 * batch * sizeof(double));
    if (results == NULL || column_results == NULL || columns == NULL) return 2;
    if (cj_detect_many(&dims, &bearings, &journals, batch, NULL, results, &processed, message,
                       sizeof message) != CJ_OK || processed != batch) {
      fprintf(stderr, "cj_detect_many failed after %zu poses: %s\n", processed, message);
      return 1;
    }
    /* The same poses column-major (MATLAB's layout): bearings then journals, batch x 6 each. */
    for (i = 0; i < batch; ++i) {
      for (c = 0; c < 6; ++c) {
        columns[i + c * batch] = first[i * RECORD + 4 + c];
        columns[6 * batch + i + c * batch] = first[i * RECORD + 10 + c];
      }
    }
    bearings = cj_pose_array_columns(columns, batch);
    journals = cj_pose_array_columns(columns + 6 * batch, batch);
    if (cj_detect_many(&dims, &bearings, &journals, batch, NULL, column_results, NULL, message,
                       sizeof message) != CJ_OK) {
      fprintf(stderr, "cj_detect_many (column-major) failed: %s\n", message);
      return 1;
    }
    for (i = 0; i < batch; ++i) {
      const double* r = first + i * RECORD;
      cj_pose bearing, journal;
      memcpy(bearing.p_WP, r + 4, sizeof bearing.p_WP);
      memcpy(bearing.axis_W, r + 7, sizeof bearing.axis_W);
      memcpy(journal.p_WP, r + 10, sizeof journal.p_WP);
      memcpy(journal.axis_W, r + 13, sizeof journal.axis_W);
      format_result(line, 'B', singles + i, &results[i]);
      fprintf(out, "%s\n", line);
      format_result(other, 'B', singles + i, &column_results[i]);
      if (strcmp(line, other) != 0) {
        fprintf(stderr, "pose %zu: row-major and column-major batches differ\n", singles + i);
        ++failures;
      }
      if (cj_detect(&dims, &bearing, &journal, NULL, &single, message, sizeof message) != CJ_OK) {
        fprintf(stderr, "pose %zu: cj_detect failed: %s\n", singles + i, message);
        ++failures;
        continue;
      }
      format_result(other, 'B', singles + i, &single);
      if (strcmp(line, other) != 0) {
        fprintf(stderr, "pose %zu: cj_detect and cj_detect_many differ\n", singles + i);
        ++failures;
      }
    }
  }
  /* Freed, so that LeakSanitizer (scripts/run-sanitizers.sh) has nothing to report. */
  free(columns);
  free(column_results);
  free(results);
  free(file_data);
  if (fclose(out) != 0) return 2;
  printf("%zu single-call and %zu batch answers written; %d differences between C calls\n", singles,
         batch, failures);
  return failures == 0 ? 0 : 1;
}
