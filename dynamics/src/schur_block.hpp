// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// One joint pair's block of the Schur matrix Phi_q M^-1 Phi_q^T (eq. 38), from the two joints'
/// Jacobian blocks on their shared body.

#include "clearjoint/dynamics/constraint_primitives.hpp"

namespace clearjoint::dynamics::detail {

/// add_product_block below, `Rows` (>= rows, a whole number of SIMD pairs) rows at a time.
template <int Rows>
void add_product_block_of(const ConstraintRows::Block& scaled, const ConstraintRows::Block& jacobian,
                          int rows, int columns, double* block, Eigen::Index stride) {
  for (int c = 0; c < columns; ++c) {
    Eigen::Matrix<double, Rows, 1> column = scaled.col(0).head<Rows>() * jacobian(c, 0);
    for (int k = 1; k < 6; ++k) column += scaled.col(k).head<Rows>() * jacobian(c, k);
    double* target = block + c * stride;
    for (int r = 0; r < rows; ++r) target[r] += column[r];
  }
}

/// block(r, c) += (scaled * jacobian^T)(r, c) for r < rows, c < columns: `scaled` is the later
/// joint's Phi_q M^-1 on the shared body, `jacobian` the earlier joint's Phi_q there, `block` the
/// pair's first entry in the column-major Schur matrix (column stride `stride`).
///
/// A Block holds kMaxJointEquations rows, zero beyond the joint's equations; only the entries of
/// the equations are computed (a 3-equation joint pair costs a quarter of the 6 x 6 product).
/// Each entry is the sum over the body coordinates k = 0..5 in that order, one multiply and one
/// add each, as Eigen evaluates the 6 x 6 product scaled * jacobian^T (a column of the result a
/// SIMD pair of rows at a time), so the entries are the full product's bit for bit.
inline void add_product_block(const ConstraintRows::Block& scaled, const ConstraintRows::Block& jacobian,
                              int rows, int columns, double* block, Eigen::Index stride) {
  if (rows <= 2) {
    add_product_block_of<2>(scaled, jacobian, rows, columns, block, stride);
  } else if (rows <= 4) {
    add_product_block_of<4>(scaled, jacobian, rows, columns, block, stride);
  } else {
    add_product_block_of<6>(scaled, jacobian, rows, columns, block, stride);
  }
}

}  // namespace clearjoint::dynamics::detail
