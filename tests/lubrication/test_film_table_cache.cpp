// SPDX-License-Identifier: BSD-3-Clause
// FilmTable's file cache (film_table_cache.cpp): a table read back is the table built, a file that
// is not a whole, undamaged table for the key is rebuilt and replaced, and a cache that cannot be
// written, or is switched off, still gives the table.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>

#include <boost/crc.hpp>

#include "clearjoint/lubrication/film_table.hpp"
#include "clearjoint/version.hpp"

namespace clearjoint::lubrication {
namespace {

namespace fs = std::filesystem;

// A small grid (16 x 4) keeps each build to a fraction of the Section 6.1 table's half second.
const FilmTableKey kKey{9.9e-3, 1e-4, 19.8e-3, 16, 4, CavitationModel::half_sommerfeld};

/// A fresh, empty folder for one test (and `part` of it), removed with it.
class Folder {
 public:
  explicit Folder(const std::string& part = "") {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("cj-film-cache-" + std::string(info->name()) + part + "-" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~Folder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// Sets (or, given nullopt, unsets) an environment variable for one scope.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value->c_str(), 1) : ::unsetenv(name);
  }
  ~ScopedVariable() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}
/// The bytes with their last four (the CRC-32) recomputed, as a forger would.
std::string with_valid_crc(std::string bytes) {
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size() - 4);
  const std::uint32_t sum = crc.checksum();
  std::memcpy(bytes.data() + bytes.size() - 4, &sum, 4);
  return bytes;
}
std::size_t file_count(const fs::path& folder) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::recursive_directory_iterator(folder)) ++n;
  return n;
}

/// Two tables give the same bits for the same states, whirl included, over the whole eps range.
void expect_same_loads(const FilmTable& a, const FilmTable& b) {
  std::mt19937 rng(49);
  std::uniform_real_distribution<double> eps(0.0, kTableLargestEccentricityRatio), rate(-300.0, 300.0);
  for (int n = 0; n < 200; ++n) {
    const PlanarFilmState state{eps(rng), rate(rng), rate(rng), rate(rng)};
    const PlanarFilmLoad x = *a.load(state, 0.04), y = *b.load(state, 0.04);
    ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << "eps = " << state.eccentricity_ratio;
  }
  EXPECT_EQ(a.error_bound(), b.error_bound());
  EXPECT_EQ(a.interval_errors(), b.interval_errors());
}

TEST(FilmTableCache, ASecondRequestReadsTheTableFromTheFileInsteadOfBuildingIt) {
  const Folder folder;
  const std::uint64_t builds = FilmTable::build_count();
  const auto built = FilmTable::cached(kKey, folder.path());
  EXPECT_EQ(FilmTable::build_count(), builds + 1);
  EXPECT_TRUE(fs::is_regular_file(folder.path() / FilmTable::cache_file_name(kKey)));
  EXPECT_EQ(file_count(folder.path()), 1u) << "the temporary file is renamed, not left behind";

  const auto read = FilmTable::cached(kKey, folder.path());
  EXPECT_EQ(FilmTable::build_count(), builds + 1);
  EXPECT_NE(read, built);
  EXPECT_EQ(read->key(), kKey);
  expect_same_loads(*built, *read);
}

TEST(FilmTableCache, TheSharedTableIsWrittenToTheFolderNamedByTheEnvironment) {
  const Folder folder;
  const ScopedVariable dir("CLEARJOINT_CACHE_DIR", folder.path().string());
  // A key no other test of this process asks shared() for: its first use in the process.
  const FilmTableKey key{kKey.journal_radius, kKey.radial_clearance, kKey.width, 16, 3, kKey.cavitation};
  const auto table = FilmTable::shared(key);
  ASSERT_NE(FilmTable::read(folder.path() / FilmTable::cache_file_name(key), key), nullptr);
}

TEST(FilmTableCache, TheFolderIsTheVariableElseXdgCacheHomeElseHomeDotCache) {
  const ScopedVariable home("HOME", "/home/someone"), xdg("XDG_CACHE_HOME", "/var/cache/someone");
  {
    const ScopedVariable dir("CLEARJOINT_CACHE_DIR", "/tmp/tables");
    EXPECT_EQ(film_table_cache_folder(), fs::path("/tmp/tables"));
  }
  {
    const ScopedVariable dir("CLEARJOINT_CACHE_DIR", "");
    EXPECT_EQ(film_table_cache_folder(), std::nullopt) << "set and empty: switched off";
  }
  const ScopedVariable dir("CLEARJOINT_CACHE_DIR", std::nullopt);
  EXPECT_EQ(film_table_cache_folder(), fs::path("/var/cache/someone/clearjoint"));
  {
    const ScopedVariable relative("XDG_CACHE_HOME", "relative/cache");
    EXPECT_EQ(film_table_cache_folder(), fs::path("/home/someone/.cache/clearjoint")) << "XDG: relative is ignored";
  }
  const ScopedVariable no_xdg("XDG_CACHE_HOME", std::nullopt);
  EXPECT_EQ(film_table_cache_folder(), fs::path("/home/someone/.cache/clearjoint"));
  const ScopedVariable no_home("HOME", std::nullopt);
  EXPECT_EQ(film_table_cache_folder(), std::nullopt);
}

TEST(FilmTableCache, TheCacheSwitchedOffWritesNothing) {
  const Folder folder;
  const ScopedVariable home("HOME", folder.path().string()), xdg("XDG_CACHE_HOME", folder.path().string());
  const ScopedVariable off("CLEARJOINT_CACHE_DIR", "");
  const FilmTableKey key{kKey.journal_radius, kKey.radial_clearance, kKey.width, 17, 3, kKey.cavitation};
  const std::uint64_t builds = FilmTable::build_count();
  ASSERT_NE(FilmTable::shared(key), nullptr);
  EXPECT_EQ(FilmTable::build_count(), builds + 1);
  EXPECT_EQ(file_count(folder.path()), 0u);
  ASSERT_NE(FilmTable::cached(key, std::nullopt), nullptr);
  EXPECT_EQ(file_count(folder.path()), 0u);
}

TEST(FilmTableCache, AFolderThatCannotBeCreatedStillGivesTheTable) {
  const Folder folder;
  write_bytes(folder.path() / "a-file", "not a folder");
  // Below a regular file: no folder can be made there, whoever runs the test (root included).
  const fs::path unwritable = folder.path() / "a-file" / "cache";
  const std::uint64_t builds = FilmTable::build_count();
  const auto table = FilmTable::cached(kKey, unwritable);
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(FilmTable::build_count(), builds + 1);
  EXPECT_FALSE(table->write(unwritable));
  EXPECT_EQ(file_count(folder.path()), 1u);
}

/// Writes the table for kKey, damages its file with `damage`, and expects the next request to
/// refuse it, rebuild, and replace it with a good file.
template <class Damage>
void expect_rebuilt_after(const Damage& damage, const std::string& what) {
  SCOPED_TRACE(what);
  const Folder folder("-damaged");
  const fs::path file = folder.path() / FilmTable::cache_file_name(kKey);
  const auto built = FilmTable::cached(kKey, folder.path());
  const std::string good = read_bytes(file);
  write_bytes(file, damage(good));
  EXPECT_TRUE(FilmTable::read(file, kKey) == nullptr) << "taken as the table";
  const std::uint64_t builds = FilmTable::build_count();
  const auto again = FilmTable::cached(kKey, folder.path());
  EXPECT_EQ(FilmTable::build_count(), builds + 1) << "rebuilt";
  EXPECT_EQ(read_bytes(file), good) << "replaced";
  expect_same_loads(*built, *again);
}

TEST(FilmTableCache, ATruncatedOrLengthenedFileIsRebuiltAndReplaced) {
  expect_rebuilt_after([](const std::string& b) { return b.substr(0, b.size() / 2); }, "half");
  expect_rebuilt_after([](const std::string& b) { return b.substr(0, b.size() - 1); }, "one byte short");
  expect_rebuilt_after([](const std::string&) { return std::string(); }, "empty");
  expect_rebuilt_after([](const std::string& b) { return b + '\0'; }, "one byte long");
}

TEST(FilmTableCache, AFileWithAnyFlippedByteIsRebuiltAndReplaced) {
  const Folder folder;
  const auto table = FilmTable::cached(kKey, folder.path());
  const std::size_t size = read_bytes(folder.path() / FilmTable::cache_file_name(kKey)).size();
  const std::size_t key_bytes = FilmTable::cache_key(kKey).size();
  // The magic, the format, the byte-order mark, the key's length, the key text (twice), the
  // sizes after it, a value, the CRC.
  for (const std::size_t at : {std::size_t{0}, std::size_t{8}, std::size_t{12}, std::size_t{16}, std::size_t{40},
                               20 + key_bytes - 2, 20 + key_bytes + 2, size / 2, size - 1}) {
    expect_rebuilt_after(
        [at](std::string b) {
          b[at] = static_cast<char>(b[at] ^ 0x10);
          return b;
        },
        "byte " + std::to_string(at));
  }
}

TEST(FilmTableCache, AFileWithNonFiniteOrWrongValuesIsRefusedEvenWithAValidChecksum) {
  const Folder folder;
  const auto table = FilmTable::cached(kKey, folder.path());
  const std::size_t size = read_bytes(folder.path() / FilmTable::cache_file_name(kKey)).size();
  const auto put_at = [](std::size_t at, double value) {
    return [at, value](std::string b) {
      std::memcpy(b.data() + at, &value, sizeof value);
      return with_valid_crc(b);
    };
  };
  const auto nudge_at = [](std::size_t at) {
    return [at](std::string b) {
      double value;
      std::memcpy(&value, b.data() + at, sizeof value);
      value *= 1.0 + 1e-6;
      std::memcpy(b.data() + at, &value, sizeof value);
      return with_valid_crc(b);
    };
  };
  // After the header: the error bound, 128 interval errors, 129 x 3 fields of 16 x 2 nodes (the
  // 4 - 1 = 3 unknown rows of each column, halved with the middle row kept), then the CRC.
  const std::size_t values = 1 + (kTableEccentricityNodes - 1) + std::size_t{kTableEccentricityNodes} * 3 * 16 * 2;
  const std::size_t bound = size - 4 - values * sizeof(double);
  const std::size_t last_value = size - 4 - sizeof(double);  // node 128's whirl field, its last node
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  expect_rebuilt_after(put_at(last_value, nan), "NaN in a field");
  expect_rebuilt_after(put_at(last_value, inf), "infinity in a field");
  expect_rebuilt_after(nudge_at(last_value), "a field value 1e-6 off the grid's at node 128");
  expect_rebuilt_after(put_at(bound, nan), "NaN as the error bound");
  expect_rebuilt_after(put_at(bound, 0.0), "an error bound below the largest interval error");
  expect_rebuilt_after(put_at(bound + sizeof(double), -1.0), "a negative interval error");
  // The header's sizes, as a file claiming other sizes (its CRC made good) would have them.
  expect_rebuilt_after(put_at(bound - 8, 1e300), "other sizes");
}

TEST(FilmTableCache, AFileForAnotherKeyUnderTheKeysNameIsRebuiltAndReplaced) {
  const Folder folder;
  const FilmTableKey other{kKey.journal_radius, kKey.radial_clearance, kKey.width * 2.0, 16, 4, kKey.cavitation};
  const auto built_other = FilmTable::cached(other, folder.path());
  const fs::path file = folder.path() / FilmTable::cache_file_name(kKey);
  // As a hash collision would: another key's whole, valid file under this key's name.
  fs::copy_file(folder.path() / FilmTable::cache_file_name(other), file);
  EXPECT_TRUE(FilmTable::read(file, kKey) == nullptr) << "taken as the table";
  const std::uint64_t builds = FilmTable::build_count();
  const auto table = FilmTable::cached(kKey, folder.path());
  EXPECT_EQ(FilmTable::build_count(), builds + 1);
  EXPECT_NE(FilmTable::read(file, kKey), nullptr);
}

TEST(FilmTableCache, ADirectoryOrAFifoUnderTheNameIsNotReadAndDoesNotHang) {
  const Folder folder;
  const fs::path file = folder.path() / FilmTable::cache_file_name(kKey);
  fs::create_directory(file);
  EXPECT_TRUE(FilmTable::read(file, kKey) == nullptr) << "taken as the table";
  ASSERT_NE(FilmTable::cached(kKey, folder.path()), nullptr);  // rename over a folder fails: not written
  fs::remove(file);
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  EXPECT_TRUE(FilmTable::read(file, kKey) == nullptr) << "taken as the table";
}

TEST(FilmTableCache, EveryKeyFieldAndTheLibraryVersionChangeTheFileName) {
  const auto next = [](double x) { return std::nextafter(x, 1.0); };  // the smallest change a double can make
  const FilmTableKey k = kKey;
  const FilmTableKey variants[] = {
      {next(k.journal_radius), k.radial_clearance, k.width, k.circumferential_cells, k.axial_cells, k.cavitation},
      {k.journal_radius, next(k.radial_clearance), k.width, k.circumferential_cells, k.axial_cells, k.cavitation},
      {k.journal_radius, k.radial_clearance, next(k.width), k.circumferential_cells, k.axial_cells, k.cavitation},
      {k.journal_radius, k.radial_clearance, k.width, k.circumferential_cells + 1, k.axial_cells, k.cavitation},
      {k.journal_radius, k.radial_clearance, k.width, k.circumferential_cells, k.axial_cells + 1, k.cavitation},
      {k.journal_radius, k.radial_clearance, k.width, k.circumferential_cells, k.axial_cells,
       CavitationModel::mass_conserving},
  };
  std::set<fs::path> names = {FilmTable::cache_file_name(k)};
  for (const FilmTableKey& v : variants) names.insert(FilmTable::cache_file_name(v));
  EXPECT_EQ(names.size(), std::size(variants) + 1);
  EXPECT_EQ(FilmTable::cache_file_name(k), FilmTable::cache_file_name(FilmTableKey(k))) << "stable";
  // The constants and versions are in the key text the name hashes (and the file holds whole).
  const std::string text = FilmTable::cache_key(k);
  for (const std::string& part : {std::string("library " CLEARJOINT_VERSION_STRING "\n"), std::string("format 1\n"),
                                 "eccentricity_nodes " + std::to_string(kTableEccentricityNodes) + "\n",
                                 "error_directions " + std::to_string(kTableErrorDirections) + "\n",
                                 std::string("largest_eccentricity_ratio 1.f5c28f5c28f5cp-1\n"),
                                 std::string("journal_radius 1.4467381d7dbf5p-7\n")}) {
    EXPECT_NE(text.find(part), std::string::npos) << part << " in\n" << text;
  }
}

TEST(FilmTableCache, TheFileNameIsTheFnv1aHashOfTheKeyText) {
  // FNV-1a 64 of "a" is af63dc4c8601ec8c (the reference vectors of draft-eastlake-fnv); the
  // name's hash is of the key text, so the same key gives the same name in any build.
  const std::string name = FilmTable::cache_file_name(kKey).string();
  EXPECT_EQ(name.rfind("film-table-", 0), 0u) << name;
  EXPECT_EQ(name.size(), std::string("film-table-").size() + 16 + std::string(".bin").size()) << name;
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char c : FilmTable::cache_key(kKey)) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  EXPECT_EQ(name, "film-table-" + std::string(hex) + ".bin");
}

}  // namespace
}  // namespace clearjoint::lubrication
