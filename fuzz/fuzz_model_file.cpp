// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the model-file reader (dynamics/src/model_file.cpp) and the model checks of
// build_model. Invariant: any text either gives a model or a ModelError (bad model) or a
// SolverError (initial conditions that cannot be made consistent); anything else, a crash or a
// sanitizer report is a bug. Models with more than kMaxBodies bodies are parsed but not built,
// to keep each input fast.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/dynamics/model_builder.hpp"
#include "clearjoint/dynamics/model_file.hpp"

namespace {
constexpr std::size_t kMaxBodies = 8;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace dyn = clearjoint::dynamics;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const dyn::ModelDescription model = dyn::parse_model(text, "fuzz.json");
    if (model.bodies.size() <= kMaxBodies && model.joints.size() <= 2 * kMaxBodies) {
      dyn::build_model(model);
    }
  } catch (const dyn::ModelError&) {
  } catch (const dyn::SolverError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz invariant broken: unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
