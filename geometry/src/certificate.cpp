// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/certificate.hpp"

namespace clearjoint::geometry {

std::string_view to_string(Certainty level) noexcept {
  switch (level) {
    case Certainty::exact: return "exact";
    case Certainty::certified: return "certified";
    case Certainty::uncertain: return "uncertain";
  }
  return "unknown";
}

}  // namespace clearjoint::geometry
