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

Certificate weakest(const Certificate& a, const Certificate& b) noexcept {
  // The enum lists levels from strongest to weakest, so the larger value is the weaker one.
  return static_cast<int>(b.level) > static_cast<int>(a.level) ? b : a;
}

}  // namespace clearjoint::geometry
