// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The spatial revolute joint with radial and axial clearance as a force element (paper
/// Sections 3-4): a bearing (body i) and a journal (body j), each a cylinder fixed in its body.
/// On every evaluation it runs the certified contact detection (geometry::detect_contacts,
/// eqs. 3-23), the contact kinematics (eqs. 24-26), a normal force law (eqs. 27-29 or an
/// alternative) and regularised Coulomb friction (eq. 32), and applies the forces at the contact
/// points: -F on the journal at C_j, +F on the bearing at C_i (eq. 35's g, "joints with clearances
/// are introduced as external forces", Sec. 5).
///
/// Impact-velocity memory (the delta_dot(-) of eq. 28). It is part of the ODE state, one variable
/// per contact slot (ContactSlot), with time derivative zero, so trial stages and rejected steps
/// of the adaptive integrator read it but can never change it. It changes only between accepted
/// steps, through update_extra_state(): a slot whose contact is present in the accepted state and
/// has no memory (0) records max(delta_dot, minimum_impact_speed); a slot whose contact is absent
/// is cleared to 0. When an accepted step ends with such a new contact (begins_event), the
/// integrator first locates the instant of first touch inside the step on its dense output and
/// records delta_dot(-) there (IntegratorSettings::onset); then it restarts its stepper from the
/// changed state (a restart costs one right-hand-side evaluation and happens twice per impact).
/// Until the memory is set, the trial stages use max(delta_dot, minimum_impact_speed) at the
/// stage itself as delta_dot(-): a pure function of the stage's state. At those stages the
/// penetration has only just begun (it is below one step's travel), so the damping term, which
/// scales with delta^n, is small.
///
/// Contact slots: radial contact at rim A, at rim B, the aligned line contact, axial (point or
/// face) contact at base A, at base B. Beyond the model a rim may cross the wall twice (two
/// radial contacts at one base): both share that base's slot (forces add, the deeper one's
/// approach speed is recorded). The paper's model has a discontinuity where the axes become
/// exactly parallel: one line contact (aligned) becomes two rim contacts of about the same depth
/// (misaligned), i.e. about twice the force. It is kept as the paper states it;
/// DetectionOptions::parallel_angle_tolerance moves where it happens.
///
/// The pin-in-hole joint (ClearanceJointParameters::pin_in_hole, issue 48): the bearing part is
/// the hole (its point midway between the link's faces), the journal part the pin (its point P
/// the one at the hole's centre when centred). geometry::detect_pin_in_hole_contacts replaces
/// detect_contacts; everything after the detection (the slots, the impact memory, the force laws,
/// friction and where the forces act) is the same code. Its contacts fill the same slots: an edge
/// of the hole at link face A or B takes radial_a or radial_b (two edge contacts of one face share
/// it), the line contact takes line, a stop or face contact at face A or B takes axial_a or
/// axial_b. No oil film (refused, naming "<name>.lubrication").
///
/// Lubrication (issue 36, joint_lubrication.hpp). A joint with parameters.lubrication also carries
/// the oil film's force at the journal's centre and its moment, faded out as the film thins to
/// the film_thickness_limit, below which the dry contact above acts alone. Its detection and
/// impact memory are those of the dry joint. It owns one more extra variable after the memory:
/// the film's work on the system, W_film(t) = integral of F . v_BJ + M . omega_BJ, so that the
/// energy balance E(t) - E(0) = W_film(t) (damping-free contact) can be checked on a run. The
/// force table gains the film's columns (output_columns); a dry joint's table is unchanged.
///
/// Threads. One joint may be evaluated from several threads at once (add_forces,
/// potential_energy, begins_event, evaluate, record_outputs, statistics): each evaluation works
/// in the joint's own work space when no other holds it, the common single-threaded case, and
/// otherwise in one of its own on the stack; either way it allocates nothing and gives the same
/// answer, bit for bit. The work space also keeps the last detection and its poses (the answer is
/// a function of the poses alone), so a second evaluation at the same poses, in the same work
/// space, reuses it. A lubricated joint's film solver keeps a warm start between solves, which
/// changes a solve's cost and not its answer: its solves take turns. update_extra_state, the
/// discrete update between accepted steps, appends to recorded_impacts() and is for one thread
/// at a time, as the integrator calls it.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clearjoint/dynamics/clearance_joint_parameters.hpp"
#include "clearjoint/dynamics/force_element.hpp"
#include "clearjoint/dynamics/force_events.hpp"
#include "clearjoint/dynamics/force_recorder.hpp"
#include "clearjoint/dynamics/joint_lubrication.hpp"
#include "clearjoint/dynamics/normal_contact_force.hpp"
#include "clearjoint/dynamics/regularised_friction.hpp"
#include "clearjoint/geometry/joint/contact_kinematics.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"

namespace clearjoint::dynamics {

/// One cylinder of the joint, fixed in a body: the centre P of its axis segment and its axis
/// direction a (need not be unit; only its direction is used), both in the body frame.
struct ClearanceJointPart {
  BodyIndex body = kGround;
  Vector3 point_B = Vector3::Zero();
  Vector3 axis_B = Vector3::UnitZ();
};

/// Where a contact's impact velocity is remembered, and its columns in the outputs.
enum class ContactSlot { radial_a, radial_b, line, axial_a, axial_b };

}  // namespace clearjoint::dynamics

/// The slots' keys prefix their output columns ("radial_a.depth"); the labels name them in plots.
template <>
struct clearjoint::geometry::EnumTable<clearjoint::dynamics::ContactSlot> {
  using S = clearjoint::dynamics::ContactSlot;
  static constexpr std::string_view type_name = "ContactSlot";
  static constexpr auto entries = std::to_array({
      named_entry(S::radial_a, "radial_a", "radial A"),
      named_entry(S::radial_b, "radial_b", "radial B"),
      named_entry(S::line, "line", "line"),
      named_entry(S::axial_a, "axial_a", "axial A"),
      named_entry(S::axial_b, "axial_b", "axial B"),
  });
};
static_assert(clearjoint::geometry::entries_in_code_order<clearjoint::dynamics::ContactSlot>());

namespace clearjoint::dynamics {

inline constexpr int kContactSlotCount = geometry::enum_count<ContactSlot>();
/// The key of the slot's entry in its table: "radial_a", "radial_b", "line", "axial_a", "axial_b".
std::string_view to_string(ContactSlot slot) noexcept;
/// The slot of a detected contact (radial at base mid is the line contact).
ContactSlot slot_of(const geometry::Contact& contact) noexcept;

/// One slot at one instant.
struct SlotState {
  bool active = false;
  double depth = 0.0;           ///< delta [m], eq. (23) (deepest contact of the slot)
  double approach_speed = 0.0;  ///< delta_dot [m/s], eq. (24)
  double impact_speed = 0.0;    ///< delta_dot(-) used [m/s]: remembered, else provisional
  double normal_force = 0.0;    ///< F_N [N], summed over the slot's contacts
  double friction_force = 0.0;  ///< |f_F| [N], summed over the slot's contacts
};

/// Everything the joint computes at one instant.
struct ClearanceJointState {
  /// The contacts found. For a pin-in-hole joint: its contacts (at most
  /// geometry::kMaxPinInHoleContacts, as detect_pin_in_hole_contacts orders them), its
  /// aligned flag and certificate; `scenario` is then none, pin_in_hole_scenario tells it.
  geometry::JointContacts contacts;
  /// A pin-in-hole joint's scenario; empty for the paper's joint.
  std::optional<geometry::PinInHoleScenario> pin_in_hole_scenario;
  /// Force on the journal of each of contacts.contacts (the bearing gets the opposite).
  std::array<Vector3, geometry::kMaxContacts> contact_force_on_journal_W{};
  std::array<SlotState, kContactSlotCount> slots{};
  /// Sum of the contact forces on the journal, and of the film's for a lubricated joint.
  Vector3 force_on_journal_W = Vector3::Zero();
  Vector3 moment_on_journal_W = Vector3::Zero();  ///< their moment about the journal's P_j
  /// The film, for a lubricated joint (its force and moment are in the totals above).
  std::optional<JointFilmState> film;
  /// Angle between the journal and bearing axes [rad], in [0, pi] (Fig. 11(b)).
  double axis_angle = 0.0;
  /// Centres of the journal rims facing bearing bases A and B, relative to the bearing's P_i, in
  /// the bearing frame (u, v, a): u, v radial (bearing_frame_u/v_B below), a along the axis.
  Vector3 rim_a_in_bearing = Vector3::Zero();
  Vector3 rim_b_in_bearing = Vector3::Zero();
};

/// Counters for benchmarks and run summaries.
struct ClearanceJointStatistics {
  /// detect_contacts calls (forces, updates, outputs, energy); a repeated query at the same
  /// poses (the accepted state after its last stage) reuses the answer and is not counted.
  long detection_calls = 0;
  long impacts = 0;               ///< impact velocities recorded (contact starts, accepted steps)
  long beyond_model_updates = 0;  ///< accepted steps whose state was beyond the paper's model
};

/// One impact velocity recorded in the memory (update_extra_state).
struct RecordedImpact {
  double time = 0.0;   ///< the accepted (or located) instant where it was recorded [s]
  ContactSlot slot = ContactSlot::line;
  double impact_speed = 0.0;  ///< delta_dot(-) recorded [m/s]
};

class JointFilm;

/// Index, in a lubricated joint's extra state, of the film's work W_film [J] (after the memory).
inline constexpr int kFilmWorkIndex = kContactSlotCount;

/// A force element with events (the impact memory) and a recorder (its table and counters).
class ClearanceRevoluteJoint final : public ForceElement, public ForceEvents, public ForceRecorder {
 public:
  /// Throws ModelError naming "<name>.<field>" for bad dimensions (non-finite, non-positive,
  /// journal not smaller than bearing), zero axes, bad force or friction parameters, or a
  /// bearing and journal on the same body.
  ClearanceRevoluteJoint(std::string name, const ClearanceJointPart& bearing,
                         const ClearanceJointPart& journal, const ClearanceJointParameters& parameters);
  ~ClearanceRevoluteJoint() override;
  ClearanceRevoluteJoint(ClearanceRevoluteJoint&&) noexcept;

  std::string_view name() const override { return name_; }
  /// Detection, forces, and application at the contact points. Throws SolverError (with the
  /// time) if the detection rejects the poses (non-finite state).
  void add_forces(const ForceContext& context, GeneralisedForces& forces) const override;
  /// Elastic energy of every contact, K delta^(n+1)/(n+1): conserved with the total when the
  /// law is hertz (or ce = 1) and there is no friction.
  double potential_energy(const SystemKinematics& kinematics) const override;
  /// The impact memory (kContactSlotCount), and W_film for a lubricated joint.
  int extra_state_count() const override;
  void initial_extra_state(std::span<double> state) const override;
  bool update_extra_state(double time, const SystemKinematics& kinematics,
                          std::span<double> state) const override;
  /// A contact present in a slot without memory: an impact begins (one detection).
  bool begins_event(const SystemKinematics& kinematics, std::span<const double> state) const override;
  std::vector<std::string> output_columns() const override;
  void record_outputs(double time, const SystemKinematics& kinematics,
                      std::span<const double> state, std::span<double> values) const override;
  std::string statistics_text() const override;

  /// Evaluate the joint at one instant with the given impact memory (kContactSlotCount values,
  /// 0 = none; further values are ignored). Used by add_forces and by the outputs; public for
  /// tests.
  ClearanceJointState evaluate(double time, const SystemKinematics& kinematics,
                               std::span<const double> impact_memory) const;

  const ClearanceJointParameters& parameters() const { return parameters_; }
  /// A pin-in-hole joint (parameters().pin_in_hole), not the paper's journal-bearing.
  bool is_pin_in_hole() const { return parameters_.pin_in_hole.has_value(); }
  /// Whether `state` (from evaluate) is beyond the model, by the scenario table of the joint's kind.
  bool beyond_model(const ClearanceJointState& state) const;
  /// The joint's radial and axial clearances [m] (eqs. 1-2; the pin-in-hole's: Rh - Rp and the
  /// play between its stops, infinite with fewer than two).
  double radial_clearance() const;
  double axial_clearance() const;
  /// The counters so far (read while other threads evaluate, each is a count that was reached).
  ClearanceJointStatistics statistics() const;
  /// Every impact velocity recorded so far, in order (grows by one per impact, never per
  /// right-hand-side evaluation).
  const std::vector<RecordedImpact>& recorded_impacts() const { return recorded_impacts_; }
  /// The bearing frame used for rim_a/b_in_bearing: u is the body axis least aligned with the
  /// bearing axis a (first on ties) made perpendicular to it, v = a x u; for a along z: x, y.
  const Vector3& bearing_frame_u_B() const { return bearing_u_B_; }
  const Vector3& bearing_frame_v_B() const { return bearing_v_B_; }

 private:
  struct Workspace;
  class WorkspaceLease;
  struct SharedState;

  /// The certified detection at the bodies' poses (the paper's, or the pin-in-hole's), written
  /// into found.contacts (in place) and found.pin_in_hole_scenario, reusing the answer
  /// `workspace` holds for the same poses; `found` is the workspace's own state or a caller's.
  void detect(double time, const SystemKinematics& kinematics, Workspace& workspace,
              ClearanceJointState& found) const;
  /// What an evaluation needs of a lubricated joint's film: nothing (the impact memory's update
  /// reads the contacts only), its force (a right-hand side), or what the force table records.
  enum class FilmNeed { none, force, outputs };
  /// Detection, contact kinematics and forces into `state` (contacts, per-contact forces, slots,
  /// totals, and the film as `film` asks); not the geometry only the outputs need (axis angle,
  /// rim centres).
  void evaluate_forces(double time, const SystemKinematics& kinematics,
                       std::span<const double> impact_memory, Workspace& workspace,
                       ClearanceJointState& state, FilmNeed film) const;
  /// The film of a lubricated joint into state.film, its force and moment into the totals.
  void evaluate_film(double time, const SystemKinematics& kinematics, ClearanceJointState& state,
                     FilmNeed film) const;
  std::string film_statistics_text() const;

  std::string name_;
  ClearanceJointPart bearing_;
  ClearanceJointPart journal_;
  ClearanceJointParameters parameters_;
  Vector3 bearing_axis_hat_B_;
  Vector3 bearing_u_B_;
  Vector3 bearing_v_B_;
  /// Only update_extra_state appends (one thread at a time, see the file comment).
  mutable std::vector<RecordedImpact> recorded_impacts_;
  /// The work space with its detection cache, its claim, the counters and the film's turn: what
  /// const evaluations share, behind one pointer so that the joint stays movable.
  std::unique_ptr<SharedState> shared_;
  /// The film of a lubricated joint (null when dry). Mutable for the grid solver's warm start,
  /// which changes a solve's cost, not its answer (joint_film.hpp); solves take turns.
  mutable std::unique_ptr<JointFilm> film_;
};

}  // namespace clearjoint::dynamics
