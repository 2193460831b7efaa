// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/csv_directory.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace clearjoint::dynamics {
namespace {

std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("clearjoint_csv_directory_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(CsvDirectory, WritesOneFilePerTableOnlyOnCommit) {
  const auto dir = fresh_directory("commit");
  CsvDirectory files(dir / "nested");
  const std::size_t energy = files.add_table("energy", {"time", "total"});
  const std::size_t body = files.add_table("body_ball", {"time", "x"});
  const double row[] = {0.5, 2.0};
  files.write_row(energy, row);
  files.write_row(body, row);
  EXPECT_FALSE(std::filesystem::exists(dir / "nested" / "energy.csv"));
  files.commit();
  std::ifstream in(dir / "nested" / "energy.csv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,total\n0.5,2\n");
  EXPECT_TRUE(std::filesystem::exists(dir / "nested" / "body_ball.csv"));
}

TEST(CsvDirectory, RefusesATableNameThatIsNoFileNameInside) {
  CsvDirectory files(fresh_directory("names"));
  for (const char* name : {"", ".", "..", "a/b"}) EXPECT_THROW(files.add_table(name, {"time"}), std::logic_error) << name;
}

}  // namespace
}  // namespace clearjoint::dynamics
