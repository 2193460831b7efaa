// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The exact tiers' one real-root isolator (docs/circle-cylinder.md, section 4): the real roots of
// a polynomial with rational coefficients, each with its multiplicity, in isolating intervals
// with rational (dyadic) ends. CGAL headers: include only from the exact tiers' .cpp files.
//
// Square-free factorisation (Yun) and Sturm sequences (subresultant remainders), in integer
// arithmetic: the polynomial is scaled to integer coefficients once, and every point the
// isolation evaluates at is dyadic (m 2^e), so a sign is that of an integer sum with no fraction
// ever reduced. Each sign is first tried in double arithmetic with a running error bound
// (error_bounded.hpp), next to a root on the polynomial expanded about a nearby point (a Taylor
// shift, exact), and computed exactly only when that cannot decide. CGAL::Polynomial<CGAL::Gmpq>
// does the same work with a gcd per rational operation, which near a tangency of the joint's rims,
// where the polynomial's coefficients reach thousands of bits and the isolation needs a hundred
// signs, cost milliseconds per query. Every decision (root counts, signs) is exact, so the
// intervals are those of the textbook algorithm, whatever decides them: the chain's last members,
// near close roots small next to their terms, come from multiprecision ball arithmetic where it
// proves them (their exact coefficients only when a sign needs them), and the walk reaches the
// node that separates a close pair of roots in one step, proved by the chain's signs at its ends.

#include <memory>
#include <vector>

#include <gmpxx.h>

#include "clearjoint/geometry/model/certificate.hpp"
#include "exact/exact_numbers.hpp"

namespace clearjoint::geometry::detail {

/// Thrown by the exact tiers (and caught by them) when they cannot finish: `why` says why.
struct ExactTierGiveUp {
  CertificateReason why;
};

/// Sign evaluations allowed per exact query (Sturm counts and bisection signs). A realistic
/// query needs a few hundred; inputs whose magnitudes lie hundreds of orders apart make
/// coefficients of thousands of bits and root clusters that bisection would chase for minutes.
/// Past this budget the tier gives up and says so (the answer is then `uncertain`), never hangs.
inline constexpr int kMaxSignEvaluations = 20000;

/// Counts sign evaluations against kMaxSignEvaluations.
struct EvaluationBudget {
  int used = 0;
  void spend(int n = 1) {
    used += n;
    if (used > kMaxSignEvaluations) throw ExactTierGiveUp{CertificateReason::exact_root_isolation_budget_exhausted};
  }
};

class IntegerPolynomial;

/// A square-free factor of the isolated polynomial, with integer coefficients.
class SquareFreeFactor {
 public:
  SquareFreeFactor(std::shared_ptr<const IntegerPolynomial> polynomial, int multiplicity);
  int multiplicity() const { return multiplicity_; }
  /// The factor divided by its leading coefficient, as CGAL's square-free factorisation of the
  /// rational polynomial gives it.
  RationalPolynomial monic() const;
  /// The exact sign of the factor (of its monic form) at x: -1, 0 or +1.
  int sign_at(const Rational& x) const;
  /// Whether the factor and g (not zero) have a common root in (low, high], low < high.
  bool shares_root_in(const RationalPolynomial& g, const Rational& low, const Rational& high) const;

 private:
  std::shared_ptr<const IntegerPolynomial> polynomial_;
  int multiplicity_;
};

struct IsolatedRoot {
  Rational low, high;  ///< the root lies in [low, high]; low == high when it is rational
  int multiplicity;
  std::shared_ptr<const SquareFreeFactor> factor;  ///< the square-free factor whose only root in [low, high] this is
};

/// The roots of one polynomial (at most its degree, four for the rim-cylinder eliminant), held
/// inside the object.
using IsolatedRoots = SmallVector<IsolatedRoot>;

/// Largest coefficient (numerator plus denominator bits) isolate_real_roots accepts. A sign
/// evaluation's cost grows with the coefficients' size, and Sturm sequences multiply it, so the
/// count budget alone let inputs whose magnitudes lie ~1e500 apart run for half a minute (27,000
/// bits). The largest met by the test suite and the detection suite (1e-6 to 1e6 m, margins down
/// to 1e-15 clearances, exact centres of detection) is 2,306 bits; this leaves 3.5 times that.
inline constexpr std::size_t kMaxCoefficientBits = 8192;

/// Isolating intervals are refined until their width is below 2^-kRefinementBits of the bound:
/// well under one double ulp of the root, so an enclosure reported from it is limited by the final
/// rounding to double, not by the isolation.
inline constexpr int kRefinementBits = 64;

/// Bits of a rational in lowest terms: numerator plus denominator.
std::size_t bit_size(const Rational& x);

/// The real roots of f in (-bound, bound] (`bound` a power of two), each with its multiplicity,
/// appended to `out`: for each square-free factor (Yun's order: multiplicity 1 first) its roots,
/// isolated by Sturm bisection from (-bound, bound] (the upper half of an interval first), then
/// shrunk to a few ulps around a double Newton iterate proved by two exact signs, or else bisected
/// to 2^-kRefinementBits bound. Throws ExactTierGiveUp when f's coefficients exceed
/// kMaxCoefficientBits or the budget runs out.
void isolate_real_roots(const RationalPolynomial& f, const Rational& bound, IsolatedRoots& out,
                        EvaluationBudget& budget);

/// The same for the polynomial with these integer coefficients (constant term first), which the
/// caller has checked against kMaxCoefficientBits in the rational form it stands for (a nonzero
/// multiple of this one, with the same roots).
void isolate_real_roots(SmallVector<mpz_class> coefficients, const Rational& bound, IsolatedRoots& out,
                        EvaluationBudget& budget);

/// Sturm's theorem on one polynomial (square-free or not): counts its distinct real roots.
class SturmSequence {
 public:
  explicit SturmSequence(const RationalPolynomial& f);
  ~SturmSequence();
  SturmSequence(SturmSequence&&) noexcept;
  /// Distinct roots in (low, high], low < high.
  int roots_in(const Rational& low, const Rational& high) const;

 private:
  std::vector<IntegerPolynomial> chain_;
};

}  // namespace clearjoint::geometry::detail
