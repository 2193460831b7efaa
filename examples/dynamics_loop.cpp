// SPDX-License-Identifier: BSD-3-Clause
// "My own dynamics loop": a caller that integrates its own equations of motion and asks clearjoint
// only for the contact physics of a clearance revolute joint. Per step: detect the contacts
// (paper Section 3), their kinematics (eqs. 24-26), the normal force (eq. 29, Lankarani-Nikravesh)
// and the friction force (eq. 32), then advance the state.
//
// The one piece of memory the loop must keep itself: Lankarani-Nikravesh's damping divides by the
// initial impact velocity delta_dot(-) (eq. 28), the approach speed at the instant a contact
// begins. It is recorded when a contact appears and kept, unchanged, while that contact lasts.
//
// The system: a journal of 1 kg, translating only (its axis stays tilted by 0.002 rad), dropped
// inside a fixed bearing of the paper's Table 2 under gravity, and bouncing until it settles.
#include <clearjoint/dynamics/normal_contact_force.hpp>
#include <clearjoint/dynamics/regularised_friction.hpp>
#include <clearjoint/geometry/joint/contact_kinematics.hpp>
#include <clearjoint/geometry/joint/detect_contacts.hpp>

#include <algorithm>
#include <array>
#include <cstdio>

namespace geo = clearjoint::geometry;
namespace dyn = clearjoint::dynamics;
using clearjoint::geometry::Vector3;

namespace {

constexpr double kMass = 1.0;                      // kg
const Vector3 kGravity{0.0, -9.81, 0.0};           // m/s^2
constexpr double kStep = 1e-6;                     // s; ~1/600 of the contact's oscillation period
constexpr double kDuration = 0.05;                 // s

/// One remembered contact: where it acts (rim base and type) and its delta_dot(-).
struct ImpactMemory {
  bool in_contact = false;
  double impact_speed = 0.0;
};

/// Memory slot of a contact: one per (type, base) pair, the way a contact persists between steps.
std::size_t slot_of(const geo::Contact& c) {
  return static_cast<std::size_t>(c.type) * 3 + static_cast<std::size_t>(c.base);
}

}  // namespace

int main() {
  const geo::JointDimensions joint{0.010, 0.020, 0.0099, 0.0198};  // Table 2, metres
  const double radial_clearance = joint.bearing_radius - joint.journal_radius;
  const geo::PartPose bearing{{0, 0, 0}, {0, 0, 1}};
  const geo::BodyMotion bearing_motion{};  // fixed: at rest at the origin

  dyn::NormalForceParameters normal;  // Table 2: Lankarani-Nikravesh, K = 1e11, n = 1.5, ce = 0.9
  dyn::FrictionParameters friction;   // Table 2: mu = 0.1, k = 1000 s/m

  Vector3 position{0, 0, 0};           // journal centre, starting concentric
  Vector3 velocity{0.02, 0, 0};        // m/s, sideways, so friction has work to do
  const Vector3 axis{0, 0.002, 1};     // tilted: point contacts at the rims, not a line

  std::array<ImpactMemory, 6> memory{};
  geo::JointContacts contacts;         // reused every step (the overload that writes into it)
  int impacts = 0;
  double deepest = 0.0;
  double first_impact_speed = 0.0;
  const auto energy = [&](const Vector3& p, const Vector3& v, double elastic) {
    return 0.5 * kMass * v.squaredNorm() - kMass * kGravity.dot(p) + elastic;
  };
  const double initial_energy = energy(position, velocity, 0.0);
  double elastic_energy = 0.0;

  for (double t = 0.0; t < kDuration; t += kStep) {
    geo::detect_contacts(joint, bearing, {position, axis}, contacts);
    const geo::BodyMotion journal_motion{position, velocity, Vector3::Zero()};

    Vector3 force = kMass * kGravity;
    std::array<bool, 6> seen{};
    elastic_energy = 0.0;
    for (int k = 0; k < contacts.contact_count; ++k) {
      const geo::Contact& c = contacts.contacts[static_cast<std::size_t>(k)];
      if (c.depth <= 0.0) continue;
      const geo::ContactKinematics kin = geo::contact_kinematics(c, bearing_motion, journal_motion);
      ImpactMemory& m = memory[slot_of(c)];
      seen[slot_of(c)] = true;
      if (!m.in_contact) {  // the contact begins: record delta_dot(-), eq. (28)
        m.in_contact = true;
        m.impact_speed = kin.approach_speed;
        ++impacts;
        if (impacts == 1) first_impact_speed = kin.approach_speed;
      }
      const double f_n = dyn::normal_contact_force(normal, c.depth, kin.approach_speed, m.impact_speed);
      // The force on the journal acts along -normal_W; friction opposes the journal's sliding.
      force -= f_n * c.normal_W;
      force -= dyn::regularised_friction_force(friction, f_n, kin.tangential_velocity_W);
      deepest = std::max(deepest, c.depth);
      elastic_energy += dyn::contact_elastic_energy(normal, c.depth);
    }
    for (std::size_t s = 0; s < memory.size(); ++s) {
      if (!seen[s]) memory[s].in_contact = false;  // separated: the next touch is a new impact
    }
    // Semi-implicit Euler: velocity first, then position with the new velocity.
    velocity += kStep * force / kMass;
    position += kStep * velocity;
  }

  const double final_energy = energy(position, velocity, elastic_energy);
  std::printf("impacts %d, first impact speed %.4f m/s, deepest %.3e m (clearance %.1e m)\n",
              impacts, first_impact_speed, deepest, radial_clearance);
  std::printf("energy %.6e J -> %.6e J, journal at (%.3e, %.3e, %.3e) m, speed %.3e m/s\n",
              initial_energy, final_energy, position.x(), position.y(), position.z(),
              velocity.norm());
  // The journal falls onto the wall, bounces and loses energy at every impact (ce = 0.9 and
  // friction): it must never get deeper than the clearance, and end with less energy.
  const bool ok = impacts > 0 && first_impact_speed > 0.0 && deepest < radial_clearance &&
                  final_energy < initial_energy;
  std::printf("%s\n", ok ? "as expected" : "UNEXPECTED");
  return ok ? 0 : 1;
}
