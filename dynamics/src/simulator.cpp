// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "clearjoint/dynamics/errors.hpp"

namespace clearjoint::dynamics {

namespace {

/// advance_to's arrival: the shortened last step ends at time + (t - time), which rounds to t or
/// to a neighbour of it; a remainder this small (relative to t) is no step worth taking, and
/// below minimum_step it would read as a collapse.
constexpr double kArrivalUlps = 4 * std::numeric_limits<double>::epsilon();

/// How far from 1 the norm of a body's Euler parameters in set_state may be. The integrator lets
/// |p| drift (it reads rotations from p / |p|, SystemKinematics::update), by far less than this
/// over a run (summary max_euler_norm_drift); a state read from state() and changed, or Euler
/// parameters computed in double, are within it. A zero or far from unit p is no rotation the
/// constraints were written for, and the next step fails ("Jacobian lost rank").
constexpr double kStateEulerNormTolerance = 1e-6;

const ClearanceRevoluteJoint* as_clearance_joint(const ForceElement& element) {
  return dynamic_cast<const ClearanceRevoluteJoint*>(&element);
}

/// Throw ModelError naming the first clearance joint that is beyond the paper's model in
/// `state` (geometry::ContactScenario::beyond_model: a penetration deeper than the clearance in
/// its direction, eqs. 1-2, or a rim beyond the wall or a base all round), with its deepest
/// contact and the clearance. A run that starts there is no clearance joint in contact: the force
/// law of Sec. 4 is fitted to depths far below the clearance, and the integrator would take steps
/// of 1e-10 s for hours pushing the journal back.
void refuse_start_beyond_model(MultibodySystem& system, double time, std::span<const double> state) {
  const auto elements = system.force_elements();
  bool kinematics_set = false;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const ClearanceRevoluteJoint* joint = as_clearance_joint(*elements[e]);
    if (joint == nullptr) continue;
    if (!kinematics_set) {
      system.begins_event(time, state);  // the kinematics at `state`
      kinematics_set = true;
    }
    const ClearanceJointState at_start = joint->evaluate(time, system.kinematics(), system.extra_state(state, e));
    const geometry::JointContacts& found = at_start.contacts;
    if (!joint->beyond_model(at_start)) continue;
    std::string deepest = "no single contact deeper than its clearance (a rim crosses the wall four times)";
    double worst = -INFINITY;
    for (int k = 0; k < found.contact_count; ++k) {
      const geometry::Contact& c = found.contacts[k];
      const bool radial = c.type == geometry::ContactType::radial;
      const double clearance = radial ? joint->radial_clearance() : joint->axial_clearance();
      if (c.depth / clearance <= worst) continue;
      worst = c.depth / clearance;
      deepest = std::string("a ") + (radial ? "radial" : "axial") + " penetration of " + format_number(c.depth) +
                " m, deeper than the " + (radial ? "radial" : "axial") + " clearance of " +
                format_number(clearance) + " m";
    }
    throw ModelError("forces: clearance joint \"" + std::string(joint->name()) + "\" starts beyond its model (" +
                     deepest + "; geometry scenario beyond_model): place the journal within its clearance "
                     "(bodies[].initial) or hold coordinates that keep it there (initial_conditions)");
  }
}

}  // namespace

Simulator::Simulator(const ModelDescription& model)
    : model_(model), built_(build_model(model_)), impacts_seen_(built_.system->force_elements().size(), 0) {
  // The compliant engine never runs a model meant for the non-smooth one (docs/nonsmooth.md).
  if (model_.solver_method != SolverMethod::dormand_prince) {
    throw ModelError("solver.method = \"" + std::string(to_string(model_.solver_method)) +
                     "\": run by clearjoint::nonsmooth (docs/nonsmooth.md), not by the compliant integrator");
  }
  refuse_start_beyond_model(*built_.system, model_.solver.start_time, built_.initial_state);
}

Simulator::~Simulator() = default;

void Simulator::start(const Observer& observer, const StepMonitor& monitor) {
  if (integrator_) throw std::logic_error("Simulator::start: already started");
  observer_ = observer;
  monitor_ = monitor;
  integrator_ = std::make_unique<Integrator>(*built_.system, built_.initial_state, model_.solver, observer_);
}

void Simulator::ensure_started() {
  if (!integrator_) start();
}

double Simulator::time() const { return integrator_ ? integrator_->time() : model_.solver.start_time; }
bool Simulator::finished() const { return integrator_ && integrator_->finished(); }

std::span<const double> Simulator::state() const {
  return integrator_ ? integrator_->state() : std::span<const double>(built_.initial_state);
}

BodyState Simulator::body_state(std::string_view body) const {
  return built_.system->body_state(state(), built_.system->body_index(body, "body"));
}

void Simulator::set_state(std::span<const double> state) {
  // Every check before anything changes: a refused state leaves the simulator as it was.
  if (state.size() != built_.initial_state.size()) {
    throw ModelError("state: " + std::to_string(state.size()) + " values for a state of " +
                     std::to_string(built_.initial_state.size()));
  }
  for (std::size_t k = 0; k < state.size(); ++k) {
    if (!std::isfinite(state[k])) {
      throw ModelError("state[" + std::to_string(k) + "]", " = " + format_number(state[k]) + ": must be finite");
    }
  }
  const StateLayout& layout = built_.system->layout();
  for (BodyIndex b = 0; b < layout.body_count; ++b) {
    const std::size_t p0 = static_cast<std::size_t>(layout.position_offset(b)) + 3;
    const Vector4 p(state[p0], state[p0 + 1], state[p0 + 2], state[p0 + 3]);
    if (!(std::fabs(p.norm() - 1.0) <= kStateEulerNormTolerance)) {
      throw ModelError("state[" + std::to_string(p0) + ":" + std::to_string(p0 + 4) + "]",
                       " = " + format_vector(p) + ": the Euler parameters of body \"" +
                           built_.system->bodies()[b].name + "\" must have norm 1 (within " +
                           format_shortest(kStateEulerNormTolerance) + "); their norm is " + format_number(p.norm()));
    }
  }
  ensure_started();
  integrator_->restart(state);
}

void Simulator::apply_load(std::string_view body, const Vector3& force_W, const Vector3& moment_W) {
  const BodyIndex b = built_.system->body_index(body, "body");
  if (b == kGround) throw ModelError("body = \"ground\": the ground does not move; load a moving body");
  built_.system->set_external_load(b, force_W, moment_W);
  if (integrator_) integrator_->right_hand_side_changed();
}

void Simulator::clear_loads() {
  built_.system->clear_external_loads();
  if (integrator_) integrator_->right_hand_side_changed();
}

void Simulator::step() {
  ensure_started();
  integrator_->step(observer_, monitor_);
}

void Simulator::advance_to(double t, const std::function<void()>& between_steps) {
  ensure_started();
  if (!(t >= time() && t <= end_time())) {
    throw ModelError("advance_to(" + format_number(t) + "): must lie in [time() = " + format_number(time()) +
                     ", end_time = " + format_number(end_time()) + "]");
  }
  const double arrived = kArrivalUlps * std::max(std::fabs(t), 1e-300);
  // To the end: on until the last report time is reported (finished), which a step just short
  // of end_time by rounding has not done yet; that step then goes past it, unshortened.
  const bool to_end = t == end_time();
  while (!finished() && (to_end || t - time() > arrived)) {
    const double remaining = t - time();
    if (remaining > arrived && integrator_->next_step() > remaining) integrator_->limit_next_step(remaining);
    integrator_->step(observer_, monitor_);
    if (between_steps) between_steps();
  }
}

std::vector<ImpactEvent> Simulator::take_impacts() {
  std::vector<ImpactEvent> events;
  const auto elements = built_.system->force_elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const ClearanceRevoluteJoint* joint = as_clearance_joint(*elements[e]);
    if (joint == nullptr) continue;
    const std::vector<RecordedImpact>& recorded = joint->recorded_impacts();
    for (std::size_t k = impacts_seen_[e]; k < recorded.size(); ++k) {
      events.push_back({recorded[k].time, std::string(joint->name()), recorded[k].slot, recorded[k].impact_speed});
    }
    impacts_seen_[e] = recorded.size();
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const ImpactEvent& a, const ImpactEvent& b) { return a.time < b.time; });
  return events;
}

ClearanceJointState Simulator::joint_state(std::string_view name) {
  const auto elements = built_.system->force_elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const ClearanceRevoluteJoint* joint = as_clearance_joint(*elements[e]);
    if (joint == nullptr || joint->name() != name) continue;
    const std::span<const double> y = state();
    // Kinematics at the current state: the last derivative() may have been a trial stage.
    built_.system->begins_event(time(), y);
    return joint->evaluate(time(), built_.system->kinematics(), built_.system->extra_state(y, e));
  }
  throw ModelError("joint = \"" + std::string(name) + "\": no clearance joint of that name");
}

const IntegrationStatistics& Simulator::statistics() const {
  static const IntegrationStatistics none{};
  return integrator_ ? integrator_->statistics() : none;
}

}  // namespace clearjoint::dynamics
