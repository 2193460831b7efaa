// SPDX-License-Identifier: BSD-3-Clause
// cj_default_options: the library's defaults (conversions.hpp has the conversions both ways).
#include "conversions.hpp"

extern "C" cj_options cj_default_options(void) {
  return clearjoint::c_api::options_of(clearjoint::geometry::DetectionOptions{});
}
