// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/simbody/clearance_revolute_force.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "clearjoint/dynamics/errors.hpp"
#include "two_body_clearance_joint.hpp"

namespace clearjoint::simbody {

namespace {

using Memory = SimTK::Vec<dynamics::kContactSlotCount>;

dynamics::Vector3 to_eigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }
SimTK::Vec3 to_simtk(const dynamics::Vector3& v) { return {v[0], v[1], v[2]}; }

dynamics::Matrix3 to_eigen(const SimTK::Rotation& R) {
  dynamics::Matrix3 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = R[i][j];
  }
  return m;
}

engines::RigidMotion motion_of(const SimTK::MobilizedBody& body, const SimTK::State& state) {
  // The ground is the world frame at rest: no cache lookups (a bearing is often grounded).
  if (body.isGround()) return {};
  const SimTK::Transform& X_GB = body.getBodyTransform(state);
  const SimTK::SpatialVec& V_GB = body.getBodyVelocity(state);
  return {to_eigen(X_GB.p()), to_eigen(X_GB.R()), to_eigen(V_GB[1]), to_eigen(V_GB[0])};
}

dynamics::ClearanceJointPart part_of(const ClearancePartInBody& part) {
  return {dynamics::kGround, to_eigen(part.point_B), to_eigen(part.axis_B)};
}

}  // namespace

/// The force element proper. The joint and its kinematics are scratch of the evaluations (the
/// joint caches its last detection), like any Simbody cache entry; the physics is a function of
/// the State alone.
class ClearanceRevoluteForce::Impl final : public SimTK::Force::Custom::Implementation {
 public:
  Impl(SimTK::SubsystemIndex forces, const std::string& name, const ClearancePartInBody& bearing,
       const ClearancePartInBody& journal, const dynamics::ClearanceJointParameters& parameters)
      : forces_(forces), bearing_(bearing), journal_(journal),
        joint_(name, part_of(bearing), part_of(journal), parameters) {
    if (bearing.body.getMobilizedBodyIndex() == journal.body.getMobilizedBodyIndex()) {
      throw dynamics::ModelError(name + ".journal.body: the journal and the bearing must be on "
                                        "different bodies");
    }
  }

  void realizeTopology(SimTK::State& state) const override {
    // A change of the memory invalidates Dynamics: the forces, and the witness below, which is
    // evaluated at Dynamics, are computed again.
    memory_index_ = state.allocateDiscreteVariable(forces_, SimTK::Stage::Dynamics,
                                                   new SimTK::Value<Memory>(Memory(0.0)));
    // W_film, a continuous state variable that Simbody integrates with the motion, as clearjoint
    // integrates it in the joint's extra state (dynamics::kFilmWorkIndex); 0 at the start.
    if (joint_.lubricated()) work_index_ = state.allocateZ(forces_, SimTK::Vector(1, 0.0));
  }

  void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    add_body_forces(state, body_forces);
  }

  void add_body_forces(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& body_forces) const {
    load(state);
    // Force and moment about each body's origin: Simbody's body forces exactly.
    const engines::BodyWrenches w = joint_.wrenches(memory(state));
    body_forces[journal_.body.getMobilizedBodyIndex()] +=
        SimTK::SpatialVec(to_simtk(w.moment_on_journal_W), to_simtk(w.force_on_journal_W));
    body_forces[bearing_.body.getMobilizedBodyIndex()] +=
        SimTK::SpatialVec(to_simtk(w.moment_on_bearing_W), to_simtk(w.force_on_bearing_W));
    // dW_film/dt: a cache entry that a force may write while Simbody realises Dynamics, and that
    // nothing else writes or clears, so every evaluation sets it.
    if (joint_.lubricated()) state.updZDot(forces_)[work_index_] = w.film_power;
  }

  double film_work(const SimTK::State& state) const {
    return joint_.lubricated() ? state.getZ(forces_)[work_index_] : 0.0;
  }

  SimTK::Real calcPotentialEnergy(const SimTK::State& state) const override {
    load_positions(state);
    return joint_.potential_energy();
  }

  void calcDecorativeGeometryAndAppend(const SimTK::State&, SimTK::Stage stage,
                                       SimTK::Array_<SimTK::DecorativeGeometry>& geometry) const override {
    if (stage != SimTK::Stage::Topology) return;
    const geometry::JointDimensions& d = joint_.joint().parameters().dimensions;
    // DecorativeCylinder lies along its y axis, centred on its origin.
    auto cylinder = [&](const ClearancePartInBody& part, double radius, double length,
                        const SimTK::Vec3& colour, double opacity) {
      const SimTK::Rotation R_BC(SimTK::UnitVec3(part.axis_B), SimTK::YAxis);
      geometry.push_back(SimTK::DecorativeCylinder(radius, 0.5 * length)
                             .setBodyId(part.body.getMobilizedBodyIndex())
                             .setTransform(SimTK::Transform(R_BC, part.point_B))
                             .setColor(colour)
                             .setOpacity(opacity));
    };
    if (const auto& pin = joint_.joint().parameters().pin_in_hole) {
      // The hole, and the pin through it as far as its farthest stop (the model takes it as long
      // as it needs to be; without stops, drawn twice the hole's length).
      double reach = pin->stop_count == 0 ? pin->hole_length : 0.5 * pin->hole_length;
      for (int k = 0; k < pin->stop_count; ++k) reach = std::max(reach, std::abs(pin->stops[k].position));
      cylinder(bearing_, pin->hole_radius, pin->hole_length, SimTK::Gray, 0.3);
      cylinder(journal_, pin->pin_radius, 2.0 * reach, SimTK::Orange, 1.0);
      return;
    }
    cylinder(bearing_, d.bearing_radius, d.bearing_length, SimTK::Gray, 0.3);
    cylinder(journal_, d.journal_radius, d.journal_length, SimTK::Orange, 1.0);
  }

  std::span<const double> memory(const SimTK::State& state) const {
    // static_cast: realizeTopology allocated exactly this type (downcast() would check it with
    // a dynamic_cast on every evaluation).
    const Memory& m =
        static_cast<const SimTK::Value<Memory>&>(state.getDiscreteVariable(forces_, memory_index_)).get();
    return {&m[0], dynamics::kContactSlotCount};
  }

  /// The witness of the onset handler: +1 when the memory must change at this state, else -1.
  double memory_witness(const SimTK::State& state) const {
    load(state);
    return joint_.memory_is_stale(memory(state)) ? 1.0 : -1.0;
  }

  /// Record the onsets and clear the ended contacts at `state`; true if the memory changed.
  bool update_memory(SimTK::State& state) const {
    load(state);
    Memory memory_now = SimTK::Value<Memory>::downcast(state.getDiscreteVariable(forces_, memory_index_));
    if (!joint_.update_impact_memory({&memory_now[0], dynamics::kContactSlotCount})) return false;
    SimTK::Value<Memory>::updDowncast(state.updDiscreteVariable(forces_, memory_index_)) = memory_now;
    return true;
  }

  dynamics::ClearanceJointState evaluate(const SimTK::State& state) const {
    load(state);
    return joint_.evaluate(memory(state));
  }
  void record_outputs(const SimTK::State& state, std::span<double> values) const {
    load(state);
    // The joint's extra state as clearjoint lays it out: the memory, then W_film.
    std::array<double, dynamics::kFilmWorkIndex + 1> extra_state{};
    const std::span<const double> m = memory(state);
    std::copy(m.begin(), m.end(), extra_state.begin());
    extra_state[dynamics::kFilmWorkIndex] = film_work(state);
    joint_.record_outputs(std::span<const double>(extra_state).first(joint_.lubricated() ? extra_state.size()
                                                                                           : m.size()),
                          values);
  }
  const dynamics::ClearanceRevoluteJoint& joint() const { return joint_.joint(); }

 private:
  void load(const SimTK::State& state) const {
    joint_.set_motions(state.getTime(), motion_of(bearing_.body, state), motion_of(journal_.body, state));
  }
  /// Positions only (potential energy is asked at Stage::Position); velocities zero.
  void load_positions(const SimTK::State& state) const {
    auto pose = [&](const SimTK::MobilizedBody& body) {
      const SimTK::Transform& X_GB = body.getBodyTransform(state);
      engines::RigidMotion motion;
      motion.origin_W = to_eigen(X_GB.p());
      motion.rotation = to_eigen(X_GB.R());
      return motion;
    };
    joint_.set_motions(state.getTime(), pose(bearing_.body), pose(journal_.body));
  }

  SimTK::SubsystemIndex forces_;
  ClearancePartInBody bearing_;
  ClearancePartInBody journal_;
  mutable engines::TwoBodyClearanceJoint joint_;
  mutable SimTK::DiscreteVariableIndex memory_index_;
  mutable SimTK::ZIndex work_index_;  ///< W_film, lubricated joints only
};

namespace {

/// Locates a contact onset (or end) inside a step and updates the memory there.
class ImpactMemoryHandler final : public SimTK::TriggeredEventHandler {
 public:
  explicit ImpactMemoryHandler(const ClearanceRevoluteForce::Impl& force)
      : SimTK::TriggeredEventHandler(SimTK::Stage::Dynamics), force_(force) {
    getTriggerInfo().setTriggerOnRisingSignTransition(true);
    getTriggerInfo().setTriggerOnFallingSignTransition(false);
  }
  SimTK::Real getValue(const SimTK::State& state) const override { return force_.memory_witness(state); }
  void handleEvent(SimTK::State& state, SimTK::Real, bool& should_terminate) const override {
    should_terminate = false;
    force_.update_memory(state);
  }

 private:
  const ClearanceRevoluteForce::Impl& force_;
};

}  // namespace

ClearanceRevoluteForce::ClearanceRevoluteForce(SimTK::MultibodySystem& system,
                                               SimTK::GeneralForceSubsystem& forces,
                                               const std::string& name,
                                               const ClearancePartInBody& bearing,
                                               const ClearancePartInBody& journal,
                                               const dynamics::ClearanceJointParameters& parameters)
    : SimTK::Force::Custom(forces, new Impl(forces.getMySubsystemIndex(), name, bearing, journal,
                                            parameters)) {
  system.addEventHandler(new ImpactMemoryHandler(impl()));
}

const ClearanceRevoluteForce::Impl& ClearanceRevoluteForce::impl() const {
  return static_cast<const Impl&>(getImplementation());
}

void ClearanceRevoluteForce::initialize_impact_memory(SimTK::State& state) const {
  impl().update_memory(state);
}

std::span<const double> ClearanceRevoluteForce::impact_memory(const SimTK::State& state) const {
  return impl().memory(state);
}

dynamics::ClearanceJointState ClearanceRevoluteForce::evaluate(const SimTK::State& state) const {
  return impl().evaluate(state);
}

void ClearanceRevoluteForce::add_body_forces(const SimTK::State& state,
                                             SimTK::Vector_<SimTK::SpatialVec>& body_forces) const {
  impl().add_body_forces(state, body_forces);
}

void ClearanceRevoluteForce::record_outputs(const SimTK::State& state, std::span<double> values) const {
  impl().record_outputs(state, values);
}

double ClearanceRevoluteForce::film_work(const SimTK::State& state) const { return impl().film_work(state); }

const dynamics::ClearanceRevoluteJoint& ClearanceRevoluteForce::joint() const { return impl().joint(); }

}  // namespace clearjoint::simbody
