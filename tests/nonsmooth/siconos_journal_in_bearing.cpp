// SPDX-License-Identifier: BSD-3-Clause
#include "siconos_journal_in_bearing.hpp"

#include <SiconosKernel.hpp>
#include <SolverOptions.h>

#include <cmath>

namespace clearjoint::nonsmooth::siconos_reference {
namespace {

/// Gap h(q) = c - |q| of a point-mass journal centre q in a bearing centred at the origin, and
/// its Jacobian, the inward normal -q / |q| (any unit vector at the centre, where the gap is c
/// and the contact is never active).
class CircleInCircle : public LagrangianScleronomousR {
 public:
  explicit CircleInCircle(double clearance) : clearance_(clearance) {}

  // The base class allocates no Jacobians for a relation without plugins: allocate them here,
  // before the simulation reads them.
  void initialize(Interaction& inter) override {
    LagrangianScleronomousR::initialize(inter);
    if (!_jachq) _jachq.reset(new SimpleMatrix(1, 2));
    if (!_dotjachq) _dotjachq.reset(new SimpleMatrix(1, 2));
  }
  void computeh(const BlockVector& q, BlockVector& /*z*/, SiconosVector& y) override {
    y.setValue(0, clearance_ - std::hypot(q.getValue(0), q.getValue(1)));
  }
  void computeJachq(const BlockVector& q, BlockVector& /*z*/) override {
    const double x = q.getValue(0), y = q.getValue(1), r = std::hypot(x, y);
    _jachq->setValue(0, 0, r > 0.0 ? -x / r : 0.0);
    _jachq->setValue(0, 1, r > 0.0 ? -y / r : -1.0);
  }
  // Only used by event-driven schemes and second-order outputs; MoreauJeanOSI never reads it.
  void computeDotJachq(const BlockVector& /*q*/, BlockVector& /*z*/, const BlockVector& /*qDot*/) override {
    _dotjachq->zero();
  }

 private:
  double clearance_;
};

/// The disc's contact with Coulomb friction: y = (h, 0) with h = c - |q| as above, and the rows
/// of H for (x, y, phi): the inward normal n = -u (u = q / |q|), and the tangent t = (u_y, -u_x)
/// with the contact point's share of the spin, -R (its velocity is v + omega R (-u_y, u_x)).
class DiscInCircle : public LagrangianScleronomousR {
 public:
  DiscInCircle(double clearance, double journal_radius) : clearance_(clearance), radius_(journal_radius) {}

  void initialize(Interaction& inter) override {
    LagrangianScleronomousR::initialize(inter);
    if (!_jachq) _jachq.reset(new SimpleMatrix(2, 3));
    if (!_dotjachq) _dotjachq.reset(new SimpleMatrix(2, 3));
  }
  void computeh(const BlockVector& q, BlockVector& /*z*/, SiconosVector& y) override {
    y.setValue(0, clearance_ - std::hypot(q.getValue(0), q.getValue(1)));
    y.setValue(1, 0.0);
  }
  void computeJachq(const BlockVector& q, BlockVector& /*z*/) override {
    const double x = q.getValue(0), y = q.getValue(1), r = std::hypot(x, y);
    const double ux = r > 0.0 ? x / r : 0.0, uy = r > 0.0 ? y / r : -1.0;
    _jachq->setValue(0, 0, -ux);
    _jachq->setValue(0, 1, -uy);
    _jachq->setValue(0, 2, 0.0);
    _jachq->setValue(1, 0, uy);
    _jachq->setValue(1, 1, -ux);
    _jachq->setValue(1, 2, -radius_);
  }
  void computeDotJachq(const BlockVector& /*q*/, BlockVector& /*z*/, const BlockVector& /*qDot*/) override {
    _dotjachq->zero();
  }

 private:
  double clearance_;
  double radius_;
};

}  // namespace

std::vector<FrictionalSample> run_siconos(const FrictionalJournal& f) {
  const PlanarJournal& s = f.planar;
  SP::SiconosVector q0(new SiconosVector(3)), v0(new SiconosVector(3));
  q0->zero();
  v0->zero();
  q0->setValue(0, s.x0);
  q0->setValue(1, s.y0);
  v0->setValue(0, s.vx0);
  v0->setValue(1, s.vy0);
  SP::SiconosMatrix mass(new SimpleMatrix(3, 3));
  mass->zero();
  mass->setValue(0, 0, s.mass);
  mass->setValue(1, 1, s.mass);
  mass->setValue(2, 2, f.inertia);
  SP::LagrangianLinearTIDS journal(new LagrangianLinearTIDS(q0, v0, mass));
  SP::SiconosVector weight(new SiconosVector(3));
  weight->zero();
  weight->setValue(1, -s.mass * s.gravity);
  journal->setFExtPtr(weight);

  SP::NonSmoothLaw law(new NewtonImpactFrictionNSL(s.restitution, 0.0, f.friction, 2));
  SP::Relation relation(new DiscInCircle(s.clearance, f.journal_radius));
  SP::Interaction contact(new Interaction(law, relation));
  const double end = s.step * static_cast<double>(s.steps);
  SP::NonSmoothDynamicalSystem nsds(new NonSmoothDynamicalSystem(0.0, end));
  nsds->insertDynamicalSystem(journal);
  nsds->link(contact, journal);
  SP::MoreauJeanOSI osi(new MoreauJeanOSI(s.theta));
  SP::TimeDiscretisation td(new TimeDiscretisation(0.0, s.step));
  SP::OneStepNSProblem problem(new FrictionContact(2));
  problem->numericsSolverOptions()->dparam[SICONOS_DPARAM_TOL] = 1e-14;
  SP::TimeStepping simulation(new TimeStepping(nsds, td, osi, problem));

  std::vector<FrictionalSample> samples;
  samples.reserve(static_cast<std::size_t>(s.steps));
  for (long k = 0; k < s.steps && simulation->hasNextEvent(); ++k) {
    simulation->computeOneStep();
    const SiconosVector& q = *journal->q();
    const SiconosVector& v = *journal->velocity();
    const SiconosVector& lambda = *contact->lambda(1);
    samples.push_back({{q.getValue(0), q.getValue(1), v.getValue(0), v.getValue(1), lambda.getValue(0)},
                       v.getValue(2), lambda.getValue(1)});
    simulation->nextStep();
  }
  return samples;
}

std::vector<PlanarSample> run_siconos(const PlanarJournal& s) {
  SP::SiconosVector q0(new SiconosVector(2)), v0(new SiconosVector(2));
  q0->setValue(0, s.x0);
  q0->setValue(1, s.y0);
  v0->setValue(0, s.vx0);
  v0->setValue(1, s.vy0);
  SP::SiconosMatrix mass(new SimpleMatrix(2, 2));
  mass->zero();
  mass->setValue(0, 0, s.mass);
  mass->setValue(1, 1, s.mass);
  SP::LagrangianLinearTIDS journal(new LagrangianLinearTIDS(q0, v0, mass));
  SP::SiconosVector weight(new SiconosVector(2));
  weight->setValue(0, 0.0);
  weight->setValue(1, -s.mass * s.gravity);
  journal->setFExtPtr(weight);

  SP::NonSmoothLaw law(new NewtonImpactNSL(s.restitution));
  SP::Relation relation(new CircleInCircle(s.clearance));
  SP::Interaction contact(new Interaction(law, relation));
  const double end = s.step * static_cast<double>(s.steps);
  SP::NonSmoothDynamicalSystem nsds(new NonSmoothDynamicalSystem(0.0, end));
  nsds->insertDynamicalSystem(journal);
  nsds->link(contact, journal);
  SP::MoreauJeanOSI osi(new MoreauJeanOSI(s.theta));
  SP::TimeDiscretisation td(new TimeDiscretisation(0.0, s.step));
  SP::OneStepNSProblem lcp(new LCP());
  SP::TimeStepping simulation(new TimeStepping(nsds, td, osi, lcp));

  std::vector<PlanarSample> samples;
  samples.reserve(static_cast<std::size_t>(s.steps));
  for (long k = 0; k < s.steps && simulation->hasNextEvent(); ++k) {
    simulation->computeOneStep();
    const SiconosVector& q = *journal->q();
    const SiconosVector& v = *journal->velocity();
    samples.push_back({q.getValue(0), q.getValue(1), v.getValue(0), v.getValue(1),
                       contact->lambda(1)->getValue(0)});
    simulation->nextStep();
  }
  return samples;
}

}  // namespace clearjoint::nonsmooth::siconos_reference
