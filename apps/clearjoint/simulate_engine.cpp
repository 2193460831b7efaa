// SPDX-License-Identifier: BSD-3-Clause
#include "simulate_engine.hpp"

#include <stdexcept>
#include <string>

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

}  // namespace clearjoint::app
