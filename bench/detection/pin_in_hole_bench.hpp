// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The pin-in-hole joint's cost beside the paper's joint (bench_detection): the same poses, both
// joints certified, measured interleaved.

#include <vector>

#include "input_families.hpp"

namespace clearjoint::bench {

/// Registers "pin_in_hole/<name>/certified", a timed loop over `inputs` read as pin-in-hole
/// joints (pin_in_hole_input below), with the counter ratio_to_paper_joint: the median over
/// rounds of (a pass over the set with the pin-in-hole joint) / (a pass with the paper's joint),
/// the two passes of a round back to back, their order alternating, so that a change of machine
/// load falls on both. Beside it, the same on the poses where both joints are free
/// (both_free_ratio) and where both are in contact (both_in_contact_ratio), and
/// contact_share_matched_ratio: the two joints' per-query costs on those subsets weighted by the
/// paper joint's contact share (paper_contact_share; contact_share is the pin's), the cost of
/// like with like (the pin touches more often on the same poses). `inputs` must outlive the
/// benchmarks.
void register_pin_in_hole_benchmark(const char* name, const std::vector<DetectionInput>& inputs);

}  // namespace clearjoint::bench
