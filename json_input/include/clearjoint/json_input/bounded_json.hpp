// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Parsing untrusted JSON text with limits, for every JSON input of clearjoint (JSON Lines queries,
// model files). nlohmann-json parses without recursion, but copying, comparing and dumping a value
// recurse once per nesting level: a line of 100,000 '[' overflows the stack in the first copy.
// A nesting limit checked while parsing keeps every later step's recursion shallow. nlohmann-json
// also reads a number that underflows (1e-400) as 0 without a word; the SAX handler below sees the
// number's text and refuses it, naming the field. A key given twice in one object (nlohmann keeps
// the last) is refused the same way. Limits are documented in docs/command-line.md
// ("Limits") and docs/dynamics.md.

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include <nlohmann/json.hpp>

#include "clearjoint/validation_error.hpp"

namespace clearjoint::json {

/// Deepest nesting of arrays and objects accepted in any JSON input. The deepest valid input
/// (a model file's solver or force settings) nests 4 levels; 64 leaves room for "comment" values
/// while keeping recursion in copies and dumps a few kilobytes of stack.
inline constexpr int kMaxNestingDepth = 64;

/// Longest JSON value quoted in an error message (bytes); longer ones are cut and end in "...".
inline constexpr std::size_t kMaxQuotedValue = 60;

/// Input that breaks a limit, a number that underflows or a key given twice: a ValidationError
/// whose path names the field (empty for nesting, whose message names the place).
class JsonLimitError : public ValidationError {
 public:
  using ValidationError::ValidationError;
};

/// `text` cut to at most `limit` bytes at a UTF-8 character boundary, with "..." when cut.
inline std::string excerpt(std::string_view text, std::size_t limit = kMaxQuotedValue) {
  if (text.size() <= limit) return std::string(text);
  std::size_t end = limit;
  // Step back over continuation bytes (10xxxxxx) so that no character is split.
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return std::string(text.substr(0, end)) + "...";
}

/// `value` as JSON text for an error message, shortened when long.
template <class BasicJson>
std::string quote(const BasicJson& value) {
  return excerpt(value.dump(-1, ' ', false, BasicJson::error_handler_t::replace));
}

namespace detail {

/// nlohmann's DOM builder, with a nesting limit and an underflow check. It tracks the path of the
/// value being read ("circle.center[2]") so that messages name the field as the readers do.
template <class BasicJson>
class BoundedSaxParser : public nlohmann::detail::json_sax_dom_parser<BasicJson> {
  using Base = nlohmann::detail::json_sax_dom_parser<BasicJson>;

 public:
  using typename Base::number_float_t;
  using typename Base::string_t;

  explicit BoundedSaxParser(BasicJson& root) : Base(root, /*allow_exceptions=*/true) {}

  bool null() { return value() && Base::null(); }
  bool boolean(bool v) { return value() && Base::boolean(v); }
  bool number_integer(typename Base::number_integer_t v) {
    return value() && Base::number_integer(v);
  }
  bool number_unsigned(typename Base::number_unsigned_t v) {
    return value() && Base::number_unsigned(v);
  }
  bool number_float(number_float_t v, const string_t& text) {
    if (!value()) return false;
    // strtod gives 0 for a literal below the smallest (subnormal) double: the digits said
    // something else. Refuse rather than read 1e-400 as 0. Subnormal values are kept: they are
    // doubles, and read back as written.
    if (v == 0.0 && has_nonzero_digit(text)) {
      throw JsonLimitError(excerpt(path(), 200), " = " + excerpt(text) +
                           ": underflows to 0 (its magnitude is below 4.9e-324, the smallest "
                           "double); write 0 or rescale");
    }
    return Base::number_float(v, text);
  }
  bool string(string_t& v) { return value() && Base::string(v); }
  bool start_object(std::size_t n) { return open(false) && Base::start_object(n); }
  bool start_array(std::size_t n) { return open(true) && Base::start_array(n); }
  bool key(string_t& k) {
    frames_.back().key = k;
    // nlohmann keeps the last of two equal keys and drops the first without a word ("gravity"
    // given twice made a ball float): one of them is a mistake, and which one is for the user.
    if (!frames_.back().keys.insert(k).second) {
      throw JsonLimitError(excerpt(path(), 200), ": key given twice in one object (each key may appear once)");
    }
    return Base::key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return Base::end_object();
  }
  bool end_array() {
    frames_.pop_back();
    return Base::end_array();
  }

 private:
  struct Frame {
    bool array = false;
    long index = -1;  // of the current element, arrays only
    std::string key;  // of the current member, objects only
    std::unordered_set<std::string> keys;  // every member key so far, objects only
  };

  static bool has_nonzero_digit(const string_t& text) {
    for (char c : text) {
      if (c == 'e' || c == 'E') return false;
      if (c >= '1' && c <= '9') return true;
    }
    return false;
  }

  /// Called before every value: moves the enclosing array to its next index.
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }

  bool open(bool array) {
    value();
    if (static_cast<int>(frames_.size()) >= kMaxNestingDepth) {
      const std::string where = frames_.empty() ? std::string("the input") : path();
      throw JsonLimitError("nesting deeper than " + std::to_string(kMaxNestingDepth) +
                           " levels of arrays and objects (the limit) at " + excerpt(where, 200));
    }
    frames_.push_back({array, -1, {}, {}});
    return true;
  }

  std::string path() const {
    std::string text;
    for (const Frame& f : frames_) {
      // Appended piece by piece: "[" + std::string trips GCC 12's -Wrestrict (a false alarm).
      if (f.array) {
        text += '[';
        text += std::to_string(f.index);
        text += ']';
      } else if (!f.key.empty() || !text.empty()) {
        if (!text.empty()) text += '.';
        text += excerpt(f.key, 40);
      }
    }
    return text.empty() ? "the value" : text;
  }

  std::vector<Frame> frames_;
};

}  // namespace detail

/// Parses `text` as one JSON value with the limits above. Throws BasicJson::parse_error for
/// malformed text (nlohmann's message) and JsonLimitError for a limit or an underflow.
/// json_reader.hpp's parse_input adds a size limit and makes every error a ValidationError.
template <class BasicJson>
BasicJson parse_bounded(std::string_view text) {
  BasicJson result;
  detail::BoundedSaxParser<BasicJson> handler(result);
  BasicJson::sax_parse(text.begin(), text.end(), &handler);
  return result;
}

}  // namespace clearjoint::json
