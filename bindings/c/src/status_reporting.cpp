// SPDX-License-Identifier: BSD-3-Clause
#include "status_reporting.hpp"

#include <algorithm>
#include <cstring>
#include <string>

namespace clearjoint::c_api {

void write_message(char* message, std::size_t capacity, std::string_view text) noexcept {
  if (message == nullptr || capacity == 0) return;
  const std::size_t length = std::min(text.size(), capacity - 1);
  std::memcpy(message, text.data(), length);
  message[length] = '\0';
}

void reject_null(const char* name, const char* must_point_to) {
  throw ValidationError(name, std::string(" = NULL: must point to ") + must_point_to);
}

}  // namespace clearjoint::c_api
