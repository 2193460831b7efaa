// SPDX-License-Identifier: BSD-3-Clause
// The command line's detection options against the library's option list
// (geometry/model/option_fields.hpp): `detect` reads every option by its key, and the query schema and
// the model schema name each one. A member added to DetectionOptions (and so to its list, which
// the compiler requires) that the command line or a schema lacks fails here, naming the key.

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <string>
#include <type_traits>

#include "clearjoint/geometry/model/option_fields.hpp"
#include "json_lines.hpp"
#include "option_changes.hpp"

namespace clearjoint::app {
namespace {

namespace geo = clearjoint::geometry;

/// The option `key` of `options` as a JSON value.
Json option_json(const geo::DetectionOptions& options, std::string_view key) {
  Json value;
  geo::visit_options(options, [&](std::string_view k, const auto& v) {
    if (k == key) value = v;
  });
  return value;
}

Json read_schema(const std::string& name) {
  std::ifstream file(std::string(CLEARJOINT_SOURCE_DIR) + "/docs/schema/" + name);
  return Json::parse(file);
}

TEST(DetectionOptions, TheDetectCommandReadsEachOptionByItsKey) {
  for (int k = 0; k < geo::kDetectionOptionCount; ++k) {
    const geo::OptionChange change = geo::change_one_option(k);
    Json object = Json::object();
    object[std::string(change.key)] = option_json(change.options, change.key);
    geo::DetectionOptions read;
    read_detection_options(object, "options", read);
    EXPECT_EQ(geo::option_values(read), geo::option_values(change.options)) << object.dump();
  }
}

TEST(DetectionOptions, TheDetectCommandRefusesAKeyOutsideTheListNamingTheList) {
  geo::DetectionOptions read;
  try {
    read_detection_options(Json::parse(R"({"certfy": false})"), "options", read);
    FAIL() << "no error";
  } catch (const ValidationError& e) {
    EXPECT_EQ(e.field_path(), "options.certfy");
    EXPECT_STREQ(e.what(), "options.certfy: unknown field (expected certify, exact_fallback, parallel_angle_tolerance)");
  }
}

TEST(DetectionOptions, TheQueryAndModelSchemasNameEveryOptionWithItsDefault) {
  // One "options" object, referred to by both joints' queries.
  const Json query = read_schema("detect-query.schema.json")["$defs"]["options"]["properties"];
  const Json model = read_schema("model.schema.json");
  // The clearance joint's "detection" object, wherever the model schema defines it.
  Json detection;
  const auto find_detection = [&](const auto& self, const Json& node) -> void {
    if (!node.is_structured()) return;
    for (const auto& item : node.items()) {
      if (item.key() == "detection" && item.value().is_object() && item.value().contains("properties")) {
        detection = item.value()["properties"];
      }
      self(self, item.value());
    }
  };
  find_detection(find_detection, model);
  ASSERT_TRUE(detection.is_object()) << "model.schema.json has no detection object";
  const geo::DetectionOptions defaults;
  geo::visit_options(defaults, [&](std::string_view key, const auto& value) {
    const std::string name(key);
    for (const Json* schema : std::array<const Json*, 2>{&query, &detection}) {
      ASSERT_TRUE(schema->contains(name)) << name;
      const Json& entry = (*schema)[name];
      const bool flag = std::is_same_v<std::decay_t<decltype(value)>, bool>;
      EXPECT_EQ(entry["type"], flag ? "boolean" : "number") << name;
      if (entry.contains("default")) {
        EXPECT_EQ(entry["default"], Json(value)) << name;
      }
    }
  });
}

}  // namespace
}  // namespace clearjoint::app
