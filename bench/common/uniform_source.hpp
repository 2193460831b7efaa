// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The random source of every benchmark input set, so that a seed means the same inputs in every
/// suite and with every standard library.

#include <cstdint>
#include <random>

namespace clearjoint::bench {

/// Uniform doubles from mt19937_64 (whose output sequence the standard fixes) with an explicit
/// 53-bit conversion (std::uniform_real_distribution's algorithm is not specified).
class UniformSource {
 public:
  explicit UniformSource(std::uint64_t seed) : engine_(seed) {}
  /// A double in [low, high).
  double operator()(double low, double high) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;  // [0, 1)
    return low + (high - low) * unit;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace clearjoint::bench
