// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/engines/engine_choice.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "clearjoint/dynamics/errors.hpp"
#include "clearjoint/validation_error.hpp"
#ifdef CLEARJOINT_WITH_NONSMOOTH
#include "clearjoint/nonsmooth/moreau_jean_run.hpp"
#endif

#ifdef CLEARJOINT_WITH_SIMBODY
#include "clearjoint/simbody/model_in_simbody.hpp"
#include "clearjoint/simbody/simulate_in_simbody.hpp"
#endif

namespace clearjoint::engines {

namespace {

/// "clearjoint, simbody": this build's engines, for messages.
std::string engine_list() {
  std::string names;
  for (const std::string_view name : available_engines()) {
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  return names;
}

/// What follows the field in the refusal of `engine` (" = 'bogus': unknown engine; ..."), or
/// nothing when it can run here.
std::string unavailable_detail(std::string_view engine) {
  const std::vector<std::string_view> engines = available_engines();
  if (std::find(engines.begin(), engines.end(), engine) != engines.end()) return {};
  const std::string value = " = '" + std::string(engine) + "': ";
  if (engine == "simbody") {
    return value + "this clearjoint was built without Simbody (CLEARJOINT_WITH_SIMBODY; Debian: "
                   "libsimbody-dev, docs/engines.md); the engines of this build are " + engine_list();
  }
  return value + "unknown engine; the engines of this build are " + engine_list();
}

}  // namespace

std::vector<std::string_view> available_engines() {
#ifdef CLEARJOINT_WITH_SIMBODY
  return {kDefaultEngine, "simbody"};
#else
  return {kDefaultEngine};
#endif
}

std::string engine_unavailable(std::string_view engine, std::string_view field) {
  const std::string detail = unavailable_detail(engine);
  return detail.empty() ? detail : std::string(field) + detail;
}

void require_engine(std::string_view engine, std::string_view field) {
  if (const std::string detail = unavailable_detail(engine); !detail.empty()) {
    throw ValidationError(field, detail);
  }
}

void check_model_for_engine(std::string_view engine, std::string_view field, const dynamics::ModelDescription& model) {
  require_engine(engine, field);
#ifdef CLEARJOINT_WITH_SIMBODY
  if (engine == "simbody") simbody::SimbodyModel check(model);
#else
  (void)model;
#endif
}

dynamics::SimulationSummary simulate_with_engine(std::string_view engine, std::string_view field,
                                                 dynamics::SimulationRun& run, dynamics::SimulationOutput& output,
                                                 const dynamics::ProgressCallback& progress) {
  require_engine(engine, field);
#ifdef CLEARJOINT_WITH_SIMBODY
  if (engine == "simbody") return simbody::simulate_in_simbody(run, output, progress);
#endif
  return run.run(output, progress);
}

PlannedRun plan_run(std::string_view engine, std::string_view field, const dynamics::ModelDescription& model,
                    const dynamics::RunOptions& options) {
  require_engine(engine, field);
  if (model.solver_method == dynamics::SolverMethod::moreau_jean) {
    if (engine != kDefaultEngine) {
      throw ValidationError(field, " = '" + std::string(engine) +
                                       "': solver.method = \"moreau_jean\" runs in clearjoint's own "
                                       "engine only (docs/nonsmooth.md)");
    }
#ifdef CLEARJOINT_WITH_NONSMOOTH
    auto run = std::make_shared<nonsmooth::MoreauJeanRun>(model, options);
    return [run](dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
      return run->run(output, progress);
    };
#else
    throw dynamics::ModelError("solver.method", " = \"moreau_jean\": this clearjoint was built without Siconos "
                                                "Numerics (CLEARJOINT_WITH_SICONOS; Debian: libsiconos-numerics-dev, "
                                                "docs/nonsmooth.md)");
#endif
  }
  auto run = std::make_shared<dynamics::SimulationRun>(model, options);
  check_model_for_engine(engine, field, model);
  const std::string name(engine), field_name(field);
  return [run, name, field_name](dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
    return simulate_with_engine(name, field_name, *run, output, progress);
  };
}

}  // namespace clearjoint::engines
