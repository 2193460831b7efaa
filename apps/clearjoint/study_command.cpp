// SPDX-License-Identifier: BSD-3-Clause
// clearjoint study ...: hands over to the Python study runner (clearjoint.study), which runs
// parameter studies on Dask (docs/studies.md), through the hand-over that plot and view use
// (python_handover.hpp): the same interpreter and the same package lookup.

#include "commands.hpp"
#include "python_handover.hpp"

namespace clearjoint::app {

int run_study(Arguments args) { return hand_over_to_python("study", "clearjoint.study", args); }

}  // namespace clearjoint::app
