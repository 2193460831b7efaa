// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The JSON model file (docs/dynamics.md has the schema; models/ has examples). Unknown keys are
/// errors (they are usually typos), except "comment" and "notes", allowed in every object.

#include <filesystem>
#include <string>
#include <string_view>

#include "clearjoint/dynamics/model_description.hpp"

namespace clearjoint::dynamics {

/// Largest model file read (bytes). The largest shipped model is a few kilobytes; the limit keeps
/// a wrong path (a log, /dev/zero) from being read whole. Nesting is limited to 64 levels and
/// numbers that underflow (1e-400) are refused (docs/dynamics.md, "Limits").
inline constexpr size_t kMaxModelFileBytes = size_t{16} << 20;

/// Ranges of a body's mass [kg] and principal moments of inertia [kg m^2], and the largest
/// gravity [m/s^2], a model file may give: far beyond any mechanism (a microgram part, a ship),
/// and far from where 1/m and the products of the equations of motion overflow (a mass of 1e-300
/// made the constraint Jacobian look rank deficient).
inline constexpr double kSmallestMass = 1e-12;
inline constexpr double kLargestMass = 1e12;
inline constexpr double kSmallestInertia = 1e-30;
inline constexpr double kLargestInertia = 1e30;
inline constexpr double kLargestGravity = 1e6;

/// Longest name of a body, joint or force element (bytes): names become file names
/// (body_<name>.csv, at most 255 bytes on common file systems) and CSV column headers.
inline constexpr size_t kMaxNameBytes = 128;

/// Parse a model from JSON text; `source` names it in messages. Throws ModelError naming the
/// field path (e.g. "model.json: bodies[1].mass = -1: must be positive").
ModelDescription parse_model(std::string_view json_text, std::string_view source);

/// A model file's text as read, unparsed (at most kMaxModelFileBytes + 1 bytes: parse_model
/// refuses a longer one): for callers that keep the text beside the model, as a run folder's
/// model.json. Throws ModelError if it cannot be read.
std::string read_model_text(const std::filesystem::path& path);

/// Read and parse a model file: parse_model(read_model_text(path), path). Throws ModelError if it
/// cannot be read or parsed.
ModelDescription read_model_file(const std::filesystem::path& path);

}  // namespace clearjoint::dynamics
