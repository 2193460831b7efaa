// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The JSON model file (docs/dynamics.md has the schema; models/ has examples). Unknown keys are
/// errors (they are usually typos), except "comment" and "notes", allowed in every object.

#include <filesystem>
#include <string_view>

#include "clearjoint/dynamics/model_description.hpp"

namespace clearjoint::dynamics {

/// Parse a model from JSON text; `source` names it in messages. Throws ModelError naming the
/// field path (e.g. "model.json: bodies[1].mass = -1: must be positive").
ModelDescription parse_model(std::string_view json_text, std::string_view source);

/// Read and parse a model file. Throws ModelError if it cannot be read or parsed.
ModelDescription read_model_file(const std::filesystem::path& path);

}  // namespace clearjoint::dynamics
