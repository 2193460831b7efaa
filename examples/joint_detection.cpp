// SPDX-License-Identifier: BSD-3-Clause
// Joint-level contact detection: which scenario of the paper's Fig. 2 holds, and each contact's
// points, normal, depth, error bounds and certificate. The joint is the paper's Table 2 one, in
// metres, with the journal tilted so that its rim at base A presses into the bearing wall.
#include <clearjoint/geometry/joint/detect_contacts.hpp>

#include <cstdio>
#include <string>

namespace geo = clearjoint::geometry;

namespace {

void print(const char* title, const geo::JointContacts& found) {
  std::printf("%s: scenario %s (%s), %s, %d contact(s), certificate %s\n", title,
              std::string(geo::to_string(found.scenario)).c_str(),
              std::string(geo::label(found.scenario)).c_str(),
              found.aligned ? "axes aligned" : "axes not aligned", found.contact_count,
              std::string(geo::to_string(found.certificate.level)).c_str());
  for (int k = 0; k < found.contact_count; ++k) {
    const geo::Contact& c = found.contacts[static_cast<std::size_t>(k)];
    std::printf("  %s contact at base %s: depth %.6e m (+- %.1e), normal (%.3f, %.3f, %.3f),\n"
                "    journal point (%.6f, %.6f, %.6f), bearing point (%.6f, %.6f, %.6f), %s%s%s\n",
                std::string(geo::to_string(c.type)).c_str(), std::string(geo::to_string(c.base)).c_str(),
                c.depth, c.depth_error, c.normal_W.x(), c.normal_W.y(), c.normal_W.z(),
                c.p_WCj.x(), c.p_WCj.y(), c.p_WCj.z(), c.p_WCi.x(), c.p_WCi.y(), c.p_WCi.z(),
                std::string(geo::to_string(c.certificate.level)).c_str(),
                c.certificate.level == geo::Certainty::certified ? "" : ": ",
                std::string(c.certificate.reason_text()).c_str());
  }
}

}  // namespace

int main() {
  // Table 2: Ri = 10 mm, Li = 20 mm, Rj = 9.9 mm, Lj = 19.8 mm (JointDimensions' field order:
  // bearing radius, bearing length, journal radius, journal length).
  const geo::JointDimensions joint{0.010, 0.020, 0.0099, 0.0198};
  const geo::PartPose bearing{{0, 0, 0}, {0, 0, 1}};  // centre and axis, world frame
  // Journal moved 0.05 mm towards +y and its axis tilted 0.01 rad about x: the rim at base A
  // (z > 0) reaches about 0.05 mm beyond the wall, the rim at base B stays inside.
  const geo::PartPose journal{{0, 0.05e-3, 0}, {0, 0.01, 1}};

  // The returning overload: a fresh result.
  const geo::JointContacts found = geo::detect_contacts(joint, bearing, journal);
  print("detect_contacts(joint, bearing, journal)", found);

  // The overload that writes into a result the caller keeps (a simulation step): no 1.6 KB
  // default result to write each call. Same answer.
  geo::JointContacts reused;
  geo::DetectionOptions options;
  options.parallel_angle_tolerance = 0.0;  // aligned only when exactly parallel (eq. 5)
  geo::detect_contacts(joint, bearing, journal, reused, options);
  print("detect_contacts(joint, bearing, journal, reused, options)", reused);

  // What the example shows must hold: scenario (a), one radial contact at A, shallower than the
  // radial clearance cr = Ri - Rj (deeper would be beyond the model), both calls alike.
  const double radial_clearance = joint.bearing_radius - joint.journal_radius;
  const bool ok = found.scenario == geo::ContactScenario::single_radial &&
                  found.contact_count == 1 && reused.contact_count == 1 &&
                  reused.scenario == found.scenario &&
                  reused.contacts[0].depth == found.contacts[0].depth &&
                  found.contacts[0].base == geo::ContactBase::a &&
                  found.certificate.level != geo::Certainty::uncertain &&
                  found.contacts[0].depth > 0 && found.contacts[0].depth < radial_clearance;
  std::printf("%s\n", ok ? "as expected" : "UNEXPECTED");
  return ok ? 0 : 1;
}
