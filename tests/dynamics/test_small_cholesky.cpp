// SPDX-License-Identifier: BSD-3-Clause
// The Schur matrix's Cholesky factorisation visits the blocks of joints on a shared body only
// (dynamics/src/small_cholesky.hpp), with the dense loops' results bit for bit.
#include "small_cholesky.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace clearjoint::dynamics::detail {
namespace {

struct Pattern {
  std::vector<int> column_start;
  std::vector<int> rows;
  CholeskyPattern view() const { return {column_start, rows}; }
};

/// The spatial slider-crank's joints: spherical (3), universal (4), translational (5), each
/// sharing a body with the next only.
Pattern chain_pattern() {
  Pattern p;
  const std::vector<int> sizes{3, 4, 5};
  block_pattern(sizes, [](int later, int earlier) { return later == earlier + 1; }, p.column_start, p.rows);
  return p;
}

TEST(CholeskyPattern, SkipsTheBlocksOfJointsThatShareNoBody) {
  const Pattern p = chain_pattern();
  // 66 entries below the diagonal of 12 x 12; the (joint 2, joint 0) block, 5 x 3, is zero.
  EXPECT_EQ(p.rows.size(), 66u - 15u);
  EXPECT_EQ(std::vector<int>(p.view().below(0).begin(), p.view().below(0).end()),
            (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(std::vector<int>(p.view().below(6).begin(), p.view().below(6).end()),
            (std::vector<int>{7, 8, 9, 10, 11}));
  EXPECT_TRUE(p.view().below(11).empty());
}

TEST(CholeskyPattern, AddsTheFillInOfBlocksCoupledThroughAnEarlierOne) {
  // Joints 1 and 2 both share a body with joint 0 only: eliminating joint 0 couples them.
  Pattern p;
  const std::vector<int> sizes{2, 1, 1};
  block_pattern(sizes, [](int, int earlier) { return earlier == 0; }, p.column_start, p.rows);
  EXPECT_EQ(std::vector<int>(p.view().below(2).begin(), p.view().below(2).end()), (std::vector<int>{3}));
}

TEST(CholeskyPattern, FactorsAndSolvesAsTheDenseLoopsBitForBit) {
  // A block-sparse SPD matrix B B^T, B with the pattern's zero blocks, with fill-in: joint 0
  // couples joints 1 and 3, joint 2 stands alone.
  const std::vector<int> sizes{3, 2, 4, 3};
  const std::vector<int> first{0, 3, 5, 9, 12};
  auto coupled = [](int later, int earlier) { return earlier == 0 && later != 2; };
  const int n = 12;
  std::mt19937 generator(7);  // fixed seed: the same matrix every run
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, n);
  for (int l = 0; l < 4; ++l) {
    for (int e = 0; e <= l; ++e) {
      if (l != e && !coupled(l, e)) continue;
      for (int i = first[l]; i < first[l + 1]; ++i) {
        for (int j = first[e]; j < first[e + 1]; ++j) b(i, j) = uniform(generator);
      }
    }
    for (int i = first[l]; i < first[l + 1]; ++i) b(i, i) += 3.0;
  }
  // Blocks (l, e) of B B^T: non-zero where B's block rows l and e share a column block.
  const Eigen::MatrixXd a = b * b.transpose();
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) rhs[i] = uniform(generator);

  Pattern dense;
  dense_pattern(n, dense.column_start, dense.rows);
  Pattern sparse;
  block_pattern(sizes, coupled, sparse.column_start, sparse.rows);
  ASSERT_LT(sparse.rows.size(), dense.rows.size());

  Eigen::MatrixXd l_dense = a, l_sparse = a;
  CholeskyPivots pivots_dense, pivots_sparse;
  ASSERT_TRUE(factor_cholesky_in_place(l_dense, dense.view(), pivots_dense));
  ASSERT_TRUE(factor_cholesky_in_place(l_sparse, sparse.view(), pivots_sparse));
  for (int j = 0; j < n; ++j) {
    for (int i = j; i < n; ++i) EXPECT_EQ(l_sparse(i, j), l_dense(i, j)) << "L(" << i << ", " << j << ")";
  }
  EXPECT_EQ(pivots_sparse.smallest, pivots_dense.smallest);
  EXPECT_EQ(pivots_sparse.largest, pivots_dense.largest);
  Eigen::VectorXd x_dense = rhs, x_sparse = rhs;
  solve_cholesky_in_place(l_dense, dense.view(), x_dense);
  solve_cholesky_in_place(l_sparse, sparse.view(), x_sparse);
  EXPECT_EQ(x_sparse, x_dense);
  EXPECT_LT((a * x_dense - rhs).norm(), 1e-12);
}

}  // namespace
}  // namespace clearjoint::dynamics::detail
