// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The shipped pin-in-hole examples (examples/pin_in_hole_scenarios.jsonl: one pose per scenario,
// the `clearjoint detect` requests the scenario table's figures are drawn from) as C++ inputs,
// for the tests that run them through the other front-ends.

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"

namespace clearjoint::testing {

struct PinInHoleExample {
  std::string id;  ///< "pin-<scenario>"
  geometry::PinInHoleDimensions dimensions;
  geometry::PartPose hole;
  geometry::PartPose pin;
};

inline std::vector<PinInHoleExample> read_pin_in_hole_examples(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const auto vector = [](const nlohmann::json& v) { return geometry::Vector3(v[0], v[1], v[2]); };
  std::vector<PinInHoleExample> examples;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    const nlohmann::json request = nlohmann::json::parse(line);
    const nlohmann::json &hole = request.at("hole"), &pin = request.at("pin");
    PinInHoleExample example;
    example.id = request.at("id");
    example.dimensions.hole_radius = hole.at("radius");
    example.dimensions.hole_length = hole.at("length");
    example.dimensions.pin_radius = pin.at("radius");
    for (const nlohmann::json& stop : pin.value("stops", nlohmann::json::array())) {
      example.dimensions.stops.at(example.dimensions.stop_count++) = {stop.at("position"), stop.at("outer_radius")};
    }
    example.hole = {vector(hole.at("center")), vector(hole.at("axis"))};
    example.pin = {vector(pin.at("center")), vector(pin.at("axis"))};
    examples.push_back(example);
  }
  return examples;
}

}  // namespace clearjoint::testing
