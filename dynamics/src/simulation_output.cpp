// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/simulation_output.hpp"

#include <stdexcept>

namespace clearjoint::dynamics {

std::size_t TablesInMemory::add_table(const std::string& name, const std::vector<std::string>& header) {
  tables_.push_back({name, header, {}});
  return tables_.size() - 1;
}

void TablesInMemory::write_row(std::size_t table, std::span<const double> values) {
  Table& t = tables_.at(table);
  if (values.size() != t.header.size()) {
    throw std::logic_error("table " + t.name + ": row of " + std::to_string(values.size()) +
                           " values for " + std::to_string(t.header.size()) + " columns");
  }
  t.values.insert(t.values.end(), values.begin(), values.end());
}

}  // namespace clearjoint::dynamics
