// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A run's tables in one HDF5 file (`clearjoint simulate --format hdf5`, Python's
/// simulate(out=..., format="hdf5")): one 2-D float64 dataset per table under /tables, rows by
/// columns, with the column names in its attribute `columns`; the model and the summary as JSON
/// text in the file's attributes `model` and `summary`; `format` = "clearjoint-run-1". The same
/// numbers as the CSV files, bit for bit (doubles are stored as they are). The file appears
/// under its name only on commit() (written under a temporary name, then renamed).
///
/// Beside it, `<name>.sha256` holds the file's SHA-256 in sha256sum's format (file_sha256.hpp),
/// written on commit() and rewritten by add_text_attribute(), so that once committed the file and
/// its checksum agree. libhdf5 trusts its input (one flipped byte in the file's metadata can
/// crash a reader), so readers check the bytes against it first (clearjoint.read_run does).
///
///   import h5py; f = h5py.File("run/run.h5"); t = f["tables/energy"]
///   dict(zip(t.attrs["columns"], t[:].T))   # column name -> array

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "clearjoint/dynamics/simulation_output.hpp"

namespace clearjoint::dynamics {

/// The file format's name, in the file's attribute `format`.
inline constexpr const char* kHdf5RunFormat = "clearjoint-run-1";

class Hdf5Tables final : public SimulationOutput {
 public:
  /// Creates the file under a temporary name next to `path` (std::runtime_error naming it and
  /// why when it cannot). `model_json` goes into the attribute `model`.
  Hdf5Tables(std::filesystem::path path, const std::string& model_json);
  Hdf5Tables(const Hdf5Tables&) = delete;
  Hdf5Tables& operator=(const Hdf5Tables&) = delete;
  /// An uncommitted file is removed.
  ~Hdf5Tables() override;

  std::size_t add_table(const std::string& name, const std::vector<std::string>& header) override;
  void write_row(std::size_t table, std::span<const double> values) override;
  /// Writes the rows still buffered, closes the file, renames it to its name and writes its
  /// checksum file.
  void commit() override;

  /// Adds a text attribute to the committed file (the run's summary, known after the run) and
  /// rewrites its checksum file.
  void add_text_attribute(const std::string& name, const std::string& text);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clearjoint::dynamics
