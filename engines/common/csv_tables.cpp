// SPDX-License-Identifier: BSD-3-Clause
#include "csv_tables.hpp"

#include <stdexcept>
#include <system_error>

namespace clearjoint::engines {

CsvTables::CsvTables(std::filesystem::path directory) : directory_(std::move(directory)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  if (error) {
    throw std::runtime_error(directory_.string() + ": cannot create the output directory (" +
                             error.message() + ")");
  }
}

std::size_t CsvTables::add_table(const std::string& name, const std::vector<std::string>& header) {
  // table_name() never makes such names; checked so that no caller can write outside.
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
    throw std::logic_error(name + ": a table name that is no file name inside the directory");
  }
  files_.push_back(std::make_unique<dynamics::CsvWriter>(directory_ / (name + ".csv"), header));
  return files_.size() - 1;
}

void CsvTables::write_row(std::size_t table, std::span<const double> values) {
  files_[table]->write_row(values);
}

void CsvTables::commit() {
  for (auto& file : files_) file->commit();
}

std::string table_name(std::string_view prefix, std::string_view name) {
  std::string table(prefix);
  for (char c : name) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_';
    table.push_back(keep ? c : '_');
  }
  return table;
}

}  // namespace clearjoint::engines
