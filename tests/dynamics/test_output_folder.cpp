// SPDX-License-Identifier: BSD-3-Clause
// The run output folder (output_folder.hpp): its manifest, what --force may replace, refusals that
// create nothing, and a destination that is a symbolic link. The command line's cases are in
// tests/apps/simulate_hostile_test.sh.
#include "clearjoint/dynamics/output_folder.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace clearjoint::dynamics {
namespace {

namespace fs = std::filesystem;

/// An empty folder of this test's own under the system's temporary folder.
fs::path fresh_root(const std::string& name) {
  const fs::path root = fs::temp_directory_path() /
                        ("clearjoint_output_folder_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(root);
  fs::create_directories(root);
  return root;
}

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A published result in `destination` holding `files` (relative names), as a run writes it.
void publish_result(const fs::path& destination, std::initializer_list<const char*> files, bool force = false) {
  OutputFolder folder(destination, force);
  for (const char* file : files) write_file(folder.staging() / file, "written by the run\n");
  folder.publish();
}

/// The message OutputFolder's constructor throws for `destination`, or "" when it accepts it.
std::string refusal(const fs::path& destination, bool force) {
  try {
    OutputFolder folder(destination, force);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

/// The manifest's entries: every line after the header.
std::string manifest_entries(const fs::path& result) {
  const std::string text = read_file(result / OutputFolder::kMarkerName);
  return text.substr(text.find('\n') + 1);
}

TEST(OutputFolder, TheManifestListsEveryFileTheRunWroteUnderItsHeader) {
  const fs::path out = fresh_root("manifest") / "res";
  publish_result(out, {"energy.csv", "body_ball.csv", "sub/nested.txt"});
  const std::string text = read_file(out / OutputFolder::kMarkerName);
  EXPECT_TRUE(text.starts_with(OutputFolder::kManifestHeader)) << text;
  EXPECT_EQ(manifest_entries(out), "body_ball.csv\nenergy.csv\nsub/nested.txt\n");
}

TEST(OutputFolder, ForceReplacesAnEarlierResultHoldingOnlyWhatItsManifestLists) {
  const fs::path out = fresh_root("replace") / "res";
  publish_result(out, {"energy.csv", "force_old.csv"});
  publish_result(out, {"energy.csv"}, true);
  EXPECT_FALSE(fs::exists(out / "force_old.csv"));
  EXPECT_EQ(manifest_entries(out), "energy.csv\n");
}

TEST(OutputFolder, ForceReplacesFilesAnotherToolRegisteredInTheManifest) {
  // What `clearjoint plot` does after a run: writes figures/ and appends them to the manifest.
  const fs::path out = fresh_root("registered") / "res";
  publish_result(out, {"energy.csv"});
  write_file(out / "figures" / "joint_pin.png", "png");
  std::ofstream(out / OutputFolder::kMarkerName, std::ios::app) << "figures/joint_pin.png\n";
  publish_result(out, {"energy.csv"}, true);
  EXPECT_FALSE(fs::exists(out / "figures"));
}

TEST(OutputFolder, ForceRefusesAnEarlierResultHoldingFilesTheUserAddedAndNamesThem) {
  const fs::path out = fresh_root("added") / "res";
  publish_result(out, {"energy.csv"});
  write_file(out / "mynotes.txt", "precious");
  write_file(out / "mysub" / "analysis.ipynb", "{}");
  const std::string error = refusal(out, true);
  EXPECT_NE(error.find("holds files no clearjoint run wrote (mynotes.txt, mysub/analysis.ipynb)"),
            std::string::npos) << error;
  EXPECT_NE(error.find("move those files out of the folder, or choose another --out"), std::string::npos) << error;
  EXPECT_EQ(read_file(out / "mynotes.txt"), "precious");
  EXPECT_EQ(read_file(out / "mysub" / "analysis.ipynb"), "{}");
}

TEST(OutputFolder, ARefusalNamesAFewAddedFilesAndCountsTheRest) {
  const fs::path out = fresh_root("many") / "res";
  publish_result(out, {"energy.csv"});
  for (int k = 0; k < 7; ++k) write_file(out / ("note" + std::to_string(k) + ".txt"), "x");
  const std::string error = refusal(out, true);
  EXPECT_NE(error.find("note0.txt, note1.txt, note2.txt and 4 more"), std::string::npos) << error;
}

TEST(OutputFolder, ALinkTheUserAddedInsideAResultCountsAsAnAddedFile) {
  const fs::path root = fresh_root("added_link");
  const fs::path out = root / "res";
  publish_result(out, {"energy.csv"});
  fs::create_directory(root / "data");
  fs::create_directory_symlink(root / "data", out / "data");
  EXPECT_NE(refusal(out, true).find("(data)"), std::string::npos) << refusal(out, true);
}

TEST(OutputFolder, RefusesAManifestWithAnEntryThatLeavesTheFolder) {
  const fs::path out = fresh_root("escape") / "res";
  publish_result(out, {"energy.csv"});
  for (const char* entry : {"../elsewhere.txt", "/etc/passwd", "a/../../b", "./energy.csv", ""}) {
    write_file(out / OutputFolder::kMarkerName, std::string(OutputFolder::kManifestHeader) + "\nenergy.csv\n" + entry + "\n");
    const std::string error = refusal(out, true);
    EXPECT_NE(error.find("is not a manifest clearjoint wrote (line 3: "), std::string::npos) << entry << ": " << error;
  }
  EXPECT_TRUE(fs::exists(out / "energy.csv"));
}

TEST(OutputFolder, RefusesAManifestLargerThanItsLimit) {
  const fs::path out = fresh_root("large") / "res";
  publish_result(out, {"energy.csv"});
  fs::resize_file(out / OutputFolder::kMarkerName, OutputFolder::kMaxManifestBytes + 1);  // sparse
  const std::string error = refusal(out, true);
  EXPECT_NE(error.find("larger than " + std::to_string(OutputFolder::kMaxManifestBytes) + " bytes"), std::string::npos)
      << error;
}

TEST(OutputFolder, RefusesAMarkerWithoutTheManifestHeader) {
  const fs::path out = fresh_root("headerless") / "res";
  publish_result(out, {"energy.csv"});
  write_file(out / OutputFolder::kMarkerName, "energy.csv\n");
  EXPECT_NE(refusal(out, true).find("its first line is not"), std::string::npos) << refusal(out, true);
}

TEST(OutputFolder, ARefusedRunCreatesNoLockFileNorParentFolder) {
  const fs::path root = fresh_root("refused");
  write_file(root / "home" / "mine.txt", "mine");
  EXPECT_NE(refusal(root / "home", false).find("use --force"), std::string::npos);
  EXPECT_NE(refusal(root / "home", true).find("not a clearjoint result"), std::string::npos);
  write_file(root / "a_file", "text");
  EXPECT_NE(refusal(root / "a_file", true).find("exists and is not a folder"), std::string::npos);
  EXPECT_FALSE(fs::exists(root / ".home.lock"));
  EXPECT_FALSE(fs::exists(root / ".a_file.lock"));
  EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 2);
}

TEST(OutputFolder, ALinkToAFolderIsPublishedAtItsTargetAndTheLinkStays) {
  const fs::path root = fresh_root("link");
  fs::create_directory(root / "target");
  fs::create_directory_symlink("target", root / "link");
  publish_result(root / "link", {"energy.csv"});
  EXPECT_TRUE(fs::is_symlink(root / "link"));
  EXPECT_TRUE(fs::is_regular_file(root / "target" / "energy.csv"));
  EXPECT_TRUE(fs::exists(root / ".target.lock"));
  publish_result(root / "link", {"summary.json"}, true);
  EXPECT_TRUE(fs::is_symlink(root / "link"));
  EXPECT_TRUE(fs::is_regular_file(root / "link" / "summary.json"));
  EXPECT_FALSE(fs::exists(root / "target" / "energy.csv"));
}

TEST(OutputFolder, ALinkThatLeadsNowhereIsRefusedNamingItsTarget) {
  const fs::path root = fresh_root("dangling");
  fs::create_directory_symlink("missing", root / "link");
  const std::string error = refusal(root / "link", false);
  EXPECT_NE(error.find("is a symbolic link to missing, which does not lead to a folder"), std::string::npos) << error;
  write_file(root / "file.txt", "text");
  fs::create_symlink("file.txt", root / "to_file");
  EXPECT_NE(refusal(root / "to_file", true).find("which is not a folder"), std::string::npos);
  EXPECT_FALSE(fs::exists(root / "missing"));
}

}  // namespace
}  // namespace clearjoint::dynamics
