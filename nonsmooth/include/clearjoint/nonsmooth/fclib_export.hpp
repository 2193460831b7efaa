// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Writing a Moreau-Jean run's frictional contact problems as FCLIB files (docs/nonsmooth.md,
/// "FCLIB problems"): the local form u = W r + q with the Coulomb cones of mu (dimension 3),
/// and the solution Siconos's fc3d found, one HDF5 file per selected step, through FCLIB's own
/// C library (libfclib-dev), so that other solvers can be run on the spatial clearance joint's
/// problems.

#include <filesystem>
#include <string>

namespace clearjoint::nonsmooth {

/// Default FclibExport::max_problems: a few hundred steps of an impact sequence is already a
/// collection; a 1 s run at h = 1e-5 has up to 1e5 contact problems, which no one wants as files.
inline constexpr long kDefaultFclibProblems = 100;
/// Largest FclibExport::max_problems: one file per step of a 1e6-step run.
inline constexpr long kMaxFclibProblems = 1000000;

/// Which steps are written: the first `max_problems` steps with at least one active contact
/// (a contact problem to solve), each as `folder/step_<k>.hdf5`, k the step's number counted
/// from 1 (the step ending at start_time + k h), zero-padded to 7 digits.
struct FclibExport {
  std::filesystem::path folder;  ///< empty: nothing written
  long max_problems = kDefaultFclibProblems;
};

/// Creates `folder` if it does not exist (its parent must) and checks that it is a folder one
/// can write into; throws dynamics::ModelError naming `option` and the value otherwise, or when
/// max_problems is outside [1, kMaxFclibProblems].
void prepare_fclib_folder(const FclibExport& fclib, const std::string& option);

/// The file of step k (FclibExport).
std::filesystem::path fclib_problem_path(const FclibExport& fclib, long step_number);

}  // namespace clearjoint::nonsmooth
