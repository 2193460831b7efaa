// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The CSV files of dynamics/simulation.hpp written by an engine adapter: one dynamics::CsvWriter
/// per table, "<table>.csv" in a directory, each file appearing only on commit(). Internal to
/// the adapters (clearjoint's own CsvDirectory is private to simulation.cpp).

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "clearjoint/dynamics/csv_writer.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"

namespace clearjoint::engines {

class CsvTables final : public dynamics::SimulationOutput {
 public:
  /// Creates `directory` if missing; throws std::runtime_error naming it when it cannot.
  explicit CsvTables(std::filesystem::path directory);
  std::size_t add_table(const std::string& name, const std::vector<std::string>& header) override;
  void write_row(std::size_t table, std::span<const double> values) override;
  void commit() override;

 private:
  std::filesystem::path directory_;
  std::vector<std::unique_ptr<dynamics::CsvWriter>> files_;
};

/// The table (and file stem) of a model name, as dynamics/simulation.hpp states it: `prefix`
/// then the name with letters, digits, '-' and '_' kept and every other byte '_'.
std::string table_name(std::string_view prefix, std::string_view name);

}  // namespace clearjoint::engines
