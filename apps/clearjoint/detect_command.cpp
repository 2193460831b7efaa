// SPDX-License-Identifier: BSD-3-Clause
// clearjoint detect [FILE]: joint contact detection (paper Section 3, eqs. 3-26) as JSON Lines.
//
// One joint configuration per input line, one answer per line, in the same order: the scenario
// of the paper's Fig. 2, the contacts with their points, normal and depth, and, when both bodies'
// motions are given, the contact velocities (eqs. 24-26). The format (every field, the error
// lines, the exit status) is specified in docs/command-line.md; keep the two in step.

#include <array>
#include <optional>
#include <string>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/joint/contact_kinematics.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
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
    "Writes one JSON line per joint line, in order (empty lines are skipped):\n"
    "  {\"v\": 1, \"id\", \"scenario\": \"none\"|\"a\"..\"l\"|\"beyond_model\", \"aligned\",\n"
    "   \"certificate\", \"certificate_reason\", \"contacts\": [{\"type\", \"base\", \"depth\",\n"
    "   \"depth_error\", \"point_journal\", \"point_bearing\", \"point_journal_error\",\n"
    "   \"point_bearing_error\", \"normal\", \"crossings\", \"crossing_errors\",\n"
    "   \"certificate\", \"certificate_reason\", \"approach_velocity\",\n"
    "   \"tangential_velocity\"}]}\n"
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

/// One detect line as the kernel's descriptions: read once, each description checked once by
/// the kernel's validate() with its fields named as in the line ("journal.radius").
struct DetectQuery {
  geo::JointDimensions dimensions;
  geo::PartPose bearing, journal;
  std::optional<geo::BodyMotion> bearing_motion, journal_motion;  // both or neither
  geo::DetectionOptions options;
};

geo::Vector3 read_vector3(const json::JsonField& value) {
  const std::array<double, 3> v = value.numbers<3>();
  return {v[0], v[1], v[2]};
}

/// One part: its dimensions go to `radius` and `length`, its pose is returned. Sizes and pose are
/// numbers only here; their signs, ranges and the zero axis are the kernel's to check.
geo::PartPose read_part(const json::JsonField& part, double& radius, double& length) {
  part.require_object({"radius", "length", "center", "axis"});
  radius = part.member("radius").number();
  length = part.member("length").number();
  geo::PartPose pose;
  pose.p_WP = read_vector3(part.member("center"));
  pose.axis_W = read_vector3(part.member("axis"));
  geo::validate(pose, part.path(), geo::kPartPoseNames);
  return pose;
}

geo::BodyMotion read_motion(const json::JsonField& motion) {
  motion.require_object({"mass_center", "velocity", "angular_velocity"});
  return {read_vector3(motion.member("mass_center")), read_vector3(motion.member("velocity")),
          read_vector3(motion.member("angular_velocity"))};
}

DetectQuery read_query(const Json& line) {
  const json::JsonField query(line, "", "the line");
  query.require_object({"id", "bearing", "journal", "bearing_motion", "journal_motion", "options"});
  DetectQuery q;
  geo::JointDimensions& d = q.dimensions;
  const json::JsonField bearing = query.member("bearing"), journal = query.member("journal");
  q.bearing = read_part(bearing, d.bearing_radius, d.bearing_length);
  q.journal = read_part(journal, d.journal_radius, d.journal_length);
  geo::validate(d, "", geo::kPartDimensionNames);
  // Velocities need both bodies' motions: one alone is most likely a mistake, not "at rest".
  const bool has_bearing_motion = query.has("bearing_motion");
  if (has_bearing_motion != query.has("journal_motion")) {
    const char* missing = has_bearing_motion ? "journal_motion" : "bearing_motion";
    const char* given = has_bearing_motion ? "bearing_motion" : "journal_motion";
    throw LineError(missing, std::string(": missing (") + given + " is given; give both motions or neither)");
  }
  if (has_bearing_motion) {
    q.bearing_motion = read_motion(query.member("bearing_motion"));
    q.journal_motion = read_motion(query.member("journal_motion"));
  }
  // Every option of the list (geometry/option_fields.hpp) by its key; detect_contacts checks them.
  if (query.has("options")) json::read_detection_options(query.member("options"), q.options);
  return q;
}

/// The answer to one joint line (JsonLinesCommand::answer).
void answer_query(const Json& line, Json& answer) {
  const DetectQuery query = read_query(line);
  const geo::JointContacts result = geo::detect_contacts(query.dimensions, query.bearing, query.journal, query.options);
  write_result(result, ResultStyle::detect, answer);
  if (!query.bearing_motion) return;
  Json& contacts = answer["contacts"];
  for (int k = 0; k < result.contact_count; ++k) {
    const std::string where = "contacts[" + std::to_string(k) + "]";
    const geo::ContactKinematics kinematics =
        geo::contact_kinematics(result.contacts[static_cast<std::size_t>(k)], *query.bearing_motion,
                                 *query.journal_motion);
    require_finite(kinematics.approach_speed, where + ".approach_velocity");
    require_finite(kinematics.tangential_velocity_W, where + ".tangential_velocity");
    Json& entry = contacts[static_cast<std::size_t>(k)];
    entry["approach_velocity"] = kinematics.approach_speed;                      // eq. (24)
    entry["tangential_velocity"] = app::to_json(kinematics.tangential_velocity_W);  // eq. (26)
  }
}

}  // namespace

const JsonLinesCommand& detect_command() {
  static const JsonLinesCommand command{"detect", kUsage, answer_query};
  return command;
}

int run_detect(Arguments args) { return run_json_lines(detect_command(), args); }

}  // namespace clearjoint::app
