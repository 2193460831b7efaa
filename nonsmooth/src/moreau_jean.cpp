// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/nonsmooth/moreau_jean.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <variant>
#include <vector>

#include "clearance_contacts.hpp"
#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/constraint_set.hpp"
#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/euler_parameters.hpp"
#include "clearjoint/dynamics/generalised_forces.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "contact_problem.hpp"
#include "fclib_problem.hpp"

namespace clearjoint::nonsmooth {

namespace {

/// Weight of the step's travel in the activation test g + gamma h u_N <= 0: Siconos's
/// MoreauJeanOSI::addInteractionInIndexSet uses gamma = 1/2 unless told otherwise, and the
/// comparison with Siconos (tests/nonsmooth) needs the same index set.
constexpr double kActivationGamma = 0.5;
/// Position projection: stop when max |Phi| is below this. Phi's rows are lengths [m] and
/// direction products [1]; 1e-12 is about 1e4 ulps of the models' coordinates (0.1-1 m) and
/// seven orders below their clearances (0.1 mm), so the projection never competes with a gap.
constexpr double kProjectionTolerance = 1e-12;
/// Newton iterations of the projection: from a drift of O(h^2) it converges quadratically in
/// two or three; ten only bounds a singular configuration's loop (reported in the statistics).
constexpr int kMaxProjectionIterations = 10;

}  // namespace

struct MoreauJean::Impl {
  dynamics::BuiltModel built;
  dynamics::MoreauJeanSettings settings;
  std::vector<double> y;
  double time = 0.0;
  /// The run's start: step k ends at start_time + k h exactly as the fixed-step scheme defines
  /// it (time += h would drift by a rounding a step: 0.05000000000000464 after 5,000 steps).
  double start_time = 0.0;
  std::vector<ClearanceSite> sites;
  std::vector<std::string> site_names;
  std::vector<size_t> smooth_elements;  ///< force elements other than the clearance joints
  dynamics::SystemKinematics kinematics;
  dynamics::GeneralisedForces applied;
  Eigen::VectorXd inverse_mass;
  std::vector<double> rate_scratch;
  std::vector<UnilateralContact> found;
  std::vector<ContactPercussion> percussions;
  Eigen::VectorXd bilateral;  ///< mu of the last step (bilateral_percussions)
  // The step's constraint Jacobian J = Phi_q(q_k), M^-1 J^T and the Cholesky factor of
  // S = J M^-1 J^T: members so that their storage is reused from step to step, and the position
  // projection after the step solves with the same factor.
  Eigen::MatrixXd J;
  Eigen::MatrixXd minv_jt;
  Eigen::LLT<Eigen::MatrixXd> schur;
  Eigen::MatrixXd schur_matrix;
  /// Per body, the rows of Phi whose joints act on it (each joint's rows touch two bodies): S is
  /// the sum over bodies of J_b M_b^-1 J_b^T on those rows.
  std::vector<std::vector<int>> body_rows;
  MoreauJeanStatistics statistics;
  FclibExport fclib;  ///< folder empty: no problem written

  explicit Impl(const dynamics::ModelDescription& model)
      : built(dynamics::build_model(model)),
        settings(model.moreau_jean),
        y(built.initial_state),
        time(model.solver.start_time),
        start_time(model.solver.start_time),
        kinematics(built.system->layout().body_count),
        applied(kinematics) {
    dynamics::validate(settings, "solver");
    dynamics::MultibodySystem& system = *built.system;
    for (size_t f = 0; f < model.forces.size(); ++f) {
      const auto* joint = std::get_if<dynamics::ClearanceRevoluteDescription>(&model.forces[f]);
      if (joint == nullptr) continue;
      const std::string field = "forces[" + std::to_string(f) + "]";
      if (joint->parameters.lubrication) {
        throw dynamics::ModelError(field + ".lubrication: a lubricated joint is not supported by "
                                   "solver.method = \"moreau_jean\" (rigid contact only)");
      }
      ClearanceSite site;
      site.name = joint->name;
      site.bearing_body = system.body_index(joint->bearing.body, field + ".bearing.body");
      site.journal_body = system.body_index(joint->journal.body, field + ".journal.body");
      site.bearing_point_B = joint->bearing.point_B;
      site.bearing_axis_B = joint->bearing.axis_B;
      site.journal_point_B = joint->journal.point_B;
      site.journal_axis_B = joint->journal.axis_B;
      site.parameters = joint->parameters;
      site.margin = activation_margin(joint->parameters.dimensions);
      sites.push_back(site);
      site_names.push_back(site.name);
    }
    const auto elements = system.force_elements();
    for (size_t e = 0; e < elements.size(); ++e) {
      if (dynamic_cast<const dynamics::ClearanceRevoluteJoint*>(elements[e].get()) == nullptr) {
        smooth_elements.push_back(e);
      }
    }
    body_rows.resize(system.bodies().size());
    const dynamics::ConstraintSet& constraints = system.constraints();
    for (size_t k = 0; k < constraints.joints().size(); ++k) {
      const dynamics::JointEquations& joint = constraints.joints()[k];
      for (dynamics::BodyIndex b : {joint.body_i(), joint.body_j()}) {
        if (b == dynamics::kGround) continue;
        for (int e = 0; e < joint.equation_count(); ++e) body_rows[b].push_back(constraints.first_row(static_cast<int>(k)) + e);
      }
    }
    const auto bodies = system.bodies();
    inverse_mass.resize(6 * static_cast<int>(bodies.size()));
    for (size_t b = 0; b < bodies.size(); ++b) {
      inverse_mass.segment<3>(6 * b).setConstant(1.0 / bodies[b].mass);
      inverse_mass.segment<3>(6 * b + 3) = bodies[b].principal_inertia.cwiseInverse();
    }
  }

  dynamics::MultibodySystem& system() { return *built.system; }

  /// g of eq. (35) without the clearance joints: the other elements' forces, and the
  /// gyroscopic term -omega' x J' omega'.
  Eigen::VectorXd generalised_forces() {
    dynamics::MultibodySystem& sys = system();
    applied.clear();
    const auto elements = sys.force_elements();
    for (size_t e : smooth_elements) {
      const auto extra = sys.extra_state(y, e);
      rate_scratch.assign(extra.size(), 0.0);
      dynamics::ForceContext context{time, kinematics, extra, rate_scratch};
      elements[e]->add_forces(context, applied);
    }
    const auto bodies = sys.bodies();
    Eigen::VectorXd g(6 * static_cast<int>(bodies.size()));
    for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
      const dynamics::BodyKinematics& k = kinematics.body(b);
      const Vector3 w = k.angular_velocity_B;
      g.segment<3>(6 * b) = applied.force_W(b);
      g.segment<3>(6 * b + 3) = k.rotation.transpose() * applied.moment_W(b) -
                                w.cross(bodies[b].principal_inertia.cwiseProduct(w));
    }
    return g;
  }

  /// S = J M^-1 J^T body by body (a joint's rows have zeros outside its two bodies' columns):
  /// a product over the non-zero blocks only, where the dense product spent most of a step.
  void assemble_schur() {
    const int m = static_cast<int>(J.rows());
    schur_matrix.setZero(m, m);
    for (size_t b = 0; b < body_rows.size(); ++b) {
      const std::vector<int>& rows = body_rows[b];
      const int column = 6 * static_cast<int>(b);
      for (size_t x = 0; x < rows.size(); ++x) {
        for (size_t y = 0; y <= x; ++y) {
          const double value = J.row(rows[x]).segment<6>(column).dot(minv_jt.col(rows[y]).segment<6>(column));
          schur_matrix(rows[x], rows[y]) += value;
          if (rows[x] != rows[y]) schur_matrix(rows[y], rows[x]) += value;
        }
      }
    }
  }

  /// Add the velocity-sized increment dx (translations, body-frame rotation vectors) to the
  /// positions of y.
  void move_positions(const Eigen::VectorXd& dx) {
    const dynamics::StateLayout& layout = system().layout();
    for (int b = 0; b < layout.body_count; ++b) {
      double* q = y.data() + layout.position_offset(b);
      Eigen::Map<Vector3> r(q);
      Eigen::Map<Vector4> p(q + 3);
      r += dx.segment<3>(6 * b);
      const Matrix3 A = dynamics::rotation_from_euler_parameters(p);
      // A(p_new) = A(p) exp(skew(theta_B)) = exp(skew(A theta_B)) A(p): the exact update for an
      // angular velocity constant over the step.
      Vector4 updated = dynamics::rotate_in_world(p, A * dx.segment<3>(6 * b + 3));
      p = updated / updated.norm();
    }
  }

  void step() {
    dynamics::MultibodySystem& sys = system();
    const dynamics::StateLayout& layout = sys.layout();
    const double h = settings.step;
    const int n = layout.velocity_size();
    kinematics.update(time, y);
    const Eigen::Map<const Eigen::VectorXd> v(y.data() + layout.velocity_offset(0), n);
    const Eigen::VectorXd v_start = v;
    const Eigen::VectorXd g = generalised_forces();
    Eigen::VectorXd v_free = v_start + h * inverse_mass.cwiseProduct(g);

    // Bilateral constraints at velocity level, Phi_q v(k+1) + Phi_t(k+1) = 0, eliminated: v_free
    // becomes the constrained free velocity, and P = M^-1 - M^-1 J^T S^-1 J M^-1 maps impulses
    // to velocity changes that keep the constraints.
    sys.constraints().evaluate(time + h, kinematics);
    J = sys.constraints().jacobian();
    const Eigen::VectorXd phi_t = sys.constraints().time_derivative();
    const int m = static_cast<int>(J.rows());
    minv_jt.noalias() = inverse_mass.asDiagonal() * J.transpose();
    if (m > 0) {
      assemble_schur();
      schur.compute(schur_matrix);
      if (schur.info() != Eigen::Success) {
        throw dynamics::SolverError("moreau_jean at t = " + dynamics::format_number(time) +
                                    " s: the ideal joints' constraint Jacobian lost rank");
      }
      bilateral = -schur.solve(J * v_free + phi_t);
      v_free += minv_jt * bilateral;
    } else {
      bilateral.resize(0);
    }

    // Unilateral contacts: found with the activation margin, kept where the gap closes within
    // half a step (Siconos's index set).
    found.clear();
    for (size_t s = 0; s < sites.size(); ++s) find_contacts(sites[s], static_cast<int>(s), time, kinematics, found);
    std::vector<UnilateralContact> active;
    Eigen::MatrixXd rows(3, n);
    std::vector<Eigen::MatrixXd> active_rows;
    for (const UnilateralContact& c : found) {
      contact_jacobian(c, sites[c.site], kinematics, rows);
      const double u_n = rows.row(0).dot(v_start);
      if (c.gap + kActivationGamma * h * u_n <= 0.0) {
        active.push_back(c);
        active_rows.push_back(rows);
      }
    }
    percussions.clear();
    Eigen::VectorXd v_next = v_free;
    if (!active.empty()) {
      const int c = static_cast<int>(active.size());
      Eigen::MatrixXd H(3 * c, n);
      Eigen::VectorXd mu(c);
      for (int k = 0; k < c; ++k) {
        H.middleRows<3>(3 * k) = active_rows[k];
        mu[k] = sites[active[k].site].parameters.friction.coefficient;
      }
      Eigen::MatrixXd Y = inverse_mass.asDiagonal() * H.transpose();
      if (m > 0) {
        const Eigen::MatrixXd S_inv_JY = schur.solve(J.lazyProduct(Y));
        Y -= minv_jt.lazyProduct(S_inv_JY);
      }
      const Eigen::MatrixXd W = H.lazyProduct(Y);
      const Eigen::VectorXd u_start = H * v_start;
      Eigen::VectorXd q = H * v_free;
      // Newton's impact law u_N(k+1) = -e u_N(k), written into the problem's free velocity as
      // Siconos's MoreauJeanOSI does for every active contact.
      for (int k = 0; k < c; ++k) q[3 * k] += sites[active[k].site].parameters.normal.restitution * u_start[3 * k];
      Eigen::VectorXd r = Eigen::VectorXd::Zero(3 * c);
      Eigen::VectorXd u;
      const ContactSolve solve =
          solve_contact_problem(W, q, mu, settings.contact_tolerance, settings.contact_max_iterations, r, u);
      ++statistics.contact_problems;
      if (!fclib.folder.empty() && statistics.fclib_problems_written < fclib.max_problems) {
        write_fclib_step(W, q, mu, r, u, solve);
      }
      statistics.solver_iterations += solve.iterations;
      if (solve.fallback) {
        ++statistics.fallback_solves;
        statistics.fallback_iterations += solve.fallback_iterations;
      }
      statistics.largest_solver_error = std::max(statistics.largest_solver_error, solve.error);
      if (!solve.converged) {
        if (statistics.unconverged_steps == 0) statistics.first_unconverged_time = time;
        ++statistics.unconverged_steps;
        if (settings.stop_on_unconverged) {
          throw dynamics::SolverError("moreau_jean at t = " + dynamics::format_number(time) +
                                      " s: the contact problem did not converge (fc3d NSGS " +
                                      std::to_string(solve.iterations) + " sweeps, then fc3d PROX " +
                                      std::to_string(solve.fallback_iterations) + " iterations: error " +
                                      dynamics::format_number(solve.error) + ")");
        }
      }
      v_next = v_free + Y * r;
      // Y r = M^-1 H^T r - M^-1 J^T S^-1 J M^-1 H^T r: the second part is the ideal joints'
      // share of the contacts' impulse.
      if (m > 0) bilateral -= schur.solve(J * (inverse_mass.asDiagonal() * (H.transpose() * r)));
      const Eigen::VectorXd u_end = H * v_next;
      for (int k = 0; k < c; ++k) {
        ContactPercussion p;
        p.joint = active[k].site;
        p.type = active[k].contact.type;
        p.base = active[k].contact.base;
        p.gap = active[k].gap;
        p.normal_W = active[k].frame.col(0);
        p.journal_point_W = active[k].journal_point_W;
        p.percussion_on_journal_W = active[k].frame * r.segment<3>(3 * k);
        const ClearanceSite& site = sites[active[k].site];
        const Vector3 centre_W = kinematics.body(site.journal_body).point_W(site.journal_point_B);
        p.moment_on_journal_W = (p.journal_point_W - centre_W).cross(p.percussion_on_journal_W);
        p.normal_percussion = r[3 * k];
        p.normal_velocity_before = u_start[3 * k];
        p.normal_velocity_after = u_end[3 * k];
        percussions.push_back(p);
      }
    }

    // Positions: q(k+1) = q(k) + h v(theta), v(theta) = (1 - theta) v(k) + theta v(k+1).
    const Eigen::VectorXd v_theta = (1.0 - settings.theta) * v_start + settings.theta * v_next;
    move_positions(h * v_theta);
    Eigen::Map<Eigen::VectorXd>(y.data() + layout.velocity_offset(0), n) = v_next;
    ++statistics.steps;
    time = start_time + static_cast<double>(statistics.steps) * h;
    project_positions();
  }

  /// The step's problem and solution as an FCLIB file (fclib_export.hpp), its info naming the
  /// solver, tolerance and outcome so that a reader can reproduce the solve.
  void write_fclib_step(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, const Eigen::VectorXd& mu,
                        const Eigen::VectorXd& r, const Eigen::VectorXd& u, const ContactSolve& solve) {
    const long number = statistics.steps + 1;
    const std::string title = "clearjoint Moreau-Jean step " + std::to_string(number) + " (t = " +
                              dynamics::format_number(time) + " s to " +
                              dynamics::format_number(time + settings.step) + " s), " +
                              std::to_string(q.size() / 3) + " contacts";
    const std::string description =
        "Local frictional contact problem of a clearance joint's contacts (clearjoint docs/nonsmooth.md); "
        "solution by Siconos Numerics fc3d NSGS, tolerance " + dynamics::format_number(settings.contact_tolerance) +
        ", at most " + std::to_string(settings.contact_max_iterations) + " sweeps, from r = 0: " +
        (solve.fallback ? "missed the tolerance after " + std::to_string(solve.iterations) +
                              " sweeps, then by fc3d PROX from r = 0 with the same tolerance and limit: " +
                              (solve.converged ? "converged" : "NOT converged") + ", error " +
                              dynamics::format_number(solve.error) + " after " +
                              std::to_string(solve.fallback_iterations) + " iterations"
                        : std::string(solve.converged ? "converged" : "NOT converged") + ", error " +
                              dynamics::format_number(solve.error) + " after " + std::to_string(solve.iterations) +
                              " sweeps");
    write_fclib_problem(fclib_problem_path(fclib, number), W, q, mu, r, u, title, description);
    ++statistics.fclib_problems_written;
  }

  /// Newton iterations on Phi(q, t) = 0 with the mass-weighted least-norm correction
  /// dq = -M^-1 J^T (J M^-1 J^T)^-1 Phi, which moves the bodies the least in kinetic-energy
  /// norm; velocities are left as the step made them. J is the step's, Phi_q(q_k), with its
  /// factor (a chord method): Phi_q moves by O(h) over the step, so each iteration still divides
  /// the residual by O(1 / h) and the O(h^2) drift reaches the tolerance in one or two, without
  /// a factorisation per iteration (the largest share of a step's cost otherwise).
  void project_positions() {
    dynamics::MultibodySystem& sys = system();
    if (sys.constraints().equation_count() == 0) return;
    double residual = 0.0;
    for (int iteration = 0; iteration <= kMaxProjectionIterations; ++iteration) {
      kinematics.update(time, y);
      sys.constraints().evaluate(time, kinematics);
      const Eigen::VectorXd& phi = sys.constraints().value();
      residual = phi.cwiseAbs().maxCoeff();
      if (residual <= kProjectionTolerance || iteration == kMaxProjectionIterations) break;
      move_positions(-minv_jt * schur.solve(phi));
    }
    statistics.largest_projection_residual = std::max(statistics.largest_projection_residual, residual);
  }

  double potential_energy() {
    kinematics.update(time, y);
    double energy = 0.0;
    const auto elements = system().force_elements();
    for (size_t e : smooth_elements) energy += elements[e]->potential_energy(kinematics);
    return energy;
  }
};

MoreauJean::MoreauJean(const dynamics::ModelDescription& model) : impl_(std::make_unique<Impl>(model)) {}
MoreauJean::~MoreauJean() = default;
void MoreauJean::step() { impl_->step(); }
double MoreauJean::time() const { return impl_->time; }
double MoreauJean::step_size() const { return impl_->settings.step; }
std::span<const double> MoreauJean::state() const { return impl_->y; }
dynamics::MultibodySystem& MoreauJean::system() { return impl_->system(); }
std::span<const ContactPercussion> MoreauJean::contacts() const { return impl_->percussions; }
std::span<const std::string> MoreauJean::clearance_joint_names() const { return impl_->site_names; }
std::span<const double> MoreauJean::bilateral_percussions() const {
  return {impl_->bilateral.data(), static_cast<size_t>(impl_->bilateral.size())};
}
double MoreauJean::kinetic_energy() const { return impl_->built.system->kinetic_energy(impl_->y); }
double MoreauJean::potential_energy() { return impl_->potential_energy(); }
const MoreauJeanStatistics& MoreauJean::statistics() const { return impl_->statistics; }
void MoreauJean::write_fclib(const FclibExport& fclib) {
  prepare_fclib_folder(fclib, "--write-fclib");
  impl_->fclib = fclib;
}

}  // namespace clearjoint::nonsmooth
