// clearjoint intersect [FILE]: rim/plane and rim/cylinder queries as JSON Lines.
//
// One JSON object per input line, one JSON object per answer line, in the same order. The format
// (every field, the error lines, the exit status) is specified in docs/command-line.md; keep the
// two in step.

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "clearjoint/geometry/certificate.hpp"
#include "clearjoint/geometry/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/intersect_circle_plane.hpp"
#include "clearjoint/geometry/primitives.hpp"
#include "clearjoint/geometry/rim_arc.hpp"
#include "commands.hpp"

namespace clearjoint::app {
namespace {

namespace geo = clearjoint::geometry;

// ordered_json keeps the keys in the order written below, so answers read like the docs.
using Json = nlohmann::ordered_json;

constexpr const char* kUsage =
    "usage: clearjoint intersect [FILE]\n"
    "\n"
    "Reads JSON Lines from FILE (no FILE or \"-\": standard input), one query per line:\n"
    "  {\"id\": ..., \"circle\": {\"center\": [x,y,z], \"normal\": [x,y,z], \"radius\": r},\n"
    "   \"plane\": {\"point\": [x,y,z], \"normal\": [x,y,z]}}\n"
    "or with \"cylinder\": {\"axis_point\": [x,y,z], \"axis\": [x,y,z], \"radius\": R} instead of\n"
    "\"plane\"; optional \"options\": {\"certify\": bool, \"exact_fallback\": bool}.\n"
    "Writes one JSON line per query line, in order (empty lines are skipped): the intersection\n"
    "with its certificate, or {\"id\": ..., \"error\": \"...\"}. Error bounds that are not known\n"
    "are written as null. See docs/command-line.md.\n"
    "\n"
    "Exit status: 0 all lines answered, 1 some line failed, 2 usage error or unreadable FILE.\n";

// Longest excerpt of an offending value quoted in an error message (characters).
constexpr std::size_t kMaxQuotedValue = 60;

/// A query line that cannot be answered; what() names the field and the offending value.
class LineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `value` as JSON text for an error message, shortened when long.
std::string quote(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > kMaxQuotedValue) text = text.substr(0, kMaxQuotedValue) + "...";
  return text;
}

/// "circle" + "radius" gives "circle.radius"; a top-level field has no prefix.
std::string field(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

/// Throws unless `object` is a JSON object whose keys are all in `allowed`: a misspelt key
/// ("normals", "certfy") must not be silently ignored.
void check_object(const Json& object, const std::string& path,
                  std::initializer_list<std::string_view> allowed) {
  if (!object.is_object()) {
    throw LineError(path.empty() ? "the line " + quote(object) + " is not a JSON object"
                                 : path + " = " + quote(object) + ": must be a JSON object");
  }
  for (const auto& item : object.items()) {
    bool known = false;
    for (std::string_view key : allowed) known = known || item.key() == key;
    if (!known) {
      std::string list;
      for (std::string_view key : allowed) list += (list.empty() ? "" : ", ") + std::string(key);
      throw LineError(field(path, item.key()) + ": unknown field (expected " + list + ")");
    }
  }
}

const Json& member(const Json& object, const std::string& path, const char* key) {
  const auto found = object.find(key);
  if (found == object.end()) throw LineError(field(path, key) + ": missing");
  return *found;
}

/// A JSON number as a double. JSON has no NaN or infinity, and the parser rejects numbers that
/// overflow, so every number read here is finite; the kernel's validate() checks the rest.
double read_number(const Json& value, const std::string& path) {
  if (!value.is_number()) throw LineError(path + " = " + quote(value) + ": must be a number");
  return value.get<double>();
}

geo::Vector3 read_vector(const Json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 3) {
    throw LineError(path + " = " + quote(value) + ": must be an array of 3 numbers");
  }
  geo::Vector3 v;
  for (int k = 0; k < 3; ++k) {
    v[k] = read_number(value[static_cast<std::size_t>(k)], path + "[" + std::to_string(k) + "]");
  }
  return v;
}

geo::Circle3 read_circle(const Json& value) {
  const std::string path = "circle";
  check_object(value, path, {"center", "normal", "radius"});
  return geo::Circle3{read_vector(member(value, path, "center"), path + ".center"),
                      read_vector(member(value, path, "normal"), path + ".normal"),
                      read_number(member(value, path, "radius"), path + ".radius")};
}

geo::Plane3 read_plane(const Json& value) {
  const std::string path = "plane";
  check_object(value, path, {"point", "normal"});
  return geo::Plane3{read_vector(member(value, path, "point"), path + ".point"),
                     read_vector(member(value, path, "normal"), path + ".normal")};
}

geo::Cylinder3 read_cylinder(const Json& value) {
  const std::string path = "cylinder";
  check_object(value, path, {"axis_point", "axis", "radius"});
  return geo::Cylinder3{read_vector(member(value, path, "axis_point"), path + ".axis_point"),
                        read_vector(member(value, path, "axis"), path + ".axis"),
                        read_number(member(value, path, "radius"), path + ".radius")};
}

geo::IntersectionOptions read_options(const Json& query) {
  geo::IntersectionOptions options;
  const auto found = query.find("options");
  if (found == query.end()) return options;
  const std::string path = "options";
  check_object(*found, path, {"certify", "exact_fallback"});
  const auto read_bool = [&](const char* key, bool& out) {
    const auto flag = found->find(key);
    if (flag == found->end()) return;
    if (!flag->is_boolean()) {
      throw LineError(path + "." + key + " = " + quote(*flag) + ": must be true or false");
    }
    out = flag->get<bool>();
  };
  read_bool("certify", options.certify);
  read_bool("exact_fallback", options.exact_fallback);
  return options;
}

/// An error bound for output: kNoErrorBound (no bound known) becomes null.
Json bound(double error) {
  if (!std::isfinite(error)) return nullptr;
  return error;
}

Json to_json(const geo::Vector3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json to_json(const geo::RimCrossing& crossing) {
  return Json{{"angle", crossing.angle},
              {"angle_error", bound(crossing.angle_error)},
              {"point", to_json(crossing.point)},
              {"point_error", bound(crossing.point_error)},
              {"multiplicity", crossing.multiplicity}};
}

Json to_json(const geo::RimArc& arc) {
  return Json{{"begin", arc.begin}, {"end", arc.end}, {"full", arc.full}, {"middle", arc.middle()}};
}

Json to_json(const geo::Certificate& certificate) {
  return Json{{"level", std::string(geo::to_string(certificate.level))},
              {"reason", certificate.reason != nullptr ? certificate.reason : ""}};
}

const char* to_string(geo::CirclePlaneTopology topology) {
  switch (topology) {
    case geo::CirclePlaneTopology::disjoint: return "disjoint";
    case geo::CirclePlaneTopology::tangent: return "tangent";
    case geo::CirclePlaneTopology::two_crossings: return "two_crossings";
    case geo::CirclePlaneTopology::circle_in_plane: return "circle_in_plane";
  }
  throw std::logic_error("unknown CirclePlaneTopology");
}

const char* to_string(geo::CircleCylinderTopology topology) {
  switch (topology) {
    case geo::CircleCylinderTopology::inside: return "inside";
    case geo::CircleCylinderTopology::outside: return "outside";
    case geo::CircleCylinderTopology::crossing: return "crossing";
    case geo::CircleCylinderTopology::on_surface: return "on_surface";
  }
  throw std::logic_error("unknown CircleCylinderTopology");
}

void answer_plane(const geo::Circle3& circle, const Json& plane_json,
                  const geo::IntersectionOptions& options, Json& answer) {
  const geo::CirclePlaneIntersection hit =
      geo::intersect_circle_plane(circle, read_plane(plane_json), options);
  Json crossings = Json::array();
  for (int k = 0; k < hit.crossing_count; ++k) {
    crossings.push_back(to_json(hit.crossings[static_cast<std::size_t>(k)]));
  }
  Json arcs = Json::array();
  if (hit.has_penetration) arcs.push_back(to_json(hit.penetration));
  answer["query"] = "circle_plane";
  answer["topology"] = to_string(hit.topology);
  answer["side"] = hit.side;
  answer["crossings"] = std::move(crossings);
  answer["penetration_arcs"] = std::move(arcs);
  answer["max_signed_distance"] = hit.max_signed_distance;
  answer["max_signed_distance_error"] = bound(hit.max_signed_distance_error);
  answer["certificate"] = to_json(hit.certificate);
}

void answer_cylinder(const geo::Circle3& circle, const Json& cylinder_json,
                     const geo::IntersectionOptions& options, Json& answer) {
  const geo::CircleCylinderIntersection hit =
      geo::intersect_circle_cylinder(circle, read_cylinder(cylinder_json), options);
  Json crossings = Json::array();
  for (int k = 0; k < hit.crossing_count; ++k) {
    crossings.push_back(to_json(hit.crossings[static_cast<std::size_t>(k)]));
  }
  Json arcs = Json::array();
  for (int k = 0; k < hit.arc_count; ++k) {
    arcs.push_back(to_json(hit.penetration_arcs[static_cast<std::size_t>(k)]));
  }
  answer["query"] = "circle_cylinder";
  answer["topology"] = to_string(hit.topology);
  answer["crossings"] = std::move(crossings);
  answer["penetration_arcs"] = std::move(arcs);
  answer["certificate"] = to_json(hit.certificate);
}

/// nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 52: ..." as
/// "parse error at column 52: ...": the tag says nothing to a user, and "line 1" is the parser's
/// line within the one input line, not the file's line number written before the message.
std::string parse_message(const char* what) {
  std::string text(what);
  if (text.starts_with('[')) {
    const auto end = text.find("] ");
    if (end != std::string::npos) text.erase(0, end + 2);
  }
  constexpr std::string_view kParserLine = "at line 1, column ";
  if (const auto at = text.find(kParserLine); at != std::string::npos) {
    text.replace(at, kParserLine.size(), "at column ");
  }
  return text;
}

/// The answer to one non-empty line; sets `failed` when it is an error line.
Json answer_line(const std::string& line, long line_number, bool& failed) {
  Json answer = Json::object();
  answer["id"] = nullptr;
  const std::string where = "line " + std::to_string(line_number) + ": ";
  try {
    Json query;
    try {
      query = Json::parse(line);
    } catch (const Json::exception& e) {
      throw LineError("malformed JSON: " + parse_message(e.what()));
    }
    if (query.is_object()) {
      if (const auto id = query.find("id"); id != query.end()) answer["id"] = *id;
    }
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
    failed = false;
    return answer;
  } catch (const LineError& e) {
    answer["error"] = where + e.what();
  } catch (const geo::InvalidInput& e) {
    answer["error"] = where + e.what();
  } catch (const std::exception& e) {
    // Not the input's fault as far as we can tell: say so, keep answering the other lines.
    answer["error"] = where + "internal error: " + e.what();
  }
  // An error line carries only the id and the message.
  Json error_line = Json::object();
  error_line["id"] = answer["id"];
  error_line["error"] = answer["error"];
  failed = true;
  return error_line;
}

/// Answers every line of `input`; returns the exit status.
int answer_all(std::istream& input, const std::string& input_name, bool flush_each_line) {
  std::string line;
  long line_number = 0;
  long failures = 0;
  while (std::getline(input, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    bool failed = false;
    const Json answer = answer_line(line, line_number, failed);
    if (failed) ++failures;
    std::cout << answer.dump(-1, ' ', false, Json::error_handler_t::replace) << '\n';
    if (flush_each_line) std::cout.flush();
  }
  std::cout.flush();
  if (input.bad()) {
    std::fprintf(stderr, "clearjoint intersect: error reading %s after line %ld\n",
                 input_name.c_str(), line_number);
    return 2;
  }
  if (failures > 0) {
    std::fprintf(stderr, "clearjoint intersect: %ld line(s) of %s could not be answered\n",
                 failures, input_name.c_str());
    return 1;
  }
  return 0;
}

int usage_error(const std::string& message) {
  std::fprintf(stderr, "clearjoint intersect: %s\n%s", message.c_str(), kUsage);
  return 2;
}

}  // namespace

int run_intersect(Arguments args) {
  const char* path = nullptr;
  for (const char* arg : args) {
    const std::string_view a(arg);
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (a.size() > 1 && a.front() == '-') return usage_error("unknown option '" + std::string(a) + "'");
    if (path != nullptr) return usage_error("more than one input file");
    path = arg;
  }

  if (path == nullptr || std::string_view(path) == "-") {
    // A program at the other end of a pipe waits for each answer: flush line by line.
    return answer_all(std::cin, "standard input", /*flush_each_line=*/true);
  }
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    std::fprintf(stderr, "clearjoint intersect: cannot read '%s': is a directory\n", path);
    return 2;
  }
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "clearjoint intersect: cannot open '%s': %s\n", path, std::strerror(errno));
    return 2;
  }
  std::string name = "'";  // built piecewise: "'" + std::string(path) trips GCC 12's -Wrestrict
  name.append(path).append("'");
  return answer_all(file, name, /*flush_each_line=*/false);
}

}  // namespace clearjoint::app
