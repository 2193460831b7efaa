// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The journal-bearing integrals of the closed forms,
//   J_f(psi1, psi2) = integral from psi1 to psi2 of f(psi) / (1 - eps cos psi)^3 dpsi,
// for f in {1, cos, sin, cos^2, sin cos, sin^2}, by the Sommerfeld substitution
//   cos gamma = (cos psi - eps) / (1 - eps cos psi),  sin gamma = s sin psi / (1 - eps cos psi),
//   s = sqrt(1 - eps^2),  dpsi / (1 - eps cos psi) = dgamma / s,
// under which each integrand becomes a trigonometric polynomial in gamma (Pinkus & Sternlicht,
// Theory of Hydrodynamic Lubrication, 1961, ch. 3; docs/lubrication.md lists the primitives).

namespace clearjoint::lubrication::detail {

/// The Sommerfeld angle gamma(psi), continuous in psi (gamma - psi is periodic, odd, |.| < pi).
double sommerfeld_angle(double eps, double psi);

struct KernelIntegrals {
  double one = 0.0, c = 0.0, s = 0.0, cc = 0.0, sc = 0.0, ss = 0.0;
};

/// J_f for every f over [psi1, psi2]; eps in [0, 1).
KernelIntegrals kernel_integrals(double eps, double psi1, double psi2);

/// The primitives at one gamma (differences of them are the integrals).
KernelIntegrals kernel_primitives(double eps, double gamma);

}  // namespace clearjoint::lubrication::detail
