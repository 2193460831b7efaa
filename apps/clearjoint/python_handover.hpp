// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Subcommands written in Python: the clearjoint program replaces itself with the interpreter the
// Python package was built for, running the package's module for the command, with the package
// found next to this program (build tree or install prefix). Configured by
// apps/python/plot_view.cmake.

#include "commands.hpp"

namespace clearjoint::app {

/// Runs `python3 -c "from <module>.__main__ import main; sys.exit(main(args))"` in place of this
/// process; `command` names the subcommand in messages. Returns only on failure (status 1).
int hand_over_to_python(const char* command, const char* module, Arguments args);

}  // namespace clearjoint::app
