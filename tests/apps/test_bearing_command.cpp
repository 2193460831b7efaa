// SPDX-License-Identifier: BSD-3-Clause
// `clearjoint bearing` end to end: the Reynolds grid's cost guard and its switch, and bad option
// values named as the options that carry them (docs/command-line.md, "clearjoint bearing").

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "program_run.hpp"

namespace {

namespace fs = std::filesystem;

using clearjoint::test::Outcome;

/// Runs `clearjoint bearing --eccentricity-ratio 0.5 --width-ratio 1 <options>`, or with
/// `options` alone when `base` is false.
Outcome bearing(const std::string& options, bool base = true) {
  const fs::path dir = fs::path(CLEARJOINT_TEST_WORK_DIR);
  fs::create_directories(dir);
  const std::string fixed = base ? "--eccentricity-ratio 0.5 --width-ratio 1 " : "";
  return clearjoint::test::run("bearing " + fixed + options, dir);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(BearingCommand, RefusesAGridAboveTheCostLimitsWithItsEstimateAndTheSwitchThatAllowsIt) {
  // 96 x 400 took 22.6 s and 378 MB when nothing guarded it.
  const Outcome o = bearing("--grid 96x400");
  EXPECT_EQ(o.exit_code, 1) << o.err;
  EXPECT_TRUE(o.out.empty());
  EXPECT_TRUE(contains(o.err, "clearjoint bearing: --grid = 96x400: ")) << o.err;
  EXPECT_TRUE(contains(o.err, "estimated 7e+02 MiB of band")) << o.err;
  EXPECT_TRUE(contains(o.err, "--allow-large-grid solves it anyway")) << o.err;
}

TEST(BearingCommand, SolvesAModestGridAboveTheLimitsWithAllowLargeGrid) {
  // 16 x 160: 1.03e9 operations a solve by estimate_cost, just above kMaxGridOperations, and
  // tens of milliseconds in fact.
  EXPECT_EQ(bearing("--grid 16x160").exit_code, 1);
  const Outcome o = bearing("--grid 16x160 --allow-large-grid");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const nlohmann::json answer = nlohmann::json::parse(o.out);
  EXPECT_EQ(answer["grid"], nlohmann::json::array({16, 160}));
  EXPECT_TRUE(answer["converged"].get<bool>());
  EXPECT_GT(answer["sommerfeld_number"].get<double>(), 0.0);
}

TEST(BearingCommand, RefusesAGridCountBeyondAnIntQuotingTheTextAsTyped) {
  const Outcome o = bearing("--grid 99999999999999999999x2");
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_TRUE(contains(o.err, "--grid = '99999999999999999999x2': must be NTHETAxNZ, two whole numbers up to "
                              "2147483647"))
      << o.err;
  EXPECT_EQ(bearing("--grid 96x24.5").exit_code, 2);
  EXPECT_EQ(bearing("--grid 96x24x3").exit_code, 2);
}

TEST(BearingCommand, RefusesAGridTooLargeToStoreEvenWhenLargeGridsAreAllowed) {
  for (const char* options : {"--grid 100000x100000", "--grid 100000x100000 --allow-large-grid"}) {
    const Outcome o = bearing(options);
    EXPECT_EQ(o.exit_code, 1) << options << ": " << o.err;
    EXPECT_TRUE(contains(o.err, "--grid = 100000x100000: ")) << o.err;
    EXPECT_TRUE(contains(o.err, "too large to store")) << o.err;
    EXPECT_FALSE(contains(o.err, "bad_alloc")) << o.err;
  }
}

TEST(BearingCommand, NamesTheOptionWhoseValueIsOutOfRange) {
  const Outcome wide = bearing("--eccentricity-ratio 0.5 --width-ratio 1e300", false);
  EXPECT_EQ(wide.exit_code, 1) << wide.err;
  EXPECT_TRUE(contains(wide.err, "clearjoint bearing: --width-ratio = 1.0000000000000001e+300: must be in "
                                 "[1e-50, 1e50]"))
      << wide.err;
  EXPECT_FALSE(contains(wide.err, "dimensions")) << wide.err;
  const Outcome eps = bearing("--eccentricity-ratio 1 --width-ratio 1", false);
  EXPECT_EQ(eps.exit_code, 1) << eps.err;
  EXPECT_TRUE(contains(eps.err, "clearjoint bearing: --eccentricity-ratio = 1: ")) << eps.err;
  const Outcome method = bearing("--method finite");
  EXPECT_EQ(method.exit_code, 1) << method.err;
  EXPECT_TRUE(contains(method.err, "clearjoint bearing: --method = 'finite': unknown (known: grid, short, long, table)"))
      << method.err;
}

TEST(BearingCommand, RefusesAnOptionGivenTwiceNamingBothValues) {
  const Outcome o = bearing("--method long --method short");
  EXPECT_EQ(o.exit_code, 2) << o.out;
  EXPECT_TRUE(o.out.empty()) << o.out;
  EXPECT_TRUE(contains(o.err, "clearjoint bearing: --method is given twice ('long', then 'short'): give it once"))
      << o.err;
  EXPECT_EQ(bearing("--allow-large-grid --allow-large-grid").exit_code, 2);
}

TEST(BearingCommand, RunsFromConcurrentThreadsEachReadTheirOwnOutput) {
  // Test cases of one binary run side by side (ctest -j2), each running the program with its
  // output in the binary's work folder: each run must read its own answer and messages.
  constexpr int kThreads = 4, kRunsEach = 8;
  std::vector<std::thread> threads;
  std::vector<int> wrong(kThreads, 0);
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([t, &wrong] {
      const std::string eps = "0." + std::to_string(t + 1);
      for (int k = 0; k < kRunsEach; ++k) {
        const Outcome o = bearing("--eccentricity-ratio " + eps + " --width-ratio 1 --method short", false);
        const bool own = o.exit_code == 0 && contains(o.out, "\"eccentricity_ratio\":" + eps + ",") && o.err.empty();
        wrong[t] += own ? 0 : 1;
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(wrong[t], 0) << "thread " << t;
}

/// The inode of the only file in `folder` whose name starts with "film-table-", or 0 if none or
/// more than one: a rebuilt table is a new file renamed over the old name, a new inode.
ino_t table_file_inode(const fs::path& folder) {
  ino_t inode = 0;
  int count = 0;
  if (!fs::is_directory(folder)) return 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().filename().string().rfind("film-table-", 0) != 0) continue;
    struct stat info {};
    if (::stat(entry.path().c_str(), &info) == 0) inode = info.st_ino;
    ++count;
  }
  return count == 1 ? inode : 0;
}

TEST(BearingCommand, ASecondTableCallReadsTheFirstCallsCachedTableAndAnswersTheSame) {
  const fs::path cache = fs::path(CLEARJOINT_TEST_WORK_DIR) / "table-cache";
  fs::remove_all(cache);
  ASSERT_EQ(::setenv("CLEARJOINT_CACHE_DIR", cache.c_str(), 1), 0);
  const Outcome first = bearing("--method table --grid 16x4");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ino_t written = table_file_inode(cache);
  ASSERT_NE(written, 0u) << "the first call writes one table file into CLEARJOINT_CACHE_DIR";
  const Outcome second = bearing("--method table --grid 16x4");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(second.out, first.out);
  EXPECT_TRUE(second.err.empty()) << second.err;
  EXPECT_EQ(table_file_inode(cache), written) << "read, not rebuilt and replaced";
  // A damaged file is rebuilt and replaced, the answer unchanged.
  std::ofstream(cache / fs::directory_iterator(cache)->path().filename(), std::ios::trunc) << "damaged";
  const Outcome third = bearing("--method table --grid 16x4");
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_EQ(third.out, first.out);
  EXPECT_NE(table_file_inode(cache), written);
  // Switched off: answers, writes nothing.
  fs::remove_all(cache);
  ASSERT_EQ(::setenv("CLEARJOINT_CACHE_DIR", "", 1), 0);
  const Outcome off = bearing("--method table --grid 16x4");
  ::unsetenv("CLEARJOINT_CACHE_DIR");
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(off.out, first.out);
  EXPECT_FALSE(fs::exists(cache));
}

}  // namespace
