// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/csv_directory.hpp"

#include <stdexcept>
#include <system_error>

namespace clearjoint::dynamics {

CsvDirectory::CsvDirectory(std::filesystem::path directory) : directory_(std::move(directory)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) {
    throw std::runtime_error(directory_.string() + ": cannot create the output directory (" + error.message() +
                             ")");
  }
}

std::size_t CsvDirectory::add_table(const std::string& name, const std::vector<std::string>& header) {
  // Table names never hold such names (simulation.cpp's table_name); checked here so that no
  // later change can write outside the directory.
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
    throw std::logic_error(name + ": a table name that is no file name inside the directory");
  }
  files_.push_back(std::make_unique<CsvWriter>(directory_ / (name + ".csv"), header));
  return files_.size() - 1;
}

void CsvDirectory::write_row(std::size_t table, std::span<const double> values) { files_[table]->write_row(values); }

void CsvDirectory::commit() {
  for (auto& file : files_) file->commit();
}

}  // namespace clearjoint::dynamics
