// SPDX-License-Identifier: BSD-3-Clause
// The detection suite's non-timing half (issue 5): the accuracy evaluation of every method on
// every input family against the multiprecision reference, and the robustness export of the
// families as `clearjoint detect` JSON Lines with their reference answers.
//
//   detection_suite accuracy [--quick] [--threads N] [--families a,b] [--out FILE]
//                            [--check]
//   detection_suite export   [--quick] [--threads N] [--families a,b] --out-dir DIR
//
// docs/reports/benchmarks.md describes the families, the scores and the file formats.

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <mpfr.h>

#include "accuracy_run.hpp"
#include "input_families.hpp"
#include "joint_reference.hpp"
#include "json_output.hpp"

namespace {

namespace bench = clearjoint::bench;

constexpr const char* kUsage =
    "usage: detection_suite accuracy [--quick] [--threads N] [--families a,b] [--out FILE]\n"
    "                                [--check]\n"
    "       detection_suite export   [--quick] [--threads N] [--families a,b] --out-dir DIR\n"
    "\n"
    "accuracy  scores the paper baseline, clearjoint uncertified and clearjoint certified on every\n"
    "          input family against the MPFR reference; writes the JSON report to FILE (default\n"
    "          detection_accuracy.json) and a summary to stdout.\n"
    "          --check: exit status 1 unless the reference decided every input and the certified\n"
    "          pipeline has no wrong scenario, no missed or spurious contact and no enclosure\n"
    "          missing the reference, scored against the joint as given (its certificates'\n"
    "          claim; joint_reference.hpp). Failures against the joint with exactly normalised\n"
    "          axes are reported beside it, not checked.\n"
    "export    writes DIR/<family>.jsonl (clearjoint detect input lines) and\n"
    "          DIR/<family>.reference.jsonl (the reference answers, same ids, same order).\n"
    "families  realistic, near_tangent, near_parallel, extreme, trajectories (default: all).\n"
    "--quick   a few inputs per group (the ctest variant).\n";

struct Arguments {
  std::string command;
  bench::SuiteSize size = bench::SuiteSize::full;
  int threads = 2;
  std::vector<std::string> families;
  std::string out = "detection_accuracy.json";
  std::string out_dir;
  bool check = false;
};

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "detection_suite: %s\n\n%s", message.c_str(), kUsage);
  std::exit(2);
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  if (argc < 2) usage_error("missing command");
  a.command = argv[1];
  if (a.command == "--help" || a.command == "-h") {
    std::fputs(kUsage, stdout);
    std::exit(0);
  }
  if (a.command != "accuracy" && a.command != "export") usage_error("unknown command '" + a.command + "'");
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--quick") {
      a.size = bench::SuiteSize::quick;
    } else if (arg == "--threads") {
      const std::string text = value();
      char* end = nullptr;
      const long n = std::strtol(text.c_str(), &end, 10);
      if (end == text.c_str() || *end != '\0' || n < 1 || n > 64) {
        usage_error("--threads = " + text + ": must be an integer from 1 to 64");
      }
      a.threads = static_cast<int>(n);
    } else if (arg == "--families") {
      std::stringstream list(value());
      for (std::string name; std::getline(list, name, ',');) {
        bool known = false;
        for (const bench::FamilySpec& spec : bench::family_specs()) known = known || name == spec.name;
        if (!known) usage_error("--families: unknown family '" + name + "'");
        a.families.push_back(name);
      }
    } else if (arg == "--out" && a.command == "accuracy") {
      a.out = value();
    } else if (arg == "--check" && a.command == "accuracy") {
      a.check = true;
    } else if (arg == "--out-dir" && a.command == "export") {
      a.out_dir = value();
    } else {
      usage_error("unknown option '" + arg + "' for " + a.command);
    }
  }
  if (a.command == "export" && a.out_dir.empty()) usage_error("export needs --out-dir DIR");
  return a;
}

void print_summary(const bench::Json& report) {
  std::printf("%-14s %-16s %6s %6s %6s %6s %6s %9s %9s\n", "family", "method", "inputs", "wrong",
              "missed", "spur.", "encl.x", "p99 pt m", "uncert.");
  for (const bench::Json& row : report["results"]) {
    if (!row["group"].get<std::string>().empty()) continue;
    const double p99 = row["point_error_m"]["p99"].is_number() ? row["point_error_m"]["p99"].get<double>() : 0.0;
    std::printf("%-14s %-16.16s %6zu %6zu %6zu %6zu %6zu %9.2e %9zu\n",
                row["family"].get<std::string>().c_str(), row["method"].get<std::string>().c_str(),
                row["inputs"].get<std::size_t>(), row["wrong_scenarios"].get<std::size_t>(),
                row["missed_contacts"].get<std::size_t>(), row["spurious_contacts"].get<std::size_t>(),
                row["enclosures_missed"].get<std::size_t>(), p99, row["answers_uncertain"].get<std::size_t>());
  }
}

int run_accuracy(const Arguments& a) {
  bench::AccuracyOptions options;
  options.size = a.size;
  options.families = a.families;
  options.threads = a.threads;
  const bench::AccuracyResult result = bench::run_accuracy(options);
  bench::write_file_atomically(a.out, result.report.dump(1) + "\n");
  print_summary(result.report);
  std::printf("\ncertified pipeline, inputs with a failure: %zu against the joint as given, %zu against "
              "the joint with exactly normalised axes; reference undecided on %zu inputs\nreport: %s\n",
              result.certified_failures_as_given, result.certified_failures_exact_axes,
              result.reference_undecided, a.out.c_str());
  if (!a.check) return 0;
  const std::size_t failures = result.certified_failures_as_given;
  if (failures > 0 || result.reference_undecided > 0) {
    std::fprintf(stderr,
                 "detection_suite: CHECK FAILED: %zu inputs with a certified failure against the joint as given, "
                 "%zu inputs the reference left undecided (\"failures\" and \"reference_undecided\" in %s)\n",
                 failures, result.reference_undecided, a.out.c_str());
    return 1;
  }
  std::printf("check passed: no certified failure against the joint as given\n");
  return 0;
}

int run_export(const Arguments& a) {
  for (const bench::FamilySpec& spec : bench::family_specs()) {
    if (!a.families.empty() && std::find(a.families.begin(), a.families.end(), spec.name) == a.families.end()) {
      continue;
    }
    const std::vector<bench::DetectionInput> inputs = bench::generate_family(spec.name, a.size);
    std::vector<std::string> reference_lines(inputs.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (std::size_t i = next++; i < inputs.size(); i = next++) {
        const bench::DetectionInput& input = inputs[i];
        const bench::ReferenceAnswer answer =
            bench::reference_detect(bench::joint_as_given(input.dimensions, input.bearing, input.journal));
        reference_lines[i] = bench::reference_answer_line(input, answer).dump();
      }
      // MPFR keeps its constant caches (pi, log 2, ...) per thread and frees a thread's only when
      // asked from that thread: Boost frees the main thread's at exit, the workers free theirs here.
      mpfr_free_cache();
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < a.threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    std::string input_text, reference_text;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      input_text += bench::detect_input_line(inputs[i]).dump() + "\n";
      reference_text += reference_lines[i] + "\n";
    }
    const std::string stem = a.out_dir + "/" + spec.name;
    bench::write_file_atomically(stem + ".jsonl", input_text);
    bench::write_file_atomically(stem + ".reference.jsonl", reference_text);
    std::fprintf(stderr, "export: %-13s %5zu lines -> %s.jsonl, %s.reference.jsonl (seed %llu)\n", spec.name,
                 inputs.size(), stem.c_str(), stem.c_str(), static_cast<unsigned long long>(spec.seed));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Arguments arguments = parse(argc, argv);
  try {
    return arguments.command == "accuracy" ? run_accuracy(arguments) : run_export(arguments);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "detection_suite: %s\n", error.what());
    return 2;
  }
}
