// SPDX-License-Identifier: BSD-3-Clause
// A joint pair's Schur block computes the joints' equations only (dynamics/src/schur_block.hpp),
// and equals the full 6 x 6 product's corner bit for bit.
#include "schur_block.hpp"

#include <gtest/gtest.h>

#include <random>

namespace clearjoint::dynamics::detail {
namespace {

using Block = ConstraintRows::Block;

/// A joint's Jacobian block: `rows` random rows, zero beyond (as ConstraintRows holds them).
Block random_rows(std::mt19937& generator, int rows) {
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  Block block = Block::Zero();
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < 6; ++c) block(r, c) = uniform(generator);
  }
  return block;
}

TEST(SchurBlock, AddsTheFullProductsCornerBitForBitAndLeavesTheRestAlone) {
  std::mt19937 generator(11);  // fixed seed: the same blocks every run
  for (int later_rows = 1; later_rows <= kMaxJointEquations; ++later_rows) {
    for (int earlier_rows = 1; earlier_rows <= kMaxJointEquations; ++earlier_rows) {
      const Block scaled = random_rows(generator, later_rows);
      const Block jacobian = random_rows(generator, earlier_rows);
      Eigen::MatrixXd schur = Eigen::MatrixXd::Constant(9, 8, 0.25);
      add_product_block(scaled, jacobian, later_rows, earlier_rows, &schur(2, 1), schur.outerStride());
      const Block product = scaled * jacobian.transpose();
      for (int c = 0; c < schur.cols(); ++c) {
        for (int r = 0; r < schur.rows(); ++r) {
          const bool inside = r >= 2 && r < 2 + later_rows && c >= 1 && c < 1 + earlier_rows;
          const double expected = inside ? 0.25 + product(r - 2, c - 1) : 0.25;
          EXPECT_EQ(schur(r, c), expected) << later_rows << " x " << earlier_rows << " block, entry ("
                                           << r << ", " << c << ")";
        }
      }
    }
  }
}

}  // namespace
}  // namespace clearjoint::dynamics::detail
