/* SPDX-License-Identifier: BSD-3-Clause */
/* The C writers' pieces of an answer line (README.md), shared by answers_c.c and
 * pin_in_hole_answers_c.c. The fields of a contact and of a crossing are written between the
 * GENERATED markers, from the field lists in the format's order
 * (scripts/projections/equivalence_lines.py; `cmake --build build --target projections`). */
#ifndef CLEARJOINT_EQUIVALENCE_CONTACT_LINE_H
#define CLEARJOINT_EQUIVALENCE_CONTACT_LINE_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "clearjoint/clearjoint.h"

#define LINE_CAPACITY 8192

/* Append printf-formatted text to `line` (capacity LINE_CAPACITY). */
static void add(char* line, const char* format, ...) {
  va_list args;
  const size_t used = strlen(line);
  va_start(args, format);
  vsnprintf(line + used, LINE_CAPACITY - used, format, args);
  va_end(args);
}

static void add_hex(char* line, double x) {
  uint64_t bits;
  memcpy(&bits, &x, sizeof bits);
  add(line, " %016llX", (unsigned long long)bits);
}

static void add_vector(char* line, const double v[3]) {
  add_hex(line, v[0]);
  add_hex(line, v[1]);
  add_hex(line, v[2]);
}

static void add_crossing(char* line, const cj_crossing* x) {
  /* BEGIN GENERATED RimCrossing fields */
  add_hex(line, x->angle);
  add_hex(line, x->angle_error_bound);
  add_vector(line, x->point);
  add_hex(line, x->point_error_bound);
  add(line, " %d", x->multiplicity);
  /* END GENERATED RimCrossing fields */
}

/* " | <contact>"; the certificates' reason texts when `with_text`. */
static void add_contact(char* line, int with_text, const cj_contact* c) {
  int m;
  add(line, " |");
  /* BEGIN GENERATED Contact fields */
  add(line, " %d", c->type);
  add(line, " %d", c->base);
  add_hex(line, c->depth);
  add_vector(line, c->p_WCj);
  add_vector(line, c->p_WCi);
  add_vector(line, c->normal_W);
  add_hex(line, c->depth_error_bound);
  add_hex(line, c->p_WCj_error_bound);
  add_hex(line, c->p_WCi_error_bound);
  add(line, " %d", c->crossing_count);
  for (m = 0; m < c->crossing_count; ++m) add_crossing(line, &c->crossings[m]);
  add(line, " %d %d", c->certificate.level, c->certificate.reason);
  if (with_text) add(line, " \"%s\"", c->certificate.reason_text);
  /* END GENERATED Contact fields */
}

#endif
