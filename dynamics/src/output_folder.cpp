// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/dynamics/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

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

/// Refuses a destination that holds anything but an earlier result: --force replaces results,
/// never a user's files (docs/command-line.md, "Output folder").
void require_replaceable(const fs::path& destination) {
  std::error_code error;
  if (fs::is_empty(destination, error) || is_earlier_result(destination)) return;
  throw std::runtime_error(destination.string() + ": holds files that are not a clearjoint result (no " +
                           OutputFolder::kMarkerName +
                           " marker); --force replaces only an earlier result: choose another --out, "
                           "or move those files away yourself");
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

/// The marker that makes a published folder recognisable as a result.
void write_marker(const fs::path& staging) {
  const fs::path marker = staging / OutputFolder::kMarkerName;
  std::FILE* file = std::fopen(marker.c_str(), "wx");
  if (file == nullptr) throw failure(marker, "cannot create the result marker", errno);
  const bool written = std::fputs("a clearjoint result folder: `clearjoint simulate --force` may replace it\n", file) >= 0;
  if (std::fclose(file) != 0 || !written) throw failure(marker, "cannot write the result marker", errno);
}

}  // namespace

OutputFolder::OutputFolder(const fs::path& destination, bool replace_existing)
    : destination_(normalised(destination)) {
  std::error_code error;
  if (holds_working_folder(destination_)) {
    throw std::runtime_error(destination.string() +
                             ": is the current folder or one of its parents, which cannot be an "
                             "output folder (publishing replaces the folder); choose a new folder "
                             "inside it, e.g. --out results");
  }
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
    remove_stale_staging(destination_);
    const fs::file_status status = fs::symlink_status(destination_, error);
    if (fs::exists(status)) {
      if (!fs::is_directory(status)) {
        throw std::runtime_error(destination_.string() + ": exists and is not a folder");
      }
      if (is_mount_point(destination_)) {
        throw std::runtime_error(destination_.string() +
                                 ": is a mount point, which a run cannot replace (the results are "
                                 "published by renaming a folder over it); choose a folder inside it");
      }
      if (!replace_existing && !fs::is_empty(destination_, error)) {
        throw std::runtime_error(destination_.string() +
                                 ": the folder exists and is not empty (an earlier result?); "
                                 "use --force to replace it");
      }
      require_replaceable(destination_);
    }
    staging_ = fresh_staging(destination_);
    write_marker(staging_);
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
