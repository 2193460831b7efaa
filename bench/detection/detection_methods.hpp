// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The detection methods the benchmarks compare, behind one call.

#include <array>
#include <string_view>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "input_families.hpp"

namespace clearjoint::bench {

enum class Method {
  paper_baseline,  ///< the paper as written: plain Newton-Raphson, eqs. 5-23 (paper_baseline.hpp)
  uncertified,     ///< clearjoint with DetectionOptions::intersection.certify = false
  certified,       ///< clearjoint with its default options (certificates and exact fallback)
};

inline constexpr std::array<Method, 3> kMethods = {Method::paper_baseline, Method::uncertified,
                                                   Method::certified};

std::string_view to_string(Method method) noexcept;

/// Runs `method` on `input`. clearjoint's methods throw geometry::InvalidInput on bad input.
geometry::JointContacts run_method(Method method, const DetectionInput& input);

}  // namespace clearjoint::bench
