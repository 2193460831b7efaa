// SPDX-License-Identifier: BSD-3-Clause
#include "accuracy_run.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

#include <mpfr.h>

#include "accuracy_scoring.hpp"
#include "detection_methods.hpp"
#include "joint_reference.hpp"

namespace clearjoint::bench {
namespace {

using geometry::ContactScenario;

constexpr std::size_t kMethodCount = kMethods.size();
constexpr std::size_t kCertifiedIndex = 2;
static_assert(kMethods[kCertifiedIndex] == Method::certified);

/// Everything learnt from one input.
struct InputOutcome {
  bool decided = true;
  std::string why;
  ContactScenario reference_scenario = ContactScenario::none;
  std::array<InputScore, kMethodCount> scores;
  std::array<ContactScenario, kMethodCount> scenarios{};
  /// The certified pipeline scored against the joint with exactly normalised axes (diagnostic).
  bool exact_axes_decided = true;
  InputScore certified_vs_exact_axes;
  ContactScenario exact_axes_scenario = ContactScenario::none;
};

InputOutcome evaluate(const DetectionInput& input) {
  InputOutcome outcome;
  const ReferenceAnswer reference =
      reference_detect(joint_as_given(input.dimensions, input.bearing, input.journal));
  outcome.decided = reference.decided;
  outcome.why = reference.why;
  outcome.reference_scenario = reference.scenario;
  if (!reference.decided) return outcome;
  std::optional<geometry::JointContacts> certified_answer;
  for (std::size_t m = 0; m < kMethodCount; ++m) {
    try {
      const geometry::JointContacts answer = run_method(kMethods[m], input);
      outcome.scores[m] = score_answer(answer, reference);
      outcome.scenarios[m] = answer.scenario;
      if (m == kCertifiedIndex) certified_answer = answer;
    } catch (const std::exception& error) {
      outcome.scores[m].threw = true;
      outcome.scores[m].problems.push_back(std::string("threw: ") + error.what());
    }
  }
  if (certified_answer) {
    const ReferenceAnswer exact_axes = reference_detect(
        joint_with_exact_unit_axes(input.dimensions, input.bearing, input.journal));
    outcome.exact_axes_decided = exact_axes.decided;
    outcome.exact_axes_scenario = exact_axes.scenario;
    if (exact_axes.decided) outcome.certified_vs_exact_axes = score_answer(*certified_answer, exact_axes);
  }
  return outcome;
}

Json summary_json(const std::vector<double>& values) {
  const Summary s = summarize(values);
  return Json{{"count", s.count}, {"median", s.median}, {"p99", s.p99}, {"max", s.max}};
}

Json tally_json(const Tally& t) {
  return Json{{"inputs", t.inputs},
              {"reference_undecided", t.reference_undecided},
              {"reference_beyond_model", t.reference_beyond_model},
              {"exceptions", t.exceptions},
              {"failed_inputs", t.failed_inputs},
              {"wrong_scenarios", t.wrong_scenarios},
              {"wrong_scenarios_within_model", t.wrong_scenarios_within_model},
              {"inputs_with_missed", t.inputs_with_missed},
              {"missed_contacts", t.missed},
              {"inputs_with_spurious", t.inputs_with_spurious},
              {"spurious_contacts", t.spurious},
              {"answers_exact", t.exact},
              {"answers_certified", t.certified},
              {"answers_uncertain", t.uncertain},
              {"enclosures_checked", t.enclosures_checked},
              {"enclosures_missed", t.enclosures_missed},
              {"crossing_error_m", summary_json(t.crossing_m)},
              {"crossing_error_ulps", summary_json(t.crossing_ulps)},
              {"point_error_m", summary_json(t.point_m)},
              {"point_error_ulps", summary_json(t.point_ulps)},
              {"depth_relative_error", summary_json(t.depth_relative)},
              {"point_error_m_rim_beyond_base_all_round", summary_json(t.all_round_point_m)},
              {"enclosure_radius_m", summary_json(t.enclosure_radius_m)}};
}

/// Runs `evaluate` on every input with `threads` workers; progress on stderr.
std::vector<InputOutcome> evaluate_all(const std::vector<DetectionInput>& inputs, int threads,
                                       const std::string& family, bool progress) {
  std::vector<InputOutcome> outcomes(inputs.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (std::size_t i = next++; i < inputs.size(); i = next++) {
      outcomes[i] = evaluate(inputs[i]);
      const std::size_t finished = ++done;
      if (progress && (finished % 256 == 0 || finished == inputs.size())) {
        const std::lock_guard lock(print);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "accuracy: %-13s %5zu / %zu inputs scored (%.0f s)\n", family.c_str(),
                     finished, inputs.size(), seconds);
      }
    }
    // MPFR keeps its constant caches (pi, log 2, ...) per thread and frees a thread's only when
    // asked from that thread: Boost frees the main thread's at exit, the workers free theirs here.
    mpfr_free_cache();
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, threads); ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return outcomes;
}

}  // namespace

AccuracyResult run_accuracy(const AccuracyOptions& options) {
  AccuracyResult result;
  Json families_json = Json::array();
  Json results_json = Json::array();
  Json failures_json = Json::array();
  Json undecided_json = Json::array();
  for (const FamilySpec& spec : family_specs()) {
    if (!options.families.empty() &&
        std::find(options.families.begin(), options.families.end(), spec.name) == options.families.end()) {
      continue;
    }
    const std::string family = spec.name;
    const auto generation_start = std::chrono::steady_clock::now();
    const std::vector<DetectionInput> inputs = generate_family(family, options.size, [&](double fraction) {
      if (options.progress) std::fprintf(stderr, "generate: %-13s %3.0f%%\n", family.c_str(), 100 * fraction);
    });
    const double generation_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - generation_start).count();
    const std::vector<InputOutcome> outcomes = evaluate_all(inputs, options.threads, family, options.progress);

    // Tallies: the whole family ("" group) and each group, per method, plus the certified
    // pipeline against the joint with exactly normalised axes.
    std::vector<std::string> groups{""};
    for (const DetectionInput& input : inputs) {
      if (!input.group.empty() && std::find(groups.begin(), groups.end(), input.group) == groups.end()) {
        groups.push_back(input.group);
      }
    }
    std::map<std::string, double> group_values;
    std::map<std::pair<std::string, std::size_t>, Tally> tallies;  // (group, method; 3 = certified vs exact unit axes)
    std::map<std::string, std::size_t> reference_scenarios;
    std::map<std::string, std::map<std::string, std::size_t>> method_listed;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const DetectionInput& input = inputs[i];
      const InputOutcome& o = outcomes[i];
      group_values[input.group] = input.group_value;
      const std::vector<std::string> own_groups =
          input.group.empty() ? std::vector<std::string>{""} : std::vector<std::string>{"", input.group};
      if (!o.decided) {
        ++result.reference_undecided;
        undecided_json.push_back(Json{{"id", input.id}, {"why", o.why}, {"input", hex_input(input)}});
        for (const std::string& g : own_groups) {
          for (std::size_t m = 0; m <= kMethodCount; ++m) tallies[{g, m}].add_undecided();
        }
        continue;
      }
      ++reference_scenarios[scenario_label(o.reference_scenario)];
      for (const std::string& g : own_groups) {
        for (std::size_t m = 0; m < kMethodCount; ++m) tallies[{g, m}].add(o.scores[m], o.reference_scenario);
        if (o.exact_axes_decided) {
          tallies[{g, kMethodCount}].add(o.certified_vs_exact_axes, o.exact_axes_scenario);
        } else {
          tallies[{g, kMethodCount}].add_undecided();
        }
      }
      const bool certified_failed = o.scores[kCertifiedIndex].failed();
      const bool exact_axes_failed = o.exact_axes_decided && o.certified_vs_exact_axes.failed();
      if (certified_failed) ++result.certified_failures_as_given;
      if (exact_axes_failed) ++result.certified_failures_exact_axes;
      for (std::size_t m = 0; m < kMethodCount; ++m) {
        const bool certified = m == kCertifiedIndex;
        const bool failed = o.scores[m].failed() || (certified && exact_axes_failed);
        if (!failed) continue;
        const std::string method(to_string(kMethods[m]));
        if (!certified && method_listed[method][family]++ >= static_cast<std::size_t>(options.listed_failures)) {
          continue;
        }
        Json entry{{"method", method},
                   {"id", input.id},
                   {"family", family},
                   {"group", input.group},
                   {"reference_scenario", scenario_label(o.reference_scenario)},
                   {"answer_scenario", scenario_label(o.scenarios[m])},
                   {"problems", o.scores[m].problems}};
        if (std::isfinite(input.measured_margin)) entry["measured_margin"] = input.measured_margin;
        if (std::isfinite(input.measured_tilt)) entry["measured_tilt"] = input.measured_tilt;
        if (certified) {
          entry["against_exact_unit_axes"] =
              Json{{"decided", o.exact_axes_decided},
                   {"reference_scenario", scenario_label(o.exact_axes_scenario)},
                   {"failed", exact_axes_failed},
                   {"problems", o.certified_vs_exact_axes.problems}};
        }
        entry["input"] = hex_input(input);
        failures_json.push_back(std::move(entry));
      }
    }
    for (const std::string& group : groups) {
      for (std::size_t m = 0; m <= kMethodCount; ++m) {
        const std::string method = m < kMethodCount ? std::string(to_string(kMethods[m]))
                                                    : std::string("certified_vs_exact_unit_axes");
        Json row{{"family", family}, {"group", group}, {"method", method}};
        if (!group.empty()) row["group_value"] = group_values[group];
        row.update(tally_json(tallies[{group, m}]));
        results_json.push_back(std::move(row));
      }
    }
    double margin_min = 0, margin_max = 0, tilt_min = 0, tilt_max = 0;
    bool first_margin = true, first_tilt = true;
    for (const DetectionInput& input : inputs) {
      if (std::isfinite(input.measured_margin)) {
        const double m = std::fabs(input.measured_margin);
        margin_min = first_margin ? m : std::min(margin_min, m);
        margin_max = first_margin ? m : std::max(margin_max, m);
        first_margin = false;
      }
      if (std::isfinite(input.measured_tilt) && input.measured_tilt > 0) {
        tilt_min = first_tilt ? input.measured_tilt : std::min(tilt_min, input.measured_tilt);
        tilt_max = first_tilt ? input.measured_tilt : std::max(tilt_max, input.measured_tilt);
        first_tilt = false;
      }
    }
    Json family_json{{"name", family},
                     {"seed", spec.seed},
                     {"description", spec.description},
                     {"inputs", inputs.size()},
                     {"groups", groups.size() - 1},
                     {"generation_seconds", generation_seconds},
                     {"reference_scenarios", reference_scenarios}};
    if (!first_margin) family_json["measured_abs_margin_range_clearances"] = {margin_min, margin_max};
    if (!first_tilt) family_json["measured_nonzero_tilt_range_rad"] = {tilt_min, tilt_max};
    families_json.push_back(std::move(family_json));
  }
  result.report = Json{{"suite_size", options.size == SuiteSize::full ? "full" : "quick"},
                       {"reference_digits", kReferenceDigits10},
                       {"methods", {"paper_baseline", "uncertified", "certified"}},
                       {"families", std::move(families_json)},
                       {"results", std::move(results_json)},
                       {"certified_failures_against_joint_as_given", result.certified_failures_as_given},
                       {"certified_failures_against_exact_unit_axes", result.certified_failures_exact_axes},
                       {"reference_undecided", std::move(undecided_json)},
                       {"failures", std::move(failures_json)}};
  return result;
}

}  // namespace clearjoint::bench
