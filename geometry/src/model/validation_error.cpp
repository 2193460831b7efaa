// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/validation_error.hpp"

namespace clearjoint {

ValidationError::ValidationError(std::string_view field_path, std::string_view detail)
    : std::invalid_argument(std::string(field_path).append(detail)), path_length_(field_path.size()) {}

ValidationError::ValidationError(const std::string& message) : std::invalid_argument(message) {}

ValidationError::ValidationError(const ValidationError& error, std::string_view source)
    : std::invalid_argument(std::string(source).append(": ").append(error.what())),
      path_offset_(source.size() + 2 + error.path_offset_),
      path_length_(error.path_length_) {}

}  // namespace clearjoint
