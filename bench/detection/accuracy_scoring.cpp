// SPDX-License-Identifier: BSD-3-Clause
#include "accuracy_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace clearjoint::bench {
namespace {

using geometry::Certainty;
using geometry::Contact;
using geometry::ContactBase;
using geometry::ContactType;
using geometry::Vector3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Lengths in failure messages: three significant digits, any magnitude.
std::string metres(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", x);
  return text;
}

std::string key_name(ContactType type, ContactBase base) {
  return std::string(geometry::to_string(type)) + " at " + std::string(geometry::to_string(base));
}

/// The spacing of doubles at |x|: ulp(x) = nextafter(|x|, inf) - |x| (the smallest subnormal
/// spacing at 0).
double ulp(double x) {
  const double m = std::fabs(x);
  return std::nextafter(m, std::numeric_limits<double>::infinity()) - m;
}

/// Error of a double point against a reference point: metres, and ulps of the reference point's
/// largest coordinate.
std::pair<double, double> point_error(const Vector3& p, const RealVector& reference) {
  const Vector3 rounded = to_double(reference);
  double largest_difference = 0.0;
  for (int i = 0; i < 3; ++i) {
    largest_difference =
        std::max(largest_difference, abs(Real(p[i]) - reference[static_cast<std::size_t>(i)]).convert_to<double>());
  }
  const double metres = distance(p, reference).convert_to<double>();
  return {metres, largest_difference / ulp(rounded.cwiseAbs().maxCoeff())};
}

void compare_matched(const Contact& contact, const ReferenceContact& reference, InputScore& score) {
  if (!reference.points_defined) return;
  const auto [journal_m, journal_ulps] = point_error(contact.p_WCj, reference.p_WCj);
  const auto [bearing_m, bearing_ulps] = point_error(contact.p_WCi, reference.p_WCi);
  if (reference.all_round) {
    score.all_round_point_m.push_back(std::max(journal_m, bearing_m));
  } else {
    score.point_m.push_back(std::max(journal_m, bearing_m));
    score.point_ulps.push_back(std::max(journal_ulps, bearing_ulps));
  }
  if (reference.depth > 0) {
    score.depth_relative.push_back(
        (abs(Real(contact.depth) - reference.depth) / reference.depth).convert_to<double>());
  }
  for (int k = 0; k < contact.crossing_count; ++k) {
    const geometry::RimCrossing& crossing = contact.crossings[static_cast<std::size_t>(k)];
    if (reference.crossings.empty()) break;
    const RealVector* nearest = nullptr;
    Real best = 0;
    for (const RealVector& r : reference.crossings) {
      const Real d = distance(crossing.point, r);
      if (nearest == nullptr || d < best) {
        best = d;
        nearest = &r;
      }
    }
    const auto [distance_m, ulps] = point_error(crossing.point, *nearest);
    score.crossing_m.push_back(distance_m);
    score.crossing_ulps.push_back(ulps);
    const bool proved = contact.certificate.level != Certainty::uncertain;
    if (proved && std::isfinite(crossing.point_error)) {
      ++score.enclosures_checked;
      score.enclosure_radius_m.push_back(crossing.point_error);
      if (best > Real(crossing.point_error)) {
        ++score.enclosures_missed;
        score.problems.push_back("crossing of " + key_name(contact.type, contact.base) +
                                 " outside its enclosure: error " + metres(distance_m) +
                                 " > point_error " + metres(crossing.point_error));
      }
    }
  }
}

}  // namespace

InputScore score_answer(const geometry::JointContacts& answer, const ReferenceAnswer& reference) {
  InputScore score;
  score.level = answer.certificate.level;
  if (answer.scenario != reference.scenario) {
    score.wrong_scenario = true;
    score.problems.push_back("scenario " + std::string(geometry::label(answer.scenario)) +
                             ", reference " + std::string(geometry::label(reference.scenario)));
  }
  std::vector<bool> used(reference.contacts.size(), false);
  for (int k = 0; k < answer.contact_count; ++k) {
    const Contact& contact = answer.contacts[static_cast<std::size_t>(k)];
    // The unused reference contact of the same key nearest to this one (by journal point).
    int match = -1;
    Real best = 0;
    for (std::size_t r = 0; r < reference.contacts.size(); ++r) {
      const ReferenceContact& candidate = reference.contacts[r];
      if (used[r] || candidate.type != contact.type || candidate.base != contact.base) continue;
      const Real d = distance(contact.p_WCj, candidate.p_WCj);
      if (match < 0 || d < best) {
        best = d;
        match = static_cast<int>(r);
      }
    }
    if (match < 0) {
      ++score.spurious;
      score.problems.push_back("spurious " + key_name(contact.type, contact.base) + " contact (depth " +
                               metres(contact.depth) + ")");
      continue;
    }
    used[static_cast<std::size_t>(match)] = true;
    compare_matched(contact, reference.contacts[static_cast<std::size_t>(match)], score);
  }
  for (std::size_t r = 0; r < reference.contacts.size(); ++r) {
    if (used[r]) continue;
    ++score.missed;
    const ReferenceContact& missed = reference.contacts[r];
    score.problems.push_back("missed " + key_name(missed.type, missed.base) + " contact (reference depth " +
                             metres(missed.depth.convert_to<double>()) + ")");
  }
  return score;
}

Summary summarize(std::vector<double> values) {
  Summary s;
  s.count = values.size();
  if (values.empty()) {
    s.median = s.p99 = s.max = kNaN;
    return s;
  }
  std::sort(values.begin(), values.end());
  // Nearest-rank percentiles.
  auto rank = [&](double fraction) {
    const auto index = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size())));
    return values[std::min(values.size() - 1, index == 0 ? 0 : index - 1)];
  };
  s.median = rank(0.5);
  s.p99 = rank(0.99);
  s.max = values.back();
  return s;
}

void Tally::add(const InputScore& score, geometry::ContactScenario reference_scenario) {
  ++inputs;
  const bool beyond = reference_scenario == geometry::ContactScenario::beyond_model;
  if (beyond) ++reference_beyond_model;
  if (score.threw) {
    ++exceptions;
    ++failed_inputs;
    return;
  }
  if (score.wrong_scenario) {
    ++wrong_scenarios;
    if (!beyond) ++wrong_scenarios_within_model;
  }
  if (score.missed > 0) ++inputs_with_missed;
  if (score.spurious > 0) ++inputs_with_spurious;
  missed += static_cast<std::size_t>(score.missed);
  spurious += static_cast<std::size_t>(score.spurious);
  if (score.failed()) ++failed_inputs;
  switch (score.level) {
    case Certainty::exact: ++exact; break;
    case Certainty::certified: ++certified; break;
    case Certainty::uncertain: ++uncertain; break;
  }
  enclosures_checked += static_cast<std::size_t>(score.enclosures_checked);
  enclosures_missed += static_cast<std::size_t>(score.enclosures_missed);
  auto append = [](std::vector<double>& to, const std::vector<double>& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  append(crossing_m, score.crossing_m);
  append(crossing_ulps, score.crossing_ulps);
  append(point_m, score.point_m);
  append(point_ulps, score.point_ulps);
  append(depth_relative, score.depth_relative);
  append(all_round_point_m, score.all_round_point_m);
  append(enclosure_radius_m, score.enclosure_radius_m);
}

}  // namespace clearjoint::bench
