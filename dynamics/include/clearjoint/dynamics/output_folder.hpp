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
///
/// A destination that is a symbolic link to a folder is resolved: the run is published at the
/// link's target (the names above sit next to the target) and the link stays as it was.
///
/// The marker file kMarkerName is also the result's manifest, the list of the files clearjoint
/// wrote into the folder. `replace_existing` replaces a folder only while it holds nothing else,
/// so that notes a user added inside an earlier result are never deleted with it. Format (text,
/// one entry a line, '\n'-terminated):
///
///   clearjoint result manifest 1            kManifestHeader, then anything up to the end of line
///   energy.csv                              a path relative to the folder, '/'-separated
///   figures/joint_pin.png                   (written by `clearjoint plot`, which appends its lines)
///
/// Directories are not listed: an empty folder inside a result is replaced with it. A manifest
/// larger than kMaxManifestBytes, without the header, or with an entry that is absolute, empty or
/// holds a "." or ".." component, is not one clearjoint wrote, and its folder is refused.

#include <cstddef>
#include <filesystem>

namespace clearjoint::dynamics {

class OutputFolder {
 public:
  /// The file every result folder holds (written into the staging folder), its manifest: only a
  /// folder with it (or an empty one) is replaced when `replace_existing` is set, and only while
  /// the folder holds no file the manifest does not list.
  static constexpr const char* kMarkerName = ".clearjoint-result";
  /// The manifest's first line starts with this text (the format's name and version).
  static constexpr const char* kManifestHeader = "clearjoint result manifest 1";
  /// Largest manifest read [bytes]. A run's files are named after the model's bodies and force
  /// elements, each of which takes more bytes of the model file than its manifest lines (its table,
  /// and a joint's two figures) take: twice the largest model file (model_file.hpp,
  /// kMaxModelFileBytes, 16 MiB) bounds every manifest clearjoint writes.
  static constexpr std::size_t kMaxManifestBytes = std::size_t{32} << 20;

  /// Refuses (std::runtime_error), before creating anything: the current folder and its parents,
  /// a mount point, a destination that exists and is not an empty folder unless
  /// `replace_existing`, and, even then, one that is not an earlier result (no kMarkerName, or a
  /// manifest that is not clearjoint's) or holds files its manifest does not list (named in the
  /// message). Then takes the destination's lock (throws if another run holds it), removes the
  /// staging folders of dead runs, and creates a fresh staging folder holding kMarkerName.
  OutputFolder(const std::filesystem::path& destination, bool replace_existing);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  /// Removes the staging folder unless published; releases the lock.
  ~OutputFolder();

  /// Where the run writes its files.
  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& destination() const { return destination_; }

  /// Writes the manifest (every file now in the staging folder), then makes the staging folder
  /// the destination in one rename (an atomic exchange when the destination exists) and removes
  /// the previous result. Checks again first that an existing destination is empty or an earlier
  /// result holding only what its manifest lists. Throws std::runtime_error.
  void publish();

 private:
  std::filesystem::path destination_;
  std::filesystem::path staging_;
  int lock_fd_ = -1;
  bool published_ = false;
};

}  // namespace clearjoint::dynamics
