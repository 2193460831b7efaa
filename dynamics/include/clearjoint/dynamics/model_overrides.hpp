// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Values of a model set in place of the model file's, without copying the file: the command
/// line's `--set PATH=VALUE` and `--end-time T`, Python's `simulate(overrides={...})`. They are
/// written into the model's JSON text before it is read, so that the model is validated exactly
/// as a file holding those values would be (parse_model, with messages naming the field).
///
/// A PATH is either
///  - a dotted path, the way messages name a field: keys separated by '.', array elements by
///    [k] (counted from 0): `solver.end_time`, `bodies[1].mass`, `gravity[1]`,
///    `forces[0].normal_force.stiffness`; or
///  - a JSON pointer (RFC 6901), beginning with '/': `/solver/end_time`, `/bodies/1/mass`.
/// Every array element and every object but the last key's must exist; the last key may be a
/// member the file leaves out (an optional field: `solver.end_time` in a file without it), and a
/// missing object on the way is created (`forces[0].friction.coefficient`); the model reader then
/// refuses a key it does not know, listing the keys it expects (a typo is an error, never
/// ignored).

#include <string>
#include <string_view>
#include <vector>

namespace clearjoint::dynamics {

/// One value set in place of the model file's.
struct ModelOverride {
  std::string path;   ///< a dotted path or a JSON pointer (above)
  std::string value;  ///< the value as JSON text ("0.01", "[0, -9.81, 0]", "\"hertz\"")
  /// How the caller gave it, to start its error messages ("--set solver.end_time=0.01",
  /// "--end-time 0.01", "overrides['solver.end_time']"); the path when empty.
  std::string origin;
};

using ModelOverrides = std::vector<ModelOverride>;

/// The command line's `PATH=VALUE` (split at the first '='). VALUE is read as JSON (1e-3, true,
/// "text", [1, 2, 3]); a VALUE that is not JSON and begins with a letter is taken as a string
/// (`model=hertz` is `model="hertz"`). Throws ModelError naming `origin` for text without '=',
/// an empty path and a VALUE that is neither.
ModelOverride parse_override_assignment(std::string_view assignment, std::string_view origin);

/// `model_text` (a model file's JSON) with each override written in, in order, as JSON text
/// indented by one space (a run folder's model.json). Throws ModelError: for malformed JSON in
/// `model_text`, as parse_model does (starting with `source`); starting with the override's
/// origin, for a value that is not JSON; a malformed path;
/// an array element that does not exist (`bodies[5]` of 3 bodies); a key used on an array
/// (`bodies.1`: "write bodies[1]") or an index on an object; a path that goes through a number or
/// a string; two overrides of the same field, or of a field and a field inside it.
/// The values are not checked here: parse_model does, naming the field.
std::string apply_overrides(std::string_view model_text, std::string_view source,
                            const ModelOverrides& overrides);

/// The overrides as a JSON object text {"<path>": <value>, ...} in the order given: what
/// summary.json records under "overrides".
std::string overrides_json(const ModelOverrides& overrides);

}  // namespace clearjoint::dynamics
