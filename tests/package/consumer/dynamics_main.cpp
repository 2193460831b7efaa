// SPDX-License-Identifier: BSD-3-Clause
// Exits 0 only if the installed dynamics library (which links the geometry library) answers: the
// Hertz force K delta^n of paper Sec. 4 at a known depth, and a full-joint detection through the
// geometry library it depends on (so a missing runtime path to it fails here).
#include <clearjoint/dynamics/normal_contact_force.hpp>
#include <clearjoint/geometry/joint/detect_contacts.hpp>

#include <cmath>
#include <cstdio>
#include <string>

int main() {
  using namespace clearjoint;
  dynamics::NormalForceParameters hertz;
  hertz.model = dynamics::NormalForceModel::hertz;
  hertz.stiffness = 4.0;
  hertz.exponent = 1.5;
  // 4 * 0.25^1.5 = 0.5 exactly in binary floating point.
  const double force = dynamics::normal_contact_force(hertz, 0.25, 0.0, 0.0);
  // Table 2 joint, journal pushed 0.15 mm sideways: one line contact 0.05 mm deep.
  const geometry::JointDimensions joint{0.01, 0.02, 0.0099, 0.0198};
  const geometry::JointContacts found = geometry::detect_contacts(
      joint, {{0, 0, 0}, {0, 0, 1}}, {{0.15e-3, 0, 0}, {0, 0, 1}});
  const bool ok = force == 0.5 && found.scenario == geometry::ContactScenario::line &&
                  found.contact_count == 1 && std::fabs(found.contacts[0].depth - 0.05e-3) < 1e-15;
  std::printf("dynamics consumer: Hertz force %.17g, scenario %s, %d contact(s), %s\n", force,
              std::string(geometry::label(found.scenario)).c_str(), found.contact_count,
              ok ? "as expected" : "UNEXPECTED");
  return ok ? 0 : 1;
}
