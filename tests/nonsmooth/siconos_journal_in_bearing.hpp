// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// The journal-in-bearing system in Siconos's own kernel (libsiconos-kernel-dev): a point mass
/// in the plane, a unilateral relation h(q) = c - |q| (circle in circle, which Siconos's kernel
/// does not ship), Newton's impact law, MoreauJeanOSI and an LCP. The reference that
/// test_siconos_comparison.cpp holds clearjoint::nonsmooth::MoreauJean to.

#include <vector>

namespace clearjoint::nonsmooth::siconos_reference {

struct PlanarJournal {
  double mass = 0.0;         ///< [kg]
  double gravity = 0.0;      ///< along -y [m/s^2]
  double clearance = 0.0;    ///< radial clearance c [m]
  double restitution = 0.0;  ///< Newton's coefficient e
  double x0 = 0.0, y0 = 0.0;    ///< journal centre relative to the bearing's at t = 0 [m]
  double vx0 = 0.0, vy0 = 0.0;  ///< its velocity at t = 0 [m/s]
  double theta = 0.5;        ///< MoreauJeanOSI's theta
  double step = 0.0;         ///< h [s]
  long steps = 0;
};

/// The state at the end of each step k = 1..steps, and the step's normal percussion.
struct PlanarSample {
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0;
  double normal_percussion = 0.0;  ///< [N s], > 0 in a step with an impact
};

std::vector<PlanarSample> run_siconos(const PlanarJournal& system);

/// The same journal as a disc that turns (x, y, phi), with Coulomb friction of coefficient mu
/// at its contact point (radius journal_radius from its centre): NewtonImpactFrictionNSL of size
/// 2 (normal, in-plane tangent; no tangential restitution) and a FrictionContact(2) problem.
struct FrictionalJournal {
  PlanarJournal planar;
  double inertia = 0.0;         ///< about the journal's axis [kg m^2]
  double journal_radius = 0.0;  ///< [m]
  double friction = 0.0;        ///< mu
};

struct FrictionalSample {
  PlanarSample planar;
  double omega = 0.0;                ///< the journal's angular velocity about z [rad/s]
  double tangent_percussion = 0.0;   ///< [N s], signed along the relation's tangent
};

std::vector<FrictionalSample> run_siconos(const FrictionalJournal& system);

}  // namespace clearjoint::nonsmooth::siconos_reference
