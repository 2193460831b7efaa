// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// How the C API turns C++ failures into a status and a message in the caller's buffer: every
/// entry point runs its body through `reporting_failures`, so that no exception crosses into C.

#include <cstddef>
#include <new>
#include <string_view>

#include "clearjoint/clearjoint.h"
#include "clearjoint/geometry/primitives.hpp"

namespace clearjoint::c_api {

/// Copy `text` into the caller's buffer, truncated to capacity - 1 bytes and NUL-terminated.
/// Nothing is written when the buffer is NULL or its capacity 0.
void write_message(char* message, std::size_t capacity, std::string_view text) noexcept;

/// An input the C layer itself rejects (a NULL pointer, a nonzero reserved field), with the
/// message that names it; reported as CJ_INVALID_INPUT like the kernel's InvalidInput.
struct RejectedInput {
  const char* text;
};

/// Run `body` (which returns nothing or throws) and map what it throws to a status:
/// InvalidInput -> CJ_INVALID_INPUT, bad_alloc -> CJ_OUT_OF_MEMORY, anything else ->
/// CJ_INTERNAL_ERROR. The message buffer gets the exception's text, or "" on success.
template <class Body>
cj_status reporting_failures(char* message, std::size_t capacity, Body&& body) noexcept {
  try {
    body();
    if (capacity > 0 && message != nullptr) message[0] = '\0';
    return CJ_OK;
  } catch (const geometry::InvalidInput& e) {
    write_message(message, capacity, e.what());
    return CJ_INVALID_INPUT;
  } catch (const RejectedInput& e) {
    write_message(message, capacity, e.text);
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

/// Throw RejectedInput("<name> = NULL: ...") when `pointer` is NULL.
inline void require_not_null(const void* pointer, const char* message_when_null) {
  if (pointer == nullptr) throw RejectedInput{message_when_null};
}

}  // namespace clearjoint::c_api
