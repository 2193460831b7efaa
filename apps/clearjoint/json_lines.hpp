// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the JSON Lines commands (`clearjoint intersect`, `clearjoint detect`) share: the
// command-line handling (FILE or standard input, --help, exit statuses), the line loop with its
// error lines, and the readers that name the offending field and value in their messages.
// docs/command-line.md specifies the behaviour common to both commands; keep the two in step.

#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/detection_options.hpp"
#include "clearjoint/geometry/model/joint_geometry.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"
#include "clearjoint/validation_error.hpp"
#include "commands.hpp"

namespace clearjoint::app {

// ordered_json keeps the keys in the order they are written, so answers read like the docs; the
// readers below are the shared JSON reader's (clearjoint/json_input/json_reader.hpp), with its messages.
// Its dump() writes every double in the shortest form that reads back to the same double, and
// writes non-finite values as null (JSON has neither NaN nor infinity).
using Json = nlohmann::ordered_json;

/// The version of the JSON Lines formats that every output line states in its first field,
/// "v". The formats are specified by the JSON Schemas in docs/schema/ (installed under
/// share/clearjoint/schema/), whose $id ends in this number; a change that can break a reader
/// of the output (a field removed, renamed or retyped) increases it.
inline constexpr int kFormatVersion = 1;

/// A query line that cannot be answered: a ValidationError whose path names the field in the
/// line ("bearing.center[2]") and whose message the offending value too; an error about the line
/// as a whole (malformed JSON) has an empty path. answer_line formats it, and the library's
/// InvalidInput likewise, as an error line.
class LineError : public ValidationError {
 public:
  using ValidationError::ValidationError;
};

/// Longest query line read (bytes, without its newline). A longer line gets an error line and the
/// lines after it are still answered. Real queries are a few hundred bytes; the limit keeps one
/// hostile line from taking the memory. Nesting and number limits: clearjoint/json_input/bounded_json.hpp.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

/// `value` as JSON text for an error message, shortened when long.
std::string quote(const Json& value);

/// Throws unless `object` is a JSON object whose keys are all in `allowed`: a misspelt key
/// ("normals", "certfy") must not be silently ignored. `path` "" is the whole line.
void check_object(const Json& object, const std::string& path,
                  std::initializer_list<std::string_view> allowed);

/// object[key]; throws "path.key: missing" when absent.
const Json& member(const Json& object, const std::string& path, const char* key);

/// A JSON number as a double. JSON has no NaN or infinity, and the parser rejects numbers that
/// overflow, so every number read here is finite.
double read_number(const Json& value, const std::string& path);

/// An array of exactly 3 numbers.
geometry::Vector3 read_vector(const Json& value, const std::string& path);

// The magnitudes a geometric input of `intersect` (a length, or a coordinate of a point or
// direction) may have, 0 aside: the kernel's accepted range for a joint's lengths and centres
// (joint_geometry.hpp), which `detect` leaves to the kernel's validate(). The kernel's primitive
// queries check finiteness only, so `intersect` applies the range itself. Within it the commands
// were checked end to end on scaled and random inputs (docs/command-line.md, "Limits"); beyond it
// the library's contact points can overflow into NaN or infinite values.
inline constexpr double kSmallestMagnitude = geometry::kSmallestAcceptedLength;
inline constexpr double kLargestMagnitude = geometry::kLargestAcceptedLength;

/// A number that is 0 or of magnitude in [kSmallestMagnitude, kLargestMagnitude].
double read_geometric_number(const Json& value, const std::string& path);

/// An array of exactly 3 such numbers.
geometry::Vector3 read_geometric_vector(const Json& value, const std::string& path);

/// Sets each detection option `object` gives, by the keys of the option list
/// (geometry/option_fields.hpp); refuses other keys.
void read_detection_options(const Json& object, const std::string& path, geometry::DetectionOptions& options);

/// Sets `out` from object[key] when present (which must then be true or false).
void read_optional_bool(const Json& object, const std::string& path, const char* key, bool& out);

/// [x, y, z].
Json to_json(const geometry::Vector3& v);

/// An error bound for output: kNoErrorBound (no bound known) becomes null.
Json error_bound(double error);

/// One JSON Lines command: its name (for messages), its --help text, and how it answers one
/// query. `answer` gets the parsed line (any JSON value) and an answer that already holds the
/// line's "id"; it adds its fields, or throws LineError or geometry::InvalidInput (the line then
/// gets an error line).
struct JsonLinesCommand {
  const char* name;
  const char* usage;
  std::function<void(const Json& query, Json& answer)> answer;
};

/// The two JSON Lines commands (intersect_command.cpp, detect_command.cpp); the fuzz targets in
/// fuzz/ call them without the process around.
const JsonLinesCommand& intersect_command();
const JsonLinesCommand& detect_command();

/// The answer to one non-empty line (the query, or an error line holding only the id and the
/// error); sets `failed` for an error line. Never throws for any input text.
Json answer_line(const JsonLinesCommand& command, const std::string& line, long line_number,
                 bool& failed);

/// `answer` (answer_line's, for `line`) as the text of its output line. A number id is written as
/// the text it had in `line`, character for character (docs/command-line.md: the id is copied
/// unchanged): 1.23e29, -0 and 123000000000000000000000000000 come back so, not as the shortest
/// form of the double they round to. Any other id is written as its JSON value.
std::string answer_text(const Json& answer, std::string_view line);

/// `clearjoint <name> [FILE]`: answers every line of FILE (or standard input, flushed line by
/// line), in order. Returns the exit status: 0 every line answered, 1 some line got an error
/// line, 2 usage error or unreadable FILE.
int run_json_lines(const JsonLinesCommand& command, Arguments args);

}  // namespace clearjoint::app
