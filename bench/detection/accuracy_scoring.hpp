// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Scoring one detection answer against the multiprecision reference, and tallying the scores.
///
/// Definitions (docs/reports/benchmarks.md repeats them):
/// * wrong scenario: the answer's scenario differs from the reference's;
/// * missed / spurious contact: contacts are keyed by (type, base); a reference contact with no
///   answer contact of its key is missed, an answer contact with no reference contact spurious
///   (a rim with two penetration arcs has two contacts of one key, matched by nearest point);
/// * crossing ("root") error: distance from each crossing point of a matched contact to the
///   nearest reference crossing point, in metres and in ulps, where the ulp is that of the
///   reference point's largest coordinate (|x - x_ref|_inf / ulp(|x_ref|_inf));
/// * contact-point error: the larger of the journal-point and bearing-point errors (p_WCj,
///   p_WCi), in metres and in ulps as above;
/// * depth relative error: |depth - depth_ref| / depth_ref;
/// * enclosure: every crossing of a certified or exact answer that carries a finite point_error
///   must lie within point_error of its reference crossing point.
/// Points of a contact whose rim is beyond the wall all round are not compared (no arc middle);
/// those of a rim beyond a base all round are tallied apart (ReferenceContact::all_round).

#include <cstddef>
#include <string>
#include <vector>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "joint_reference.hpp"

namespace clearjoint::bench {

struct InputScore {
  bool threw = false;
  bool wrong_scenario = false;
  int missed = 0;
  int spurious = 0;
  geometry::Certainty level = geometry::Certainty::uncertain;
  int enclosures_checked = 0;
  int enclosures_missed = 0;
  std::vector<double> crossing_m, crossing_ulps, point_m, point_ulps, depth_relative;
  /// Point errors of contacts whose rim is beyond a base all round (ReferenceContact::all_round).
  std::vector<double> all_round_point_m;
  /// The point_error (enclosure radius, m) of every checked crossing: how tight the promises are.
  std::vector<double> enclosure_radius_m;
  std::vector<std::string> problems;  ///< one line per failure, for the failure list

  bool failed() const {
    return threw || wrong_scenario || missed > 0 || spurious > 0 || enclosures_missed > 0;
  }
};

/// Scores `answer` against `reference` (which must be decided).
InputScore score_answer(const geometry::JointContacts& answer, const ReferenceAnswer& reference);

/// Median, 99th percentile and maximum of a sample (NaN when empty).
struct Summary {
  std::size_t count = 0;
  double median = 0.0, p99 = 0.0, max = 0.0;
};
Summary summarize(std::vector<double> values);

/// Counts over many inputs of one method (and one family, or one group of a family).
struct Tally {
  std::size_t inputs = 0;
  std::size_t reference_undecided = 0;  ///< not scored
  std::size_t reference_beyond_model = 0;
  std::size_t exceptions = 0;
  std::size_t wrong_scenarios = 0;
  std::size_t wrong_scenarios_within_model = 0;  ///< where the reference is not beyond_model
  std::size_t inputs_with_missed = 0, missed = 0;
  std::size_t inputs_with_spurious = 0, spurious = 0;
  std::size_t failed_inputs = 0;
  std::size_t exact = 0, certified = 0, uncertain = 0;
  std::size_t enclosures_checked = 0, enclosures_missed = 0;
  std::vector<double> crossing_m, crossing_ulps, point_m, point_ulps, depth_relative;
  std::vector<double> all_round_point_m;
  std::vector<double> enclosure_radius_m;

  void add_undecided() {
    ++inputs;
    ++reference_undecided;
  }
  void add(const InputScore& score, geometry::ContactScenario reference_scenario);
};

}  // namespace clearjoint::bench
