// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/clearance_revolute_joint.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <numbers>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/kernel_pose.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "joint_film.hpp"

namespace clearjoint::dynamics {

namespace {

using geometry::Contact;
using geometry::ContactBase;
using geometry::ContactType;

constexpr std::array<ContactSlot, kContactSlotCount> kSlots{
    ContactSlot::radial_a, ContactSlot::radial_b, ContactSlot::line, ContactSlot::axial_a,
    ContactSlot::axial_b};

int index_of(ContactSlot slot) { return static_cast<int>(slot); }

geometry::BodyMotion motion_of(const BodyKinematics& body) {
  return {body.position_W, body.velocity_W, body.angular_velocity_W};
}

void validate_part(const ClearanceJointPart& part, const std::string& field) {
  require_finite(field + ".point", part.point_B);
  require_nonzero(field + ".axis", part.axis_B);
}

/// One of the kernel's validate()s (the one check of that description), its InvalidInput
/// reported as the dynamics' ModelError with the same field path and message.
template <class Description, class... Names>
void validate_in_kernel(const Description& description, const std::string& path, const Names&... names) {
  try {
    geometry::validate(description, path, names...);
  } catch (const geometry::InvalidInput& e) {
    throw ModelError(e.field_path(), e.detail());
  }
}

/// Angle between two directions in [0, pi], from atan2(|a x b|, a . b): accurate near 0 and pi,
/// where acos of the dot product loses half the digits.
double angle_between(const Vector3& a, const Vector3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

std::string_view to_string(ContactSlot slot) noexcept { return geometry::key_of(slot); }

ContactSlot slot_of(const Contact& contact) noexcept {
  if (contact.type == ContactType::axial) {
    return contact.base == ContactBase::b ? ContactSlot::axial_b : ContactSlot::axial_a;
  }
  switch (contact.base) {
    case ContactBase::a: return ContactSlot::radial_a;
    case ContactBase::b: return ContactSlot::radial_b;
    case ContactBase::mid: return ContactSlot::line;
  }
  return ContactSlot::line;
}

/// Where an evaluation works: its state, and the last detection it made with that detection's
/// poses (P_i, a_i, P_j, a_j, world), reused for the same poses bit for bit.
struct ClearanceRevoluteJoint::Workspace {
  ClearanceJointState state;
  std::array<Vector3, 4> poses{};
  bool holds_poses = false;
};

/// What const evaluations share. The workspace is claimed, not locked: an evaluation that finds
/// it claimed by another thread works in a workspace of its own instead of waiting.
struct ClearanceRevoluteJoint::SharedState {
  Workspace workspace;
  std::atomic<bool> workspace_claimed{false};
  std::atomic<long> detection_calls{0};
  std::atomic<long> impacts{0};
  std::atomic<long> beyond_model_updates{0};
  /// The film solver's turn (lubricated joints only; its warm start is state).
  std::mutex film_turn;
};

/// The joint's workspace for the duration of one evaluation when it is free, else a fresh one on
/// the stack (2 KB of default values, no allocation; no cached detection to reuse).
class ClearanceRevoluteJoint::WorkspaceLease {
 public:
  explicit WorkspaceLease(SharedState& shared)
      : shared_(shared), claimed_(!shared.workspace_claimed.exchange(true, std::memory_order_acquire)) {
    if (!claimed_) own_.emplace();
  }
  ~WorkspaceLease() {
    if (claimed_) shared_.workspace_claimed.store(false, std::memory_order_release);
  }
  WorkspaceLease(const WorkspaceLease&) = delete;
  WorkspaceLease& operator=(const WorkspaceLease&) = delete;

  Workspace& get() { return claimed_ ? shared_.workspace : *own_; }

 private:
  SharedState& shared_;
  bool claimed_;
  std::optional<Workspace> own_;
};

ClearanceRevoluteJoint::ClearanceRevoluteJoint(std::string name, const ClearanceJointPart& bearing,
                                               const ClearanceJointPart& journal,
                                               const ClearanceJointParameters& parameters)
    : name_(std::move(name)),
      bearing_(bearing),
      journal_(journal),
      parameters_(parameters),
      shared_(std::make_unique<SharedState>()) {
  validate_part(bearing_, name_ + ".bearing");
  validate_part(journal_, name_ + ".journal");
  if (bearing_.body == journal_.body) {
    throw ModelError(name_ + ".journal.body", ": the journal and the bearing must be on different bodies");
  }
  if (parameters_.pin_in_hole) {
    // Named as in a model file: "<joint>.hole.radius", "<joint>.pin.stops[1].position".
    validate_in_kernel(*parameters_.pin_in_hole, name_, geometry::kPinInHolePartNames);
    if (parameters_.lubrication) {
      throw ModelError(name_ + ".lubrication",
                       ": not supported with \"geometry\": \"pin_in_hole\" (the oil film is the "
                       "journal-bearing's; remove \"lubrication\" or use the paper's joint)");
    }
  } else {
    // Named as in a model file: "<joint>.journal.radius".
    validate_in_kernel(parameters_.dimensions, name_, geometry::kPartDimensionNames);
  }
  validate(parameters_.normal, name_ + ".normal_force");
  validate(parameters_.friction, name_ + ".friction");
  validate_in_kernel(parameters_.detection, name_ + ".detection");
  // Output frame (u, v, a) of the bearing: u is the body axis least aligned with a (first on
  // ties), made perpendicular to a; v = a x u. For a bearing along z that is (x, y, z).
  bearing_axis_hat_B_ = bearing_.axis_B.normalized();
  Eigen::Index least_aligned = 0;
  bearing_axis_hat_B_.cwiseAbs().minCoeff(&least_aligned);
  const Vector3 e = Vector3::Unit(least_aligned);
  bearing_u_B_ = (e - e.dot(bearing_axis_hat_B_) * bearing_axis_hat_B_).normalized();
  bearing_v_B_ = bearing_axis_hat_B_.cross(bearing_u_B_);
  if (parameters_.lubrication) {
    JointLubrication& lubrication = *parameters_.lubrication;
    // A model's 0 means "as wide as the limit" (joint_lubrication.hpp).
    if (lubrication.transition_width == 0.0) {
      lubrication.transition_width = lubrication.film_thickness_limit;
    }
    validate(lubrication, name_ + ".lubrication",
             parameters_.dimensions.bearing_radius - parameters_.dimensions.journal_radius);
    film_ = std::make_unique<JointFilm>(lubrication, parameters_.dimensions);
  }
}

ClearanceRevoluteJoint::~ClearanceRevoluteJoint() = default;
ClearanceRevoluteJoint::ClearanceRevoluteJoint(ClearanceRevoluteJoint&&) noexcept = default;

int ClearanceRevoluteJoint::extra_state_count() const {
  return kContactSlotCount + (film_ ? 1 : 0);
}

void ClearanceRevoluteJoint::detect(double time, const SystemKinematics& kinematics, Workspace& workspace,
                                    ClearanceJointState& found) const {
  geometry::JointContacts& contacts = found.contacts;
  const BodyKinematics& bi = kinematics.body(bearing_.body);
  const BodyKinematics& bj = kinematics.body(journal_.body);
  const geometry::PartPose bearing_pose = kernel_pose(bi, bearing_.point_B, bearing_.axis_B);
  const geometry::PartPose journal_pose = kernel_pose(bj, journal_.point_B, journal_.axis_B);
  const std::array<Vector3, 4> poses{bearing_pose.p_WP, bearing_pose.axis_W, journal_pose.p_WP,
                                     journal_pose.axis_W};
  const bool into_workspace = &found == &workspace.state;
  // The detection is a function of the poses alone: the same poses, bit for bit, give the same
  // answer. The last stage of a Dormand-Prince step is evaluated at the accepted state (FSAL),
  // where begins_event and update_extra_state detect again: they find the answer in place.
  // Outputs at a report time follow the right-hand side at the same state: they copy.
  if (workspace.holds_poses && std::memcmp(poses.data(), workspace.poses.data(), sizeof poses) == 0) {
    if (!into_workspace) {
      contacts = workspace.state.contacts;
      found.pin_in_hole_scenario = workspace.state.pin_in_hole_scenario;
    }
    return;
  }
  shared_->detection_calls.fetch_add(1, std::memory_order_relaxed);
  if (into_workspace) workspace.holds_poses = false;  // until the detection below succeeds
  try {
    if (parameters_.pin_in_hole) {
      // The hole is the bearing's pose, the pin the journal's; its Contact is the paper's.
      const geometry::PinInHoleContacts pin = geometry::detect_pin_in_hole_contacts(
          *parameters_.pin_in_hole, bearing_pose, journal_pose, parameters_.detection);
      static_assert(geometry::kMaxPinInHoleContacts <= geometry::kMaxContacts);
      contacts.scenario = geometry::ContactScenario::none;
      contacts.aligned = pin.aligned;
      contacts.certificate = pin.certificate;
      contacts.contact_count = pin.contact_count;
      std::copy_n(pin.contacts.begin(), pin.contact_count, contacts.contacts.begin());
      found.pin_in_hole_scenario = pin.scenario;
    } else {
      // In place: a fresh JointContacts is 1.4 KB of default values (detect_contacts.hpp).
      geometry::detect_contacts(parameters_.dimensions, bearing_pose, journal_pose, contacts,
                                parameters_.detection);
    }
  } catch (const geometry::InvalidInput& e) {
    throw SolverError("clearance joint '" + name_ + "' at t = " + format_number(time) +
                      ": the contact detection rejected the poses (" + e.what() + ")");
  }
  if (into_workspace) {
    workspace.poses = poses;
    workspace.holds_poses = true;
  }
}

void ClearanceRevoluteJoint::evaluate_forces(double time, const SystemKinematics& kinematics,
                                             std::span<const double> impact_memory, Workspace& workspace,
                                             ClearanceJointState& state, FilmNeed film) const {
  detect(time, kinematics, workspace, state);
  state.slots = {};
  state.film.reset();
  state.force_on_journal_W.setZero();
  state.moment_on_journal_W.setZero();
  const BodyKinematics& bi = kinematics.body(bearing_.body);
  const BodyKinematics& bj = kinematics.body(journal_.body);
  const geometry::BodyMotion bearing_motion = motion_of(bi);
  const geometry::BodyMotion journal_motion = motion_of(bj);
  const Vector3 p_WPj = bj.point_W(journal_.point_B);
  const NormalForceParameters& normal = parameters_.normal;

  for (int c = 0; c < state.contacts.contact_count; ++c) {
    const Contact& contact = state.contacts.contacts[c];
    const geometry::ContactKinematics velocity =
        geometry::contact_kinematics(contact, bearing_motion, journal_motion);  // eqs. (24)-(26)
    const int slot = index_of(slot_of(contact));
    // delta_dot(-): remembered from the accepted step where the contact began, else this
    // stage's own approach speed (see the file comment).
    const double impact_speed = impact_memory[slot] > 0.0
                                    ? impact_memory[slot]
                                    : std::max(velocity.approach_speed, normal.minimum_impact_speed);
    const double normal_force =
        normal_contact_force(normal, contact.depth, velocity.approach_speed, impact_speed);
    const Vector3 friction = regularised_friction_force(parameters_.friction, normal_force,
                                                        velocity.tangential_velocity_W);
    // The journal is pushed back along -n (n points where it penetrates) and dragged against its
    // tangential velocity relative to the bearing.
    const Vector3 force_on_journal = -normal_force * contact.normal_W - friction;
    state.contact_force_on_journal_W[c] = force_on_journal;
    state.force_on_journal_W += force_on_journal;
    state.moment_on_journal_W += (contact.p_WCj - p_WPj).cross(force_on_journal);

    SlotState& s = state.slots[slot];
    if (!s.active || contact.depth > s.depth) {
      s.depth = contact.depth;
      s.approach_speed = velocity.approach_speed;
      s.impact_speed = impact_speed;
    }
    s.active = true;
    s.normal_force += normal_force;
    s.friction_force += friction.norm();
  }
  if (film_ && film != FilmNeed::none) evaluate_film(time, kinematics, state, film);
}

void ClearanceRevoluteJoint::evaluate_film(double time, const SystemKinematics& kinematics,
                                           ClearanceJointState& state, FilmNeed film) const {
  const BodyKinematics& bi = kinematics.body(bearing_.body);
  const BodyKinematics& bj = kinematics.body(journal_.body);
  const Vector3 p_WPi = bi.point_W(bearing_.point_B);
  const Vector3 p_WPj = bj.point_W(journal_.point_B);
  // The journal seen from the bearing body (relative_motion.hpp).
  lubrication::RelativeMotion motion;
  motion.v_BJ_W = bj.point_velocity_W(journal_.point_B) - bi.point_velocity_W(bearing_.point_B) -
                  bi.angular_velocity_W.cross(p_WPj - p_WPi);
  motion.omega_BJ_W = bj.angular_velocity_W - bi.angular_velocity_W;
  const std::optional<Vector3>& groove_B = parameters_.lubrication->groove_direction_B;
  const std::optional<Vector3> groove_W =
      groove_B ? std::optional<Vector3>(bi.rotation * *groove_B) : std::nullopt;
  try {
    const std::lock_guard turn(shared_->film_turn);
    state.film = film_->evaluate(kernel_pose(bi, bearing_.point_B, bearing_.axis_B),
                                 kernel_pose(bj, journal_.point_B, journal_.axis_B), groove_W, motion,
                                 film == FilmNeed::outputs ? FilmDetail::outputs : FilmDetail::force);
  } catch (const std::exception& e) {  // geometry::InvalidInput, or a singular grid system
    throw SolverError("clearance joint '" + name_ + "' at t = " + format_number(time) +
                      ": the oil film cannot be solved (" + e.what() + ")");
  }
  state.force_on_journal_W += state.film->force_on_journal_W;
  state.moment_on_journal_W += state.film->moment_on_journal_W;
}

ClearanceJointState ClearanceRevoluteJoint::evaluate(double time, const SystemKinematics& kinematics,
                                                     std::span<const double> impact_memory) const {
  ClearanceJointState state;
  WorkspaceLease lease(*shared_);
  evaluate_forces(time, kinematics, impact_memory, lease.get(), state, FilmNeed::outputs);
  const BodyKinematics& bi = kinematics.body(bearing_.body);
  const BodyKinematics& bj = kinematics.body(journal_.body);
  // The centres the detection saw (kernel_pose.hpp).
  const geometry::PartPose journal_pose = kernel_pose(bj, journal_.point_B, journal_.axis_B);
  const Vector3 p_WPi = kernel_pose(bi, bearing_.point_B, bearing_.axis_B).p_WP;

  const Vector3 bearing_axis_W = bi.rotation * bearing_axis_hat_B_;
  const Vector3& journal_axis_W = journal_pose.axis_W;
  state.axis_angle = angle_between(bearing_axis_W, journal_axis_W);
  // Rim labels follow the bearing's bases, as in the detection: when the axes point opposite
  // ways, the journal's base "B" faces the bearing's base A.
  // A pin has no rims: its axis points in the planes of the link's faces stand for them.
  const geometry::BaseCenters rims = geometry::base_centers(
      journal_pose, parameters_.pin_in_hole ? parameters_.pin_in_hole->hole_length
                                            : parameters_.dimensions.journal_length);
  const bool same_direction = bearing_axis_W.dot(journal_axis_W) >= 0.0;
  const Matrix3 to_bearing_frame =
      (Matrix3() << (bi.rotation * bearing_u_B_).transpose(),
       (bi.rotation * bearing_v_B_).transpose(), bearing_axis_W.transpose())
          .finished();
  state.rim_a_in_bearing = to_bearing_frame * ((same_direction ? rims.p_WA : rims.p_WB) - p_WPi);
  state.rim_b_in_bearing = to_bearing_frame * ((same_direction ? rims.p_WB : rims.p_WA) - p_WPi);
  return state;
}

void ClearanceRevoluteJoint::add_forces(const ForceContext& context, GeneralisedForces& forces) const {
  WorkspaceLease lease(*shared_);
  Workspace& workspace = lease.get();
  ClearanceJointState& state = workspace.state;
  evaluate_forces(context.time, context.kinematics, context.extra_state, workspace, state, FilmNeed::force);
  for (int c = 0; c < state.contacts.contact_count; ++c) {
    const Contact& contact = state.contacts.contacts[c];
    const Vector3& force = state.contact_force_on_journal_W[c];
    forces.add_force_at_point(journal_.body, force, contact.p_WCj);
    forces.add_force_at_point(bearing_.body, -force, contact.p_WCi);
  }
  if (state.film) {
    // At the journal's centre, with the moment about it; the bearing gets the opposite at the
    // same point, so that the pair does work F . v_BJ + M . omega_BJ only.
    const BodyKinematics& bj = context.kinematics.body(journal_.body);
    const Vector3 p_WPj = bj.point_W(journal_.point_B);
    forces.add_force_at_point(journal_.body, state.film->force_on_journal_W, p_WPj);
    forces.add_moment(journal_.body, state.film->moment_on_journal_W);
    forces.add_force_at_point(bearing_.body, -state.film->force_on_journal_W, p_WPj);
    forces.add_moment(bearing_.body, -state.film->moment_on_journal_W);
    // A caller that keeps the impact memory only passes no room for W_film.
    if (context.extra_state_rate.size() > static_cast<size_t>(kFilmWorkIndex)) {
      context.extra_state_rate[kFilmWorkIndex] = state.film->power;
    }
  }
  // The memory changes only in update_extra_state(); its rate stays zero (the context zeroes it).
}

double ClearanceRevoluteJoint::potential_energy(const SystemKinematics& kinematics) const {
  WorkspaceLease lease(*shared_);
  Workspace& workspace = lease.get();
  geometry::JointContacts& contacts = workspace.state.contacts;
  detect(kinematics.time(), kinematics, workspace, workspace.state);
  double energy = 0.0;
  for (int c = 0; c < contacts.contact_count; ++c) {
    energy += contact_elastic_energy(parameters_.normal, contacts.contacts[c].depth);
  }
  return energy;
}

void ClearanceRevoluteJoint::initial_extra_state(std::span<double> state) const {
  std::fill(state.begin(), state.end(), 0.0);
}

bool ClearanceRevoluteJoint::update_extra_state(double time, const SystemKinematics& kinematics,
                                                std::span<double> state) const {
  WorkspaceLease lease(*shared_);
  Workspace& workspace = lease.get();
  ClearanceJointState& now = workspace.state;
  // The memory follows the contacts alone: the film is not solved here.
  evaluate_forces(time, kinematics, state, workspace, now, FilmNeed::none);
  if (beyond_model(now)) {
    shared_->beyond_model_updates.fetch_add(1, std::memory_order_relaxed);
  }
  bool changed = false;
  for (int slot = 0; slot < kContactSlotCount; ++slot) {
    const SlotState& s = now.slots[slot];
    if (s.active && state[slot] == 0.0) {
      state[slot] = s.impact_speed;  // max(delta_dot, floor) where the contact was first seen
      shared_->impacts.fetch_add(1, std::memory_order_relaxed);
      recorded_impacts_.push_back({time, kSlots[slot], s.impact_speed});
      changed = true;
    } else if (!s.active && state[slot] != 0.0) {
      state[slot] = 0.0;
      changed = true;
    }
  }
  return changed;
}

bool ClearanceRevoluteJoint::begins_event(const SystemKinematics& kinematics,
                                          std::span<const double> state) const {
  WorkspaceLease lease(*shared_);
  Workspace& workspace = lease.get();
  geometry::JointContacts& contacts = workspace.state.contacts;
  detect(kinematics.time(), kinematics, workspace, workspace.state);
  for (int c = 0; c < contacts.contact_count; ++c) {
    if (state[index_of(slot_of(contacts.contacts[c]))] == 0.0) return true;
  }
  return false;
}

std::vector<std::string> ClearanceRevoluteJoint::output_columns() const {
  std::vector<std::string> columns{"scenario", "aligned", "certainty", "contact_count",
                                   "axis_angle", "rim_a_u", "rim_a_v", "rim_a_axial", "rim_b_u",
                                   "rim_b_v", "rim_b_axial", "fx", "fy", "fz", "mx", "my", "mz"};
  for (ContactSlot slot : kSlots) {
    for (const char* quantity :
         {"depth", "approach_speed", "impact_speed", "normal_force", "friction_force"}) {
      columns.push_back(std::string(to_string(slot)) + "." + quantity);
    }
  }
  if (film_) {
    for (const char* quantity : {"min_thickness", "max_pressure", "eccentricity_ratio",
                                 "attitude_angle", "regime", "weight", "work"}) {
      columns.push_back(std::string("film.") + quantity);
    }
  }
  return columns;
}

void ClearanceRevoluteJoint::record_outputs(double time, const SystemKinematics& kinematics,
                                            std::span<const double> state,
                                            std::span<double> values) const {
  const ClearanceJointState s = evaluate(time, kinematics, state);
  size_t k = 0;
  // The scenario's number in the table of the joint's kind (ContactScenario or PinInHoleScenario).
  values[k++] = s.pin_in_hole_scenario ? static_cast<double>(*s.pin_in_hole_scenario)
                                       : static_cast<double>(s.contacts.scenario);
  values[k++] = s.contacts.aligned ? 1.0 : 0.0;
  values[k++] = static_cast<double>(s.contacts.certificate.level);
  values[k++] = s.contacts.contact_count;
  values[k++] = s.axis_angle;
  for (const Vector3* v : {&s.rim_a_in_bearing, &s.rim_b_in_bearing, &s.force_on_journal_W,
                           &s.moment_on_journal_W}) {
    for (int i = 0; i < 3; ++i) values[k++] = (*v)[i];
  }
  for (const SlotState& slot : s.slots) {
    // No contact: no depth or speeds (NaN), no force (0).
    const double missing = std::numeric_limits<double>::quiet_NaN();
    values[k++] = slot.active ? slot.depth : missing;
    values[k++] = slot.active ? slot.approach_speed : missing;
    values[k++] = slot.active ? slot.impact_speed : missing;
    values[k++] = slot.normal_force;
    values[k++] = slot.friction_force;
  }
  if (s.film) {
    values[k++] = s.film->min_thickness;
    values[k++] = s.film->max_pressure;
    values[k++] = s.film->eccentricity_ratio;
    values[k++] = s.film->attitude_angle;
    values[k++] = static_cast<double>(s.film->regime);
    values[k++] = s.film->weight;
    values[k++] = state.size() > static_cast<size_t>(kFilmWorkIndex)
                      ? state[kFilmWorkIndex]
                      : std::numeric_limits<double>::quiet_NaN();
  }
}

bool ClearanceRevoluteJoint::beyond_model(const ClearanceJointState& state) const {
  return parameters_.pin_in_hole ? state.pin_in_hole_scenario == geometry::PinInHoleScenario::beyond_model
                                 : state.contacts.scenario == geometry::ContactScenario::beyond_model;
}

double ClearanceRevoluteJoint::radial_clearance() const {
  return parameters_.pin_in_hole ? parameters_.pin_in_hole->radial_clearance()
                                 : parameters_.dimensions.radial_clearance();
}

double ClearanceRevoluteJoint::axial_clearance() const {
  return parameters_.pin_in_hole ? parameters_.pin_in_hole->axial_clearance()
                                 : parameters_.dimensions.axial_clearance();
}

ClearanceJointStatistics ClearanceRevoluteJoint::statistics() const {
  return {shared_->detection_calls.load(std::memory_order_relaxed),
          shared_->impacts.load(std::memory_order_relaxed),
          shared_->beyond_model_updates.load(std::memory_order_relaxed)};
}

std::string ClearanceRevoluteJoint::statistics_text() const {
  const ClearanceJointStatistics counts = statistics();
  return "clearance joint '" + name_ + "': " + std::to_string(counts.detection_calls) +
         " contact detections, " + std::to_string(counts.impacts) +
         " impacts recorded, " + std::to_string(counts.beyond_model_updates) +
         " accepted steps beyond the paper's model" + film_statistics_text();
}

std::string ClearanceRevoluteJoint::film_statistics_text() const {
  if (!film_) return {};
  const std::lock_guard turn(shared_->film_turn);
  const JointFilmStatistics s = film_->statistics();
  return "; " + std::string(lubrication::to_string(parameters_.lubrication->method)) + " film: " +
         std::to_string(s.solves) + " solutions, " + std::to_string(s.linear_solves) +
         " grid linear solves, " + std::to_string(s.not_converged) + " not converged";
}

}  // namespace clearjoint::dynamics
