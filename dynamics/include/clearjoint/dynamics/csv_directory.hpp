// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The tables of a run as CSV files in a folder, <table>.csv each (simulation.hpp lists them);
/// each file appears only on commit() (CsvWriter).

#include <filesystem>
#include <memory>
#include <vector>

#include "clearjoint/dynamics/csv_writer.hpp"
#include "clearjoint/dynamics/simulation_output.hpp"

namespace clearjoint::dynamics {

class CsvDirectory final : public SimulationOutput {
 public:
  /// Creates `directory` if missing (std::runtime_error naming it and why otherwise).
  explicit CsvDirectory(std::filesystem::path directory);
  std::size_t add_table(const std::string& name, const std::vector<std::string>& header) override;
  void write_row(std::size_t table, std::span<const double> values) override;
  void commit() override;

 private:
  std::filesystem::path directory_;
  std::vector<std::unique_ptr<CsvWriter>> files_;
};

}  // namespace clearjoint::dynamics
