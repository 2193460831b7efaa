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

const ClearanceRevoluteJoint* as_clearance_joint(const ForceElement& element) {
  return dynamic_cast<const ClearanceRevoluteJoint*>(&element);
}

}  // namespace

Simulator::Simulator(const ModelDescription& model)
    : model_(model), built_(build_model(model_)), impacts_seen_(built_.system->force_elements().size(), 0) {}

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
  ensure_started();
  if (state.size() != integrator_->state().size()) {
    throw ModelError("state: " + std::to_string(state.size()) + " values for a state of " +
                     std::to_string(integrator_->state().size()));
  }
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
