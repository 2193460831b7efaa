// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/integrator.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <memory>
#include <cstdio>
#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/stall_guard.hpp"

namespace clearjoint::dynamics {

namespace odeint = boost::numeric::odeint;

namespace {

/// span / report_step is an integer up to rounding for the usual settings (1 s / 1e-5 s); this
/// relative slack keeps a rounding excess from adding a report time a few ulps before end_time.
constexpr double kReportCountSlack = 1e-9;

/// Most report times counted: beyond it std::lround of the count overflows (2^63) or loses
/// integers (2^53), and the reports stop or never end.
constexpr double kMaxReportCount = 1e15;

bool all_finite(const std::vector<double>& y) {
  return std::all_of(y.begin(), y.end(), [](double x) { return std::isfinite(x); });
}

/// Bracket the first instant of [interval.first, interval.second] at which system.begins_event
/// holds on the dense output, knowing it does not at the start (the extra state was updated
/// there) and does at the end. Bisection, because the event is a predicate (a contact present or
/// not) and its depth is defined on one side only. Bracket width: sqrt(relative_tolerance) times
/// the step. A contact force grows at least linearly from first touch (K delta^n, n >= 1, with
/// delta growing linearly), so the approach speed lost between the onset and the bracket's upper
/// end is at most (width / step)^2 = relative_tolerance of what the whole step would lose: the
/// recorded delta_dot(-) is as accurate as the step. Narrower brackets only add probes at nearly
/// tangent poses, the detection's most expensive ones. Returns the upper end; `onset` holds the
/// interpolated state there.
template <class Stepper>
double locate_onset(MultibodySystem& system, Stepper& stepper, std::pair<double, double> interval,
                    double relative_tolerance, std::vector<double>& onset,
                    IntegrationStatistics& stats) {
  double before = interval.first;
  double after = interval.second;
  const double width = std::sqrt(relative_tolerance) * (after - before);
  while (after - before > width) {
    const double middle = 0.5 * (before + after);
    if (!(middle > before && middle < after)) break;  // adjacent doubles
    stepper.calc_state(middle, onset);
    ++stats.onset_probes;
    (system.begins_event(middle, onset) ? after : before) = middle;
  }
  stepper.calc_state(after, onset);
  ++stats.located_onsets;
  return after;
}

/// `x` with three significant digits: a rate and a projection, not values to read back.
std::string three_digits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

/// Every kStallWindowSteps accepted steps: whether the rest of the run, at the mean step of the
/// window just ended, needs more steps than the budget allows. Stops it then, naming the step.
class StepBudget {
 public:
  StepBudget(const IntegratorSettings& settings, double start_time)
      : settings_(settings), window_start_(start_time) {}

  void check(long steps, double time) {
    if (steps % kStallWindowSteps != 0) return;
    const double mean_step = (time - window_start_) / static_cast<double>(kStallWindowSteps);
    window_start_ = time;
    const double projected = static_cast<double>(steps) + (settings_.end_time - time) / mean_step;
    if (!(projected > static_cast<double>(settings_.max_steps))) return;
    throw SolverError("integration stopped at t = " + format_number(time) +
                      ": the step size has collapsed to a mean of " + three_digits(mean_step) +
                      " s over the last " + std::to_string(kStallWindowSteps) +
                      " steps; at that rate the run needs about " + three_digits(projected) +
                      " steps, more than solver.max_steps = " + std::to_string(settings_.max_steps) +
                      ". Often a body starts far beyond a clearance or a contact is too stiff to "
                      "resolve: check the initial conditions and the force laws, or raise "
                      "solver.max_steps");
  }

 private:
  const IntegratorSettings& settings_;
  double window_start_;
};

}  // namespace

/// The largest step budget (solver.max_steps): far beyond any run (1e15 steps of a microsecond
/// of wall time each are 30 years), and exact in double, so that a model file's count converts
/// to the budget without rounding.
constexpr long kLargestMaxSteps = 1'000'000'000'000'000;

void validate(const IntegratorSettings& s) {
  require_finite("solver.start_time", s.start_time);
  require_finite("solver.end_time", s.end_time);
  if (!(s.end_time > s.start_time)) {
    throw ModelError("solver.end_time", " = " + format_number(s.end_time) +
                                            ": must be after solver.start_time = " + format_number(s.start_time));
  }
  require_positive("solver.report_step", s.report_step);
  if (!((s.end_time - s.start_time) / s.report_step <= kMaxReportCount)) {
    throw ModelError("solver.report_step", " = " + format_number(s.report_step) + ": gives " +
                     format_number((s.end_time - s.start_time) / s.report_step) +
                     " report times, more than " + format_number(kMaxReportCount) +
                     ", the most the integrator counts");
  }
  require_positive("solver.relative_tolerance", s.relative_tolerance);
  if (!(s.relative_tolerance >= kMinRelativeTolerance && s.relative_tolerance <= kMaxRelativeTolerance)) {
    throw ModelError("solver.relative_tolerance", " = " + format_number(s.relative_tolerance) + ": must be in [" +
                                                      format_shortest(kMinRelativeTolerance) + ", " +
                                                      format_shortest(kMaxRelativeTolerance) + "]");
  }
  require_positive("solver.absolute_tolerance", s.absolute_tolerance);
  require_positive("solver.initial_step", s.initial_step);
  require_positive("solver.minimum_step", s.minimum_step);
  const double span = s.end_time - s.start_time;
  if (!(s.minimum_step < span)) {
    throw ModelError("solver.minimum_step", " = " + format_number(s.minimum_step) +
                                                ": must be shorter than the run, solver.end_time - "
                                                "solver.start_time = " + format_number(span) + " s");
  }
  if (!(s.minimum_step < s.report_step)) {
    throw ModelError("solver.minimum_step", " = " + format_number(s.minimum_step) +
                                                ": must be shorter than solver.report_step = " +
                                                format_number(s.report_step) + " s");
  }
  if (!(s.minimum_step <= s.initial_step)) {
    throw ModelError("solver.minimum_step", " = " + format_number(s.minimum_step) +
                                                ": must not be longer than solver.initial_step = " +
                                                format_number(s.initial_step) + " s");
  }
  if (!(s.max_steps >= 1 && s.max_steps <= kLargestMaxSteps)) {
    throw ModelError("solver.max_steps", " = " + std::to_string(s.max_steps) + ": must be in [1, 1e15]");
  }
  require_positive("solver.stall_wall_time", s.stall_wall_time);
}

/// The dense-output stepper and everything one accepted step needs, behind Integrator's pimpl
/// (odeint's types stay out of the header).
struct Integrator::Impl {
  using State = std::vector<double>;
  using Stepper = decltype(odeint::make_dense_output(1.0, 1.0, odeint::runge_kutta_dopri5<State>()));

  Impl(MultibodySystem& s, const IntegratorSettings& settings_in)
      : system(s),
        settings(settings_in),
        stepper(odeint::make_dense_output(settings.absolute_tolerance, settings.relative_tolerance,
                                          odeint::runge_kutta_dopri5<State>())),
        budget(settings, settings.start_time),
        stall(settings, settings.start_time, 0) {}

  MultibodySystem& system;
  IntegratorSettings settings;
  Stepper stepper;
  StepBudget budget;
  StallGuard stall;
  IntegrationStatistics stats;
  long report_count = 0;
  long next_report = 1;
  State reported, accepted, onset;
  bool finished = false;

  void rhs(const State& x, State& dxdt, double t) {
    ++stats.derivative_calls;
    system.derivative(t, x, dxdt);
  }
  double report_time(long k) const {
    return k == report_count ? settings.end_time
                             : settings.start_time + static_cast<double>(k) * settings.report_step;
  }
};

Integrator::Integrator(MultibodySystem& system, std::span<const double> initial_state,
                       const IntegratorSettings& settings, const Observer& observer) {
  validate(settings);
  std::vector<double> y(initial_state.begin(), initial_state.end());
  if (!all_finite(y)) throw SolverError("initial state is not finite");
  impl_ = std::make_unique<Impl>(system, settings);
  Impl& m = *impl_;
  m.stats.smallest_step = INFINITY;
  const double span = settings.end_time - settings.start_time;
  m.report_count = std::max(1L, std::lround(std::ceil(span / settings.report_step * (1.0 - kReportCountSlack))));
  // Discrete changes of force elements' extra state (impact memory) happen only at accepted
  // states: here at the start, and after every accepted step (step()).
  if (system.update_extra_states(settings.start_time, y)) ++m.stats.restarts;
  m.stepper.initialize(y, settings.start_time, std::min(settings.initial_step, span));
  if (observer) observer(settings.start_time, y);
  m.reported.resize(y.size());
  m.accepted.resize(y.size());
  m.onset.resize(y.size());
  m.reported = y;
}

Integrator::~Integrator() = default;

double Integrator::time() const { return impl_->stepper.current_time(); }
std::span<const double> Integrator::state() const { return impl_->stepper.current_state(); }
double Integrator::next_step() const { return impl_->stepper.current_time_step(); }
bool Integrator::finished() const { return impl_->finished; }
const IntegrationStatistics& Integrator::statistics() const { return impl_->stats; }
const IntegratorSettings& Integrator::settings() const { return impl_->settings; }
std::span<const double> Integrator::last_reported_state() const { return impl_->reported; }

void Integrator::restart(std::span<const double> y, double step) {
  Impl& m = *impl_;
  if (!all_finite(std::vector<double>(y.begin(), y.end()))) throw SolverError("the state set is not finite");
  if (!(step > 0.0)) step = m.stepper.current_time_step();
  m.accepted.assign(y.begin(), y.end());
  if (m.system.update_extra_states(m.stepper.current_time(), m.accepted)) ++m.stats.restarts;
  m.stepper.initialize(m.accepted, m.stepper.current_time(), step);
}

void Integrator::step(const Observer& observer, const StepMonitor& monitor) {
  Impl& m = *impl_;
  if (m.finished) return;
  const IntegratorSettings& settings = m.settings;
  auto& stepper = m.stepper;
  auto& stats = m.stats;
  auto rhs = [&m](const Impl::State& x, Impl::State& dxdt, double t) { m.rhs(x, dxdt, t); };
  std::pair<double, double> interval;
  for (;;) {
    try {
      interval = stepper.do_step(rhs);
      break;
    } catch (const odeint::step_adjustment_error& e) {
      throw SolverError("integration stopped at t = " + format_number(stepper.current_time()) +
                        ": no acceptable step size found (" + e.what() + ")");
    } catch (const SolverError& e) {
      // A trial stage of a long step can land where the right-hand side is undefined although
      // the solution is not there: e.g. a stage that carries a journal far beyond its clearance
      // gets a huge contact force, and the next stage finds the mechanism in a singular pose.
      // Such a step would fail its error test anyway; treat it as rejected and retry a quarter
      // of it from the last accepted state (odeint left that state and its time untouched).
      // A failure that persists down to minimum_step is real and stops the run.
      const double retry = 0.25 * stepper.current_time_step();
      if (!(retry >= settings.minimum_step)) {
        throw SolverError(std::string(e.what()) + " (persisting down to steps of " +
                          format_number(retry) + " s)");
      }
      ++stats.failed_attempts;
      m.accepted = stepper.current_state();
      stepper.initialize(m.accepted, stepper.current_time(), retry);
    }
  }
  ++stats.steps;
  const double taken = interval.second - interval.first;
  stats.smallest_step = std::min(stats.smallest_step, taken);
  stats.largest_step = std::max(stats.largest_step, taken);
  if (!all_finite(stepper.current_state())) {
    throw SolverError("integration stopped at t = " + format_number(interval.second) +
                      ": the state is no longer finite");
  }
  if (stepper.current_time_step() < settings.minimum_step) {
    throw SolverError("integration stopped at t = " + format_number(interval.second) +
                      ": step size collapsed to " + format_number(stepper.current_time_step()) +
                      " s (minimum " + format_number(settings.minimum_step) + " s)");
  }
  if (stats.steps >= settings.max_steps) {
    throw SolverError("integration stopped at t = " + format_number(interval.second) +
                      ": more than solver.max_steps = " + std::to_string(settings.max_steps) +
                      " steps");
  }
  m.budget.check(stats.steps, interval.second);
  m.stall.check(interval.second, stats.steps);
  // A new event (contact onset) seen at the end of the step: bracket its first instant.
  double onset_time = stepper.current_time();
  bool located = false;
  if (settings.onset != OnsetHandling::step_end &&
      m.system.begins_event(stepper.current_time(), stepper.current_state())) {
    onset_time = locate_onset(m.system, stepper, interval, settings.relative_tolerance, m.onset, stats);
    located = true;
  }
  const bool restart_at_onset = located && settings.onset == OnsetHandling::restart_at_onset;
  // Report times inside this step (up to the onset when restarting there), interpolated before
  // a restart discards the interpolant.
  const double reported_up_to = restart_at_onset ? onset_time : stepper.current_time();
  long& k = m.next_report;
  for (; k <= m.report_count && m.report_time(k) <= reported_up_to; ++k) {
    stepper.calc_state(m.report_time(k), m.reported);
    if (observer) observer(m.report_time(k), m.reported);
  }
  if (monitor) monitor(reported_up_to);  // after the reports: times reach it in order
  if (k > m.report_count) {
    m.finished = true;
    return;
  }
  // Record delta_dot(-) at the onset; then (keeping the end state) the usual update at the end
  // of the step adds events seen only there and clears those that ended.
  if (located) m.system.update_extra_states(onset_time, m.onset);
  if (restart_at_onset) {
    // The rest of the step was integrated with a provisional delta_dot(-): drop it.
    stepper.initialize(m.onset, onset_time, stepper.current_time_step());
    ++stats.restarts;
    return;
  }
  m.accepted = stepper.current_state();
  if (located) {
    const auto extra = static_cast<std::ptrdiff_t>(m.system.layout().extra_offset());
    std::copy(m.onset.begin() + extra, m.onset.end(), m.accepted.begin() + extra);
  }
  if (m.system.update_extra_states(stepper.current_time(), m.accepted) || located) {
    // odeint's dense-output stepper keeps the last derivative (FSAL); a changed state needs a
    // fresh start from it, keeping the step size the controller had chosen.
    stepper.initialize(m.accepted, stepper.current_time(), stepper.current_time_step());
    ++stats.restarts;
  }
}

void Integrator::right_hand_side_changed() {
  Impl& m = *impl_;
  m.accepted = m.stepper.current_state();
  m.stepper.initialize(m.accepted, m.stepper.current_time(), m.stepper.current_time_step());
}

void Integrator::limit_next_step(double step) {
  Impl& m = *impl_;
  if (!(step > 0.0) || step >= m.stepper.current_time_step()) return;
  m.accepted = m.stepper.current_state();
  m.stepper.initialize(m.accepted, m.stepper.current_time(), step);
}

IntegrationStatistics integrate(MultibodySystem& system, std::vector<double>& y,
                                const IntegratorSettings& settings, const Observer& observer,
                                const StepMonitor& monitor) {
  Integrator integrator(system, y, settings, observer);
  while (!integrator.finished()) integrator.step(observer, monitor);
  const std::span<const double> last = integrator.last_reported_state();
  y.assign(last.begin(), last.end());
  return integrator.statistics();
}

}  // namespace clearjoint::dynamics
