// SPDX-License-Identifier: BSD-3-Clause
#include "siconos_journal_in_bearing.hpp"

#include <SiconosKernel.hpp>

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

}  // namespace

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
