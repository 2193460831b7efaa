// SPDX-License-Identifier: BSD-3-Clause
#include "json_output.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

namespace clearjoint::bench {
namespace {

using geometry::ContactBase;
using geometry::ContactScenario;
using geometry::ContactType;

Json vector_json(const geometry::Vector3& v) { return Json::array({v.x(), v.y(), v.z()}); }
Json vector_json(const RealVector& v) { return vector_json(to_double(v)); }
Json hex_vector(const geometry::Vector3& v) { return Json::array({hex(v.x()), hex(v.y()), hex(v.z())}); }

Json part_line(double radius, double length, const geometry::PartPose& pose) {
  return Json{{"radius", radius}, {"length", length}, {"center", vector_json(pose.p_WP)},
              {"axis", vector_json(pose.axis_W)}};
}

}  // namespace

const char* scenario_label(ContactScenario scenario) {
  // The key is static text, NUL-terminated.
  return geometry::to_string(scenario).data();
}

Json detect_input_line(const DetectionInput& input) {
  const geometry::JointDimensions& d = input.dimensions;
  return Json{{"id", input.id},
              {"bearing", part_line(d.bearing_radius, d.bearing_length, input.bearing)},
              {"journal", part_line(d.journal_radius, d.journal_length, input.journal)}};
}

Json reference_answer_line(const DetectionInput& input, const ReferenceAnswer& answer) {
  Json line{{"id", input.id}, {"family", input.family}, {"group", input.group}};
  if (std::isfinite(input.measured_margin)) line["measured_margin"] = input.measured_margin;
  if (std::isfinite(input.measured_tilt)) line["measured_tilt"] = input.measured_tilt;
  line["scenario"] = scenario_label(answer.scenario);
  line["aligned"] = answer.aligned;
  Json contacts = Json::array();
  for (const ReferenceContact& c : answer.contacts) {
    Json crossings = Json::array();
    for (const RealVector& x : c.crossings) crossings.push_back(vector_json(x));
    contacts.push_back(Json{
        {"type", std::string(geometry::to_string(c.type))},
        {"base", std::string(geometry::to_string(c.base))},
        {"depth", c.depth.convert_to<double>()},
        {"point_journal", vector_json(c.p_WCj)},
        {"point_bearing", vector_json(c.p_WCi)},
        {"normal", vector_json(c.normal_W)},
        {"crossings", std::move(crossings)},
        {"points_defined", c.points_defined},
        {"rim_beyond_base_all_round", c.all_round}});
  }
  line["contacts"] = std::move(contacts);
  line["reference"] = Json{{"digits", kReferenceDigits10}, {"decided", answer.decided}, {"why", answer.why}};
  return line;
}

std::string hex(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}

Json hex_input(const DetectionInput& input) {
  const geometry::JointDimensions& d = input.dimensions;
  return Json{{"bearing_radius", hex(d.bearing_radius)},
              {"bearing_length", hex(d.bearing_length)},
              {"journal_radius", hex(d.journal_radius)},
              {"journal_length", hex(d.journal_length)},
              {"bearing_center", hex_vector(input.bearing.p_WP)},
              {"bearing_axis", hex_vector(input.bearing.axis_W)},
              {"journal_center", hex_vector(input.journal.p_WP)},
              {"journal_axis", hex_vector(input.journal.axis_W)}};
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::filesystem::path target(path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary + ": " + std::strerror(errno));
  }
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (error) throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " + error.message());
}

}  // namespace clearjoint::bench
