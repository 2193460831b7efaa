// SPDX-License-Identifier: BSD-3-Clause
// simulate's engine choice (engines/choice, shared with Python's simulate): an engine that cannot
// run the model is refused with the project's ValidationError naming --engine, as every bad input is.

#include <gtest/gtest.h>

#include <string>

#include "clearjoint/dynamics/model_description.hpp"
#include "clearjoint/validation_error.hpp"
#include "clearjoint/engines/engine_choice.hpp"

namespace clearjoint::engines {
namespace {

/// The ValidationError plan_run throws, as "field_path | what()"; "no error" or "other error".
std::string refusal(std::string_view engine, const dynamics::ModelDescription& model) {
  try {
    plan_run(engine, "--engine", model, {});
  } catch (const ValidationError& e) {
    return std::string(e.field_path()) + " | " + e.what();
  } catch (const std::exception& e) {
    return std::string("other error: ") + e.what();
  }
  return "no error";
}

TEST(SimulateEngine, RefusesAnUnknownEngineWithAValidationErrorNamingTheOptionAndThisBuildsEngines) {
  // The words of Python's simulate(engine=...) too, which has the same check under its keyword.
  std::string engines;
  for (const std::string_view name : available_engines()) engines += (engines.empty() ? "" : ", ") + std::string(name);
  EXPECT_EQ(refusal("bogus", {}),
            "--engine | --engine = 'bogus': unknown engine; the engines of this build are " + engines);
}

TEST(SimulateEngine, RefusesAMoreauJeanModelOutsideItsOwnEngineNamingTheOption) {
  dynamics::ModelDescription model;
  model.solver_method = dynamics::SolverMethod::moreau_jean;
  // Simbody cannot run it, whether or not this program was built with Simbody.
  EXPECT_EQ(refusal("simbody", model).rfind("--engine | --engine = 'simbody': ", 0), 0u)
      << refusal("simbody", model);
}

}  // namespace
}  // namespace clearjoint::engines
