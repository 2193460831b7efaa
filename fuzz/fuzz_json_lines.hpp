// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The body of the two JSON Lines fuzz targets (fuzz_intersect_lines.cpp, fuzz_detect_lines.cpp):
// every line of the input goes through the command's line handler, exactly as `clearjoint
// intersect` / `clearjoint detect` answer it. Invariants: answer_line never throws, every answer
// is a JSON object with "id" and either "error" (a string, beside "v" and "id" only) or the
// answer's fields, and its
// text dumps and parses back (the line the program would print is valid JSON).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <string_view>

#include "json_lines.hpp"

namespace clearjoint::fuzz {

inline void check(bool condition, const char* what) {
  if (!condition) {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
    std::abort();
  }
}

inline void answer_lines(const app::JsonLinesCommand& command, const std::uint8_t* data,
                         std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::size_t start = 0;
  long line_number = 0;
  while (start <= input.size()) {
    std::size_t end = input.find('\n', start);
    if (end == std::string_view::npos) end = input.size();
    const std::string line(input.substr(start, end - start));
    ++line_number;
    if (line.size() <= app::kMaxLineBytes && line.find_first_not_of(" \t\r") != std::string::npos) {
      bool failed = false;
      const app::Json answer = app::answer_line(command, line, line_number, failed);
      check(answer.is_object() && answer.contains("id"), "an answer is an object with an id");
      check(!failed || (answer.size() == 3 && answer.contains("v") && answer["error"].is_string()),
            "an error line holds only the format version, the id and the error message");
      const std::string text = app::answer_text(answer, line);
      check(app::Json::accept(text), "the printed answer is valid JSON");
    }
    start = end + 1;
  }
}

}  // namespace clearjoint::fuzz
