// SPDX-License-Identifier: BSD-3-Clause
// clearjoint intersect [FILE]: rim/plane and rim/cylinder queries as JSON Lines.
//
// One JSON object per input line, one JSON object per answer line, in the same order. The format
// (every field, the error lines, the exit status) is specified in docs/command-line.md; keep the
// two in step.

#include <string>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "commands.hpp"
#include "json_lines.hpp"
#include "result_json.hpp"

namespace clearjoint::app {
namespace {

namespace geo = clearjoint::geometry;

constexpr const char* kUsage =
    "usage: clearjoint intersect [FILE]\n"
    "\n"
    "Reads JSON Lines from FILE (no FILE or \"-\": standard input), one query per line:\n"
    "  {\"id\": ..., \"circle\": {\"center\": [x,y,z], \"normal\": [x,y,z], \"radius\": r},\n"
    "   \"plane\": {\"point\": [x,y,z], \"normal\": [x,y,z]}}\n"
    "or with \"cylinder\": {\"axis_point\": [x,y,z], \"axis\": [x,y,z], \"radius\": R} instead of\n"
    "\"plane\"; optional \"options\": {\"certify\": bool, \"exact_fallback\": bool}.\n"
    "Writes one JSON line per query line, in order (empty lines are skipped): the intersection\n"
    "with its certificate, or {\"v\": 1, \"id\": ..., \"error\": \"...\"}. Every output line\n"
    "starts with \"v\": 1, the version of these formats. Error bounds that are not known are\n"
    "written as null. See docs/command-line.md.\n"
    "\n"
    "Formats (JSON Schema 2020-12, in docs/schema/ and installed in share/clearjoint/schema/):\n"
    "  input  intersect-query.schema.json\n"
    "  output intersect-answer.schema.json (answers and error lines)\n"
    "\n"
    "Exit status: 0 all lines answered, 1 some line failed, 2 usage error, unreadable FILE\n"
    "or unwritable standard output.\n";

geo::Circle3 read_circle(const Json& value) {
  const std::string path = "circle";
  check_object(value, path, {"center", "normal", "radius"});
  return geo::Circle3{read_geometric_vector(member(value, path, "center"), path + ".center"),
                      read_geometric_vector(member(value, path, "normal"), path + ".normal"),
                      read_geometric_number(member(value, path, "radius"), path + ".radius")};
}

geo::Plane3 read_plane(const Json& value) {
  const std::string path = "plane";
  check_object(value, path, {"point", "normal"});
  return geo::Plane3{read_geometric_vector(member(value, path, "point"), path + ".point"),
                     read_geometric_vector(member(value, path, "normal"), path + ".normal")};
}

geo::Cylinder3 read_cylinder(const Json& value) {
  const std::string path = "cylinder";
  check_object(value, path, {"axis_point", "axis", "radius"});
  return geo::Cylinder3{
      read_geometric_vector(member(value, path, "axis_point"), path + ".axis_point"),
      read_geometric_vector(member(value, path, "axis"), path + ".axis"),
      read_geometric_number(member(value, path, "radius"), path + ".radius")};
}

geo::IntersectionOptions read_options(const Json& query) {
  geo::IntersectionOptions options;
  const auto found = query.find("options");
  if (found == query.end()) return options;
  const std::string path = "options";
  check_object(*found, path, {"certify", "exact_fallback"});
  read_optional_bool(*found, path, "certify", options.certify);
  read_optional_bool(*found, path, "exact_fallback", options.exact_fallback);
  return options;
}

void answer_plane(const geo::Circle3& circle, const Json& plane_json,
                  const geo::IntersectionOptions& options, Json& answer) {
  const geo::CirclePlaneIntersection hit =
      geo::intersect_circle_plane(circle, read_plane(plane_json), options);
  answer["query"] = "circle_plane";
  write_result(hit, ResultStyle::intersect, answer);
}

void answer_cylinder(const geo::Circle3& circle, const Json& cylinder_json,
                     const geo::IntersectionOptions& options, Json& answer) {
  const geo::CircleCylinderIntersection hit =
      geo::intersect_circle_cylinder(circle, read_cylinder(cylinder_json), options);
  answer["query"] = "circle_cylinder";
  write_result(hit, ResultStyle::intersect, answer);
}

/// The answer to one query line (JsonLinesCommand::answer).
void answer_query(const Json& query, Json& answer) {
  check_object(query, "", {"id", "circle", "plane", "cylinder", "options"});
  const bool has_plane = query.contains("plane");
  const bool has_cylinder = query.contains("cylinder");
  if (has_plane == has_cylinder) {
    throw LineError(has_plane ? "plane and cylinder: give one of them, not both"
                              : "plane or cylinder: missing (give one of them)");
  }
  const geo::Circle3 circle = read_circle(member(query, "", "circle"));
  const geo::IntersectionOptions options = read_options(query);
  if (has_plane) {
    answer_plane(circle, query["plane"], options, answer);
  } else {
    answer_cylinder(circle, query["cylinder"], options, answer);
  }
}

}  // namespace

const JsonLinesCommand& intersect_command() {
  static const JsonLinesCommand command{"intersect", kUsage, answer_query};
  return command;
}

int run_intersect(Arguments args) { return run_json_lines(intersect_command(), args); }

}  // namespace clearjoint::app
