// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The 1-D impact m x'' = -F(x, x') of a contact law, integrated independently of the library's
// integrator (odeint's Dormand-Prince with dense output), and the effective restitution that the
// damped Hertz laws give in closed form.

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>

#include "clearjoint/dynamics/normal_contact_force.hpp"

namespace clearjoint::dynamics::test {

/// -v_out / v_in of a body of mass `mass` hitting at `speed` (x the penetration, from x = 0 until
/// it is 0 again), the force from normal_contact_force with impact speed `speed`.
inline double integrated_restitution(const NormalForceParameters& law, double mass, double speed,
                                     double tolerance = 1e-14) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 2>;
  State x{0.0, speed};
  auto rhs = [&](const State& s, State& ds, double) {
    ds[0] = s[1];
    ds[1] = -normal_contact_force(law, s[0], s[1], speed) / mass;
  };
  auto stepper = odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  stepper.initialize(x, 0.0, 1e-8);
  while (stepper.current_state()[0] >= 0.0) stepper.do_step(rhs);
  // The exit time t* (x(t*) = 0) by bisection on the dense output.
  double lo = stepper.previous_time(), hi = stepper.current_time();
  State s;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    stepper.calc_state(mid, s);
    (s[0] >= 0.0 ? lo : hi) = mid;
  }
  stepper.calc_state(hi, s);
  return -s[1] / speed;
}

/// The effective restitution of F = K x^n (1 + a x' / v_in) (every damped law of
/// normal_contact_force.hpp, a = hysteresis_factor), whatever K, n and m: along the impact
/// m v dv/dx = -K x^n (1 + a v / v_in), so with u = v / v_in the quantity
/// G(u) = u - ln(1 + a u) / a (the integral of u du / (1 + a u), times a constant) plus
/// K x^(n+1) / ((n+1) m v_in^2) is conserved; at x = 0 on the way in (u = 1) and out (u = -e)
/// G(1) = G(-e). G decreases on (-1/a, 0] from +inf to 0, so e is its unique root there, found by
/// bisection. (Hunt and Crossley 1975; Lankarani and Nikravesh 1990 expand the same balance to
/// first order in 1 - ce.) a = 0 (Hertz) gives e = 1.
inline double closed_form_restitution(double a) {
  if (a == 0.0) return 1.0;
  using Real = long double;
  const Real A = a;
  auto G = [&](Real u) { return u - std::log1p(A * u) / A; };
  const Real target = G(1);
  Real lo = 0, hi = 1 / A;  // G(-lo) = 0 < target < G(-hi) = +inf
  if (hi > 1e6L) hi = 1e6L;
  for (int k = 0; k < 200; ++k) {
    const Real mid = 0.5L * (lo + hi);
    (G(-mid) < target ? lo : hi) = mid;
  }
  return static_cast<double>(0.5L * (lo + hi));
}

}  // namespace clearjoint::dynamics::test
