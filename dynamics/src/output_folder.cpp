// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace clearjoint::dynamics {

namespace fs = std::filesystem;

namespace {

std::runtime_error failure(const fs::path& path, const std::string& what, int error_number) {
  return std::runtime_error(path.string() + ": " + what + " (" + std::strerror(error_number) + ")");
}

/// `destination` as an absolute path without "." or ".." parts or a trailing '/', so that its
/// leaf name and its parent are well defined ("out/", "./out", "results/..").
fs::path normalised(const fs::path& destination) {
  if (destination.empty()) throw std::runtime_error("the output folder name is empty");
  fs::path path = fs::absolute(destination).lexically_normal();
  if (!path.has_filename()) path = path.parent_path();  // "out/" -> "out"
  if (path == path.root_path()) {
    throw std::runtime_error(destination.string() + ": cannot be an output folder (no parent)");
  }
  return path;
}

fs::path sibling(const fs::path& destination, const std::string& suffix) {
  std::string name = ".";  // built piecewise: "." + std::string trips GCC 12's -Wrestrict
  name += destination.filename().string();
  name += suffix;
  return destination.parent_path() / name;
}

/// Cleans up after dead runs next to `destination`. Called with the lock held, so that no live
/// run owns any of these names. A run killed inside the two-rename fallback of publish() left
/// its previous result as .<leaf>.replaced and no destination: that result is put back first.
void remove_stale_staging(const fs::path& destination) {
  const std::string leaf = destination.filename().string();
  const fs::path replaced = sibling(destination, ".replaced");
  std::error_code error;
  if (fs::exists(fs::symlink_status(replaced, error))) {
    if (!fs::exists(fs::symlink_status(destination, error))) {
      fs::rename(replaced, destination, error);
    }
    fs::remove_all(replaced, error);
  }
  std::string prefix = ".";
  prefix += leaf;
  prefix += ".staging-";
  for (const fs::directory_entry& entry : fs::directory_iterator(destination.parent_path(), error)) {
    if (entry.path().filename().string().starts_with(prefix)) {
      std::error_code ignored;
      fs::remove_all(entry.path(), ignored);
    }
  }
}

/// Whether `path` is the current working folder or one of its ancestors: renaming it away would
/// pull the floor from under the user's shell (`--out .`, `--out ..`, `--out ~` from inside it).
bool holds_working_folder(const fs::path& path) {
  std::error_code error;
  const fs::path working = fs::current_path(error);
  if (error) return false;
  for (fs::path folder = working; !folder.empty(); folder = folder.parent_path()) {
    if (fs::equivalent(folder, path, error)) return true;
    if (folder == folder.root_path()) break;
  }
  return false;
}

/// Whether `path` is a mount point (its device differs from its parent's): a rename cannot
/// replace it, so publish() would fail after the whole run.
bool is_mount_point(const fs::path& path) {
  struct stat own {}, parent {};
  if (::lstat(path.c_str(), &own) != 0 || ::stat(path.parent_path().c_str(), &parent) != 0) return false;
  return own.st_dev != parent.st_dev;
}

/// Whether `folder` is an earlier result: it holds the marker file as a regular file (not a
/// link, so that a link cannot lend a user's folder the marker).
bool is_earlier_result(const fs::path& folder) {
  std::error_code error;
  return fs::is_regular_file(fs::symlink_status(folder / OutputFolder::kMarkerName, error));
}

/// Files named in a refusal; the rest are counted ("and 12 more").
constexpr std::size_t kNamedFiles = 3;
/// Longest manifest entry [bytes]: Linux's PATH_MAX, the longest path a system call takes.
constexpr std::size_t kMaxEntryBytes = 4096;

std::runtime_error not_clearjoints_manifest(const fs::path& destination, const std::string& why) {
  return std::runtime_error(destination.string() + ": its " + OutputFolder::kMarkerName +
                            " is not a manifest clearjoint wrote (" + why +
                            "); --force replaces only an earlier result: choose another --out, or move the "
                            "folder away yourself");
}

/// Why `entry` is not a path inside the folder, or "" when it is one.
std::string entry_problem(const std::string& entry) {
  if (entry.empty()) return "an empty entry";
  if (entry.size() > kMaxEntryBytes) return "an entry longer than " + std::to_string(kMaxEntryBytes) + " bytes";
  if (entry.find('\0') != std::string::npos) return "an entry holding a NUL byte";
  if (entry.front() == '/') return "the absolute entry \"" + entry.substr(0, 200) + "\"";
  size_t start = 0;
  while (start <= entry.size()) {
    const size_t end = std::min(entry.find('/', start), entry.size());
    const std::string part = entry.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") {
      return "the entry \"" + entry.substr(0, 200) + "\", which does not name a file inside the folder";
    }
    start = end + 1;
  }
  return "";
}

/// The entries of `destination`'s manifest (format: output_folder.hpp). Read through a
/// descriptor opened without following a link, at most kMaxManifestBytes + 1 bytes.
std::set<std::string> read_manifest(const fs::path& destination) {
  const fs::path path = destination / OutputFolder::kMarkerName;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw failure(path, "cannot read the result's manifest", errno);
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    throw not_clearjoints_manifest(destination, "not a regular file");
  }
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int error_number = errno;
      ::close(fd);
      throw failure(path, "cannot read the result's manifest", error_number);
    }
    if (got == 0) break;
    text.append(buffer, static_cast<size_t>(got));
    if (text.size() > OutputFolder::kMaxManifestBytes) {
      ::close(fd);
      throw not_clearjoints_manifest(destination, "larger than " + std::to_string(OutputFolder::kMaxManifestBytes) +
                                                      " bytes");
    }
  }
  ::close(fd);
  const size_t header_end = text.find('\n');
  if (header_end == std::string::npos || !text.starts_with(OutputFolder::kManifestHeader)) {
    throw not_clearjoints_manifest(destination, std::string("its first line is not \"") +
                                                    OutputFolder::kManifestHeader +
                                                    " ...\"; results of a clearjoint older than the "
                                                    "manifest have none");
  }
  std::set<std::string> entries;
  size_t line_number = 1;
  for (size_t start = header_end + 1; start < text.size();) {
    ++line_number;
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string entry = text.substr(start, end - start);
    start = end + 1;
    if (const std::string problem = entry_problem(entry); !problem.empty()) {
      throw not_clearjoints_manifest(destination, "line " + std::to_string(line_number) + ": " + problem);
    }
    entries.insert(std::move(entry));
  }
  return entries;
}

/// Every file (anything but a folder, links included, which are never followed) under `folder`,
/// as '/'-separated paths relative to it, the marker aside, passed to `visit`.
template <class Visit>
void for_each_file(const fs::path& folder, Visit&& visit) {
  std::error_code error;
  fs::recursive_directory_iterator it(folder, fs::directory_options::none, error);
  for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    std::error_code status_error;
    if (fs::is_directory(it->symlink_status(status_error))) continue;
    const std::string relative = it->path().lexically_relative(folder).generic_string();
    if (relative != OutputFolder::kMarkerName) visit(relative);
  }
  if (error) {
    throw std::runtime_error(folder.string() + ": cannot list the folder's files (" + error.message() +
                             "); --force replaces only a result it can check");
  }
}

/// Refuses a destination that holds anything but an earlier result, or an earlier result beside
/// files its manifest does not list: --force replaces what runs wrote, never a user's files
/// (docs/command-line.md, "Output folder").
void require_replaceable(const fs::path& destination) {
  std::error_code error;
  if (fs::is_empty(destination, error)) return;
  if (!is_earlier_result(destination)) {
    throw std::runtime_error(destination.string() + ": holds files that are not a clearjoint result (no " +
                             OutputFolder::kMarkerName +
                             " marker); --force replaces only an earlier result: choose another --out, "
                             "or move those files away yourself");
  }
  const std::set<std::string> listed = read_manifest(destination);
  std::vector<std::string> named;
  size_t unlisted = 0;
  // The first kNamedFiles in name order, whatever order the directory lists them in.
  for_each_file(destination, [&](const std::string& file) {
    if (listed.contains(file)) return;
    ++unlisted;
    named.insert(std::upper_bound(named.begin(), named.end(), file), file);
    if (named.size() > kNamedFiles) named.pop_back();
  });
  if (unlisted == 0) return;
  std::string list;
  for (const std::string& file : named) list += (list.empty() ? "" : ", ") + file;
  if (unlisted > named.size()) list += " and " + std::to_string(unlisted - named.size()) + " more";
  throw std::runtime_error(destination.string() + ": holds files no clearjoint run wrote (" + list +
                           "); --force replaces only the files listed in an earlier result's " +
                           OutputFolder::kMarkerName + ": move those files out of the folder, or choose "
                           "another --out");
}

/// Everything that refuses `destination` as it is now; creates nothing.
void require_usable(const fs::path& destination, bool replace_existing) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(destination, error);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw std::runtime_error(destination.string() + ": exists and is not a folder");
  }
  if (is_mount_point(destination)) {
    throw std::runtime_error(destination.string() +
                             ": is a mount point, which a run cannot replace (the results are "
                             "published by renaming a folder over it); choose a folder inside it");
  }
  if (!replace_existing && !fs::is_empty(destination, error)) {
    throw std::runtime_error(destination.string() +
                             ": the folder exists and is not empty (an earlier result?); "
                             "use --force to replace it");
  }
  require_replaceable(destination);
}

/// `destination`, or the folder it links to when it is a symbolic link: a run is published at
/// the link's target, next to which its lock and staging folder go, and the link stays.
fs::path resolved(const fs::path& destination) {
  std::error_code error;
  if (!fs::is_symlink(fs::symlink_status(destination, error))) return destination;
  const fs::path target = fs::canonical(destination, error);
  if (error) {
    const fs::path link = fs::read_symlink(destination, error);
    throw std::runtime_error(destination.string() + ": is a symbolic link to " + link.string() +
                             ", which does not lead to a folder; create that folder, or give --out a "
                             "folder's own name");
  }
  if (!fs::is_directory(target, error)) {
    throw std::runtime_error(destination.string() + ": is a symbolic link to " + target.string() +
                             ", which is not a folder");
  }
  return target;
}

/// A name no other staging folder has: the process id and 64 random bits.
fs::path fresh_staging(const fs::path& destination) {
  std::random_device device;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const unsigned long long tag =
        (static_cast<unsigned long long>(device()) << 32) ^ static_cast<unsigned long long>(device());
    char suffix[64];
    std::snprintf(suffix, sizeof suffix, ".staging-%ld-%016llx", static_cast<long>(::getpid()), tag);
    const fs::path path = sibling(destination, suffix);
    if (::mkdir(path.c_str(), 0777) == 0) return path;
    if (errno != EEXIST) throw failure(path, "cannot create the staging folder", errno);
  }
  throw std::runtime_error(destination.string() + ": cannot find a free staging folder name");
}

/// The manifest (output_folder.hpp) that makes a published folder recognisable as a result:
/// its header, then `files`, one a line.
void write_manifest(const fs::path& staging, const std::vector<std::string>& files, const char* mode) {
  const fs::path marker = staging / OutputFolder::kMarkerName;
  std::FILE* file = std::fopen(marker.c_str(), mode);
  if (file == nullptr) throw failure(marker, "cannot create the result marker", errno);
  bool written = std::fprintf(file,
                              "%s: the files clearjoint wrote into this folder; `clearjoint simulate --force` "
                              "replaces the folder only while it holds nothing else\n",
                              OutputFolder::kManifestHeader) >= 0;
  for (const std::string& entry : files) {
    written = written && std::fputs(entry.c_str(), file) >= 0 && std::fputc('\n', file) != EOF;
  }
  if (std::fclose(file) != 0 || !written) throw failure(marker, "cannot write the result marker", errno);
}

}  // namespace

OutputFolder::OutputFolder(const fs::path& destination, bool replace_existing)
    : destination_(resolved(normalised(destination))) {
  std::error_code error;
  if (holds_working_folder(destination_)) {
    throw std::runtime_error(destination.string() +
                             ": is the current folder or one of its parents, which cannot be an "
                             "output folder (publishing replaces the folder); choose a new folder "
                             "inside it, e.g. --out results");
  }
  // Every refusal before anything is created (the lock file, a parent folder): a refused run
  // leaves the file system as it was. Checked again below, under the lock.
  require_usable(destination_, replace_existing);
  if (!fs::is_directory(destination_.parent_path(), error)) {
    fs::create_directories(destination_.parent_path(), error);
    if (error) {
      throw std::runtime_error(destination_.parent_path().string() +
                               ": cannot create the folder (" + error.message() + ")");
    }
  }
  const fs::path lock = sibling(destination_, ".lock");
  // Read-only is enough for flock, so another user of a shared, group-writable folder can lock a
  // lock file the first user created (with the usual umask, 0644).
  lock_fd_ = ::open(lock.c_str(), O_RDONLY | O_CREAT | O_CLOEXEC, 0666);
  if (lock_fd_ < 0) throw failure(lock, "cannot create the lock file", errno);
  // flock is released by the kernel when the process ends, however it ends: a dead run never
  // leaves a stale lock.
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error_number = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (error_number == EWOULDBLOCK) {
      throw std::runtime_error(destination_.string() +
                               ": another run is writing this output folder (its lock " +
                               lock.string() + " is held); wait for it or choose another --out");
    }
    throw failure(lock, "cannot lock", error_number);
  }
  try {
    // A dead run's earlier result may be put back, and another run may have published since the
    // first check: the checks again, now that no other run can change the destination.
    remove_stale_staging(destination_);
    require_usable(destination_, replace_existing);
    staging_ = fresh_staging(destination_);
    write_manifest(staging_, {}, "wx");
  } catch (...) {
    ::close(lock_fd_);
    throw;
  }
}

OutputFolder::~OutputFolder() {
  if (!published_ && !staging_.empty()) {
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
  }
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

void OutputFolder::publish() {
  std::vector<std::string> files;
  for_each_file(staging_, [&files](const std::string& file) { files.push_back(file); });
  std::sort(files.begin(), files.end());
  write_manifest(staging_, files, "w");
  // Checked again just before the swap: the folder may have been filled since the constructor.
  std::error_code error;
  if (fs::exists(fs::symlink_status(destination_, error))) require_replaceable(destination_);
  // Exchange when the destination exists: at every instant one of the two names holds the
  // complete previous result and the other the complete new one. renameat2(RENAME_EXCHANGE)
  // is Linux's (glibc 2.28+); std::filesystem has no atomic exchange, hence the system call.
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, destination_.c_str(), RENAME_EXCHANGE) == 0) {
    published_ = true;
    fs::remove_all(staging_, error);  // now the previous result; a leftover is removed next run
    return;
  }
  if (errno == EINVAL || errno == ENOSYS) {
    // A file system without the exchange: move the previous result aside, then rename. Killed
    // in between, the next run puts the previous result back (remove_stale_staging).
    const fs::path replaced = sibling(destination_, ".replaced");
    if (::rename(destination_.c_str(), replaced.c_str()) != 0) {
      throw failure(destination_, "cannot move the previous results aside", errno);
    }
    if (::rename(staging_.c_str(), destination_.c_str()) != 0) {
      const int error_number = errno;
      ::rename(replaced.c_str(), destination_.c_str());
      throw failure(destination_, "cannot publish the results", error_number);
    }
    published_ = true;
    fs::remove_all(replaced, error);
    return;
  }
  if (errno != ENOENT) throw failure(destination_, "cannot publish the results", errno);
  // No destination yet: a plain rename that refuses to replace one created meanwhile.
  if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, destination_.c_str(), RENAME_NOREPLACE) != 0) {
    throw failure(destination_, "cannot publish the results", errno);
  }
  published_ = true;
}

}  // namespace clearjoint::dynamics
