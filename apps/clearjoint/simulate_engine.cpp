// SPDX-License-Identifier: BSD-3-Clause
#include "simulate_engine.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "clearjoint/dynamics/errors.hpp"
#ifdef CLEARJOINT_WITH_NONSMOOTH
#include "clearjoint/nonsmooth/moreau_jean_run.hpp"
#endif

#ifdef CLEARJOINT_WITH_SIMBODY
#include "clearjoint/simbody/model_in_simbody.hpp"
#include "clearjoint/simbody/simulate_in_simbody.hpp"
#endif

namespace clearjoint::app {

std::string engine_unavailable(std::string_view engine) {
  if (engine == kDefaultEngine) return {};
  if (engine == "simbody") {
#ifdef CLEARJOINT_WITH_SIMBODY
    return {};
#else
    return "--engine simbody: this clearjoint was built without Simbody (CLEARJOINT_WITH_SIMBODY; "
           "Debian: libsimbody-dev, docs/engines.md)";
#endif
  }
  return "--engine " + std::string(engine) + ": unknown engine; the engines are " + kEngineNames;
}

void check_model_for_engine(std::string_view engine, const dynamics::ModelDescription& model) {
  if (const std::string why = engine_unavailable(engine); !why.empty()) throw std::invalid_argument(why);
#ifdef CLEARJOINT_WITH_SIMBODY
  if (engine == "simbody") simbody::SimbodyModel check(model);
#else
  (void)model;
#endif
}

dynamics::SimulationSummary simulate_with_engine(std::string_view engine, dynamics::SimulationRun& run,
                                                 dynamics::SimulationOutput& output,
                                                 const dynamics::ProgressCallback& progress) {
  if (const std::string why = engine_unavailable(engine); !why.empty()) throw std::invalid_argument(why);
#ifdef CLEARJOINT_WITH_SIMBODY
  if (engine == "simbody") return simbody::simulate_in_simbody(run, output, progress);
#endif
  return run.run(output, progress);
}

PlannedRun plan_run(std::string_view engine, const dynamics::ModelDescription& model,
                    const dynamics::RunOptions& options) {
  if (const std::string why = engine_unavailable(engine); !why.empty()) throw std::invalid_argument(why);
  if (model.solver_method == dynamics::SolverMethod::moreau_jean) {
    if (engine != kDefaultEngine) {
      throw std::invalid_argument("--engine " + std::string(engine) +
                                  ": solver.method = \"moreau_jean\" runs in clearjoint's own engine only "
                                  "(docs/nonsmooth.md)");
    }
#ifdef CLEARJOINT_WITH_NONSMOOTH
    auto run = std::make_shared<nonsmooth::MoreauJeanRun>(model, options);
    return [run](dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
      return run->run(output, progress);
    };
#else
    throw dynamics::ModelError("solver.method = \"moreau_jean\": this clearjoint was built without Siconos "
                               "Numerics (CLEARJOINT_WITH_SICONOS; Debian: libsiconos-numerics-dev, "
                               "docs/nonsmooth.md)");
#endif
  }
  auto run = std::make_shared<dynamics::SimulationRun>(model, options);
  check_model_for_engine(engine, model);
  const std::string name(engine);
  return [run, name](dynamics::SimulationOutput& output, const dynamics::ProgressCallback& progress) {
    return simulate_with_engine(name, *run, output, progress);
  };
}

}  // namespace clearjoint::app
