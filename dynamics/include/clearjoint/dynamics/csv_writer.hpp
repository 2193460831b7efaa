// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A CSV file written atomically: rows go to a temporary file in the same directory, which
/// commit() renames over the destination, so readers never see a half-written result.

#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace clearjoint::dynamics {

class CsvWriter {
 public:
  /// Create the temporary file and write the header. Throws std::runtime_error naming the path.
  CsvWriter(std::filesystem::path destination, const std::vector<std::string>& header);
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~CsvWriter();

  /// One row; each number in the shortest form that reads back exactly (round-trip). Must have the header's width.
  void write_row(std::span<const double> values);
  /// Flush, close and rename onto the destination. Throws std::runtime_error on failure.
  void commit();

  const std::filesystem::path& destination() const { return destination_; }

 private:
  /// Throws std::runtime_error if a write to the file failed (e.g. the disk is full).
  void check_written();

  std::filesystem::path destination_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
  size_t width_ = 0;
};

}  // namespace clearjoint::dynamics
