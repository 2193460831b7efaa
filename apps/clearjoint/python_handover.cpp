// SPDX-License-Identifier: BSD-3-Clause
// The hand-over to Python for subcommands written in it (python_handover.hpp). The interpreter is
// the one the package was built for, found at configure time; the package is looked up next to
// this program: in the build tree (build/bindings/python) or under the install prefix. Used by
// plot, view and study.

#include "python_handover.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace clearjoint::app {

namespace {

namespace fs = std::filesystem;

/// Imports the command's main and hands it the arguments; a package that cannot be imported is
/// reported in one line instead of a traceback. With -c, Python puts the current folder ('') first
/// on sys.path, where a folder named clearjoint would shadow the package this program was built
/// with (PYTHONPATH puts that first otherwise); the bootstrap drops it, as -P does from Python
/// 3.11 on.
std::string bootstrap(const std::string& command, const std::string& module) {
  return "import sys\n"
         "if sys.path and sys.path[0] == '':\n"
         "    del sys.path[0]\n"
         "try:\n"
         "    from " + module + ".__main__ import main\n"
         "except ImportError as error:\n"
         "    sys.exit('clearjoint " + command + ": the clearjoint Python package is not importable by ' +\n"
         "             sys.executable + ' (' + str(error) + '); build it (CLEARJOINT_BUILD_PYTHON) and '\n"
         "             'install it, or set PYTHONPATH')\n"
         "sys.exit(main(sys.argv[1:]))\n";
}

/// The directory holding the clearjoint package for this program: the build tree's when the
/// program runs from the build tree, else the install location relative to the program.
fs::path package_directory() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  const fs::path program_directory = error ? fs::path() : program.parent_path();
  const fs::path build_program_directory = CLEARJOINT_PYTHON_BUILD_PROGRAM_DIR;
  if (!program_directory.empty() && fs::equivalent(program_directory, build_program_directory, error)) {
    return CLEARJOINT_PYTHON_BUILD_PYTHONPATH;
  }
  const fs::path installed = CLEARJOINT_PYTHON_INSTALL_PYTHONPATH;
  if (installed.is_absolute() || program_directory.empty()) return installed;
  return (program_directory / CLEARJOINT_PYTHON_INSTALL_PREFIX_FROM_BINDIR / installed).lexically_normal();
}

}  // namespace

int hand_over_to_python(const char* command, const char* module, Arguments args) {
  const std::string python = CLEARJOINT_PYTHON_EXECUTABLE;
  std::string path = package_directory().string();
  if (const char* existing = std::getenv("PYTHONPATH"); existing != nullptr && *existing != '\0') {
    path.append(":").append(existing);
  }
  if (::setenv("PYTHONPATH", path.c_str(), 1) != 0) {
    std::fprintf(stderr, "clearjoint %s: cannot set PYTHONPATH (%s)\n", command, std::strerror(errno));
    return 1;
  }
  const std::string code = bootstrap(command, module);
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(python.c_str()));
  argv.push_back(const_cast<char*>("-c"));
  argv.push_back(const_cast<char*>(code.c_str()));
  for (char* a : args) argv.push_back(a);
  argv.push_back(nullptr);
  ::execv(python.c_str(), argv.data());
  std::fprintf(stderr,
               "clearjoint %s: cannot start the Python interpreter %s (%s); it needs the "
               "interpreter the clearjoint Python package was built for\n",
               command, python.c_str(), std::strerror(errno));
  return 1;
}

int run_plot(Arguments args) { return hand_over_to_python("plot", "clearjoint.plot", args); }

int run_view(Arguments args) { return hand_over_to_python("view", "clearjoint.view", args); }

}  // namespace clearjoint::app
