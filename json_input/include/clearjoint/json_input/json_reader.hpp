// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one reader of JSON input in clearjoint: the command line's JSON Lines queries and the model
// files. It parses with limits (size, nesting, numbers, duplicate keys: bounded_json.hpp) and
// reads values by their path, so that every refusal is a clearjoint::ValidationError whose path
// names the field ("joints[2].axis_i[1]") and whose message quotes the offending value:
//   <path>: missing
//   <path>: unknown field (expected a, b, c)
//   <path> = <value>: must be a JSON object | an array | an array of 3 numbers | a number |
//                     a string | true or false
// Each front-end only prefixes where the text came from ("line 4: ", "m.json: ").

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "clearjoint/validation_error.hpp"
#include "clearjoint/json_input/bounded_json.hpp"

namespace clearjoint::json {

/// Keys kept in the order they are written: messages name the first offending key of the text.
using Json = nlohmann::ordered_json;

/// nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 52: ..." without
/// the tag, which says nothing to a user; for text of one line (a JSON Lines query, whose line
/// number the caller writes) "at line 1, column 52" is "at column 52".
inline std::string parse_error_message(std::string_view what, bool one_line) {
  std::string text(what);
  if (text.starts_with('[')) {
    const auto end = text.find("] ");
    if (end != std::string::npos) text.erase(0, end + 2);
  }
  constexpr std::string_view kParserLine = "at line 1, column ";
  if (const auto at = text.find(kParserLine); one_line && at != std::string::npos) {
    text.replace(at, kParserLine.size(), "at column ");
  }
  return text;
}

/// `text` as one JSON value. Throws ValidationError: with an empty path for text longer than
/// `max_bytes` ("<n> bytes, more than <max>, the limit for <what>") and for malformed text or a
/// number that overflows ("malformed JSON: ..."); naming the field for a number that underflows
/// and a key given twice, and the place for nesting deeper than kMaxNestingDepth.
inline Json parse_input(std::string_view text, std::size_t max_bytes, std::string_view what) {
  if (text.size() > max_bytes) {
    throw ValidationError(std::to_string(text.size()) + " bytes, more than " + std::to_string(max_bytes) +
                          ", the limit for " + std::string(what));
  }
  try {
    return parse_bounded<Json>(text);
  } catch (const Json::exception& e) {
    // parse_error for malformed text, out_of_range for a number that overflows (1e400).
    throw ValidationError("malformed JSON: " +
                          parse_error_message(e.what(), text.find('\n') == std::string_view::npos));
  }
}

/// A JSON value with its path in the input, for messages like "bodies[1].mass = -1: ...".
/// The value is referenced, not copied: it must outlive the reader.
class JsonField {
 public:
  /// `path` "" is the whole input, which messages call `whole` ("the line", "the model").
  JsonField(const Json& value, std::string path, std::string_view whole = "the input")
      : value_(&value), path_(std::move(path)), whole_(whole) {}

  const Json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  /// "circle" and "radius" give "circle.radius"; the whole input's members have no prefix.
  std::string member_path(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  /// "center" and 2 give "center[2]".
  std::string entry_path(std::size_t k) const { return path_ + "[" + std::to_string(k) + "]"; }

  /// Throws ValidationError "<path> = <value>: <what_is_wrong>".
  [[noreturn]] void refuse(std::string_view what_is_wrong) const {
    if (path_.empty()) {
      throw ValidationError(std::string(whole_) + " " + quote(*value_) + ": " + std::string(what_is_wrong));
    }
    throw ValidationError(path_, " = " + quote(*value_) + ": " + std::string(what_is_wrong));
  }

  /// Throws unless the value is an object whose keys are all in `allowed` or in
  /// `allowed_anywhere` (a misspelt key must not be silently ignored); the message lists
  /// `allowed`.
  void require_object(std::initializer_list<std::string_view> allowed,
                      std::initializer_list<std::string_view> allowed_anywhere = {}) const {
    require_object(std::vector<std::string_view>(allowed), allowed_anywhere);
  }
  void require_object(const std::vector<std::string_view>& allowed,
                      std::initializer_list<std::string_view> allowed_anywhere = {}) const {
    if (!value_->is_object()) {
      if (path_.empty()) {
        throw ValidationError(std::string(whole_) + " " + quote(*value_) + " is not a JSON object");
      }
      refuse("must be a JSON object");
    }
    for (const auto& item : value_->items()) {
      bool known = false;
      for (std::string_view key : allowed) known = known || item.key() == key;
      for (std::string_view key : allowed_anywhere) known = known || item.key() == key;
      if (known) continue;
      std::string list;
      for (std::string_view key : allowed) list += (list.empty() ? "" : ", ") + std::string(key);
      throw ValidationError(member_path(excerpt(item.key(), 40)), ": unknown field (expected " + list + ")");
    }
  }

  /// Whether the value (an object) has `key`.
  bool has(std::string_view key) const { return value_->is_object() && value_->contains(key); }

  /// The member `key`; throws "<path>.<key>: missing".
  JsonField member(std::string_view key) const {
    const auto found = value_->is_object() ? value_->find(key) : value_->end();
    if (!value_->is_object() || found == value_->end()) {
      throw ValidationError(member_path(key), ": missing");
    }
    return {*found, member_path(key), whole_};
  }

  /// The entries of an array.
  std::vector<JsonField> items() const {
    if (!value_->is_array()) refuse("must be an array");
    std::vector<JsonField> entries;
    entries.reserve(value_->size());
    for (std::size_t k = 0; k < value_->size(); ++k) entries.emplace_back((*value_)[k], entry_path(k), whole_);
    return entries;
  }

  /// A JSON number as a double. The parser refuses numbers that overflow or underflow, and JSON
  /// has no NaN or infinity: every number read is finite.
  double number() const {
    if (!value_->is_number()) refuse("must be a number");
    return value_->get<double>();
  }
  bool boolean() const {
    if (!value_->is_boolean()) refuse("must be true or false");
    return value_->get<bool>();
  }
  std::string text() const {
    if (!value_->is_string()) refuse("must be a string");
    return value_->get<std::string>();
  }
  /// An array of exactly N numbers.
  template <std::size_t N>
  std::array<double, N> numbers() const {
    if (!value_->is_array() || value_->size() != N) {
      refuse("must be an array of " + std::to_string(N) + " numbers");
    }
    std::array<double, N> out{};
    for (std::size_t k = 0; k < N; ++k) out[k] = JsonField((*value_)[k], entry_path(k), whole_).number();
    return out;
  }

 private:
  const Json* value_;
  std::string path_;
  std::string_view whole_;
};

}  // namespace clearjoint::json
