// SPDX-License-Identifier: BSD-3-Clause
#include "exact/real_root_isolation.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "arithmetic/error_bounded.hpp"
#include "exact/dyadic_number.hpp"
#include "exact/integer_polynomial.hpp"
#include "exact/local_expansion.hpp"
#include "exact/sturm_chain.hpp"

namespace clearjoint::geometry::detail {
namespace {

/// A point of the isolation with the chain's signs there.
struct Endpoint {
  Dyadic x;
  ChainSigns signs;
};

/// Shrinks an isolating interval (low, high] of the square-free factor f to a few ulps around a
/// double Newton approximation, proved by two exact sign evaluations at double (hence dyadic)
/// points. Exact bisection to the same width costs ~64 evaluations; this costs two.
/// `monic` holds f's coefficients divided by its leading one, as doubles (CGAL::to_double).
bool tighten_with_double_newton(const IntegerPolynomial& f, const SmallVector<double>& monic, Dyadic& low,
                                Dyadic& high, int sign_high) {
  const int degree = f.degree();
  double coefficient[5] = {0, 0, 0, 0, 0};
  double scale = 0.0;
  for (int i = 0; i <= degree && i < 5; ++i) scale = std::max(scale, std::fabs(monic[static_cast<std::size_t>(i)]));
  if (!(scale > 0.0) || !std::isfinite(scale) || degree > 4) return false;
  for (int i = 0; i <= degree; ++i) coefficient[i] = monic[static_cast<std::size_t>(i)] / scale;
  const double lo = low.to_double(), hi = high.to_double();
  if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
  double x = 0.5 * (lo + hi);
  for (int step = 0; step < 60; ++step) {
    double value = 0.0, slope = 0.0;
    for (int i = degree; i >= 0; --i) {
      slope = slope * x + value;
      value = value * x + coefficient[i];
    }
    if (slope == 0.0) break;
    const double next = std::clamp(x - value / slope, lo, hi);
    if (next == x) break;
    x = next;
  }
  // The signs near x from f expanded about x (LocalExpansion), taken at the first need.
  std::optional<LocalExpansion> expansion;
  const auto sign_near_x = [&](const Dyadic& point) {
    if (!expansion) expansion.emplace(f, Dyadic::of_double(x));
    const int filtered = expansion->filtered_sign_at(point);
    return filtered != 0 ? filtered : exact_sign(f, point);
  };
  for (double spread = 4; spread < 0x1p20; spread *= 16) {
    const double delta = spread * std::numeric_limits<double>::epsilon() * std::max(std::fabs(x), 1e-300);
    if (!std::isfinite(x - delta) || !std::isfinite(x + delta)) return false;
    const Dyadic a = Dyadic::of_double(x - delta), b = Dyadic::of_double(x + delta);
    if (a <= low || b > high) return false;
    const int sign_a = sign_near_x(a), sign_b = sign_near_x(b);
    if (sign_a == 0 || sign_b == 0) {
      low = high = sign_a == 0 ? a : b;
      return true;
    }
    if (sign_a != sign_b && sign_b == sign_high) {
      // A sign change inside (low, high], which holds exactly one root: that root.
      low = a;
      high = b;
      return true;
    }
  }
  return false;
}

/// Levels beyond which jump_to_last_level leaves the bisection to itself: its index must be an
/// exact double.
constexpr long kMostJumpLevels = 50;
/// Tries of jump_to_last_level's index (its guess, then a neighbour per try).
constexpr int kJumpTries = 4;

/// The interval bisect would end with, found without its levels: the levels L it would take
/// (the first with w 2^-L <= width_goal, w = b - a), the index j of the level-L interval
/// (a + j w 2^-L, a + (j + 1) w 2^-L] guessed from where G's rounded coefficients change sign,
/// and the guess proved by f's exact signs at both ends (the expansion's filter first): opposite
/// to sign_b at the lower end (not needed at a itself), sign_b at the upper end (known at b).
/// Then the root lies strictly between two level-L points, so none of bisect's midpoints (all
/// level-L points) is the root, each of them sends the bisection towards the root, and it ends
/// on this interval having spent L. Near a pair of close roots the double Newton of
/// tighten_with_double_newton does not settle and bisect runs some 40 levels, each with its
/// dyadic arithmetic; this proves the same end with two signs. False (nothing spent, a and b
/// untouched) when the guess is not proved within kJumpTries, or the levels are too many.
template <class Point>
bool jump_to_last_level(const IntegerPolynomial& f, const LocalExpansion& expansion, const Bounded& origin_offset,
                        const Point& point, Dyadic& a, Dyadic& b, int sign_b, const Dyadic& width_goal,
                        EvaluationBudget& budget) {
  long levels = 0;
  for (Dyadic current = b - a; current > width_goal && levels <= kMostJumpLevels; current.exponent -= 1) ++levels;
  if (levels > kMostJumpLevels) return false;
  const double low = origin_offset.value, high = expansion.offset(b).value;
  if (!(std::isfinite(low) && std::isfinite(high) && low < high)) return false;
  const double guess = expansion.approximate_sign_change(low, high, sign_b);
  const double count = std::ldexp(1.0, static_cast<int>(levels));  // level-L intervals
  double index = std::floor((guess - low) / (high - low) * count);
  if (!std::isfinite(index)) return false;
  const auto sign_at = [&](const Dyadic& x) {
    const int filtered = expansion.filtered_sign_at(x);
    return filtered != 0 ? filtered : exact_sign(f, x);
  };
  for (int attempt = 0; attempt < kJumpTries; ++attempt) {
    index = std::clamp(index, 0.0, count - 1);
    const Integer j(index);  // exact: a whole number below 2^kMostJumpLevels
    const Dyadic lower = point(j, levels), upper = point(j + 1, levels);
    const int at_upper = index + 1 == count ? sign_b : sign_at(upper);
    if (at_upper != sign_b) {  // the root lies above upper (or at it: then bisect hits it)
      if (at_upper == 0 || index + 1 == count) return false;
      index += 1;
      continue;
    }
    const int at_lower = index == 0 ? -sign_b : sign_at(lower);
    if (at_lower != -sign_b) {  // the root lies at or below lower
      if (at_lower == 0 || index == 0) return false;
      index -= 1;
      continue;
    }
    budget.spend(static_cast<int>(levels));
    a = lower;
    b = upper;
    return true;
  }
  return false;
}

/// Bisection of (a, b], which holds exactly one root of f (simple: f is square-free), until it is
/// at most `width_goal` wide or a midpoint is the root. Only the sign at the upper end is compared,
/// and it stays sign_b: b only ever moves to a point of that sign. The points are a + j w 2^-i
/// (w = b - a), kept as the integer j and the level i; their signs come from a local expansion of
/// f about the interval's middle, whose argument for such a point is (a - c) 2^k + j w 2^(k - i),
/// a Bounded sum, taken again about the current middle once the interval has shrunk by 2^20 and
/// the expansion's filter no longer decides; the exact sum decides the rest.
void bisect(const IntegerPolynomial& f, Dyadic& a, Dyadic& b, int sign_b, const Dyadic& width_goal,
            EvaluationBudget& budget) {
  const Dyadic width = b - a;
  if (!(width > width_goal)) return;
  const Dyadic origin = a;
  const auto point = [&](const Integer& j, long level) {  // origin + j width 2^-level
    Dyadic step;
    step.mantissa = j * width.mantissa;
    step.exponent = width.exponent - level;
    step.normalise();
    return origin + step;
  };
  std::optional<LocalExpansion> expansion(std::in_place, f, midpoint(a, b));
  Bounded origin_offset = expansion->offset(origin);
  if (jump_to_last_level(f, *expansion, origin_offset, point, a, b, sign_b, width_goal, budget)) return;
  long expansion_level = 0;
  constexpr long kRecentreShrink = 20;
  Bounded width_length = expansion->length(width);  // w 2^k
  Integer j = 0, middle_index;
  long level = 0;
  for (Dyadic current = width; current > width_goal; current.exponent -= 1, ++level) {
    budget.spend();
    mpz_mul_2exp(middle_index.get_mpz_t(), j.get_mpz_t(), 1);  // the middle, 2 j + 1 at level + 1
    mpz_add_ui(middle_index.get_mpz_t(), middle_index.get_mpz_t(), 1);
    const auto filtered = [&] {
      const double index = mpz_get_d(middle_index.get_mpz_t());  // truncated: within an ulp
      const Bounded bounded_index(index, mpz_sizeinbase(middle_index.get_mpz_t(), 2) > 53 ? std::fabs(index) * 0x1p-52 : 0.0);
      // w 2^(k - level - 1): a power-of-two scaling, exact but for underflow.
      const int down = static_cast<int>(std::min(level + 1, 2000L));
      const Bounded step_length(std::ldexp(width_length.value, -down),
                                std::ldexp(width_length.error, -down) + kUnderflowError);
      return expansion->filtered_sign_at_offset(origin_offset + bounded_index * step_length);
    };
    int at_middle = filtered();
    if (at_middle == 0 && level >= expansion_level + kRecentreShrink) {
      expansion.emplace(f, point(middle_index, level + 1));
      origin_offset = expansion->offset(origin);
      width_length = expansion->length(width);
      expansion_level = level;
      at_middle = filtered();
    }
    if (at_middle == 0) {
      const Dyadic middle = point(middle_index, level + 1);
      at_middle = exact_sign(f, middle);
      if (at_middle == 0) {
        a = b = middle;
        return;
      }
    }
    // b to the middle (j stays the lower end's index, doubled) or a to it.
    if (at_middle == sign_b) {
      mpz_mul_2exp(j.get_mpz_t(), j.get_mpz_t(), 1);
    } else {
      std::swap(j, middle_index);
    }
  }
  a = point(j, level);
  b = point(j + 1, level);
}

/// f's coefficients over its leading one, each as CGAL::to_double gives that rational (mpq_get_d
/// truncates the exact quotient, whatever the fraction's form, so no gcd is needed).
SmallVector<double> monic_doubles(const IntegerPolynomial& f) {
  SmallVector<double> out(f.c.size());
  mpq_t quotient;
  mpq_init(quotient);
  for (std::size_t i = 0; i < f.c.size(); ++i) {
    mpz_set(mpq_numref(quotient), f.c[i].get_mpz_t());
    mpz_set(mpq_denref(quotient), f.leading().get_mpz_t());  // positive (square_free_factors)
    out[i] = mpq_get_d(quotient);
  }
  mpq_clear(quotient);
  return out;
}

/// Levels of the isolation's walk the node descend_to_pair proves is left above the two roots'
/// guessed separation: room for the guess's error.
constexpr long kPairDescentMargin = 2;
/// Fewest levels descend_to_pair skips: one proof costs two chain evaluations, as one level does.
constexpr long kFewestPairDescentLevels = 2;

/// The node the isolation's walk (isolate_factor) would reach from (low, high], which holds
/// exactly two distinct roots of f, without its levels in between: where two roots lie close
/// together, the walk halves the node some 30 times, each time evaluating the chain at the
/// midpoint, before a midpoint separates them. The two roots are guessed from f expanded about
/// the node's middle (LocalExpansion::approximate_root_pair), the deepest node of the walk's grid
/// (a + j w 2^-K, a + (j + 1) w 2^-K] holding both guesses found from their binary digits, and
/// that node, K - kPairDescentMargin levels down, proved to hold two roots by the chain's exact
/// signs at its ends. Every node between (low, high] and it then holds both roots too, and each
/// one's other half none: the walk would have split each of them and found their other halves
/// empty, 2 K - 1 evaluations the budget is charged for (the node itself is charged when the walk
/// takes it). The walk goes on from that node and isolates the same roots in the same intervals.
/// Empty (nothing spent) where the guess is not proved or skips too few levels.
std::optional<std::pair<Endpoint, Endpoint>> descend_to_pair(const IntegerPolynomial& f,
                                                             const SturmChain& chain,
                                                             const Endpoint& low, const Endpoint& high,
                                                             EvaluationBudget& budget) {
  const LocalExpansion expansion(f, midpoint(low.x, high.x));
  const double from = expansion.offset(low.x).value, to = expansion.offset(high.x).value;
  if (!(std::isfinite(from) && std::isfinite(to) && from < to)) return std::nullopt;
  double first = 0.0, second = 0.0;
  if (!expansion.approximate_root_pair(from, to, first, second)) return std::nullopt;
  const double t1 = std::clamp((first - from) / (to - from), 0.0, 1.0);
  const double t2 = std::clamp((second - from) / (to - from), 0.0, 1.0);
  long common = 0;  // levels down which both guesses stay in one node
  while (common < kMostJumpLevels &&
         std::floor(std::ldexp(t1, static_cast<int>(common + 1))) == std::floor(std::ldexp(t2, static_cast<int>(common + 1)))) {
    ++common;
  }
  const long levels = common - kPairDescentMargin;
  if (levels < kFewestPairDescentLevels) return std::nullopt;
  const double count = std::ldexp(1.0, static_cast<int>(levels));
  const double index = std::min(std::floor(std::ldexp(t1, static_cast<int>(levels))), count - 1);
  Dyadic step = high.x - low.x;
  step.exponent -= levels;
  const auto point = [&](double j) {  // low + j step, j a whole number below 2^kMostJumpLevels
    Dyadic offset = step;
    offset.mantissa *= Integer(j);
    offset.normalise();
    return low.x + offset;
  };
  Endpoint node_low{point(index), {}}, node_high{point(index + 1), {}};
  node_low.signs = index == 0 ? low.signs : chain_signs(chain, node_low.x);
  node_high.signs = index + 1 == count ? high.signs : chain_signs(chain, node_high.x);
  if (node_low.signs.variations - node_high.signs.variations != 2) return std::nullopt;
  budget.spend(static_cast<int>(2 * levels - 1));
  return std::make_pair(std::move(node_low), std::move(node_high));
}

void isolate_factor(const std::shared_ptr<const SquareFreeFactor>& factor, const IntegerPolynomial& f,
                    const SturmChain& chain, const Dyadic& bound, IsolatedRoots& out,
                    EvaluationBudget& budget) {
  Dyadic width_goal = bound;
  width_goal.exponent -= kRefinementBits;
  const Dyadic lowest = -bound;
  // Nodes still to visit; a node below one where descend_to_pair was tried (and took the walk as
  // far down as its guess allows, or failed) does not try again: the guess there would be the
  // same pair, a few levels from its separation.
  struct Node {
    Endpoint low, high;
    bool may_descend;
  };
  SmallVector<Node> pending;
  pending.push_back({{lowest, chain_signs(chain, lowest)}, {bound, chain_signs(chain, bound)}, true});
  SmallVector<double> monic;
  while (!pending.empty()) {
    auto [low, high, may_descend] = std::move(pending.back());
    pending.pop_back();
    budget.spend();
    const int n = low.signs.variations - high.signs.variations;
    if (n == 0) continue;
    if (n == 2 && may_descend) {
      may_descend = false;
      if (auto node = descend_to_pair(f, chain, low, high, budget)) {
        pending.push_back({std::move(node->first), std::move(node->second), false});
        continue;
      }
    }
    if (n >= 2) {
      Dyadic middle = midpoint(low.x, high.x);
      const ChainSigns at_middle = chain_signs(chain, middle);
      pending.push_back({std::move(low), {middle, at_middle}, may_descend});
      pending.push_back({{std::move(middle), at_middle}, std::move(high), may_descend});
      continue;
    }
    // One root in (low, high]: bisect on the sign of the square-free factor.
    if (high.signs.first == 0) {
      out.push_back({high.x.to_rational(), high.x.to_rational(), factor->multiplicity(), factor});
      continue;
    }
    if (monic.empty()) monic = monic_doubles(f);
    Dyadic a = low.x, b = high.x;
    if (!tighten_with_double_newton(f, monic, a, b, high.signs.first)) {
      bisect(f, a, b, high.signs.first, width_goal, budget);
    }
    out.push_back({a.to_rational(), b.to_rational(), factor->multiplicity(), factor});
  }
}

/// Yun's square-free factorisation of p (primitive, positive leading coefficient, deg >= 1) into primitive factors with
/// positive leading coefficients, multiplicity 1 first, as CGAL's for the same polynomial up to
/// constant factors; factors of degree 0 left out. `chain` is p's Sturm chain, whose last member
/// is gcd(p, p').
SmallVector<std::pair<IntegerPolynomial, int>> square_free_factors(const IntegerPolynomial& p,
                                                                   const SturmChain& chain) {
  SmallVector<std::pair<IntegerPolynomial, int>> factors;
  IntegerPolynomial a = p;
  if (chain.back().degree() == 0) {
    factors.emplace_back(std::move(a), 1);
    return factors;
  }
  IntegerPolynomial c = chain.back();
  make_primitive(c, true);
  IntegerPolynomial w = exact_quotient(a, c), y = exact_quotient(derivative(a), c);
  IntegerPolynomial z = difference(y, derivative(w));
  int i = 1;
  while (!z.is_zero()) {
    IntegerPolynomial g = polynomial_gcd(w, z);
    if (g.degree() > 0) factors.emplace_back(g, i);
    ++i;
    w = exact_quotient(w, g);
    y = exact_quotient(z, g);
    z = difference(y, derivative(w));
  }
  make_primitive(w, true);
  if (w.degree() > 0) factors.emplace_back(std::move(w), i);
  return factors;
}

}  // namespace

SquareFreeFactor::SquareFreeFactor(std::shared_ptr<const IntegerPolynomial> polynomial, int multiplicity)
    : polynomial_(std::move(polynomial)), multiplicity_(multiplicity) {}

RationalPolynomial SquareFreeFactor::monic() const {
  std::vector<Rational> coefficients;
  const CGAL::Gmpz leading(polynomial_->leading().get_mpz_t());
  for (const Integer& x : polynomial_->c) coefficients.emplace_back(CGAL::Gmpz(x.get_mpz_t()), leading);
  return RationalPolynomial(coefficients.begin(), coefficients.end());
}

namespace {

void isolate(IntegerPolynomial p, const Rational& bound, IsolatedRoots& out, EvaluationBudget& budget) {
  if (p.degree() < 1) return;
  const Dyadic dyadic_bound = Dyadic::of_rational(bound);
  SturmChain chain = sturm_chain(p);
  auto factors = square_free_factors(p, chain);
  for (auto& [polynomial, multiplicity] : factors) {
    polynomial.prepare_filter();
    const bool whole = polynomial.degree() == p.degree();  // p was square-free: its chain serves
    SturmChain own_chain;
    if (!whole) own_chain = sturm_chain(polynomial);
    const auto shared = std::make_shared<const IntegerPolynomial>(std::move(polynomial));
    const auto factor = std::make_shared<const SquareFreeFactor>(shared, multiplicity);
    isolate_factor(factor, *shared, whole ? chain : own_chain, dyadic_bound, out, budget);
  }
}

}  // namespace

std::size_t bit_size(const Rational& x) {
  return mpz_sizeinbase(mpq_numref(x.mpq()), 2) + mpz_sizeinbase(mpq_denref(x.mpq()), 2);
}

int SquareFreeFactor::sign_at(const Rational& x) const {
  // The factor's leading coefficient is positive: its sign is the monic form's.
  return detail::sign_at(*polynomial_, x, bounded(x));
}

bool SquareFreeFactor::shares_root_in(const RationalPolynomial& g, const Rational& low, const Rational& high) const {
  const IntegerPolynomial common = polynomial_gcd(*polynomial_, integer_multiple(g));
  if (common.degree() < 1) return false;
  const SturmChain chain = sturm_chain(common);
  return chain_signs(chain, low).variations - chain_signs(chain, high).variations > 0;
}

void isolate_real_roots(const RationalPolynomial& f, const Rational& bound, IsolatedRoots& out,
                        EvaluationBudget& budget) {
  if (f.is_zero() || f.degree() < 1) return;
  for (int i = 0; i <= f.degree(); ++i) {
    if (bit_size(f[i]) > kMaxCoefficientBits) throw ExactTierGiveUp{CertificateReason::exact_coefficients_too_large};
  }
  isolate(integer_multiple(f), bound, out, budget);
}

void isolate_real_roots(SmallVector<mpz_class> coefficients, const Rational& bound, IsolatedRoots& out,
                        EvaluationBudget& budget) {
  IntegerPolynomial p;
  p.c = std::move(coefficients);
  p.trim();
  if (p.degree() < 1) return;
  // Only the roots matter: the common power of two goes (it costs no gcd) and the leading
  // coefficient is made positive, as integer_multiple leaves it.
  mp_bitcnt_t twos = std::numeric_limits<mp_bitcnt_t>::max();
  for (const Integer& x : p.c) {
    if (sgn(x) != 0) twos = std::min(twos, mpz_scan1(x.get_mpz_t(), 0));
  }
  const bool negate = sgn(p.leading()) < 0;
  for (Integer& x : p.c) {
    if (twos > 0) mpz_tdiv_q_2exp(x.get_mpz_t(), x.get_mpz_t(), twos);
    if (negate) x = -x;
  }
  isolate(std::move(p), bound, out, budget);
}

SturmSequence::SturmSequence(const RationalPolynomial& f) {
  const IntegerPolynomial p = integer_multiple(f);
  if (p.is_zero()) return;
  SturmChain chain = sturm_chain(p);
  chain_.assign(std::make_move_iterator(chain.begin()), std::make_move_iterator(chain.end()));
}
SturmSequence::~SturmSequence() = default;
SturmSequence::SturmSequence(SturmSequence&&) noexcept = default;

int SturmSequence::roots_in(const Rational& low, const Rational& high) const {
  if (chain_.empty()) return 0;
  return chain_signs(chain_, low).variations - chain_signs(chain_, high).variations;
}

}  // namespace clearjoint::geometry::detail
