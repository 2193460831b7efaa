// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// Running the built `clearjoint` program from a GoogleTest, as a user's shell would: its exit
/// status and what it wrote to stdout and stderr. CLEARJOINT_PROGRAM names the program
/// (tests/apps/CMakeLists.txt).

#include <sys/wait.h>

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
inline Outcome run(const std::string& arguments, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "\"" CLEARJOINT_PROGRAM "\" " + arguments + " > \"" + out.string() + "\" 2> \"" +
                              err.string() + "\" < /dev/null";
  const int status = std::system(command.c_str());
  Outcome o;
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  o.out = read_text(out);
  o.err = read_text(err);
  return o;
}

}  // namespace clearjoint::test
