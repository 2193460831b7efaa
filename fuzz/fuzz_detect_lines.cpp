// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the JSON Lines reader of `clearjoint detect` (fuzz_json_lines.hpp).
#include "fuzz_json_lines.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  clearjoint::fuzz::answer_lines(clearjoint::app::detect_command(), data, size);
  return 0;
}
