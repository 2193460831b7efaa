// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The detection options as a JSON object, for every JSON input that has them (the command line's
// "options" of `detect`, a model file's "detection" of a clearance joint): one key per entry of
// the option list (clearjoint/geometry/model/option_fields.hpp), so that an option added to the
// library is read by both at once.

#include <initializer_list>
#include <string_view>
#include <type_traits>
#include <vector>

#include "clearjoint/geometry/model/option_fields.hpp"
#include "clearjoint/json_input/json_reader.hpp"

namespace clearjoint::json {

/// Sets each option whose key `object` has; absent options keep their value in `options`. Flags
/// must be true or false, numbers numbers; ranges are the detection's to check. Keys other than
/// the options' (and `allowed_anywhere`) are refused, naming the key and listing the options.
inline void read_detection_options(const JsonField& object, geometry::DetectionOptions& options,
                                   std::initializer_list<std::string_view> allowed_anywhere = {}) {
  std::vector<std::string_view> keys;
  geometry::visit_options(options, [&keys](std::string_view key, const auto&) { keys.push_back(key); });
  object.require_object(keys, allowed_anywhere);
  geometry::visit_options(options, [&object](std::string_view key, auto& value) {
    if (!object.has(key)) return;
    const JsonField entry = object.member(key);
    using Option = std::remove_reference_t<decltype(value)>;
    if constexpr (std::is_same_v<Option, bool>) {
      value = entry.boolean();
    } else {
      static_assert(std::is_same_v<Option, double>, "an option of a type JSON input cannot read yet");
      value = entry.number();
    }
  });
}

}  // namespace clearjoint::json
