// SPDX-License-Identifier: BSD-3-Clause
#include "detection_methods.hpp"

#include "paper_baseline.hpp"

namespace clearjoint::bench {

std::string_view to_string(Method method) noexcept {
  switch (method) {
    case Method::paper_baseline: return "paper_baseline";
    case Method::uncertified: return "uncertified";
    case Method::certified: return "certified";
  }
  return "";
}

geometry::JointContacts run_method(Method method, const DetectionInput& input) {
  switch (method) {
    case Method::paper_baseline:
      return detect_contacts_paper_baseline(input.dimensions, input.bearing, input.journal);
    case Method::uncertified: {
      geometry::DetectionOptions options;
      options.intersection.certify = false;
      return geometry::detect_contacts(input.dimensions, input.bearing, input.journal, options);
    }
    case Method::certified:
      return geometry::detect_contacts(input.dimensions, input.bearing, input.journal);
  }
  return {};
}

}  // namespace clearjoint::bench
