// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// JSON pieces shared by the accuracy report and the robustness export: inputs in the
/// `clearjoint detect` input format, answers in its output format, inputs as hex floats, and
/// atomic file writes.

#include <string>

#include <nlohmann/json.hpp>

#include "clearjoint/geometry/model/contact_scenario.hpp"
#include "input_families.hpp"
#include "joint_reference.hpp"

namespace clearjoint::bench {

/// Keys in the order written; dump() prints each double in the shortest form that reads back to
/// the same double.
using Json = nlohmann::ordered_json;

/// "none", "a" .. "l", "beyond_model": the `clearjoint detect` labels (paper Fig. 2).
const char* scenario_label(geometry::ContactScenario scenario);

/// `{"id", "bearing": {"radius", "length", "center", "axis"}, "journal": {...}}`, the
/// `clearjoint detect` input line (issue 4, docs/command-line.md).
Json detect_input_line(const DetectionInput& input);

/// The reference answer in the `clearjoint detect` output format (every MPFR number rounded to the
/// nearest double), plus "family", "group", "measured_margin" / "measured_tilt" where defined, and
/// "reference": {"digits", "decided", "why"} in place of "certificate", and per contact
/// "points_defined" and "rim_beyond_base_all_round" (ReferenceContact's fields of those names).
Json reference_answer_line(const DetectionInput& input, const ReferenceAnswer& answer);

/// The input with every double as a C99 hex float ("0x1.47ae147ae147bp-7"), for failure reports
/// that must reproduce the input bit for bit.
Json hex_input(const DetectionInput& input);
std::string hex(double x);

/// Writes `text` to `path` through a temporary file in the same folder and a rename, so that a
/// reader never sees a half-written file. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace clearjoint::bench
