// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Where a simulation's time series go: a sink of named tables, one per output file of
/// simulation.hpp. simulate() declares every table before the first step, writes one row per
/// report time and commits after the last; a run that stops early (an exception, including one
/// thrown by the progress callback) never commits.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace clearjoint::dynamics {

/// A table a run will write: its name (the CSV file's stem) and its columns, "time" first.
struct TablePlan {
  std::string name;
  std::vector<std::string> header;
};

class SimulationOutput {
 public:
  virtual ~SimulationOutput() = default;
  /// Declare a table: `name` is the CSV file's stem ("energy", "reactions", "body_crank",
  /// "force_<element>"), `header` its column names, "time" first. Returns the index that
  /// write_row takes.
  virtual std::size_t add_table(const std::string& name, const std::vector<std::string>& header) = 0;
  /// One row of table `table`, as wide as its header.
  virtual void write_row(std::size_t table, std::span<const double> values) = 0;
  /// The run completed: every row has been written.
  virtual void commit() = 0;
};

/// The tables kept in memory, for programs and bindings that want the numbers rather than files.
/// After a completed run, tables() holds exactly the values the CSV files would (the files print
/// each double in its shortest round-trip form, so they read back bit for bit).
class TablesInMemory final : public SimulationOutput {
 public:
  struct Table {
    std::string name;
    std::vector<std::string> header;
    std::vector<double> values;  ///< row-major: row r, column c at values[r * header.size() + c]
    std::size_t rows() const { return header.empty() ? 0 : values.size() / header.size(); }
  };

  std::size_t add_table(const std::string& name, const std::vector<std::string>& header) override;
  /// Throws std::logic_error when the row is not as wide as the table's header.
  void write_row(std::size_t table, std::span<const double> values) override;
  void commit() override { committed_ = true; }

  const std::vector<Table>& tables() const { return tables_; }
  bool committed() const { return committed_; }

 private:
  std::vector<Table> tables_;
  bool committed_ = false;
};

}  // namespace clearjoint::dynamics
