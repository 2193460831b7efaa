// SPDX-License-Identifier: BSD-3-Clause
// FilmTable's file cache (film_table.hpp, docs/lubrication.md): the folder, the file's name and
// layout, reading a file back without trusting it, and writing one atomically.
//
// The file, in the machine's byte order (the byte-order mark is part of the compared header):
//   "CJFILMTB"  u32 format  u32 0x01020304  u32 key bytes  key text (FilmTable::cache_key)
//   u32 eps nodes  u32 interval count  u64 field values
//   f64 error_bound  f64 interval_errors[interval count]  f64 fields[field values]
//   u32 CRC-32 (Boost.CRC's crc_32_type: the zlib/PNG CRC) of everything before it
// Everything up to the field values is determined by the key, so a reader builds the header it
// expects and compares it byte for byte, and knows the file's whole size before reading it.

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include <boost/crc.hpp>

#include "clearjoint/lubrication/film_table.hpp"

namespace clearjoint::lubrication {

namespace {

constexpr std::string_view kMagic = "CJFILMTB";
constexpr std::uint32_t kByteOrderMark = 0x01020304;

/// FNV-1a, 64 bits (Fowler, Noll, Vo; the IETF draft-eastlake-fnv): a stable, well-spread hash in
/// five lines. std::hash may differ between builds, and boost::hash's values are not promised
/// stable across Boost versions; a collision is harmless (the full key is compared on read).
std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  return hash;
}

template <class T>
void put(std::string& out, const T& value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

/// Everything before the values: what a file for this table must start with, byte for byte.
std::string header(const std::string& key_text, std::size_t intervals, std::size_t field_values) {
  std::string out(kMagic);
  put(out, FilmTable::kCacheFormat);
  put(out, kByteOrderMark);
  put(out, static_cast<std::uint32_t>(key_text.size()));
  out += key_text;
  put(out, static_cast<std::uint32_t>(kTableEccentricityNodes));
  put(out, static_cast<std::uint32_t>(intervals));
  put(out, static_cast<std::uint64_t>(field_values));
  return out;
}

std::uint32_t crc32(const char* data, std::size_t size) {
  boost::crc_32_type crc;
  crc.process_bytes(data, size);
  return crc.checksum();
}

/// Reads exactly `size` bytes of a regular file whose size is exactly `size`, else nothing.
/// O_NONBLOCK: a FIFO planted under the name must not hang the open.
std::optional<std::string> read_exactly(const std::filesystem::path& file, std::size_t size) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::nullopt;
  struct stat info {};
  std::optional<std::string> bytes;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && static_cast<std::uintmax_t>(info.st_size) == size) {
    std::string buffer(size, '\0');
    std::size_t done = 0;
    while (done < size) {
      const ssize_t n = ::read(fd, buffer.data() + done, size - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    if (done == size) bytes = std::move(buffer);
  }
  ::close(fd);
  return bytes;
}

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

std::optional<std::filesystem::path> film_table_cache_folder() {
  if (const char* dir = std::getenv("CLEARJOINT_CACHE_DIR")) {
    if (*dir == '\0') return std::nullopt;  // switched off
    return std::filesystem::path(dir);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && std::filesystem::path(xdg).is_absolute()) {
    return std::filesystem::path(xdg) / "clearjoint";
  }
  if (const char* home = std::getenv("HOME"); home && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "clearjoint";
  }
  return std::nullopt;
}

std::filesystem::path FilmTable::cache_file_name(const FilmTableKey& key) {
  std::array<char, 17> hex{};
  std::snprintf(hex.data(), hex.size(), "%016llx", static_cast<unsigned long long>(fnv1a(cache_key(key))));
  return "film-table-" + std::string(hex.data()) + ".bin";
}

std::shared_ptr<const FilmTable> FilmTable::read(const std::filesystem::path& file, const FilmTableKey& key) {
  // The sizes come from the key (validated here, throwing as a build would), never from the file.
  std::shared_ptr<FilmTable> table(new FilmTable(key, Unsampled{}));
  const std::string expected =
      header(cache_key(key), table->interval_errors_.size(), table->fields_.size());
  const std::size_t values = 1 + table->interval_errors_.size() + table->fields_.size();
  const std::size_t size = expected.size() + values * sizeof(double) + sizeof(std::uint32_t);
  const std::optional<std::string> bytes = read_exactly(file, size);
  if (!bytes || bytes->compare(0, expected.size(), expected) != 0) return nullptr;
  std::uint32_t stored_crc = 0;
  std::memcpy(&stored_crc, bytes->data() + size - sizeof stored_crc, sizeof stored_crc);
  if (stored_crc != crc32(bytes->data(), size - sizeof stored_crc)) return nullptr;
  const char* at = bytes->data() + expected.size();
  std::memcpy(&table->error_bound_, at, sizeof(double));
  at += sizeof(double);
  std::memcpy(table->interval_errors_.data(), at, table->interval_errors_.size() * sizeof(double));
  at += table->interval_errors_.size() * sizeof(double);
  std::memcpy(table->fields_.data(), at, table->fields_.size() * sizeof(double));
  // A table's errors are non-negative and its bound is their largest (measure_error).
  const auto& errors = table->interval_errors_;
  if (!all_finite(errors) || !all_finite(table->fields_) ||
      std::any_of(errors.begin(), errors.end(), [](double e) { return e < 0.0; }) ||
      table->error_bound_ != *std::max_element(errors.begin(), errors.end())) {
    return nullptr;
  }
  if (!table->agrees_with_grid_at_spot_nodes()) return nullptr;
  return table;
}

bool FilmTable::write(const std::filesystem::path& folder) const {
  std::string bytes = header(cache_key(key_), interval_errors_.size(), fields_.size());
  put(bytes, error_bound_);
  for (const double e : interval_errors_) put(bytes, e);
  bytes.append(reinterpret_cast<const char*>(fields_.data()), fields_.size() * sizeof(double));
  put(bytes, crc32(bytes.data(), bytes.size()));

  std::error_code error;
  std::filesystem::create_directories(folder, error);
  const std::filesystem::path target = folder / cache_file_name(key_);
  // mkstemp: a name no other writer holds, in the target's folder so that rename is atomic.
  std::string temporary = (folder / (cache_file_name(key_).string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) return false;
  const bool written = write_all(fd, bytes) && ::fsync(fd) == 0;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed || std::rename(temporary.c_str(), target.c_str()) != 0) {
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

std::shared_ptr<const FilmTable> FilmTable::cached(const FilmTableKey& key,
                                                   const std::optional<std::filesystem::path>& folder) {
  if (folder) {
    if (auto table = read(*folder / cache_file_name(key), key)) return table;
  }
  auto table = std::make_shared<const FilmTable>(key);
  if (folder) table->write(*folder);  // a cache that cannot be written costs the next process a build, nothing more
  return table;
}

}  // namespace clearjoint::lubrication
