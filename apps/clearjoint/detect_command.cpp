// SPDX-License-Identifier: BSD-3-Clause
// clearjoint detect [FILE]: joint contact detection (paper Section 3, eqs. 3-26) as JSON Lines.
//
// One joint configuration per input line, one answer per line, in the same order: the scenario
// of the paper's Fig. 2, the contacts with their points, normal and depth, and, when both bodies'
// motions are given, the contact velocities (eqs. 24-26). The format (every field, the error
// lines, the exit status) is specified in docs/command-line.md; keep the two in step.

#include <optional>
#include <string>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/joint/contact_kinematics.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
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

/// A size (radius or length): a number; the kernel's validate() checks its sign and magnitude.
double read_size(const Json& object, const std::string& path, const char* key) {
  return read_number(member(object, path, key), field(path, key));
}

/// A centre or axis: 3 numbers, each 0 or within the accepted magnitudes (json_lines.hpp).
geo::Vector3 read_pose_vector(const Json& object, const std::string& path, const char* key) {
  return read_geometric_vector(member(object, path, key), field(path, key));
}

/// One part: its dimensions go to `radius` and `length`, its pose is returned.
geo::PartPose read_part(const Json& object, const std::string& path, double& radius,
                        double& length) {
  check_object(object, path, {"radius", "length", "center", "axis"});
  radius = read_size(object, path, "radius");
  length = read_size(object, path, "length");
  geo::PartPose pose;
  pose.p_WP = read_pose_vector(object, path, "center");
  pose.axis_W = read_pose_vector(object, path, "axis");
  geo::validate(pose, path, geo::kPartPoseNames);  // the kernel's one check, named as in the line
  return pose;
}

geo::BodyMotion read_motion(const Json& object, const std::string& path) {
  check_object(object, path, {"mass_center", "velocity", "angular_velocity"});
  geo::BodyMotion motion;
  motion.p_WM = read_vector(member(object, path, "mass_center"), path + ".mass_center");
  motion.v_WM = read_vector(member(object, path, "velocity"), path + ".velocity");
  motion.w_W = read_vector(member(object, path, "angular_velocity"), path + ".angular_velocity");
  return motion;
}

geo::DetectionOptions read_options(const Json& query) {
  geo::DetectionOptions options;
  const auto found = query.find("options");
  if (found == query.end()) return options;
  // Every option of the list (geometry/option_fields.hpp) by its key.
  read_detection_options(*found, "options", options);
  return options;
}

/// The answer to one joint line (JsonLinesCommand::answer).
void answer_query(const Json& query, Json& answer) {
  check_object(query, "",
               {"id", "bearing", "journal", "bearing_motion", "journal_motion", "options"});
  geo::JointDimensions dimensions;
  const Json& bearing_json = member(query, "", "bearing");
  const Json& journal_json = member(query, "", "journal");
  const geo::PartPose bearing =
      read_part(bearing_json, "bearing", dimensions.bearing_radius, dimensions.bearing_length);
  const geo::PartPose journal =
      read_part(journal_json, "journal", dimensions.journal_radius, dimensions.journal_length);
  // The kernel's one check, with the fields named as in the line ("journal.radius").
  geo::validate(dimensions, "", geo::kPartDimensionNames);

  // Velocities need both bodies' motions: one alone is most likely a mistake, not "at rest".
  const bool has_bearing_motion = query.contains("bearing_motion");
  const bool has_journal_motion = query.contains("journal_motion");
  if (has_bearing_motion != has_journal_motion) {
    throw LineError(has_bearing_motion ? "journal_motion" : "bearing_motion",
                    std::string(": missing (") + (has_bearing_motion ? "bearing_motion" : "journal_motion") +
                    " is given; give both motions or neither)");
  }
  std::optional<geo::BodyMotion> bearing_motion, journal_motion;
  if (has_bearing_motion) {
    bearing_motion = read_motion(query["bearing_motion"], "bearing_motion");
    journal_motion = read_motion(query["journal_motion"], "journal_motion");
  }

  const geo::JointContacts result =
      geo::detect_contacts(dimensions, bearing, journal, read_options(query));
  write_result(result, ResultStyle::detect, answer);
  if (!bearing_motion) return;
  Json& contacts = answer["contacts"];
  for (int k = 0; k < result.contact_count; ++k) {
    const std::string where = "contacts[" + std::to_string(k) + "]";
    const geo::ContactKinematics kinematics =
        geo::contact_kinematics(result.contacts[static_cast<std::size_t>(k)], *bearing_motion, *journal_motion);
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
