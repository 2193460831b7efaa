// SPDX-License-Identifier: BSD-3-Clause
// --write-fclib: a short Moreau-Jean run's contact problems written as FCLIB files, read back
// with FCLIB's own reader, and solved again by Siconos's fc3d.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <string>

// fclib.h declares C functions without extern "C".
extern "C" {
#include <fclib.h>
}

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_file.hpp"
#include "clearjoint/nonsmooth/fclib_export.hpp"
#include "clearjoint/nonsmooth/moreau_jean.hpp"
#include "contact_problem.hpp"

namespace clearjoint::nonsmooth {
namespace {

constexpr double kTolerance = 1e-10;     // fc3d's relative residual, as the model file sets it
constexpr int kMaxIterations = 1000;     // NSGS sweeps, as the model file sets it
constexpr long kProblems = 3;

/// The journal of test_moreau_jean.cpp falling at 0.5 m/s onto its bearing's wall (first
/// contact after about 0.2 ms), with friction so that the tangential part of W and r matters.
dynamics::ModelDescription falling_journal() {
  return dynamics::parse_model(R"({"name": "falling journal", "gravity": [0, -9.81, 0],
    "bodies": [{"name": "journal", "mass": 0.5, "inertia": [1e-4, 1e-4, 2e-5],
                "position": [0, 0, 0], "velocity": [0.1, -0.5, 0], "angular_velocity": [0, 0, 50]}],
    "forces": [{"type": "clearance_revolute", "name": "joint",
      "bearing": {"body": "ground", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.01, "length": 0.02},
      "journal": {"body": "journal", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.0099, "length": 0.0198},
      "normal_force": {"model": "hertz", "stiffness": 1e11, "exponent": 1.5, "restitution": 0.5},
      "friction": {"coefficient": 0.3}}],
    "solver": {"method": "moreau_jean", "step": 1e-5, "contact_tolerance": 1e-10,
               "contact_max_iterations": 1000}})",
                               "test");
}

std::filesystem::path fresh_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  return folder;
}

/// W as FCLIB holds it (compressed columns, compressed rows or triplets), dense.
Eigen::MatrixXd dense(const fclib_matrix& m) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(m.m, m.n);
  if (m.nz == -1) {
    for (int j = 0; j < m.n; ++j)
      for (int k = m.p[j]; k < m.p[j + 1]; ++k) out(m.i[k], j) += m.x[k];
  } else if (m.nz == -2) {
    for (int i = 0; i < m.m; ++i)
      for (int k = m.p[i]; k < m.p[i + 1]; ++k) out(i, m.i[k]) += m.x[k];
  } else {
    for (int k = 0; k < m.nz; ++k) out(m.p[k], m.i[k]) += m.x[k];
  }
  return out;
}

struct Written {
  long step = 0;
  Eigen::MatrixXd W;
  Eigen::VectorXd q, mu, r, u;
};

TEST(FclibExport, WritesProblemsThatReadBackAndSolveToTheSameSolution) {
  const auto folder = fresh_folder("clearjoint_fclib");
  MoreauJean scheme(falling_journal());
  scheme.write_fclib({folder, kProblems});
  for (int k = 0; k < 100 && scheme.time() < 1e-3; ++k) scheme.step();
  ASSERT_GE(scheme.statistics().contact_problems, kProblems);
  EXPECT_EQ(scheme.statistics().fclib_problems_written, kProblems);

  long files = 0;
  long with_percussion = 0;  // a contact in the index set may open in the step with r = 0
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    ++files;
    const std::string path = entry.path().string();
    ASSERT_EQ(entry.path().extension(), ".hdf5") << path;
    fclib_local* problem = fclib_read_local(path.c_str());
    ASSERT_NE(problem, nullptr) << path;
    fclib_solution* solution = fclib_read_solution(path.c_str());
    ASSERT_NE(solution, nullptr) << path;
    ASSERT_EQ(problem->spacedim, 3);
    ASSERT_NE(problem->W, nullptr);
    const Eigen::MatrixXd W = dense(*problem->W);
    const int n = static_cast<int>(W.rows());
    ASSERT_EQ(n % 3, 0);
    ASSERT_GT(n, 0);
    const Eigen::Map<const Eigen::VectorXd> q(problem->q, n), mu(problem->mu, n / 3), r_file(solution->r, n),
        u_file(solution->u, n);
    // The problem as the scheme posed it: symmetric W, u = W r + q at the solution written.
    EXPECT_LE((W - W.transpose()).norm(), 1e-12 * W.norm()) << path;
    EXPECT_LE((W * r_file + q - u_file).norm(), 1e-9 * (q.norm() + 1e-12)) << path;
    for (int c = 0; c < n / 3; ++c) EXPECT_DOUBLE_EQ(mu[c], 0.3) << path;
    if (r_file.norm() > 0.0) ++with_percussion;

    // Solved again from the read problem by the same solver and tolerance.
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n), u;
    const ContactSolve solve = solve_contact_problem(W, q, mu, kTolerance, kMaxIterations, r, u);
    EXPECT_TRUE(solve.converged) << path;
    const double scale = r_file.norm();
    EXPECT_LE((r - r_file).norm(), 1e3 * kTolerance * scale + 1e-15) << path;
    EXPECT_LE((u - u_file).norm(), 1e3 * kTolerance * (u_file.norm() + q.norm()) + 1e-15) << path;
    fclib_delete_local(problem);
    fclib_delete_solutions(solution, 1);
  }
  EXPECT_EQ(files, kProblems);
  EXPECT_GT(with_percussion, 0);
  std::filesystem::remove_all(folder);
}

TEST(FclibExport, WritesTheFirstStepsWithAContactAndNoOthers) {
  const auto folder = fresh_folder("clearjoint_fclib_first");
  MoreauJean scheme(falling_journal());
  scheme.write_fclib({folder, 1});
  long first_contact_step = 0;
  for (int k = 1; k <= 100 && first_contact_step == 0; ++k) {
    scheme.step();
    if (!scheme.contacts().empty()) first_contact_step = k;
  }
  ASSERT_GT(first_contact_step, 0);
  for (int k = 0; k < 20; ++k) scheme.step();
  const FclibExport fclib{folder, 1};
  EXPECT_TRUE(std::filesystem::exists(fclib_problem_path(fclib, first_contact_step)));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()), 1);
  std::filesystem::remove_all(folder);
}

TEST(FclibExport, RefusesAFolderThatIsAFileNamingTheOption) {
  const auto file = fresh_folder("clearjoint_fclib_file");
  std::ofstream(file) << "not a folder";
  MoreauJean scheme(falling_journal());
  try {
    scheme.write_fclib({file, kProblems});
    FAIL() << "no error";
  } catch (const dynamics::ModelError& e) {
    EXPECT_EQ(std::string(e.what()), "--write-fclib = '" + file.string() + "': not a folder");
  }
  std::filesystem::remove(file);
}

TEST(FclibExport, RefusesAFolderThatCannotBeCreatedNamingTheOption) {
  MoreauJean scheme(falling_journal());
  try {
    scheme.write_fclib({"/nonexistent-parent/fclib", kProblems});
    FAIL() << "no error";
  } catch (const dynamics::ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("--write-fclib = '/nonexistent-parent/fclib': cannot create the folder"),
              std::string::npos)
        << e.what();
  }
}

TEST(FclibExport, RefusesACountBelowOne) {
  MoreauJean scheme(falling_journal());
  EXPECT_THROW(scheme.write_fclib({std::filesystem::temp_directory_path(), 0}), dynamics::ModelError);
}

}  // namespace
}  // namespace clearjoint::nonsmooth
