// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// Running the built `clearjoint` program from a GoogleTest, as a user's shell would: its exit
/// status and what it wrote to stdout and stderr. CLEARJOINT_PROGRAM names the program
/// (tests/apps/CMakeLists.txt).

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace clearjoint::test {

struct Outcome {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `clearjoint <arguments>` (already quoted as needed) with no input, its output in `dir`.
/// ctest runs each test case of a binary in a process of its own, two at a time, and a test may
/// run the program from several threads: the output files are named by process and call, so no
/// two runs share them (fixed names let one test read another's stderr), and removed once read.
inline Outcome run(const std::string& arguments, const std::filesystem::path& dir) {
  static std::atomic<unsigned long> calls{0};
  const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(calls.fetch_add(1));
  const std::filesystem::path out = dir / ("stdout-" + tag + ".txt"), err = dir / ("stderr-" + tag + ".txt");
  const std::string command = "\"" CLEARJOINT_PROGRAM "\" " + arguments + " > \"" + out.string() + "\" 2> \"" +
                              err.string() + "\" < /dev/null";
  const int status = std::system(command.c_str());
  Outcome o;
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  o.out = read_text(out);
  o.err = read_text(err);
  std::error_code ignored;
  std::filesystem::remove(out, ignored);
  std::filesystem::remove(err, ignored);
  return o;
}

}  // namespace clearjoint::test
