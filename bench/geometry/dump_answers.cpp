// SPDX-License-Identifier: BSD-3-Clause
// dump_answers: every field of 192,000 answers of the geometry kernel, one answer a line, doubles
// in %a, on standard output. Two builds of the library that print the same text gave the same
// answers bit for bit on these inputs; scripts/compare-answers.sh builds two revisions and
// compares them (docs/verifying-refactors.md). The inputs are answer_families.hpp's, the line
// format answer_text.hpp's.

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "answer_families.hpp"

namespace {

using clearjoint::bench::AnswerFamily;
using clearjoint::bench::kLinesPerInput;

constexpr int kBadArguments = 2;

constexpr const char* kUsage =
    "usage: dump_answers [--family NAME]... | --list | --help\n"
    "\n"
    "Prints every field of many detect_contacts, intersect_circle_cylinder and\n"
    "intersect_circle_plane answers, one a line, doubles in %a (hexadecimal, exact bits),\n"
    "to standard output. The inputs come from fixed seeds: the text depends only on the\n"
    "library build. Compare two builds with scripts/compare-answers.sh.\n"
    "\n"
    "  --family NAME  print only this family (repeat for more, printed in the order given)\n"
    "  --list         list the families: name, lines, what the inputs are\n"
    "  --help         this text\n"
    "\n"
    "Exit status: 0 printed, 1 writing failed, 2 bad arguments.\n";

int fail_with_usage(const std::string& message) {
  std::fprintf(stderr, "dump_answers: %s (see dump_answers --help)\n", message.c_str());
  return kBadArguments;
}

std::string family_names() {
  std::string names;
  for (const AnswerFamily& family : clearjoint::bench::answer_families()) {
    if (!names.empty()) names += ", ";
    names += family.name;
  }
  return names;
}

void list_families() {
  for (const AnswerFamily& family : clearjoint::bench::answer_families()) {
    std::printf("%-20.*s %7d  %.*s\n", static_cast<int>(family.name.size()), family.name.data(),
                family.input_count * kLinesPerInput, static_cast<int>(family.description.size()),
                family.description.data());
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<const AnswerFamily*> chosen;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument == "--help" || argument == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (argument == "--list") {
      list = true;
    } else if (argument == "--family" || argument.starts_with("--family=")) {
      std::string_view name;
      if (argument == "--family") {
        if (i + 1 == argc) return fail_with_usage("--family needs a family name");
        name = argv[++i];
      } else {
        name = argument.substr(std::string_view("--family=").size());
      }
      const AnswerFamily* family = clearjoint::bench::find_answer_family(name);
      if (family == nullptr) {
        return fail_with_usage("no family '" + std::string(name) + "'; the families are " +
                               family_names());
      }
      chosen.push_back(family);
    } else {
      return fail_with_usage("unknown argument '" + std::string(argument) + "'");
    }
  }
  if (list && !chosen.empty()) return fail_with_usage("--list and --family do not go together");
  if (list) {
    list_families();
    return std::fflush(stdout) == 0 ? 0 : 1;
  }
  if (chosen.empty()) {
    for (const AnswerFamily& family : clearjoint::bench::answer_families()) chosen.push_back(&family);
  }

  long lines = 0;
  const clearjoint::bench::LineSink to_stdout = [&lines](std::string_view line) {
    std::fwrite(line.data(), 1, line.size(), stdout);
    std::fputc('\n', stdout);
    ++lines;
  };
  for (const AnswerFamily* family : chosen) clearjoint::bench::print_family(*family, to_stdout);
  // A full disk or a closed pipe must not pass for a shorter dump.
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fputs("dump_answers: writing the answers failed\n", stderr);
    return 1;
  }
  std::fprintf(stderr, "dump_answers: %ld lines from %zu families\n", lines, chosen.size());
  return 0;
}
