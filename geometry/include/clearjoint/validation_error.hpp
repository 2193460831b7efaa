// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The one error type for bad input, whichever check finds it: the kernel's (geometry::
/// InvalidInput), the model reader's and the clearance joint's (dynamics::ModelError), the command
/// line's JSON Lines reader (app::LineError), the C API's own checks. It carries the path of the
/// offending field and a message naming it and its value; each front-end only formats it (C: the
/// message buffer and CJ_INVALID_INPUT; Python: ValueError, with the field spelt as the Python
/// argument; the command line: an error line).

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace clearjoint {

/// Bad input. The message is the field's path followed by what is wrong with it:
///   ValidationError("bodies[1].mass", " = -0.3: must be positive")
/// has what() "bodies[1].mass = -0.3: must be positive", field_path() "bodies[1].mass" and
/// detail() " = -0.3: must be positive". The path is in the caller's terms: members joined by
/// '.', array entries by [k] ("journal.axis_W", "options.parallel_angle_tolerance",
/// "contacts[0].depth"). An error about no one field (text that is not JSON) has an empty path.
///
/// An error found inside a file is named with the file (ValidationError(error, source)): what()
/// is "<source>: " followed by the original message, while field_path() stays the original path,
/// in the terms of the file's content ("bodies[1].mass", not "model.json: bodies[1].mass"), and
/// detail() the original detail: a program matches the field whatever the file is called.
class ValidationError : public std::invalid_argument {
 public:
  /// Out of line (validation_error.cpp), as std::invalid_argument's are: a check's throw stays a
  /// call, which keeps the code around the check on the hot path the same size.
  ValidationError(std::string_view field_path, std::string_view detail);
  /// An error about no one field: what() is `message`, the path is empty.
  explicit ValidationError(const std::string& message);
  /// `error` as found in `source` (a file name): what() is `source` + ": " + error.what();
  /// field_path() and detail() are error's.
  ValidationError(const ValidationError& error, std::string_view source);

  /// The path of the offending field; empty when no one field is at fault.
  std::string_view field_path() const noexcept { return std::string_view(what()).substr(path_offset_, path_length_); }
  /// The message after the path (and after the source, when there is one).
  std::string_view detail() const noexcept { return std::string_view(what()).substr(path_offset_ + path_length_); }

 private:
  std::size_t path_offset_ = 0;  ///< length of the "<source>: " prefix
  std::size_t path_length_ = 0;
};

}  // namespace clearjoint
