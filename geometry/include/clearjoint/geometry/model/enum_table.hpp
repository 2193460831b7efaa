// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// One table per public enum: each value's stable code, its name, its key and a label for people.
/// Every front-end (the command line's JSON, the C API's strings and codes, Python's IntEnum
/// classes, the docs) takes its spellings from these tables, so that a value is written down once.
///
/// A table is a specialisation of EnumTable<E> in this namespace (for an enum of another module
/// too), written right after its enum:
///   template <> struct EnumTable<ContactType> {
///     static constexpr std::string_view type_name = "ContactType";
///     static constexpr auto entries = std::to_array({named_entry(ContactType::radial, ...), ...});
///   };
/// listing every value in code order from 0 (entries_in_code_order() checks it). A value added
/// to an enum gets its row here; tests/bindings/c/test_c_descriptions.cpp then fails until each
/// front-end that lists codes by hand (clearjoint.h, the Fortran module) has it too.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace clearjoint::geometry {

/// One value of a public enum. The code is the value's integer (static_cast<int>(value)): the C
/// API's enum constants and the int8 codes of Python's array results are these, and they never
/// change once released (a new value takes the next code).
template <class E>
struct EnumEntry {
  E value;
  /// The C++ enumerator's name: Python's IntEnum member, and, upper-cased, the suffix of the C
  /// constant (CJ_SCENARIO_SINGLE_RADIAL).
  std::string_view name;
  /// What text outputs write for the value (the command line's JSON, C's cj_*_string): stable,
  /// machine-readable. Equal to `name` except where a shorter established spelling exists (the
  /// scenarios' letters of the paper's Fig. 2).
  std::string_view key;
  /// A phrase for people: docstrings, reports, messages.
  std::string_view label;
};

/// An entry whose key is its name (most of them).
template <class E>
constexpr EnumEntry<E> named_entry(E value, std::string_view name, std::string_view label) noexcept {
  return {value, name, name, label};
}

/// Specialised after each public enum (see the file comment).
template <class E>
struct EnumTable;

template <class E>
concept TabledEnum = requires {
  EnumTable<E>::type_name;
  EnumTable<E>::entries;
};

/// How many values E has.
template <TabledEnum E>
constexpr int enum_count() noexcept {
  return static_cast<int>(EnumTable<E>::entries.size());
}

/// Whether the table lists its values in code order from 0, with no gap: the lookups below index
/// the table by code.
template <TabledEnum E>
constexpr bool entries_in_code_order() noexcept {
  int code = 0;
  for (const EnumEntry<E>& entry : EnumTable<E>::entries) {
    if (static_cast<int>(entry.value) != code++) return false;
  }
  return true;
}

/// The entry of a code, or nullptr for a code E does not have.
template <TabledEnum E>
constexpr const EnumEntry<E>* entry_of_code(int code) noexcept {
  if (code < 0 || code >= enum_count<E>()) return nullptr;
  return &EnumTable<E>::entries[static_cast<std::size_t>(code)];
}

template <TabledEnum E>
constexpr const EnumEntry<E>* entry_of(E value) noexcept {
  return entry_of_code<E>(static_cast<int>(value));
}

/// The value's key, or "unknown" for a value outside the table (a cast from a bad integer).
template <TabledEnum E>
constexpr std::string_view key_of(E value) noexcept {
  const EnumEntry<E>* entry = entry_of(value);
  return entry != nullptr ? entry->key : std::string_view("unknown");
}

/// The value's label, or "unknown".
template <TabledEnum E>
constexpr std::string_view label_of(E value) noexcept {
  const EnumEntry<E>* entry = entry_of(value);
  return entry != nullptr ? entry->label : std::string_view("unknown");
}

/// The value whose key is `key`, if any (the inverse of key_of).
template <TabledEnum E>
constexpr std::optional<E> from_string(std::string_view key) noexcept {
  for (const EnumEntry<E>& entry : EnumTable<E>::entries) {
    if (entry.key == key) return entry.value;
  }
  return std::nullopt;
}

/// Every key of E in code order, joined by ", ": what an error message lists as the known values.
template <TabledEnum E>
std::string known_keys() {
  std::string text;
  for (const EnumEntry<E>& entry : EnumTable<E>::entries) {
    if (!text.empty()) text += ", ";
    text += entry.key;
  }
  return text;
}

}  // namespace clearjoint::geometry
