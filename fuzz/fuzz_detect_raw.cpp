// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: detect_contacts on raw doubles. The input's first byte chooses how the rest
// is read: as 16 plain doubles (dimensions, centres, axes; most are rejected with InvalidInput)
// or as the parameters of a joint near contact (joint_properties.hpp's generator, driven by the input's
// bytes instead of a random engine), so that the fuzzer reaches every scenario. Invariants
// (joint_properties.hpp): no exception but InvalidInput; counts, certificates, depths and points
// consistent; the same answer after an A/B swap, a reversed journal axis and a power-of-two
// change of units.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <random>

#include <fuzzer/FuzzedDataProvider.h>

#include "clearjoint/geometry/model/primitives.hpp"
#include "joint_properties.hpp"

namespace {

namespace geo = clearjoint::geometry;
namespace props = clearjoint::geometry::properties;

// Raw doubles beyond this magnitude range (0 aside) are skipped: detection is correct there too,
// but vectors mixing magnitudes hundreds of orders apart take seconds in the exact fallback
// (docs/command-line.md, "Limits"), which would stall the fuzzer rather than test anything new.
constexpr double kSmallest = 1e-40;
constexpr double kLargest = 1e40;

bool in_range(double x) {
  const double m = std::fabs(x);
  return m == 0.0 || (m >= kSmallest && m <= kLargest);
}

/// A uniform random bit generator reading the fuzzer's bytes, so that the property generator
/// explores what the fuzzer steers. Once the bytes run out it continues with splitmix64 seeded
/// by what it read: a constant stream (FuzzedDataProvider's zeros) would keep the standard
/// distributions' rejection sampling looping forever.
class ByteEngine {
 public:
  using result_type = std::uint32_t;
  explicit ByteEngine(FuzzedDataProvider& data) : data_(data) {}
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() {
    if (data_.remaining_bytes() >= sizeof(result_type)) {
      const result_type value = data_.ConsumeIntegral<result_type>();
      state_ = state_ * 31 + value;
      return value;
    }
    state_ += 0x9E3779B97F4A7C15ULL;  // splitmix64
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return static_cast<result_type>((z ^ (z >> 31)) >> 32);
  }

 private:
  FuzzedDataProvider& data_;
  std::uint64_t state_ = 0;
};

void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
  std::abort();
}

void check_joint(const props::Joint& joint, int unit_exponent) {
  try {
    const std::string violation = props::check_properties(joint, std::nullopt, unit_exponent);
    if (!violation.empty()) fail(violation);
  } catch (const geo::InvalidInput&) {
  } catch (const std::exception& e) {
    fail(std::string("unexpected exception: ") + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  const bool raw = data.ConsumeBool();
  const int unit_exponent = data.ConsumeIntegralInRange<int>(-60, 60);
  if (raw) {
    // The bytes themselves (the seeds' layout, fuzz/make_seed_corpus.py), so that mutations of
    // single bits, exponents and signs reach the detection as such; missing bytes read as 0.
    double v[16] = {};
    data.ConsumeData(v, sizeof v);
    for (double x : v) {
      if (!in_range(x)) return 0;
    }
    const props::Joint joint{{v[0], v[1], v[2], v[3]},
                             {{v[4], v[5], v[6]}, {v[7], v[8], v[9]}},
                             {{v[10], v[11], v[12]}, {v[13], v[14], v[15]}}};
    // The power-of-two scaling must stay exact: keep every length within the normal range.
    if (props::joint_size(joint) * std::ldexp(1.0, unit_exponent) > 1e200) return 0;
    check_joint(joint, unit_exponent);
  } else {
    ByteEngine engine(data);
    check_joint(props::random_joint(engine), unit_exponent);
  }
  return 0;
}
