// SPDX-License-Identifier: BSD-3-Clause
#include "sommerfeld_integrals.hpp"

#include <cmath>
#include <numbers>

namespace clearjoint::lubrication::detail {

double sommerfeld_angle(double eps, double psi) {
  const double s = std::sqrt((1.0 - eps) * (1.0 + eps));  // 1 - eps^2 without cancellation
  // cos psi - eps = (1 - eps) - 2 sin^2(psi / 2): exact near psi = 0, where cos psi and eps
  // both near 1 would cancel. The common factor 1 / (1 - eps cos psi) > 0 leaves atan2 unchanged.
  const double half = std::sin(0.5 * psi);
  const double principal = std::atan2(s * std::sin(psi), (1.0 - eps) - 2.0 * half * half);
  // gamma - psi lies in (-pi, pi): bring the principal value next to psi.
  const double two_pi = 2.0 * std::numbers::pi;
  return psi + std::remainder(principal - psi, two_pi);
}

KernelIntegrals kernel_primitives(double eps, double gamma) {
  const double s2 = (1.0 - eps) * (1.0 + eps);
  const double s = std::sqrt(s2);
  const double s3 = s2 * s, s4 = s2 * s2, s5 = s4 * s;
  const double sin_g = std::sin(gamma), cos_g = std::cos(gamma);
  const double sin_2g = 2.0 * sin_g * cos_g;
  const double e2 = eps * eps;
  KernelIntegrals p;
  p.one = (gamma * (1.0 + 0.5 * e2) + 2.0 * eps * sin_g + 0.25 * e2 * sin_2g) / s5;
  p.c = ((1.0 + e2) * sin_g + eps * (1.5 * gamma + 0.25 * sin_2g)) / s5;
  p.s = (-cos_g + 0.5 * eps * sin_g * sin_g) / s4;
  p.cc = (gamma * (0.5 + e2) + 0.25 * sin_2g + 2.0 * eps * sin_g) / s5;
  p.sc = (0.5 * sin_g * sin_g - eps * cos_g) / s4;
  p.ss = (0.5 * gamma - 0.25 * sin_2g) / s3;
  return p;
}

KernelIntegrals kernel_integrals(double eps, double psi1, double psi2) {
  const KernelIntegrals a = kernel_primitives(eps, sommerfeld_angle(eps, psi1));
  const KernelIntegrals b = kernel_primitives(eps, sommerfeld_angle(eps, psi2));
  return KernelIntegrals{b.one - a.one, b.c - a.c, b.s - a.s, b.cc - a.cc, b.sc - a.sc, b.ss - a.ss};
}

}  // namespace clearjoint::lubrication::detail
