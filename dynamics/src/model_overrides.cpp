// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/model_overrides.hpp"

#include <cctype>
#include <charconv>
#include <optional>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/json_input/json_reader.hpp"

namespace clearjoint::dynamics {

namespace {

using json::Json;

/// One step of a path. A dotted path says whether a step is a key or an element ([k]); a JSON
/// pointer does not ("/bodies/1" is element 1 of an array, "/a/1" member "1" of an object), so
/// its steps are resolved against the value they are applied to.
struct Step {
  enum class Kind { key, element, either };
  std::string text;
  Kind kind;
};

class OverrideError {
 public:
  explicit OverrideError(const ModelOverride& o) : origin_(o.origin.empty() ? o.path : o.origin) {}
  [[noreturn]] void operator()(const std::string& what) const { throw ModelError(origin_ + ": " + what); }
  const std::string& origin() const { return origin_; }

 private:
  std::string origin_;
};

/// RFC 6901: "~1" is '/', "~0" is '~'; any other '~' is malformed.
std::string unescape_pointer_step(std::string_view text, const OverrideError& fail) {
  std::string out;
  for (size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '~') {
      out += text[k];
      continue;
    }
    if (k + 1 < text.size() && (text[k + 1] == '0' || text[k + 1] == '1')) {
      out += text[++k] == '0' ? '~' : '/';
    } else {
      fail("a JSON pointer writes '~' as ~0 and '/' as ~1");
    }
  }
  return out;
}

std::vector<Step> parse_path(std::string_view path, const OverrideError& fail) {
  std::vector<Step> steps;
  if (path.starts_with('/')) {
    size_t begin = 1;
    while (true) {
      const size_t end = path.find('/', begin);
      const std::string_view text = path.substr(begin, end == std::string_view::npos ? path.npos : end - begin);
      steps.push_back({unescape_pointer_step(text, fail), Step::Kind::either});
      if (end == std::string_view::npos) break;
      begin = end + 1;
    }
    return steps;
  }
  if (path.empty()) fail("the path is empty");
  size_t k = 0;
  while (k < path.size()) {
    const size_t key_end = path.find_first_of(".[]", k);
    const std::string_view key = path.substr(k, key_end == std::string_view::npos ? path.npos : key_end - k);
    if (key.empty()) {
      fail("malformed path: an empty key at character " + std::to_string(k + 1) +
           " (write keys separated by '.' and array elements as [k], e.g. bodies[1].mass)");
    }
    steps.push_back({std::string(key), Step::Kind::key});
    k = key_end == std::string_view::npos ? path.size() : key_end;
    while (k < path.size() && path[k] == '[') {
      const size_t close = path.find(']', k);
      if (close == std::string_view::npos) fail("malformed path: '[' without ']'");
      steps.push_back({std::string(path.substr(k + 1, close - k - 1)), Step::Kind::element});
      k = close + 1;
    }
    if (k < path.size()) {
      if (path[k] != '.') {
        fail("malformed path: '" + std::string(1, path[k]) + "' at character " + std::to_string(k + 1) +
             " (write keys separated by '.' and array elements as [k], e.g. bodies[1].mass)");
      }
      if (++k == path.size()) fail("malformed path: it ends with '.'");
    }
  }
  return steps;
}

/// A step's text as an array index: digits only, no leading zero (RFC 6901), within the array.
std::optional<size_t> index_of(const std::string& text) {
  if (text.empty() || (text.size() > 1 && text[0] == '0')) return std::nullopt;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  }
  size_t index = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return index;
}

std::string members_of(const Json& object) {
  std::string list;
  for (const auto& item : object.items()) list += (list.empty() ? "" : ", ") + json::excerpt(item.key(), 40);
  return list.empty() ? "none" : list;
}

const char* kind_of(const Json& value) {
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_boolean()) return "true or false";
  return "null";
}

/// Writes `value` at `steps` in `document`; returns the field's name as messages give it
/// ("bodies[1].mass"), the name two overrides are compared by.
std::string write_value(Json& document, const std::vector<Step>& steps, Json value, const OverrideError& fail) {
  Json* node = &document;
  std::string field;
  const auto name = [&field] { return field.empty() ? std::string("the model") : field; };
  for (size_t s = 0; s < steps.size(); ++s) {
    const Step& step = steps[s];
    const bool last = s + 1 == steps.size();
    if (node->is_array()) {
      if (step.kind == Step::Kind::key) {
        const std::string advice = index_of(step.text) ? field + "[" + step.text + "]" : field + "[k]";
        fail(name() + " is an array: write its elements as " + advice);
      }
      const std::optional<size_t> index = index_of(step.text);
      if (!index) fail("[" + json::excerpt(step.text, 40) + "]: an array element is a whole number, from 0");
      if (*index >= node->size()) {
        fail(node->empty() ? name() + " has no elements: there is no [" + step.text + "]"
                     : node->size() == 1 ? name() + " has 1 element, [0]: there is no [" + step.text + "]"
                                         : name() + " has " + std::to_string(node->size()) + " elements, [0] to [" +
                                               std::to_string(node->size() - 1) + "]: there is no [" + step.text + "]");
      }
      field += "[" + step.text + "]";
      node = &(*node)[*index];
    } else if (node->is_object()) {
      if (step.kind == Step::Kind::element) {
        fail(name() + " is an object, not an array: [" + json::excerpt(step.text, 40) +
             "] names no member (members: " + members_of(*node) + ")");
      }
      const std::string parent = name();
      field += (field.empty() ? "" : ".") + step.text;
      if (!node->contains(step.text) && !last) {
        // A missing object on the way is created (the model reader then checks its keys); a
        // missing array cannot be, since its elements would not exist.
        if (steps[s + 1].kind == Step::Kind::element) {
          fail(parent + " has no member " + json::excerpt(step.text, 40) + " (members: " + members_of(*node) + ")");
        }
        (*node)[step.text] = Json::object();
      }
      node = &(*node)[step.text];
    } else {
      fail(name() + " is " + kind_of(*node) + ", which has no member or element " + json::excerpt(step.text, 40));
    }
  }
  *node = std::move(value);
  return field;
}

/// Whether `inner` is `outer` or a field inside it ("solver.end_time" is inside "solver").
bool within(const std::string& inner, const std::string& outer) {
  return inner.starts_with(outer) &&
         (inner.size() == outer.size() || inner[outer.size()] == '.' || inner[outer.size()] == '[');
}

Json parse_value(const ModelOverride& o, const OverrideError& fail) {
  try {
    return json::parse_input(o.value, kMaxModelFileBytes, "a value");
  } catch (const ValidationError& e) {
    fail(std::string("the value: ") + e.what());
  }
}

}  // namespace

ModelOverride parse_override_assignment(std::string_view assignment, std::string_view origin) {
  const std::string origin_text(origin);
  const size_t equals = assignment.find('=');
  if (equals == std::string_view::npos) {
    throw ModelError(origin_text + ": must be PATH=VALUE, e.g. solver.end_time=0.01");
  }
  ModelOverride o{std::string(assignment.substr(0, equals)), std::string(assignment.substr(equals + 1)),
                  origin_text};
  if (o.path.empty()) throw ModelError(origin_text + ": no PATH before '=' (PATH=VALUE, e.g. solver.end_time=0.01)");
  if (o.value.empty()) throw ModelError(origin_text + ": no VALUE after '=' (PATH=VALUE, e.g. solver.end_time=0.01)");
  try {
    (void)json::parse_bounded<Json>(o.value);
  } catch (const std::exception& e) {
    if (!std::isalpha(static_cast<unsigned char>(o.value[0]))) {
      throw ModelError(origin_text + ": the VALUE is not JSON (" +
                       json::parse_error_message(e.what(), true) +
                       "); write a number, true, false, [...], {...} or a string (quoted, or a word "
                       "that begins with a letter)");
    }
    // A bare word is a string: model=hertz rather than model='"hertz"' in a shell.
    o.value = Json(o.value).dump();
  }
  return o;
}

std::string apply_overrides(std::string_view model_text, std::string_view source, const ModelOverrides& overrides) {
  Json document;
  try {
    document = json::parse_input(model_text, kMaxModelFileBytes, "a model file");
  } catch (const ValidationError& e) {
    throw ModelError(e, source);
  }
  std::vector<std::pair<std::string, std::string>> written;  // (field, origin) of each override
  for (const ModelOverride& o : overrides) {
    const OverrideError fail(o);
    const std::vector<Step> steps = parse_path(o.path, fail);
    const std::string field = write_value(document, steps, parse_value(o, fail), fail);
    for (const auto& [other, other_origin] : written) {
      if (field == other) fail("sets " + field + ", which " + other_origin + " sets too");
      if (within(field, other) || within(other, field)) {
        fail("sets " + field + ", which overlaps " + other + " set by " + other_origin);
      }
    }
    written.emplace_back(field, fail.origin());
  }
  return document.dump(1) + "\n";
}

std::string overrides_json(const ModelOverrides& overrides) {
  Json object = Json::object();
  for (const ModelOverride& o : overrides) object[o.path] = parse_value(o, OverrideError(o));
  return object.dump();
}

}  // namespace clearjoint::dynamics
