// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Subcommands of the clearjoint program. Each takes the arguments after the subcommand name and
// returns the process exit status.

#include <span>
#include <string_view>

namespace clearjoint::app {

using Arguments = std::span<char* const>;

/// clearjoint intersect [FILE]: rim/plane and rim/cylinder queries as JSON Lines.
int run_intersect(Arguments args);
/// clearjoint detect [FILE]: joint contact detection (scenario, contacts, velocities), JSON Lines.
int run_detect(Arguments args);
/// clearjoint bearing --eccentricity-ratio EPS --width-ratio B/D: a journal bearing's handbook
/// characteristics (lubrication/), one JSON object.
int run_bearing(Arguments args);
#ifdef CLEARJOINT_WITH_DYNAMICS
/// clearjoint simulate MODEL --out DIR: multibody simulation (dynamics/).
int run_simulate(Arguments args);
/// What `simulate --plot` calls once the run is published: the plot command's handover to
/// Python, set by main() when the program has it; null, --plot is refused.
extern int (*plot_published_run)(const char* run_dir);
#endif
#ifdef CLEARJOINT_WITH_STUDY
/// clearjoint study run|plot|summary STUDY: parameter studies on Dask, in Python
/// (python3 -m clearjoint.study; docs/studies.md). Replaces this process with the interpreter.
int run_study(Arguments args);
#endif
#ifdef CLEARJOINT_WITH_PLOT_VIEW
/// clearjoint plot RUN_DIR: figures of a run's clearance joints (python3 -m clearjoint.plot;
/// docs/viewing-runs.md). Replaces this process with the interpreter.
int run_plot(Arguments args);
/// clearjoint view RUN_DIR: the run animated in the browser (python3 -m clearjoint.view).
int run_view(Arguments args);
#endif

}  // namespace clearjoint::app
