// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Contact detection between a journal and its bearing: paper Section 3, eqs. (5)-(23).
///
/// Misaligned axes: four candidate point contacts, each one certified kernel query:
///   radial at base X (X = A, B): journal rim X against the bearing's lateral wall, eqs. (16)-(21),
///     intersect_circle_cylinder;
///   axial at base X: journal rim X against the bearing's base plane X, eqs. (11)-(15),
///     intersect_circle_plane (base plane A has outward normal +a_i, base plane B -a_i).
/// Parallel axes (eq. (5), decided exactly): a line contact along the wall at the journal's
/// mid-length, eqs. (6)-(8), and face contacts at a base, eqs. (9)-(10).
///
/// Labels: A and B are the bearing's bases (eqs. 3-4). The journal rim facing bearing base A is
/// rim A, whichever way the journal's axis points (sign of a_i . a_j).
///
/// Model limits (documented, not detected): the journal's lateral surface against a bearing's
/// base edge, and a rim against the opposite base, are not candidate contacts (the paper's
/// small-tilt model).
///
/// What the certificates are about: the joint exactly as its input numbers define it
/// (joint_geometry.hpp: base centres P +- (L/2) a_hat, a_hat = unit_axis(pose)). Detection works
/// in a frame centred on the bearing and rounds the centres there to double, but each rounded
/// centre carries a rigorous bound on its distance to the exact one (geometry/src/rounded_point.hpp):
/// the kernel's proofs hold for every centre within that bound, crossing-point errors include it,
/// and where the floating-point proofs fail (a rim within the rounding of touching) the exact tier
/// decides on the exact centres, rebuilt in rationals. bench/detection (docs/reports/benchmarks.md)
/// checks this against an MPFR reference of the joint as given.

#include <array>
#include <string_view>
#include <tuple>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/model/detection_options.hpp"
#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"

namespace clearjoint::geometry {

enum class ContactType {
  radial,  ///< against the lateral wall (a point, eqs. 16-21; or a line, eqs. 6-8)
  axial,   ///< against a base (a point, eqs. 11-15; or a face, eqs. 9-10)
};

enum class ContactBase {
  a,    ///< at bearing base A (eq. 3) and the journal rim facing it
  b,    ///< at bearing base B (eq. 4) and the journal rim facing it
  mid,  ///< at the journal's mid-length (aligned line contact, eqs. 6-8)
};

template <>
struct EnumTable<ContactType> {
  static constexpr std::string_view type_name = "ContactType";
  static constexpr auto entries = std::to_array({
      named_entry(ContactType::radial, "radial", "against the lateral wall (eqs. 16-21; line: eqs. 6-8)"),
      named_entry(ContactType::axial, "axial", "against a base (eqs. 11-15; face: eqs. 9-10)"),
  });
};
static_assert(entries_in_code_order<ContactType>());

/// The bases' keys are lower case, as the enumerators: "a", "b", "mid".
template <>
struct EnumTable<ContactBase> {
  static constexpr std::string_view type_name = "ContactBase";
  static constexpr auto entries = std::to_array({
      named_entry(ContactBase::a, "a", "at bearing base A (eq. 3) and the journal rim facing it"),
      named_entry(ContactBase::b, "b", "at bearing base B (eq. 4) and the journal rim facing it"),
      named_entry(ContactBase::mid, "mid", "at the journal's mid-length (line contact, eqs. 6-8)"),
  });
};
static_assert(entries_in_code_order<ContactBase>());

/// The keys: "radial", "axial"; "a", "b", "mid".
constexpr std::string_view to_string(ContactType type) noexcept { return key_of(type); }
constexpr std::string_view to_string(ContactBase base) noexcept { return key_of(base); }

/// One contact.
///
/// Convention (eqs. 22-23): `normal_W = (p_WCj - p_WCi) / |p_WCj - p_WCi|` points out of the
/// bearing, in the direction the journal penetrates; `depth = |p_WCj - p_WCi| >= 0`. Hence
///   p_WCj - p_WCi = depth * normal_W   (up to rounding),
/// and the contact force on the journal acts along -normal_W. `normal_W` is the wall's outward
/// normal at p_WCi (radial, eq. 20, eq. 6) or the base's outward normal (+-a_i/|a_i|, axial); it
/// is defined even at depth 0.
///
/// Invariants: p_WCi lies on the bearing surface (wall: distance Ri from its axis; base: in the
/// base plane), up to rounding; for point contacts p_WCj is a journal rim point (distance Rj
/// from the rim centre, in the rim plane) at the middle of its penetration arc (eqs. 13, 18).
/// A rim entirely beyond a surface (beyond the model) has no arc middle: p_WCj is then the rim
/// point farthest along the base normal (axial; the deepest point, with bounds as tight as an arc
/// middle's) or along the radial direction of the rim centre (radial; an approximation of the
/// deepest point, whose point bound is that of any rim point: the rim's diameter).
struct Contact {
  ContactType type = ContactType::radial;
  ContactBase base = ContactBase::a;
  Vector3 p_WCj = Vector3::Zero();  ///< contact point on the journal (eqs. 8, 10, 14, 19)
  Vector3 p_WCi = Vector3::Zero();  ///< contact point on the bearing (eqs. 7, 9, 15, 21)
  Vector3 normal_W = Vector3::UnitZ();
  double depth = 0.0;               ///< metres (the unit of the input)
  /// Error bounds in metres: the contact the joint as given defines (its exact centres and
  /// crossings, the paper's formulas evaluated in real arithmetic at the exact arc middle) has
  /// its journal point within p_WCj_error of p_WCj (Euclidean), its bearing point within
  /// p_WCi_error of p_WCi and its depth within depth_error of depth. Certified enclosures, always
  /// finite, when `certificate` is exact or certified; kNoErrorBound when it is uncertain. A
  /// contact whose points or depth cannot be bounded in double (its direction lost in the
  /// rounding of a joint far from the origin, or an overflow) is uncertain for that reason
  /// (CertificateReason::contact_not_representable_in_world), though its existence was decided.
  double p_WCj_error = kNoErrorBound;
  double p_WCi_error = kNoErrorBound;
  double depth_error = kNoErrorBound;
  /// Rim crossings bounding the penetration arc (point contacts; 0 for line and face contacts,
  /// 1 when the rim touches from outside everywhere but one point).
  std::array<RimCrossing, 2> crossings{};
  int crossing_count = 0;
  /// Trust in this contact's existence and crossings (the kernel query's, or the parallelism
  /// decision's). Points, normal and depth are double-precision evaluations of the paper's
  /// formulas at the certified arc middle, with the error bounds above.
  Certificate certificate{};
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
/// The keys of the command line and of Python: "point_journal" is p_WCj, "normal" normal_W.
template <>
struct ResultFields<Contact> {
  using C = Contact;
  static constexpr std::string_view type_name = "Contact";
  static constexpr std::tuple fields{
      fields::plain("type", &C::type),
      fields::plain("base", &C::base),
      fields::plain("depth", &C::depth, "penetration depth >= 0"),
      fields::bound("depth_error", &C::depth_error, "bound on the depth's error; certified unless uncertain (then inf)"),
      fields::plain("point_journal", &C::p_WCj, "C_j on the journal (eqs. 8, 10, 14, 19)"),
      fields::plain("point_bearing", &C::p_WCi, "C_i on the bearing (eqs. 7, 9, 15, 21)"),
      fields::bound("point_journal_error", &C::p_WCj_error, "bound on point_journal's error (Euclidean)"),
      fields::bound("point_bearing_error", &C::p_WCi_error, "bound on point_bearing's error (Euclidean)"),
      fields::plain("normal", &C::normal_W, "unit normal, out of the bearing"),
      fields::list("crossings", &C::crossings, &C::crossing_count,
                   "the rim crossings bounding the penetration arc (none for line and face contacts)"),
      fields::plain("certificate", &C::certificate)};
};
static_assert(detail::lists_every_member<Contact>(), "a member of Contact is missing from its field list");

/// Up to two radial contacts per rim (beyond the model a rim may have two penetration arcs)
/// plus two axial ones.
inline constexpr int kMaxContacts = 6;

struct JointContacts {
  ContactScenario scenario = ContactScenario::none;
  /// Axes parallel: exactly (eq. 5) or within DetectionOptions::parallel_angle_tolerance.
  bool aligned = false;
  /// Every contact found, radial before axial, base A before B. Also filled when
  /// scenario == beyond_model.
  std::array<Contact, kMaxContacts> contacts{};
  int contact_count = 0;
  /// The weakest certificate over every decision taken, including the "no contact" answers.
  Certificate certificate{};
};

/// Its field list (model/field_lists.hpp): a member added above needs its line here.
template <>
struct ResultFields<JointContacts> {
  using J = JointContacts;
  static constexpr std::string_view type_name = "JointContacts";
  static constexpr std::tuple fields{
      fields::plain("scenario", &J::scenario),
      fields::plain("aligned", &J::aligned, "axes parallel (exactly, eq. 5, or within parallel_angle_tolerance)"),
      fields::plain("certificate", &J::certificate, "the weakest over every decision taken, including 'no contact'"),
      fields::list("contacts", &J::contacts, &J::contact_count, "radial before axial, base A before B")};
};
static_assert(detail::lists_every_member<JointContacts>(), "a member of JointContacts is missing from its field list");

/// Detect every contact between a journal (pose `journal`) and its bearing (pose `bearing`).
/// Validates its inputs (InvalidInput names the field). Fixed-size results; no heap allocation
/// on the double-precision path. The exact fallbacks may allocate (GMP integers, CGAL rationals):
/// the rim-against-wall query's near a tangency, the rim-against-base query's only for inputs
/// hundreds of binades apart, and eq. (5)'s when an axis component lies outside [2^-450, 2^450].
JointContacts detect_contacts(const JointDimensions& dimensions, const PartPose& bearing,
                              const PartPose& journal, const DetectionOptions& options = {});

/// The same answer written into `out`, for loops that detect again and again (a simulation
/// step): scenario, aligned, contact_count, certificate and contacts[0, contact_count) are set
/// exactly as the call above returns them; contacts[contact_count, kMaxContacts) keep whatever
/// they held: a fresh JointContacts is about 1.6 KB of default values, whose writing is a
/// sizeable part of a free-flight detection. On bad input it throws before touching `out`.
void detect_contacts(const JointDimensions& dimensions, const PartPose& bearing,
                     const PartPose& journal, JointContacts& out, const DetectionOptions& options = {});

}  // namespace clearjoint::geometry
