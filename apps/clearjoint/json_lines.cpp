// SPDX-License-Identifier: BSD-3-Clause
#include "json_lines.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <istream>
#include <optional>
#include <string_view>

#include "clearjoint/geometry/model/primitives.hpp"
#include "clearjoint/json_input/json_reader.hpp"
#include "clearjoint/json_input/read_detection_options.hpp"
#include "result_json.hpp"

namespace clearjoint::app {
namespace {

namespace geo = clearjoint::geometry;

/// What read_line found.
enum class LineRead { line, too_long, end };

/// The next line of `input` without its '\n' (and '\r' of CRLF files), reading at most
/// kMaxLineBytes of it: a longer line is skipped to its end and reported, so that one huge line
/// can neither exhaust memory nor stop the answers to the lines after it. std::getline has no
/// such bound, hence the loop over the stream buffer.
LineRead read_line(std::streambuf& input, std::string& line) {
  line.clear();
  bool too_long = false;
  for (;;) {
    const int c = input.sbumpc();
    if (c == std::char_traits<char>::eof()) {
      if (line.empty() && !too_long) return LineRead::end;
      break;
    }
    if (c == '\n') break;
    if (too_long) continue;
    if (line.size() == kMaxLineBytes) {
      too_long = true;
      line.clear();
      continue;
    }
    line.push_back(static_cast<char>(c));
  }
  if (too_long) return LineRead::too_long;
  if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
  return LineRead::line;
}

bool is_json_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/// The end of the JSON string that starts at `text[at]` ('"'): one past its closing quote.
std::size_t string_end(std::string_view text, std::size_t at) {
  for (std::size_t k = at + 1; k < text.size(); ++k) {
    if (text[k] == '\\') {
      ++k;  // the escaped character, whatever it is
    } else if (text[k] == '"') {
      return k + 1;
    }
  }
  return std::string_view::npos;
}

/// The end of the JSON value that starts at `text[at]`: a string, an array or object (brackets
/// counted, strings skipped), or a literal or number (up to the next delimiter).
std::size_t value_end(std::string_view text, std::size_t at) {
  if (text[at] == '"') return string_end(text, at);
  if (text[at] == '{' || text[at] == '[') {
    long depth = 0;
    for (std::size_t k = at; k < text.size();) {
      const char c = text[k];
      if (c == '"') {
        k = string_end(text, k);
        if (k == std::string_view::npos) return k;
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      if (c == '}' || c == ']') --depth;
      ++k;
      if (depth == 0) return k;
    }
    return std::string_view::npos;
  }
  std::size_t k = at;
  while (k < text.size() && text[k] != ',' && text[k] != '}' && text[k] != ']' && !is_json_space(text[k])) ++k;
  return k;
}

/// The text of the member "id" of the JSON object `line` (already parsed, so well formed) when it
/// is a number: the digits as the user wrote them. A scan of the top level, not a second parse:
/// nlohmann-json keeps a number's value, not its text (-0 becomes 0, and an integer beyond 64 bits
/// a double). Keys are compared after decoding ("\u0069d" is "id"); a key is unique in a line
/// (the reader refuses one given twice).
std::optional<std::string_view> id_number_text(std::string_view line) {
  std::size_t k = 0;
  const auto skip_space = [&] {
    while (k < line.size() && is_json_space(line[k])) ++k;
  };
  skip_space();
  if (k == line.size() || line[k] != '{') return std::nullopt;
  ++k;
  for (;;) {
    skip_space();
    if (k >= line.size() || line[k] != '"') return std::nullopt;
    const std::size_t key_end = string_end(line, k);
    if (key_end == std::string_view::npos) return std::nullopt;
    const std::string_view key = line.substr(k, key_end - k);
    k = key_end;
    skip_space();
    if (k >= line.size() || line[k] != ':') return std::nullopt;
    ++k;
    skip_space();
    if (k >= line.size()) return std::nullopt;
    const std::size_t start = k;
    k = value_end(line, start);
    if (k == std::string_view::npos) return std::nullopt;
    const bool is_id = key == "\"id\"" || (key.find('\\') != std::string_view::npos &&
                                            Json::parse(key, nullptr, false) == "id");
    if (is_id) {
      const char first = line[start];
      if (first == '-' || (first >= '0' && first <= '9')) return line.substr(start, k - start);
      return std::nullopt;
    }
    skip_space();
    if (k >= line.size() || line[k] != ',') return std::nullopt;
    ++k;
  }
}

}  // namespace

std::string answer_text(const Json& answer, std::string_view line) {
  std::string text = answer.dump(-1, ' ', false, Json::error_handler_t::replace);
  const auto id = answer.find("id");
  if (id == answer.end() || !id->is_number()) return text;
  const std::optional<std::string_view> written = id_number_text(line);
  if (!written) return text;
  // Every answer and error line starts with the format version, then the id (json_lines.hpp).
  const std::string head = "{\"v\":" + std::to_string(kFormatVersion) + ",\"id\":";
  const std::string printed = head + id->dump();
  if (text.compare(0, printed.size(), printed) != 0) return text;
  return head + std::string(*written) + text.substr(printed.size());
}

Json answer_line(const JsonLinesCommand& command, const std::string& line, long line_number,
                 bool& failed) {
  Json answer = Json::object();
  answer["v"] = kFormatVersion;
  answer["id"] = nullptr;
  std::string error;
  try {
    // Malformed text and the limits: ValidationErrors with the reader's messages.
    const Json query = json::parse_input(line, kMaxLineBytes, "one line");
    if (query.is_object()) {
      if (const auto id = query.find("id"); id != query.end()) answer["id"] = *id;
    }
    command.answer(query, answer);
    failed = false;
    return answer;
  } catch (const ValidationError& e) {  // the reader's, LineError, or the library's InvalidInput
    error = e.what();
  } catch (const std::exception& e) {
    // Not the input's fault as far as we can tell: say so, keep answering the other lines.
    error = std::string("internal error: ") + e.what();
  }
  // An error line carries only the id and the message.
  Json error_line = Json::object();
  error_line["v"] = kFormatVersion;
  error_line["id"] = answer["id"];
  error_line["error"] = "line " + std::to_string(line_number) + ": " + error;
  failed = true;
  return error_line;
}

namespace {

/// The message and exit status of a failed write to standard output (a full disk, /dev/full, a
/// closed pipe): answers that cannot be delivered must not end with status 0.
int write_error(const JsonLinesCommand& command, long line_number, int error_number) {
  std::fprintf(stderr, "clearjoint %s: cannot write the answers to standard output after line %ld: %s\n",
               command.name, line_number,
               error_number != 0 ? std::strerror(error_number) : "write error");
  return 2;
}

/// Answers every line of `input`; returns the exit status.
int answer_all(const JsonLinesCommand& command, std::istream& input, const std::string& input_name,
               bool flush_each_line) {
  std::string line;
  long line_number = 0;
  long failures = 0;
  errno = 0;
  for (;;) {
    const LineRead read = read_line(*input.rdbuf(), line);
    if (read == LineRead::end) break;
    ++line_number;
    bool failed = true;
    Json answer;
    if (read == LineRead::too_long) {
      answer = Json::object();
      answer["v"] = kFormatVersion;
      answer["id"] = nullptr;
      answer["error"] = "line " + std::to_string(line_number) + ": longer than " +
                        std::to_string(kMaxLineBytes) + " bytes, the limit for one line";
    } else {
      if (line.find_first_not_of(" \t") == std::string::npos) continue;
      answer = answer_line(command, line, line_number, failed);
    }
    if (failed) ++failures;
    std::cout << answer_text(answer, line) << '\n';
    if (flush_each_line) std::cout.flush();
    if (!std::cout) return write_error(command, line_number, errno);
  }
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    return write_error(command, line_number, errno);
  }
  if (input.bad()) {
    std::fprintf(stderr, "clearjoint %s: error reading %s after line %ld\n", command.name,
                 input_name.c_str(), line_number);
    return 2;
  }
  if (failures > 0) {
    std::fprintf(stderr, "clearjoint %s: %ld line(s) of %s could not be answered\n", command.name,
                 failures, input_name.c_str());
    return 1;
  }
  return 0;
}

int usage_error(const JsonLinesCommand& command, const std::string& message) {
  std::fprintf(stderr, "clearjoint %s: %s\n%s", command.name, message.c_str(), command.usage);
  return 2;
}

}  // namespace

std::string quote(const Json& value) { return json::quote(value); }

void check_object(const Json& object, const std::string& path,
                  std::initializer_list<std::string_view> allowed) {
  json::JsonField(object, path, "the line").require_object(allowed);
}

const Json& member(const Json& object, const std::string& path, const char* key) {
  return json::JsonField(object, path, "the line").member(key).json();
}

double read_number(const Json& value, const std::string& path) {
  return json::JsonField(value, path, "the line").number();
}

geo::Vector3 read_vector(const Json& value, const std::string& path) {
  const std::array<double, 3> v = json::JsonField(value, path, "the line").numbers<3>();
  return {v[0], v[1], v[2]};
}

void read_detection_options(const Json& object, const std::string& path, geo::DetectionOptions& options) {
  json::read_detection_options(json::JsonField(object, path, "the line"), options);
}

double read_geometric_number(const Json& value, const std::string& path) {
  const double x = read_number(value, path);
  const double magnitude = std::fabs(x);
  if (magnitude == 0.0 || (magnitude >= kSmallestMagnitude && magnitude <= kLargestMagnitude)) {
    return x;
  }
  throw LineError(path, " = " + quote(value) +
                  ": magnitude outside [1e-150, 1e150], the range accepted (rescale the input, "
                  "or write 0 for a negligible component)");
}

geo::Vector3 read_geometric_vector(const Json& value, const std::string& path) {
  const geo::Vector3 v = read_vector(value, path);  // checks the shape and the types
  for (std::size_t k = 0; k < 3; ++k) {
    read_geometric_number(value[k], path + "[" + std::to_string(k) + "]");
  }
  return v;
}

void read_optional_bool(const Json& object, const std::string& path, const char* key, bool& out) {
  const json::JsonField fields(object, path, "the line");
  if (fields.has(key)) out = fields.member(key).boolean();
}

void require_finite(double value, const std::string& what) {
  if (std::isfinite(value)) return;
  throw LineError(what, std::string(" is ") + (std::isnan(value) ? "NaN" : "infinite") +
                  ": overflow or underflow in double arithmetic; rescale the input (any unit "
                  "will do, e.g. millimetres instead of metres)");
}

void require_finite(const geo::Vector3& v, const std::string& what) {
  for (int k = 0; k < 3; ++k) require_finite(v[k], what + "[" + std::to_string(k) + "]");
}

Json to_json(const geo::Vector3& v) { return Json::array({v.x(), v.y(), v.z()}); }

Json error_bound(double error) {
  if (!std::isfinite(error)) return nullptr;
  return error;
}

int run_json_lines(const JsonLinesCommand& command, Arguments args) {
  const char* path = nullptr;
  for (const char* arg : args) {
    const std::string_view a(arg);
    if (a == "--help" || a == "-h") {
      std::fputs(command.usage, stdout);
      return 0;
    }
    if (a.size() > 1 && a.front() == '-') {
      return usage_error(command, "unknown option '" + std::string(a) + "'");
    }
    if (path != nullptr) return usage_error(command, "more than one input file");
    path = arg;
  }

  if (path == nullptr || std::string_view(path) == "-") {
    // A directory as standard input (`< /tmp`) reads as an empty file on some systems and fails
    // with EISDIR on others: refuse it either way rather than answer nothing with status 0.
    struct stat input_status {};
    if (::fstat(STDIN_FILENO, &input_status) == 0 && S_ISDIR(input_status.st_mode)) {
      std::fprintf(stderr, "clearjoint %s: cannot read standard input: is a directory\n",
                   command.name);
      return 2;
    }
    // A program at the other end of a pipe waits for each answer: flush line by line.
    return answer_all(command, std::cin, "standard input", /*flush_each_line=*/true);
  }
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    std::fprintf(stderr, "clearjoint %s: cannot read '%s': is a directory\n", command.name, path);
    return 2;
  }
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "clearjoint %s: cannot open '%s': %s\n", command.name, path,
                 std::strerror(errno));
    return 2;
  }
  std::string name = "'";  // built piecewise: "'" + std::string(path) trips GCC 12's -Wrestrict
  name.append(path).append("'");
  return answer_all(command, file, name, /*flush_each_line=*/false);
}

}  // namespace clearjoint::app
