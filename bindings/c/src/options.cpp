// SPDX-License-Identifier: BSD-3-Clause
// cj_default_options and the rejection of reserved option fields.
#include <sstream>
#include <string>

#include "conversions.hpp"

namespace clearjoint::c_api {

void reject_reserved(const cj_options& options) {
  for (int k = 0; k < 4; ++k) {
    if (options.reserved[k] != 0.0) {
      std::ostringstream message;
      message.precision(17);
      message << " = " << options.reserved[k]
              << ": must be 0 (start from cj_default_options() or a zero-initialised struct)";
      throw ValidationError("options.reserved[" + std::to_string(k) + "]", message.str());
    }
  }
  throw ValidationError("options.reserved", ": must be 0");
}

}  // namespace clearjoint::c_api

extern "C" cj_options cj_default_options(void) {
  const clearjoint::geometry::DetectionOptions defaults;
  cj_options options{};
  options.certify = defaults.intersection.certify ? 1 : 0;
  options.exact_fallback = defaults.intersection.exact_fallback ? 1 : 0;
  options.parallel_angle_tolerance = defaults.parallel_angle_tolerance;
  return options;
}
