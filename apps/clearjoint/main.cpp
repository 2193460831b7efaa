// SPDX-License-Identifier: BSD-3-Clause
// clearjoint: the command-line front of the library, so that any language can call it.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>

#include "clearjoint/version.hpp"
#include "commands.hpp"

namespace {

struct Command {
  const char* name;
  int (*run)(clearjoint::app::Arguments);
  const char* summary;
};

constexpr Command kCommands[] = {
    {"intersect", clearjoint::app::run_intersect,
     "rim/plane and rim/cylinder intersections from JSON Lines (file or stdin)"},
    {"detect", clearjoint::app::run_detect,
     "joint contact detection: scenario, contacts, velocities, from JSON Lines (file or stdin)"},
    {"bearing", clearjoint::app::run_bearing,
     "a journal bearing's Sommerfeld number, attitude angle and side flow (JSON)"},
#ifdef CLEARJOINT_WITH_DYNAMICS
    {"simulate", clearjoint::app::run_simulate, "simulate a multibody model file"},
#endif
#ifdef CLEARJOINT_WITH_STUDY
    {"study", clearjoint::app::run_study, "parameter studies on Dask: run, plot (python3 -m clearjoint.study)"},
#endif
#ifdef CLEARJOINT_WITH_PLOT_VIEW
    {"plot", clearjoint::app::run_plot, "figures of a run's clearance joints, PNG and SVG (python3 -m clearjoint.plot)"},
    {"view", clearjoint::app::run_view, "a run animated in 3-D in the browser (python3 -m clearjoint.view)"},
#endif
};

int print_usage(std::FILE* to) {
  std::fprintf(to, "usage: clearjoint COMMAND [ARGS...]\n       clearjoint --version\ncommands:\n");
  for (const Command& c : kCommands) std::fprintf(to, "  %-10s %s\n", c.name, c.summary);
  std::fprintf(to,
               "'clearjoint COMMAND --help' describes a command. The formats it reads and writes are\n"
               "JSON Schemas (draft 2020-12) in docs/schema/, installed in share/clearjoint/schema/:\n"
               "intersect-query, intersect-answer, detect-query, detect-answer, error-line and\n"
               "model (simulate's model files), each NAME.schema.json.\n");
  return to == stdout ? 0 : 2;
}

/// Every command's status, unless standard output could not be written: a full disk or
/// /dev/full must not end with status 0 and nothing said.
int checked_exit(int status) {
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    std::fprintf(stderr, "clearjoint: cannot write to standard output: %s\n", std::strerror(errno));
    return status == 0 || status == 1 ? 2 : status;
  }
  return status;
}

int run(int argc, char** argv) {
  if (argc < 2) return print_usage(stderr);
  if (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    return print_usage(stdout);
  }
  if (std::strcmp(argv[1], "--version") == 0) {
    std::printf("clearjoint %s\n", clearjoint::version_string());
    return 0;
  }
  for (const Command& c : kCommands) {
    if (std::strcmp(argv[1], c.name) == 0) {
      try {
        return c.run(clearjoint::app::Arguments(argv + 2, static_cast<size_t>(argc - 2)));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "clearjoint %s: %s\n", c.name, e.what());
        return 1;
      }
    }
  }
  std::fprintf(stderr, "clearjoint: unknown command '%s'\n", argv[1]);
  return print_usage(stderr);
}

}  // namespace

#if defined(CLEARJOINT_WITH_DYNAMICS) && defined(CLEARJOINT_WITH_PLOT_VIEW)
/// simulate --plot: `clearjoint plot RUN_DIR`, which replaces this process.
static int plot_run(const char* run_dir) {
  char* plot_arguments[] = {const_cast<char*>(run_dir)};
  return clearjoint::app::run_plot(clearjoint::app::Arguments(plot_arguments, 1));
}
#endif

int main(int argc, char** argv) {
#if defined(CLEARJOINT_WITH_DYNAMICS) && defined(CLEARJOINT_WITH_PLOT_VIEW)
  clearjoint::app::plot_published_run = plot_run;
#endif
  return checked_exit(run(argc, argv));
}
