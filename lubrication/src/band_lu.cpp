// SPDX-License-Identifier: BSD-3-Clause
#include "band_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace clearjoint::lubrication::detail {

void BandLu::resize(int n, int lower, int upper) {
  n_ = n;
  lower_ = lower;
  upper_ = upper;
  // Rows 0 .. lower + upper - 1 of a column hold U's fill from row exchanges (LAPACK's KV).
  stride_ = 2 * lower + upper + 1;
  values_.assign(static_cast<std::size_t>(n) * stride_, 0.0);
  pivot_.assign(n, 0);
}

void BandLu::clear() { std::fill(values_.begin(), values_.end(), 0.0); }

bool BandLu::factorize() {
  const int diagonal = lower_ + upper_;
  int last_touched = 0;  // the rightmost column that a row of U reaches so far (LAPACK's JU)
  for (int j = 0; j < n_; ++j) {
    double* column = values_.data() + static_cast<std::size_t>(j) * stride_;
    const int below = std::min(lower_, n_ - 1 - j);
    int pivot = 0;
    double largest = std::abs(column[diagonal]);
    for (int p = 1; p <= below; ++p) {
      if (std::abs(column[diagonal + p]) > largest) {
        largest = std::abs(column[diagonal + p]);
        pivot = p;
      }
    }
    pivot_[j] = j + pivot;
    if (!(largest > 0.0)) return false;
    last_touched = std::max(last_touched, std::min(j + upper_ + pivot, n_ - 1));
    if (pivot != 0) {
      for (int c = j; c <= last_touched; ++c) {
        std::swap(values_[slot(j, c)], values_[slot(j + pivot, c)]);
      }
    }
    const double inverse = 1.0 / column[diagonal];
    for (int p = 1; p <= below; ++p) column[diagonal + p] *= inverse;
    // Rank-one update of the trailing band: A(j + p, c) -= L(j + p, j) U(j, c).
    for (int c = j + 1; c <= last_touched; ++c) {
      double* target = values_.data() + static_cast<std::size_t>(c) * stride_ + (diagonal + j - c);
      const double u = target[0];
      if (u == 0.0) continue;
      for (int p = 1; p <= below; ++p) target[p] -= column[diagonal + p] * u;
    }
  }
  return true;
}

void BandLu::solve(double* b) const {
  const int diagonal = lower_ + upper_;
  for (int j = 0; j < n_; ++j) {  // L y = P b, exchanges applied as they were made
    const double* column = values_.data() + static_cast<std::size_t>(j) * stride_;
    if (pivot_[j] != j) std::swap(b[j], b[pivot_[j]]);
    const double bj = b[j];
    const int below = std::min(lower_, n_ - 1 - j);
    for (int p = 1; p <= below; ++p) b[j + p] -= column[diagonal + p] * bj;
  }
  for (int j = n_ - 1; j >= 0; --j) {  // U x = y; U has diagonal = lower + upper super-diagonals
    const double* column = values_.data() + static_cast<std::size_t>(j) * stride_;
    b[j] /= column[diagonal];
    const double bj = b[j];
    for (int i = std::max(0, j - diagonal); i < j; ++i) b[i] -= column[diagonal + i - j] * bj;
  }
}

}  // namespace clearjoint::lubrication::detail
