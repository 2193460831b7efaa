// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// One local frictional contact problem (contact_problem.hpp) and its solution, as an FCLIB
/// HDF5 file (fclib_write_local, then fclib_write_solution into the same file).

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace clearjoint::nonsmooth {

/// Writes W (dense, stored as FCLIB's compressed columns), q, mu (spacedim 3) with `title` and
/// `description` in the problem's info, then r and u as its solution. Throws
/// dynamics::SolverError naming the file when FCLIB reports a failure.
void write_fclib_problem(const std::filesystem::path& path, const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& mu, const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                         const std::string& title, const std::string& description);

}  // namespace clearjoint::nonsmooth
