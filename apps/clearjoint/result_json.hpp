// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The library's results as the JSON Lines answers write them, through their field lists
// (clearjoint/geometry/joint/result_fields.hpp): a field added to a result reaches both commands' output
// with its key; a field of a type written nowhere here does not compile. The formats themselves
// (docs/command-line.md, docs/schema/) are as before:
//  - enum values are their keys (enum_table.hpp), a certificate reason its sentence;
//  - error bounds that are not known (kNoErrorBound) are null;
//  - `detect` writes a certificate flat ("certificate": level, "certificate_reason": sentence),
//    and a contact's crossings as two lists, their points ("crossings") and their points' error
//    bounds ("crossing_errors"); it refuses a non-finite number (require_finite);
//  - `intersect` writes a certificate as {"level", "reason"}, crossings as objects, an arc with
//    its "middle", and the plane's optional penetration arc as a list of 0 or 1 arcs,
//    "penetration_arcs", the key of the cylinder's list.

#include <cmath>
#include <string>
#include <string_view>

#include "clearjoint/geometry/joint/result_fields.hpp"
#include "json_lines.hpp"

namespace clearjoint::app {

enum class ResultStyle {
  detect,     ///< flat certificates, crossings as points and errors, finite numbers only
  intersect,  ///< nested certificates, crossings and arcs as objects
};

/// Throws LineError when a computed value is not finite. The contact points and velocities are
/// double-precision evaluations of the paper's formulas (not the certified kernel); speeds near
/// the limits of double (motions are not range-checked) overflow them, and a null in the answer
/// would hide that.
void require_finite(double value, const std::string& what);
void require_finite(const geometry::Vector3& v, const std::string& what);

/// Writes the fields it visits into `out`; `path` names the result in messages ("contacts[1]").
class ResultJsonWriter {
 public:
  ResultJsonWriter(Json& out, ResultStyle style, std::string path)
      : out_(out), style_(style), path_(std::move(path)) {}

  void operator()(std::string_view key, const double& x) {
    if (style_ == ResultStyle::detect) require_finite(x, where(key));
    out_[std::string(key)] = x;
  }
  void operator()(std::string_view key, const int& n) { out_[std::string(key)] = n; }
  void operator()(std::string_view key, const bool& b) { out_[std::string(key)] = b; }
  void operator()(std::string_view key, const geometry::Vector3& v) {
    if (style_ == ResultStyle::detect) require_finite(v, where(key));
    out_[std::string(key)] = to_json(v);
  }
  void operator()(std::string_view key, const geometry::PlaneSide& side) {
    out_[std::string(key)] = static_cast<int>(side);  // -1, 0, +1
  }
  template <geometry::TabledEnum E>
  void operator()(std::string_view key, const E& value) {
    out_[std::string(key)] = std::string(geometry::to_string(value));
  }
  void operator()(std::string_view key, geometry::ErrorBound<const double> bound) {
    out_[std::string(key)] = error_bound(bound.value);
  }
  void operator()(std::string_view key, const geometry::Certificate& certificate) {
    if (style_ == ResultStyle::detect) {
      out_[std::string(key)] = std::string(geometry::to_string(certificate.level));
      out_[std::string(key) + "_reason"] = std::string(certificate.reason_text());
    } else {
      out_[std::string(key)] = object(certificate, where(key));
    }
  }
  void operator()(std::string_view key, const geometry::RimArc& arc) { out_[std::string(key)] = object(arc, where(key)); }

  template <class Array>
  void operator()(std::string_view key, geometry::FieldList<const Array, const int> list) {
    if constexpr (std::is_same_v<typename Array::value_type, geometry::RimCrossing>) {
      if (style_ == ResultStyle::detect) return write_crossing_points(key, list);
    }
    Json items = Json::array();
    for (int k = 0; k < list.count; ++k) {
      items.push_back(object(list.items[static_cast<std::size_t>(k)], where(key) + "[" + std::to_string(k) + "]"));
    }
    out_[std::string(key)] = std::move(items);
  }

  /// An optional arc: a list of 0 or 1 arcs, under the key of the cylinder's list.
  void operator()(std::string_view key, geometry::OptionalField<const geometry::RimArc, const bool> arc) {
    Json items = Json::array();
    if (arc.present) items.push_back(object(arc.value, where(key)));
    out_[std::string(key) + "_arcs"] = std::move(items);
  }

  /// A described result as a JSON object, with the extras a type has in this format.
  template <geometry::DescribedResult Result>
  Json object(const Result& result, const std::string& path) const {
    Json json = Json::object();
    geometry::visit_fields(result, ResultJsonWriter(json, style_, path));
    if constexpr (std::is_same_v<Result, geometry::RimArc>) json["middle"] = result.middle();
    return json;
  }

 private:
  std::string where(std::string_view key) const { return path_.empty() ? std::string(key) : path_ + "." + std::string(key); }

  template <class Array>
  void write_crossing_points(std::string_view key, geometry::FieldList<const Array, const int> list) {
    Json points = Json::array();
    Json errors = Json::array();
    for (int k = 0; k < list.count; ++k) {
      const geometry::RimCrossing& crossing = list.items[static_cast<std::size_t>(k)];
      require_finite(crossing.point, where(key) + "[" + std::to_string(k) + "]");
      points.push_back(to_json(crossing.point));
      errors.push_back(error_bound(crossing.point_error));
    }
    out_[std::string(key)] = std::move(points);
    out_["crossing_errors"] = std::move(errors);
  }

  Json& out_;
  ResultStyle style_;
  std::string path_;
};

/// Adds the fields of `result` to `out` (an answer that already holds "v" and "id").
template <geometry::DescribedResult Result>
void write_result(const Result& result, ResultStyle style, Json& out) {
  geometry::visit_fields(result, ResultJsonWriter(out, style, ""));
}

}  // namespace clearjoint::app
