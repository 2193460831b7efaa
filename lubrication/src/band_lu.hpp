// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A square band matrix factorised in place by Gaussian elimination with partial pivoting: the
// algorithm of LAPACK's dgbtf2/dgbtrs (Golub & Van Loan, Matrix Computations, 4th ed., 4.3.5),
// in LAPACK's band storage, so that the pivots' fill above the band has its room.
//
// Why not a library: the Reynolds grid refactorises one small matrix of fixed pattern at every
// call. Eigen's SparseLU, general-purpose, redoes its symbolic work (column depth-first searches,
// supernodes) and allocates and zeroes its workspace at each factorisation: 3.5 M instructions
// per factorisation at 48 x 12 cells against 0.42 M for this elimination (callgrind). Eigen has
// no band solver; LAPACK's dgbtrf would add a Fortran link dependency to the installed library
// for these few loops.

#include <vector>

namespace clearjoint::lubrication::detail {

class BandLu {
 public:
  /// An n x n matrix with `lower` sub- and `upper` super-diagonals, all zero.
  void resize(int n, int lower, int upper);

  int size() const noexcept { return n_; }
  /// Where A(row, column) is stored in values(); |row - column| within the band.
  int slot(int row, int column) const noexcept {
    return column * stride_ + (lower_ + upper_ + row - column);
  }
  double* values() noexcept { return values_.data(); }
  /// Zero every entry, the pivots' fill room included (before assembling A again).
  void clear();

  /// Factorise P A = L U in place. False when a column has no non-zero pivot (A singular).
  bool factorize();
  /// Overwrite b (size n) with A^-1 b; after a successful factorize.
  void solve(double* b) const;

 private:
  int n_ = 0, lower_ = 0, upper_ = 0, stride_ = 1;
  std::vector<double> values_;  // column-major, stride_ = 2 lower + upper + 1 rows per column
  std::vector<int> pivot_;      // row exchanged with row j at step j
};

}  // namespace clearjoint::lubrication::detail
