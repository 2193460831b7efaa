// SPDX-License-Identifier: BSD-3-Clause
// The long run of the detection property test (support/testing/joint_properties.hpp):
// N random joints (default 1e7), each checked under an A/B swap, a reversed journal axis, a
// power-of-two change of units and a random rigid motion. Not a timing: a count of violations,
// which must be 0. Prints a JSON summary (seed, joints, violations, scenarios seen, seconds).
//
//   joint_properties_run [--joints N] [--seed S]
// Exit status 0 when no joint violates a property, 1 otherwise (the first ten are listed).

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "joint_properties.hpp"

int main(int argc, char** argv) {
  namespace geo = clearjoint::geometry;
  namespace props = clearjoint::geometry::properties;
  long joints = 10'000'000;
  unsigned long long seed = 20170401;
  for (int k = 1; k + 1 < argc; k += 2) {
    if (std::strcmp(argv[k], "--joints") == 0) {
      joints = std::atol(argv[k + 1]);
    } else if (std::strcmp(argv[k], "--seed") == 0) {
      seed = std::strtoull(argv[k + 1], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: joint_properties_run [--joints N] [--seed S]\n");
      return 2;
    }
  }
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> unit_exponent(-40, 40);
  std::array<long, static_cast<int>(geo::ContactScenario::beyond_model) + 1> scenarios{};
  long violations = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < joints; ++i) {
    const props::Joint joint = props::random_joint(rng);
    const Eigen::Isometry3d motion = props::random_motion(rng, 100.0 * props::joint_size(joint));
    const std::string violation = props::check_properties(joint, motion, unit_exponent(rng));
    if (!violation.empty() && ++violations <= 10) {
      std::fprintf(stderr, "joint %ld: %s\n", i, violation.c_str());
    }
    scenarios[static_cast<std::size_t>(
        geo::detect_contacts(joint.dimensions, joint.bearing, joint.journal).scenario)] += 1;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("{\"seed\": %llu, \"joints\": %ld, \"violations\": %ld, \"seconds\": %.1f, \"scenarios\": {",
              seed, joints, violations, seconds);
  for (std::size_t s = 0; s < scenarios.size(); ++s) {
    std::printf("%s\"%s\": %ld", s ? ", " : "",
                std::string(geo::to_string(static_cast<geo::ContactScenario>(s))).c_str(), scenarios[s]);
  }
  std::printf("}}\n");
  return violations == 0 ? 0 : 1;
}
