// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How the C API turns C++ failures into a status and a message in the caller's buffer: every
/// entry point runs its body through `reporting_failures`, so that no exception crosses into C.

#include <cstddef>
#include <new>
#include <string_view>

#include "clearjoint/clearjoint.h"
#include "clearjoint/validation_error.hpp"

namespace clearjoint::c_api {

/// Copy `text` into the caller's buffer, truncated to capacity - 1 bytes and NUL-terminated.
/// Nothing is written when the buffer is NULL or its capacity 0.
void write_message(char* message, std::size_t capacity, std::string_view text) noexcept;

/// Run `body` (which returns nothing or throws) and map what it throws to a status:
/// ValidationError (the kernel's InvalidInput, or this layer's own checks) -> CJ_INVALID_INPUT,
/// bad_alloc -> CJ_OUT_OF_MEMORY, anything else -> CJ_INTERNAL_ERROR. The message buffer gets
/// the exception's text, or "" on success.
template <class Body>
cj_status reporting_failures(char* message, std::size_t capacity, Body&& body) noexcept {
  try {
    body();
    if (capacity > 0 && message != nullptr) message[0] = '\0';
    return CJ_OK;
  } catch (const ValidationError& e) {
    write_message(message, capacity, e.what());
    return CJ_INVALID_INPUT;
  } catch (const std::bad_alloc&) {
    write_message(message, capacity, "out of memory in the exact arithmetic fallback");
    return CJ_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    write_message(message, capacity, e.what());
    return CJ_INTERNAL_ERROR;
  } catch (...) {
    write_message(message, capacity, "unknown exception");
    return CJ_INTERNAL_ERROR;
  }
}

/// Throws ValidationError(name, " = NULL: must point to <must_point_to>"); out of line, so that
/// the checks on the path of every call stay a compare and a branch.
[[noreturn]] void reject_null(const char* name, const char* must_point_to);

/// reject_null(name, must_point_to) when `pointer` is NULL.
inline void require_not_null(const void* pointer, const char* name, const char* must_point_to) {
  if (pointer == nullptr) [[unlikely]] reject_null(name, must_point_to);
}

}  // namespace clearjoint::c_api
