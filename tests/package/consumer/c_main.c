/* SPDX-License-Identifier: BSD-3-Clause */
/* Exits 0 only if the installed C API answers from a C program: the paper's joint (Table 2, mm)
 * with the journal pushed towards the wall and base A is scenario (e), two contacts; and a bad
 * axis is rejected with its field named. */
#include <clearjoint/clearjoint.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void) {
  const cj_dimensions joint = {10.0, 20.0, 9.9, 19.8};
  const cj_pose bearing = {{0, 0, 0}, {0, 0, 1}};
  const cj_pose journal = {{0, 0.08, 0.08}, {0, sin(0.005), cos(0.005)}};
  const cj_pose broken = {{0, 0, 0}, {0, 0, 0}};
  cj_result found;
  char message[256];
  const int status = cj_detect(&joint, &bearing, &journal, NULL, &found, message, sizeof message);
  const int rejected = cj_detect(&joint, &bearing, &broken, NULL, &found, message, sizeof message) ==
                           CJ_INVALID_INPUT &&
                       strncmp(message, "journal.axis_W", 14) == 0;
  const int ok = status == CJ_OK && found.scenario == CJ_SCENARIO_RADIAL_AND_AXIAL_SAME_BASE &&
                 found.contact_count == 2 && rejected && cj_abi_version() == CJ_ABI_VERSION;
  printf("C consumer: clearjoint %s, %s, %d contacts, bad axis %s: %s\n", cj_version(),
         cj_scenario_string(found.scenario), found.contact_count, rejected ? "rejected" : "NOT rejected",
         ok ? "as expected" : "UNEXPECTED");
  return ok ? 0 : 1;
}
