// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/csv_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace clearjoint::dynamics {
namespace {

std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("clearjoint_csv_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string contents(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(CsvWriter, WritesRoundTripNumbersOnlyWhenCommitted) {
  const auto dir = fresh_directory("commit");
  {
    CsvWriter csv(dir / "out.csv", {"time", "x"});
    const double row[] = {0.1, 1.0 / 3.0};
    csv.write_row(row);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
    csv.commit();
  }
  EXPECT_EQ(contents(dir / "out.csv"), "time,x\n0.1,0.3333333333333333\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(CsvWriter, LeavesNothingBehindWhenAbandoned) {
  const auto dir = fresh_directory("abandon");
  {
    CsvWriter csv(dir / "out.csv", {"time"});
    const double row[] = {1.0};
    csv.write_row(row);
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 0);
}

TEST(CsvWriter, KeepsThePreviousFileUntilTheNewOneIsComplete) {
  const auto dir = fresh_directory("replace");
  std::ofstream(dir / "out.csv") << "old\n";
  {
    CsvWriter csv(dir / "out.csv", {"time"});
    EXPECT_EQ(contents(dir / "out.csv"), "old\n");
  }
  EXPECT_EQ(contents(dir / "out.csv"), "old\n");
}

TEST(CsvWriter, ReportsAnUnwritableDirectory) {
  EXPECT_THROW(CsvWriter("/nonexistent-dir/out.csv", {"t"}), std::runtime_error);
}

}  // namespace
}  // namespace clearjoint::dynamics
