// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A model built once and integrated step by step, for callers that drive a run themselves:
/// controls applied between steps, co-simulation with another engine, their own event logic.
/// simulate() (simulation.hpp) is a loop over it that writes the tables.
///
///   Simulator sim(read_model_file("models/slider_crank_spatial_clearance.json"));
///   while (!sim.finished()) {
///     sim.apply_load("crank", Vector3::Zero(), torque(sim));   // held until set again
///     sim.advance_to(sim.time() + 1e-3);
///     for (const ImpactEvent& impact : sim.take_impacts()) { ... }
///   }

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"

namespace clearjoint::dynamics {

/// An impact recorded by a clearance joint: the onset of a contact, where the integrator located
/// it, with the approach speed its force law remembers (delta_dot(-), eq. 28).
struct ImpactEvent {
  double time = 0.0;         ///< [s]
  std::string joint;         ///< the clearance joint's name
  ContactSlot slot = ContactSlot::line;
  double impact_speed = 0.0;  ///< [m/s]
};

class Simulator {
 public:
  /// Builds the model (build_model: consistent initial conditions). Throws ModelError or
  /// SolverError as build_model does.
  explicit Simulator(const ModelDescription& model);
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;
  ~Simulator();

  const ModelDescription& model() const { return model_; }
  MultibodySystem& system() { return *built_.system; }
  const MultibodySystem& system() const { return *built_.system; }
  const BuiltModel& built() const { return built_; }

  /// Begin integrating: the start's discrete update, and `observer` (may be empty) called at
  /// start_time and at every report time after it; `monitor` after every accepted step. The
  /// first step(), advance_to() or set_state() starts without them when start() was not called.
  void start(const Observer& observer = {}, const StepMonitor& monitor = {});

  /// Time of the current state [s]; solver.start_time before the first step.
  double time() const;
  double end_time() const { return model_.solver.end_time; }
  /// Every report time up to end_time has been reported: no further step is taken.
  bool finished() const;
  /// The packed state (StateLayout: positions, velocities, force elements' extra state).
  std::span<const double> state() const;
  /// One body's state in the current state (ModelError for an unknown name).
  BodyState body_state(std::string_view body) const;
  /// Continue from `state` (as wide as state()) at time(): the force elements' discrete update
  /// runs on it and the stepper restarts. The caller keeps the constraints satisfied.
  void set_state(std::span<const double> state);

  /// A force at the body's mass centre and a moment, world frame, held from now on until set
  /// again or cleared (MultibodySystem::set_external_load). ModelError for an unknown body or a
  /// value that is not finite.
  void apply_load(std::string_view body, const Vector3& force_W, const Vector3& moment_W);
  void clear_loads();

  /// One accepted step of the integrator (nothing once finished()).
  void step();
  /// Steps until time() reaches `t`, the last one shortened to end there (up to rounding: within
  /// a few ulps of t). `t` must lie in [time(), end_time]; ModelError otherwise.
  /// `between_steps` (may be empty) is called after every step and may throw to stop (an
  /// interrupt), leaving the simulator at that step.
  void advance_to(double t, const std::function<void()>& between_steps = {});

  /// The impacts recorded since the last call, over every clearance joint, in time order.
  std::vector<ImpactEvent> take_impacts();
  /// The clearance joint called `name` at the current state: its contacts, forces and slots.
  ClearanceJointState joint_state(std::string_view name);

  const IntegrationStatistics& statistics() const;

 private:
  void ensure_started();

  ModelDescription model_;
  BuiltModel built_;
  std::unique_ptr<Integrator> integrator_;
  Observer observer_;
  StepMonitor monitor_;
  std::vector<std::size_t> impacts_seen_;  ///< per force element: recorded impacts taken so far
};

}  // namespace clearjoint::dynamics
