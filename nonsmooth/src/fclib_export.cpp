// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/nonsmooth/fclib_export.hpp"

#include <unistd.h>

#include <cstdio>
#include <system_error>
#include <vector>

// fclib.h declares C functions without extern "C".
extern "C" {
#include <fclib.h>
}

#include "clearjoint/dynamics/errors.hpp"
#include "fclib_problem.hpp"

namespace clearjoint::nonsmooth {

void prepare_fclib_folder(const FclibExport& fclib, const std::string& option) {
  if (!(fclib.max_problems >= 1 && fclib.max_problems <= kMaxFclibProblems)) {
    throw dynamics::ModelError(option + " count = " + std::to_string(fclib.max_problems) + ": must be in [1, " +
                               std::to_string(kMaxFclibProblems) + "]");
  }
  const std::string named = option + " = '" + fclib.folder.string() + "'";
  if (fclib.folder.empty()) throw dynamics::ModelError(named + ": must name a folder");
  std::error_code error;
  if (!std::filesystem::exists(fclib.folder, error)) {
    std::filesystem::create_directory(fclib.folder, error);
    if (error) throw dynamics::ModelError(named + ": cannot create the folder (" + error.message() + ")");
  }
  if (!std::filesystem::is_directory(fclib.folder, error)) throw dynamics::ModelError(named + ": not a folder");
  if (::access(fclib.folder.c_str(), W_OK | X_OK) != 0) {
    throw dynamics::ModelError(named + ": the folder is not writable");
  }
}

std::filesystem::path fclib_problem_path(const FclibExport& fclib, long step_number) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%07ld.hdf5", step_number);
  return fclib.folder / name;
}

void write_fclib_problem(const std::filesystem::path& path, const Eigen::MatrixXd& W, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& mu, const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                         const std::string& title, const std::string& description) {
  const int n = static_cast<int>(W.rows());
  // W dense in FCLIB's compressed-column form (nz = -1): every entry stored, column by column,
  // as Eigen holds it.
  std::vector<int> column_start(static_cast<size_t>(n) + 1), row_index(static_cast<size_t>(n) * n);
  std::vector<double> values(W.data(), W.data() + static_cast<std::ptrdiff_t>(n) * n);
  for (int j = 0; j <= n; ++j) column_start[static_cast<size_t>(j)] = j * n;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) row_index[static_cast<size_t>(j) * n + i] = i;
  }
  fclib_matrix matrix{};
  matrix.nzmax = n * n;
  matrix.m = n;
  matrix.n = n;
  matrix.p = column_start.data();
  matrix.i = row_index.data();
  matrix.x = values.data();
  matrix.nz = -1;
  matrix.info = nullptr;
  // FCLIB's structures take non-const pointers; they are only read when writing.
  std::string title_text = title, description_text = description,
              math_text = "W symmetric positive semi-definite (Delassus operator of the active contacts)";
  fclib_info info{title_text.data(), description_text.data(), math_text.data()};
  Eigen::VectorXd q_copy = q, mu_copy = mu, r_copy = r, u_copy = u;
  fclib_local problem{};
  problem.W = &matrix;
  problem.mu = mu_copy.data();
  problem.q = q_copy.data();
  problem.spacedim = 3;
  problem.info = &info;
  const std::string file = path.string();
  if (fclib_write_local(&problem, file.c_str()) != 1) {
    throw dynamics::SolverError("--write-fclib: FCLIB could not write the problem to '" + file + "'");
  }
  fclib_solution solution{};
  solution.u = u_copy.data();
  solution.r = r_copy.data();
  if (fclib_write_solution(&solution, file.c_str()) != 1) {
    throw dynamics::SolverError("--write-fclib: FCLIB could not write the solution to '" + file + "'");
  }
}

}  // namespace clearjoint::nonsmooth
