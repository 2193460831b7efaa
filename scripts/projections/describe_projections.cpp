// SPDX-License-Identifier: BSD-3-Clause
// Prints the library's descriptions of its public enums (the EnumTable of each) and results (the
// ResultFields of each) as one JSON document: the input of generate_projections.py, which writes
// from it every front-end that lists values or fields in another language (the C header's enums
// and detection structs, the Fortran constants and types, the Python stubs, the JSON schemas' enum
// lists and detect answer properties, detect --help's answer keys).
//
// The lists below name the enum and result *types*; their values and fields come from the tables.

#include <array>
#include <iostream>
#include <string>
#include <string_view>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "clearjoint/geometry/joint/result_fields.hpp"
#include "clearjoint/geometry/model/circle_plane_topology.hpp"
#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/geometry/model/pin_in_hole_scenario.hpp"

#ifdef CLEARJOINT_DESCRIBE_DYNAMICS
#include "clearjoint/dynamics/clearance_revolute_joint.hpp"
#include "clearjoint/dynamics/joint_description.hpp"
#include "clearjoint/dynamics/normal_contact_force.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"
#endif

namespace {

namespace geo = clearjoint::geometry;
using nlohmann::json;

template <geo::TabledEnum E>
json describe_enum(std::string_view module) {
  json entries = json::array();
  for (const geo::EnumEntry<E>& entry : geo::EnumTable<E>::entries) {
    entries.push_back({{"code", static_cast<int>(entry.value)},
                       {"name", entry.name},
                       {"key", entry.key},
                       {"label", entry.label}});
  }
  return {{"type", geo::EnumTable<E>::type_name}, {"module", module}, {"entries", entries}};
}

// The name of a field's value type in the dump: "float", "int", "bool", "vector3", "plane_side", an
// enum's or a result's type name.
template <class T>
std::string value_type() {
  using V = std::remove_cv_t<T>;
  if constexpr (std::is_same_v<V, double>) return "float";
  else if constexpr (std::is_same_v<V, int>) return "int";
  else if constexpr (std::is_same_v<V, bool>) return "bool";
  else if constexpr (std::is_same_v<V, geo::Vector3>) return "vector3";
  else if constexpr (std::is_same_v<V, geo::PlaneSide>) return "plane_side";
  else if constexpr (geo::TabledEnum<V>) return std::string(geo::EnumTable<V>::type_name);
  else if constexpr (geo::DescribedResult<V>) return std::string(geo::ResultFields<V>::type_name);
  else static_assert(sizeof(V) == 0, "a field of a type the dump has no name for");
}

template <class View>
void describe_view(json& field, const View&) {
  field["kind"] = "plain";
  field["value"] = value_type<std::remove_reference_t<View>>();
}
template <class D>
void describe_view(json& field, const geo::ErrorBound<D>&) {
  field["kind"] = "bound";
  field["value"] = "float";
}
template <class A, class C>
void describe_view(json& field, const geo::FieldList<A, C>& list) {
  field["kind"] = "list";
  field["value"] = value_type<typename std::remove_cv_t<A>::value_type>();
  field["capacity"] = list.items.size();
}
template <class V, class F>
void describe_view(json& field, const geo::OptionalField<V, F>&) {
  field["kind"] = "optional";
  field["value"] = value_type<V>();
}

template <geo::DescribedResult R>
json describe_result() {
  const R result{};
  json fields = json::array();
  std::apply(
      [&](const auto&... entry) {
        (
            [&] {
              json field{{"key", entry.key}, {"doc", entry.doc}};
              describe_view(field, entry.view(result));
              fields.push_back(field);
            }(),
            ...);
      },
      geo::ResultFields<R>::fields);
  return {{"type", geo::ResultFields<R>::type_name}, {"fields", fields}};
}

}  // namespace

int main() {
  json enums = json::array({
      describe_enum<geo::Certainty>("geometry"),
      describe_enum<geo::CertificateReason>("geometry"),
      describe_enum<geo::ContactScenario>("geometry"),
      describe_enum<geo::ContactType>("geometry"),
      describe_enum<geo::ContactBase>("geometry"),
      describe_enum<geo::CirclePlaneTopology>("geometry"),
      describe_enum<geo::CircleCylinderTopology>("geometry"),
      describe_enum<geo::PinInHoleScenario>("geometry"),
  });
#ifdef CLEARJOINT_DESCRIBE_DYNAMICS
  namespace dyn = clearjoint::dynamics;
  enums.push_back(describe_enum<dyn::NormalForceModel>("dynamics"));
  enums.push_back(describe_enum<dyn::JointType>("dynamics"));
  enums.push_back(describe_enum<dyn::ContactSlot>("dynamics"));
  namespace lub = clearjoint::lubrication;  // linked through dynamics
  enums.push_back(describe_enum<lub::CavitationModel>("lubrication"));
  enums.push_back(describe_enum<lub::OilSupply::Kind>("lubrication"));
  enums.push_back(describe_enum<lub::ReynoldsLinearSolver>("lubrication"));
  enums.push_back(describe_enum<lub::BearingMotion>("lubrication"));
  enums.push_back(describe_enum<lub::BearingMethod>("lubrication"));
#endif
  const json results = json::array({
      describe_result<geo::Certificate>(),
      describe_result<geo::RimCrossing>(),
      describe_result<geo::RimArc>(),
      describe_result<geo::Contact>(),
      describe_result<geo::JointContacts>(),
      describe_result<geo::CirclePlaneIntersection>(),
      describe_result<geo::CircleCylinderIntersection>(),
      describe_result<geo::PinInHoleContacts>(),
  });
  std::cout << json{{"enums", enums}, {"results", results}}.dump(2) << '\n';
  return 0;
}
