// SPDX-License-Identifier: BSD-3-Clause
// The band LU of the Reynolds grid, by its residual and against Eigen's dense partial-pivoting
// LU: random band
// matrices, one whose leading entry is zero (a row exchange is required), a tridiagonal one,
// a 1 x 1 one, and a singular one.
#include "band_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

namespace clearjoint::lubrication::detail {
namespace {

// Gaussian elimination with partial pivoting is backward stable: the residual is a modest
// multiple of the unit roundoff times |A| |x| (Higham, Accuracy and Stability of Numerical
// Algorithms, thm. 9.5), whatever the condition number (random triangular matrices have huge
// ones). 1e-13 leaves a factor of about 500 over 2^-52.
constexpr double kBackwardError = 1e-13;

struct Filled {
  BandLu band;
  Eigen::MatrixXd dense;
};

Filled random_band(int n, int lower, int upper, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Filled f;
  f.band.resize(n, lower, upper);
  f.dense = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = std::max(0, j - upper); i <= std::min(n - 1, j + lower); ++i) {
      const double a = entry(random);
      f.dense(i, j) = a;
      f.band.values()[f.band.slot(i, j)] = a;
    }
  }
  return f;
}

void expect_solves_like_dense(Filled& f, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::VectorXd b(f.dense.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = entry(random);
  const Eigen::VectorXd dense_x = f.dense.partialPivLu().solve(b);
  ASSERT_TRUE(f.band.factorize());
  Eigen::VectorXd x = b;
  f.band.solve(x.data());
  const double scale = f.dense.norm() * x.norm();
  EXPECT_LT((f.dense * x - b).norm(), kBackwardError * scale);
  // And no worse than the dense LU's own residual, within the same margin.
  EXPECT_LT((f.dense * x - b).norm(), (f.dense * dense_x - b).norm() + kBackwardError * scale);
}

TEST(BandLu, SolvesRandomBandMatricesLikeTheDenseLu) {
  for (const auto& [n, lower, upper] : {std::tuple{50, 3, 2}, std::tuple{40, 7, 7},
                                        std::tuple{30, 0, 4}, std::tuple{30, 4, 0}}) {
    Filled f = random_band(n, lower, upper, 7u + n);
    expect_solves_like_dense(f, 11u + n);
  }
}

TEST(BandLu, ExchangesRowsWhenTheDiagonalEntryIsZero) {
  Filled f = random_band(20, 3, 3, 3u);
  f.dense(0, 0) = 0.0;
  f.band.values()[f.band.slot(0, 0)] = 0.0;
  f.dense(5, 5) = 1e-14;  // a tiny pivot that partial pivoting must not keep
  f.band.values()[f.band.slot(5, 5)] = 1e-14;
  expect_solves_like_dense(f, 5u);
}

TEST(BandLu, SolvesATridiagonalAndAOneByOneMatrix) {
  Filled tridiagonal = random_band(25, 1, 1, 13u);
  expect_solves_like_dense(tridiagonal, 17u);
  Filled single = random_band(1, 0, 0, 19u);
  expect_solves_like_dense(single, 23u);
}

TEST(BandLu, ReportsASingularMatrix) {
  BandLu band;
  band.resize(6, 1, 1);  // all zero
  EXPECT_FALSE(band.factorize());
  Filled f = random_band(6, 1, 1, 29u);
  for (int i = 0; i < 6; ++i) {  // a zero column
    if (std::abs(i - 3) <= 1) f.band.values()[f.band.slot(i, 3)] = 0.0;
  }
  EXPECT_FALSE(f.band.factorize());
}

}  // namespace
}  // namespace clearjoint::lubrication::detail
