// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A check for the writers of results that are not written through visit_fields (the C API's
/// structs, the equivalence writers, the answer dumps): change one field of a result at a time,
/// and require the writer's output to change. A field added to a result (and so to its field
/// list, which the compiler requires) that a writer leaves out fails that writer's test, naming
/// the field.

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "clearjoint/geometry/joint/result_fields.hpp"

namespace clearjoint::geometry {

namespace detail {

/// Visits the leaves of a result in order and changes the one numbered `target`, recording its
/// path ("contacts[0].crossings[1].angle"). A leaf is a number, a flag, an enum, a vector
/// component, a list's count or an optional value's flag; lists and optional values are entered.
class FieldChanger {
 public:
  FieldChanger(int target, int& counter, std::string& changed_path, std::string prefix)
      : target_(target), counter_(counter), changed_path_(changed_path), prefix_(std::move(prefix)) {}

  void operator()(std::string_view key, double& x) {
    if (hit(key)) x = std::isfinite(x) && x != 0.0 ? 2.0 * x : 1.0;
  }
  void operator()(std::string_view key, ErrorBound<double> bound) { (*this)(key, bound.value); }
  void operator()(std::string_view key, int& n) {
    if (hit(key)) n += 1;
  }
  void operator()(std::string_view key, bool& b) {
    if (hit(key)) b = !b;
  }
  void operator()(std::string_view key, Vector3& v) {
    for (int k = 0; k < 3; ++k) (*this)(std::string(key) + "[" + std::to_string(k) + "]", v[k]);
  }
  void operator()(std::string_view key, PlaneSide& side) {
    if (hit(key)) side = side == PlaneSide::positive ? PlaneSide::negative : PlaneSide(static_cast<int>(side) + 1);
  }
  template <TabledEnum E>
  void operator()(std::string_view key, E& value) {
    if (hit(key)) value = static_cast<E>((static_cast<int>(value) + 1) % enum_count<E>());
  }
  template <DescribedResult Nested>
  void operator()(std::string_view key, Nested& nested) {
    visit_fields(nested, FieldChanger(target_, counter_, changed_path_, path(key) + "."));
  }
  template <class Array>
  void operator()(std::string_view key, FieldList<Array, int> list) {
    const int count = list.count;  // the entries of the result as given are entered
    if (hit(std::string(key) + ".count")) {
      list.count = count == static_cast<int>(list.items.size()) ? count - 1 : count + 1;
    }
    for (int k = 0; k < count; ++k) {
      (*this)(std::string(key) + "[" + std::to_string(k) + "]", list.items[static_cast<std::size_t>(k)]);
    }
  }
  template <class Value>
  void operator()(std::string_view key, OptionalField<Value, bool> optional) {
    const bool present = optional.present;
    if (hit(std::string(key) + ".present")) optional.present = !present;
    if (present) (*this)(key, optional.value);
  }

 private:
  std::string path(std::string_view key) const { return prefix_ + std::string(key); }
  bool hit(std::string_view key) {
    if (counter_++ != target_) return false;
    changed_path_ = path(key);
    return true;
  }

  int target_;
  int& counter_;
  std::string& changed_path_;
  std::string prefix_;
};

/// Sets every leaf to a value of its own, away from the defaults: lists to one entry in use,
/// optional values present, enums to code 1, numbers to 0.5, 0.75, 1, ... in visiting order.
class FieldFiller {
 public:
  explicit FieldFiller(int& counter) : counter_(counter) {}

  void operator()(std::string_view, double& x) { x = 0.5 + 0.25 * counter_++; }
  void operator()(std::string_view key, ErrorBound<double> bound) { (*this)(key, bound.value); }
  void operator()(std::string_view, int& n) { n = 1 + counter_++ % 2; }
  void operator()(std::string_view, bool& b) { b = true; }
  void operator()(std::string_view key, Vector3& v) {
    for (int k = 0; k < 3; ++k) (*this)(key, v[k]);
  }
  void operator()(std::string_view, PlaneSide& side) { side = PlaneSide::negative; }
  template <TabledEnum E>
  void operator()(std::string_view, E& value) {
    value = static_cast<E>(1 % enum_count<E>());
  }
  template <DescribedResult Nested>
  void operator()(std::string_view, Nested& nested) {
    visit_fields(nested, FieldFiller(counter_));
  }
  template <class Array>
  void operator()(std::string_view key, FieldList<Array, int> list) {
    list.count = 1;
    (*this)(key, list.items[0]);
  }
  template <class Value>
  void operator()(std::string_view key, OptionalField<Value, bool> optional) {
    optional.present = true;
    (*this)(key, optional.value);
  }

 private:
  int& counter_;
};

}  // namespace detail

/// A result whose every field is set away from its default (detail::FieldFiller), for
/// for_each_field_change.
template <DescribedResult Result>
Result result_with_every_field_set() {
  Result result{};
  int counter = 0;
  visit_fields(result, detail::FieldFiller(counter));
  return result;
}

/// Calls check(path, changed) once for every leaf of `base` (see FieldChanger), where `changed`
/// is `base` with that one leaf changed and `path` names it. Give `base` lists with entries in
/// use and optional values present, so that their fields are reached too.
template <DescribedResult Result, class Check>
void for_each_field_change(const Result& base, Check&& check) {
  for (int target = 0;; ++target) {
    Result changed = base;
    int counter = 0;
    std::string path;
    visit_fields(changed, detail::FieldChanger(target, counter, path, ""));
    if (path.empty()) return;  // every leaf has been changed once
    check(std::string_view(path), static_cast<const Result&>(changed));
  }
}

}  // namespace clearjoint::geometry
