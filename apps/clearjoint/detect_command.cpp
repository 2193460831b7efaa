// SPDX-License-Identifier: BSD-3-Clause
// clearjoint detect [FILE]: joint contact detection (paper Section 3, eqs. 3-26) as JSON Lines.
//
// One joint configuration per input line, one answer per line, in the same order: the scenario
// of the paper's Fig. 2 (or of the pin-in-hole joint's table, for a line with "joint":
// "pin_in_hole"), the contacts with their points, normal and depth, and, when both bodies'
// motions are given, the contact velocities (eqs. 24-26). The format (every field, the error
// lines, the exit status) is specified in docs/command-line.md; keep the two in step.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/joint/contact_kinematics.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/model/pin_in_hole_dimensions.hpp"
#include "clearjoint/json_input/json_reader.hpp"
#include "clearjoint/json_input/read_detection_options.hpp"
#include "commands.hpp"
#include "json_lines.hpp"
#include "result_json.hpp"

namespace clearjoint::app {
namespace {

namespace geo = clearjoint::geometry;

constexpr const char* kUsage =
    "usage: clearjoint detect [FILE]\n"
    "\n"
    "Reads JSON Lines from FILE (no FILE or \"-\": standard input), one joint per line:\n"
    "  {\"id\": ...,\n"
    "   \"bearing\": {\"radius\": Ri, \"length\": Li, \"center\": [x,y,z], \"axis\": [x,y,z]},\n"
    "   \"journal\": {\"radius\": Rj, \"length\": Lj, \"center\": [x,y,z], \"axis\": [x,y,z]}}\n"
    "optionally with \"bearing_motion\" and \"journal_motion\" (both or neither):\n"
    "  {\"mass_center\": [x,y,z], \"velocity\": [x,y,z], \"angular_velocity\": [x,y,z]}\n"
    "and \"options\": {\"certify\": bool, \"exact_fallback\": bool,\n"
    "                \"parallel_angle_tolerance\": radians}.\n"
    "\"joint\": \"journal_bearing\" (the default: the paper's joint, as above) or \"pin_in_hole\":\n"
    "  {\"id\": ..., \"joint\": \"pin_in_hole\",\n"
    "   \"hole\": {\"radius\": Rh, \"length\": L, \"center\": [x,y,z], \"axis\": [x,y,z]},\n"
    "   \"pin\": {\"radius\": Rp, \"center\": [x,y,z], \"axis\": [x,y,z],\n"
    "           \"stops\": [{\"position\": s, \"outer_radius\": Rs}, ...]}}  (0, 1 or 2 stops)\n"
    "optionally with \"hole_motion\" and \"pin_motion\" (both or neither) and \"options\";\n"
    "its answer has \"joint\": \"pin_in_hole\" after the id, a pin-in-hole \"scenario\"\n"
    "(\"none\", \"one_edge\", ..., \"beyond_model\") and the same contacts (\"point_journal\"\n"
    "on the pin, \"point_bearing\" on the link).\n"
    "Writes one JSON line per joint line, in order (empty lines are skipped):\n"
    // BEGIN GENERATED answer keys (the schema's answer and contact keys: scripts/projections)
    "  {\"v\": 1, \"id\", \"scenario\": \"none\"|\"a\"..\"l\"|\"beyond_model\", \"aligned\",\n"
    "   \"certificate\", \"certificate_reason\", \"contacts\": [{\"type\", \"base\",\n"
    "   \"depth\", \"depth_error\", \"point_journal\", \"point_bearing\",\n"
    "   \"point_journal_error\", \"point_bearing_error\", \"normal\", \"crossings\",\n"
    "   \"crossing_errors\", \"certificate\", \"certificate_reason\",\n"
    "   \"approach_velocity\", \"tangential_velocity\"}]}\n"
    // END GENERATED answer keys
    "(velocities only with motions), or {\"v\": 1, \"id\": ..., \"error\": \"...\"}; \"v\" is the\n"
    "version of these formats. Any consistent units (SI: metres, m/s, rad/s).\n"
    "See docs/command-line.md and docs/contact-detection.md.\n"
    "\n"
    "Formats (JSON Schema 2020-12, in docs/schema/ and installed in share/clearjoint/schema/):\n"
    "  input  detect-query.schema.json\n"
    "  output detect-answer.schema.json (answers and error lines)\n"
    "\n"
    "Exit status: 0 all lines answered, 1 some line failed, 2 usage error, unreadable FILE\n"
    "or unwritable standard output.\n";

/// The joints a line can describe ("joint"), the paper's by default.
constexpr std::string_view kJournalBearing = "journal_bearing";
constexpr std::string_view kPinInHole = "pin_in_hole";

/// Both bodies' motions, or neither: (bearing, journal) or (hole, pin).
struct Motions {
  geo::BodyMotion outer, inner;
};

/// One detect line as the kernel's descriptions: read once, each description checked once by
/// the kernel's validate() with its fields named as in the line ("journal.radius").
struct DetectQuery {
  geo::JointDimensions dimensions;
  geo::PartPose bearing, journal;
  std::optional<Motions> motions;
  geo::DetectionOptions options;
};

/// A pin-in-hole line: the hole is the bearing (body i), the pin the journal (body j).
struct PinInHoleQuery {
  geo::PinInHoleDimensions dimensions;
  geo::PartPose hole, pin;
  std::optional<Motions> motions;
  geo::DetectionOptions options;
};

geo::Vector3 read_vector3(const json::JsonField& value) {
  const std::array<double, 3> v = value.numbers<3>();
  return {v[0], v[1], v[2]};
}

/// A part's pose from its "center" and "axis", checked by the kernel with the fields named as in
/// the line.
geo::PartPose read_pose(const json::JsonField& part) {
  geo::PartPose pose;
  pose.p_WP = read_vector3(part.member("center"));
  pose.axis_W = read_vector3(part.member("axis"));
  geo::validate(pose, part.path(), geo::kPartPoseNames);
  return pose;
}

/// One part: its dimensions go to `radius` and `length`, its pose is returned. Sizes and pose are
/// numbers only here; their signs, ranges and the zero axis are the kernel's to check.
geo::PartPose read_part(const json::JsonField& part, double& radius, double& length) {
  part.require_object({"radius", "length", "center", "axis"});
  radius = part.member("radius").number();
  length = part.member("length").number();
  return read_pose(part);
}

/// The pin: its radius, pose and stops. The stops' positions and sizes are the kernel's to check
/// (validate(PinInHoleDimensions): outside the hole, larger than it, on opposite sides); only
/// their number is checked here, as the description holds at most kMaxAxialStops.
geo::PartPose read_pin(const json::JsonField& pin, geo::PinInHoleDimensions& d) {
  pin.require_object({"radius", "center", "axis", "stops"});
  d.pin_radius = pin.member("radius").number();
  const json::JsonField stops = pin.member("stops");
  const std::vector<json::JsonField> entries = stops.items();
  if (entries.size() > static_cast<std::size_t>(geo::kMaxAxialStops)) {
    stops.refuse("at most " + std::to_string(geo::kMaxAxialStops) +
                 " stops (one on each side of the hole; [] for a free sliding pin)");
  }
  d.stop_count = static_cast<int>(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    entries[k].require_object({"position", "outer_radius"});
    d.stops[k] = {entries[k].member("position").number(), entries[k].member("outer_radius").number()};
  }
  return read_pose(pin);
}

/// The motions under `outer_key` and `inner_key`: both or neither. One alone is most likely a
/// mistake, not "at rest".
std::optional<Motions> read_motions(const json::JsonField& query, const char* outer_key, const char* inner_key) {
  const auto read_motion = [](const json::JsonField& motion) {
    motion.require_object({"mass_center", "velocity", "angular_velocity"});
    return geo::BodyMotion{read_vector3(motion.member("mass_center")), read_vector3(motion.member("velocity")),
                           read_vector3(motion.member("angular_velocity"))};
  };
  const bool has_outer = query.has(outer_key);
  if (has_outer != query.has(inner_key)) {
    const char* missing = has_outer ? inner_key : outer_key;
    const char* given = has_outer ? outer_key : inner_key;
    throw LineError(missing, std::string(": missing (") + given + " is given; give both motions or neither)");
  }
  if (!has_outer) return std::nullopt;
  return Motions{read_motion(query.member(outer_key)), read_motion(query.member(inner_key))};
}

DetectQuery read_query(const json::JsonField& query) {
  query.require_object({"id", "joint", "bearing", "journal", "bearing_motion", "journal_motion", "options"});
  DetectQuery q;
  geo::JointDimensions& d = q.dimensions;
  const json::JsonField bearing = query.member("bearing"), journal = query.member("journal");
  q.bearing = read_part(bearing, d.bearing_radius, d.bearing_length);
  q.journal = read_part(journal, d.journal_radius, d.journal_length);
  geo::validate(d, "", geo::kPartDimensionNames);
  q.motions = read_motions(query, "bearing_motion", "journal_motion");
  // Every option of the list (geometry/option_fields.hpp) by its key; detect_contacts checks them.
  if (query.has("options")) json::read_detection_options(query.member("options"), q.options);
  return q;
}

PinInHoleQuery read_pin_in_hole_query(const json::JsonField& query) {
  query.require_object({"id", "joint", "hole", "pin", "hole_motion", "pin_motion", "options"});
  PinInHoleQuery q;
  const json::JsonField hole = query.member("hole"), pin = query.member("pin");
  q.hole = read_part(hole, q.dimensions.hole_radius, q.dimensions.hole_length);
  q.pin = read_pin(pin, q.dimensions);
  geo::validate(q.dimensions, "", geo::kPinInHolePartNames);
  q.motions = read_motions(query, "hole_motion", "pin_motion");
  if (query.has("options")) json::read_detection_options(query.member("options"), q.options);
  return q;
}

/// Adds each contact's velocities (eqs. 24-26) to the answer's contacts.
template <class Result>
void write_velocities(const Result& result, const Motions& motions, Json& answer) {
  Json& contacts = answer["contacts"];
  for (int k = 0; k < result.contact_count; ++k) {
    const std::string where = "contacts[" + std::to_string(k) + "]";
    const geo::ContactKinematics kinematics =
        geo::contact_kinematics(result.contacts[static_cast<std::size_t>(k)], motions.outer, motions.inner);
    require_finite(kinematics.approach_speed, where + ".approach_velocity");
    require_finite(kinematics.tangential_velocity_W, where + ".tangential_velocity");
    Json& entry = contacts[static_cast<std::size_t>(k)];
    entry["approach_velocity"] = kinematics.approach_speed;                      // eq. (24)
    entry["tangential_velocity"] = app::to_json(kinematics.tangential_velocity_W);  // eq. (26)
  }
}

/// The answer to one joint line (JsonLinesCommand::answer).
void answer_query(const Json& line, Json& answer) {
  const json::JsonField query(line, "", "the line");
  std::string joint(kJournalBearing);
  if (query.has("joint")) {
    const json::JsonField field = query.member("joint");
    joint = field.text();
    if (joint != kJournalBearing && joint != kPinInHole) {
      field.refuse("must be \"journal_bearing\" (the paper's joint, the default) or \"pin_in_hole\"");
    }
  }
  if (joint == kPinInHole) {
    const PinInHoleQuery q = read_pin_in_hole_query(query);
    const geo::PinInHoleContacts result = geo::detect_pin_in_hole_contacts(q.dimensions, q.hole, q.pin, q.options);
    answer["joint"] = std::string(kPinInHole);  // the scenario names are the pin-in-hole table's
    write_result(result, ResultStyle::detect, answer);
    if (q.motions) write_velocities(result, *q.motions, answer);
    return;
  }
  const DetectQuery q = read_query(query);
  const geo::JointContacts result = geo::detect_contacts(q.dimensions, q.bearing, q.journal, q.options);
  write_result(result, ResultStyle::detect, answer);
  if (q.motions) write_velocities(result, *q.motions, answer);
}

}  // namespace

const JsonLinesCommand& detect_command() {
  static const JsonLinesCommand command{"detect", kUsage, answer_query};
  return command;
}

int run_detect(Arguments args) { return run_json_lines(detect_command(), args); }

}  // namespace clearjoint::app
