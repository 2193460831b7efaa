// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// A run's output folder published as one unit. Files are written into a fresh staging folder
/// next to the destination; publish() swaps it in with one atomic rename, so that the destination
/// holds the complete previous result or the complete new one, whenever the process is killed.
///
/// Names next to the destination `<parent>/<leaf>` (docs/command-line.md, "Output folder"):
///   .<leaf>.lock           a lock file (flock) held while a run writes <leaf>; left in place
///   .<leaf>.staging-<id>   the run's files until publish(); left behind only by a killed run,
///                          and removed by the next run into the same destination
///   .<leaf>.replaced       the previous result, only for an instant on file systems without
///                          an atomic exchange (then put back by the next run if it was killed)

#include <filesystem>

namespace clearjoint::dynamics {

class OutputFolder {
 public:
  /// The file every result folder holds (written into the staging folder): only a folder with it
  /// (or an empty one) is replaced when `replace_existing` is set.
  static constexpr const char* kMarkerName = ".clearjoint-result";


  /// Takes the destination's lock (throws std::runtime_error if another run holds it), removes
  /// the staging folders of dead runs, and creates a fresh staging folder holding kMarkerName.
  /// Refuses (std::runtime_error) the current folder and its parents, a mount point, a
  /// destination that exists and is not an empty folder unless `replace_existing`, and, even
  /// then, one that is not an earlier result (no kMarkerName).
  OutputFolder(const std::filesystem::path& destination, bool replace_existing);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  /// Removes the staging folder unless published; releases the lock.
  ~OutputFolder();

  /// Where the run writes its files.
  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& destination() const { return destination_; }

  /// Makes the staging folder the destination in one rename (an atomic exchange when the
  /// destination exists), then removes the previous result. Checks again first that an existing
  /// destination is empty or an earlier result. Throws std::runtime_error.
  void publish();

 private:
  std::filesystem::path destination_;
  std::filesystem::path staging_;
  int lock_fd_ = -1;
  bool published_ = false;
};

}  // namespace clearjoint::dynamics
