// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A shipped model run in clearjoint and in Simbody, for the agreement tests: the impacts each
// engine recorded and the bodies' mass-centre positions at common sample times.

#include <string>
#include <vector>

#include "clearjoint/dynamics/integrator.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/simbody/model_in_simbody.hpp"

namespace clearjoint::simbody::testing {

struct EngineRun {
  std::vector<dynamics::RecordedImpact> impacts;  ///< of the model's first clearance joint
  std::vector<double> sample_times;
  /// positions[k][b]: body b's mass centre at sample_times[k].
  std::vector<std::vector<dynamics::Vector3>> positions;
  double initial_energy = 0.0;
  double final_energy = 0.0;
};

inline dynamics::ModelDescription shipped_model(const std::string& file, double tolerance) {
  dynamics::ModelDescription model = dynamics::read_model_file(std::string(CLEARJOINT_MODELS_DIR) + "/" + file);
  model.solver.relative_tolerance = model.solver.absolute_tolerance = tolerance;
  return model;
}

inline EngineRun run_in_clearjoint(const dynamics::ModelDescription& model, double sample_step) {
  dynamics::BuiltModel built = dynamics::build_model(model);
  dynamics::MultibodySystem& system = *built.system;
  dynamics::IntegratorSettings settings = model.solver;
  settings.report_step = sample_step;
  EngineRun run;
  std::vector<double> y = built.initial_state;
  auto energy = [&](double t, std::span<const double> state) {
    return system.kinetic_energy(state) + system.potential_energy(t, state);
  };
  run.initial_energy = energy(settings.start_time, y);
  dynamics::integrate(system, y, settings, [&](double t, std::span<const double> state) {
    run.sample_times.push_back(t);
    std::vector<dynamics::Vector3> p;
    for (int b = 0; b < system.layout().body_count; ++b) {
      const double* q = state.data() + system.layout().position_offset(b);
      p.emplace_back(q[0], q[1], q[2]);
    }
    run.positions.push_back(std::move(p));
  });
  run.final_energy = energy(settings.end_time, y);
  for (const auto& element : system.force_elements()) {
    if (const auto* joint = dynamic_cast<const dynamics::ClearanceRevoluteJoint*>(element.get())) {
      run.impacts = joint->recorded_impacts();
      break;
    }
  }
  return run;
}

inline EngineRun run_in_simbody(const dynamics::ModelDescription& model, double sample_step) {
  SimbodyModel built(model);
  SimTK::RungeKuttaMersonIntegrator integrator(built.system());
  integrator.setAccuracy(model.solver.relative_tolerance);
  SimTK::TimeStepper stepper(built.system(), integrator);
  stepper.initialize(built.initial_state());
  EngineRun run;
  run.initial_energy = built.system().calcEnergy(built.initial_state());
  const long samples = std::lround((model.solver.end_time - model.solver.start_time) / sample_step);
  for (long k = 0; k <= samples; ++k) {
    const double t = k == samples ? model.solver.end_time : model.solver.start_time + double(k) * sample_step;
    while (stepper.getTime() < t) stepper.stepTo(t);
    const SimTK::State& state = stepper.getState();
    run.sample_times.push_back(t);
    std::vector<dynamics::Vector3> p;
    for (const auto& body : model.bodies) {
      const SimTK::Vec3 r = built.body(body.properties.name, "bodies").getBodyOriginLocation(state);
      p.emplace_back(r[0], r[1], r[2]);
    }
    run.positions.push_back(std::move(p));
  }
  built.system().realize(stepper.getState(), SimTK::Stage::Dynamics);
  run.final_energy = built.system().calcEnergy(stepper.getState());
  run.impacts = built.clearance_joints().front()->joint().recorded_impacts();
  return run;
}

}  // namespace clearjoint::simbody::testing
