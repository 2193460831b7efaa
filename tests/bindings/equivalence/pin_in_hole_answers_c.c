/* SPDX-License-Identifier: BSD-3-Clause */
/* The C API's answers for the pin-in-hole equivalence test (README.md): cj_detect_pin_in_hole on
 * every record. Compiled as strict C99, as answers_c.c is.
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

int main(int argc, char** argv) {
  size_t doubles = 0, count, i;
  double* data;
  FILE* out;
  char line[LINE_CAPACITY], message[1024];
  cj_pin_in_hole_result result;
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
  for (i = 0; i < count; ++i) {
    const double* r = data + (i + 1) * RECORD;
    cj_pin_in_hole_dimensions dims;
    cj_pose hole, pin;
    cj_options options = cj_default_options();
    int status;
    memset(&dims, 0, sizeof dims); /* the reserved members */
    dims.hole_radius = r[0];
    dims.hole_length = r[1];
    dims.pin_radius = r[2];
    dims.stop_count = (int32_t)r[3];
    dims.stops[0].position = r[4];
    dims.stops[0].outer_radius = r[5];
    dims.stops[1].position = r[6];
    dims.stops[1].outer_radius = r[7];
    memcpy(hole.p_WP, r + 8, sizeof hole.p_WP);
    memcpy(hole.axis_W, r + 11, sizeof hole.axis_W);
    memcpy(pin.p_WP, r + 14, sizeof pin.p_WP);
    memcpy(pin.axis_W, r + 17, sizeof pin.axis_W);
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
  free(data);
  if (fclose(out) != 0) return 2;
  printf("%zu answers written\n", count);
  return 0;
}
