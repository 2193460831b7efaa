// SPDX-License-Identifier: BSD-3-Clause
#include "run_folder.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "clearjoint/dynamics/csv_directory.hpp"
#include "clearjoint/dynamics/output_folder.hpp"
#include "clearjoint/validation_error.hpp"
#ifdef CLEARJOINT_WITH_HDF5
#include "hdf5_tables.hpp"
#endif

namespace clearjoint::dynamics {

namespace {

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(file.string() + ": cannot write the output file (" + std::strerror(errno) + ")");
}

}  // namespace

bool hdf5_available() {
#ifdef CLEARJOINT_WITH_HDF5
  return true;
#else
  return false;
#endif
}

RunFormat run_format(const std::string& name, std::string_view field) {
  if (name == "csv") return RunFormat::csv;
  if (name == "hdf5") {
    if (!hdf5_available()) {
      throw ValidationError(field, " = 'hdf5': this clearjoint was built without HDF5 (libhdf5-dev)");
    }
    return RunFormat::hdf5;
  }
  throw ValidationError(field, " = '" + name + "': must be csv or hdf5");
}

SimulationSummary write_run_folder(SimulationRun& run, const std::string& model_json,
                                   const std::filesystem::path& destination, const RunFolderOptions& options,
                                   const ProgressCallback& progress) {
  return write_run_folder([&](SimulationOutput& output) { return run.run(output, progress); }, model_json,
                          destination, options);
}

SimulationSummary write_run_folder(const std::function<SimulationSummary(SimulationOutput&)>& run_into,
                                   const std::string& model_json, const std::filesystem::path& destination,
                                   const RunFolderOptions& options) {
  OutputFolder folder(destination, options.replace_existing);
  SimulationSummary summary;
  if (options.format == RunFormat::hdf5) {
#ifdef CLEARJOINT_WITH_HDF5
    Hdf5Tables file(folder.staging() / "run.h5", model_json);
    summary = run_into(file);
    summary.overrides = options.overrides;
    file.add_text_attribute("summary", summary_json(summary));
#else
    throw ValidationError("format", " = 'hdf5': this clearjoint was built without HDF5 (libhdf5-dev)");
#endif
  } else {
    CsvDirectory files(folder.staging());
    summary = run_into(files);
    summary.overrides = options.overrides;
  }
  write_text(folder.staging() / "model.json", model_json);
  write_text(folder.staging() / "summary.json", summary_json(summary));
  folder.publish();
  return summary;
}

}  // namespace clearjoint::dynamics
