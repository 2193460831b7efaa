// SPDX-License-Identifier: BSD-3-Clause
// Lubrication's enums each have one EnumTable (film_conditions.hpp, reynolds_grid.hpp,
// bearing_characteristics.hpp), from which the model files, the command line and Python read
// their names: every value has a row, keys and names are unique and read back to their value,
// and to_string is the table's key.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <string_view>

#include "clearjoint/geometry/model/enum_table.hpp"
#include "clearjoint/lubrication/bearing_characteristics.hpp"
#include "clearjoint/lubrication/film_conditions.hpp"
#include "clearjoint/lubrication/reynolds_grid.hpp"

namespace clearjoint::lubrication {
namespace {

namespace geo = clearjoint::geometry;

/// Every row reads back to its value by its key, and no two rows share a key, a name or a label.
template <geo::TabledEnum E>
void expect_table_reads_back() {
  std::set<std::string_view> keys, names, labels;
  for (const geo::EnumEntry<E>& entry : geo::EnumTable<E>::entries) {
    EXPECT_EQ(geo::from_string<E>(entry.key), entry.value) << geo::EnumTable<E>::type_name << " " << entry.key;
    EXPECT_EQ(geo::key_of(entry.value), entry.key);
    EXPECT_TRUE(keys.insert(entry.key).second) << "duplicate key " << entry.key;
    EXPECT_TRUE(names.insert(entry.name).second) << "duplicate name " << entry.name;
    EXPECT_TRUE(labels.insert(entry.label).second) << "duplicate label " << entry.label;
    EXPECT_FALSE(entry.label.empty()) << entry.key;
  }
  EXPECT_EQ(geo::from_string<E>("no such name"), std::nullopt);
}

TEST(LubricationEnumTables, ReadEveryRowBackByItsKey) {
  expect_table_reads_back<CavitationModel>();
  expect_table_reads_back<OilSupply::Kind>();
  expect_table_reads_back<ReynoldsLinearSolver>();
  expect_table_reads_back<BearingMotion>();
  expect_table_reads_back<BearingMethod>();
}

TEST(LubricationEnumTables, GiveToStringTheirKeysAndTheFrontEndsTheirEstablishedSpellings) {
  EXPECT_EQ(to_string(BearingMethod::short_bearing), "short");
  EXPECT_EQ(to_string(BearingMethod::long_bearing), "long");
  EXPECT_EQ(to_string(CavitationModel::mass_conserving), "mass_conserving");
  EXPECT_EQ(to_string(ReynoldsLinearSolver::sparse_lu), "sparse_lu");
  EXPECT_EQ(to_string(BearingMotion::squeeze), "squeeze");
  EXPECT_EQ(geo::known_keys<BearingMethod>(), "grid, short, long, table");
}

}  // namespace
}  // namespace clearjoint::lubrication
