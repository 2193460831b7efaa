# SPDX-License-Identifier: BSD-3-Clause
# Checks of `clearjoint intersect` (apps/clearjoint/intersect_command.cpp) against
# docs/command-line.md. Run by ctest, one case per test:
#   cmake -DCLEARJOINT=<program> -DSOURCE_DIR=<repository> -DWORK_DIR=<scratch dir> -DCASE=<case>
#         -P intersect_command_test.cmake
# Cases: example, stdin, bad_lines, number_ids, missing_file, directory, usage, help.
# Any failed check ends the script with FATAL_ERROR, which fails the test. The checks themselves
# are in json_lines_checks.cmake.

cmake_minimum_required(VERSION 3.20)  # string(JSON)

foreach(var CLEARJOINT SOURCE_DIR WORK_DIR CASE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "intersect_command_test: -D${var}=... is required")
  endif()
endforeach()

set(EXAMPLE "${SOURCE_DIR}/examples/rims.jsonl")
set(BAD_LINES "${SOURCE_DIR}/tests/apps/bad_lines.jsonl")

set(SUBCOMMAND intersect)
set(TEST_NAME intersect_command_test)
include(${CMAKE_CURRENT_LIST_DIR}/json_lines_checks.cmake)

# The example: every line answered, and the answers the example's comments in
# docs/command-line.md promise.
function(check_example_answers)
  split_lines("${OUT}" ANSWER_LINE)
  math(EXPR last "${ANSWER_LINE_COUNT} - 1")
  foreach(k RANGE ${last})
    expect_no_error(${k})
  endforeach()
  expect_member(base-B-nominal "disjoint" topology)
  expect_member(base-B-nominal "-1" side)
  expect_member(base-B-tilted-crossing "two_crossings" topology)
  expect_length(base-B-tilted-crossing 2 crossings)
  expect_length(base-B-tilted-crossing 1 penetration_arcs)
  expect_member(base-B-exact-tangent "tangent" topology)
  expect_member(base-B-exact-tangent "exact" certificate level)
  expect_member(base-B-exact-tangent "2" crossings 0 multiplicity)
  expect_member(base-A-tilted-crossing "two_crossings" topology)
  expect_member(wall-A-nominal "inside" topology)
  expect_member(wall-A-nominal "circle_cylinder" query)
  expect_member(wall-B-offset-crossing "crossing" topology)
  expect_length(wall-B-offset-crossing 2 crossings)
  expect_member(wall-B-offset-uncertified "uncertain" certificate level)
  expect_member(wall-B-exact-tangent "crossing" topology)
  expect_length(wall-B-exact-tangent 1 crossings)
  expect_member(wall-B-exact-tangent "2" crossings 0 multiplicity)
  expect_member(wall-B-exact-tangent "exact" certificate level)
  expect_member(wall-B-exact-tangent-no-fallback "uncertain" certificate level)
  expect_member(wall-four-crossings "crossing" topology)
  expect_length(wall-four-crossings 4 crossings)
  expect_length(wall-four-crossings 2 penetration_arcs)
endfunction()

if(CASE STREQUAL "example")
  run("" "${EXAMPLE}")
  expect_status(0)
  file(READ "${EXAMPLE}" input)
  expect_ids_in_order("${input}" "${OUT}")
  check_example_answers()

elseif(CASE STREQUAL "stdin")
  # No FILE and "-" both read standard input, and answer as the file does.
  run("" "${EXAMPLE}")
  set(from_file "${OUT}")
  file(READ "${EXAMPLE}" input)
  expect_ids_in_order("${input}" "${from_file}")
  run("${EXAMPLE}")
  expect_status(0)
  if(NOT OUT STREQUAL from_file)
    fail("standard input (no FILE) answered differently from the file")
  endif()
  run("${EXAMPLE}" -)
  expect_status(0)
  if(NOT OUT STREQUAL from_file)
    fail("standard input (\"-\") answered differently from the file")
  endif()

elseif(CASE STREQUAL "bad_lines")
  run("" "${BAD_LINES}")
  expect_status(1)
  file(READ "${BAD_LINES}" input)
  expect_ids_in_order("${input}" "${OUT}")
  split_lines("${OUT}" ANSWER_LINE)
  # Indices are output lines; bad_lines.jsonl has a blank and a whitespace-only line, skipped.
  expect_no_error(0)
  expect_error(1 "line 2" "malformed JSON")
  expect_error(2 "line 3" "circle.radius" "missing")
  expect_error(3 "circle.radius" "\"NaN\"" "number")
  expect_error(4 "circle.center" "[1,2]" "3")
  expect_error(5 "line 7" "circle.radius" "-1")             # InvalidInput from the kernel
  expect_error(6 "plane" "cylinder")
  expect_error(7 "line 10" "cylinder.axes" "unknown")
  expect_error(8 "options.certify" "\"yes\"")
  expect_error(9 "line 12" "[1,2,3]" "object")
  expect_error(10 "plane.normal" "0")                        # InvalidInput from the kernel
  expect_error(11 "1e999")
  expect_error(12 "line 15" "circle.radius" "1e+300" "[1e-150, 1e150]")
  expect_no_error(13)
  expect_in("${ERR}" "bad_lines.jsonl" "stderr")

elseif(CASE STREQUAL "number_ids")
  # Number ids come back as the text they were written in: the shortest forms of doubles
  # (subnormals, the largest double, -0.0, 0.1 + 0.2) and forms no double prints (1.23e29, -0,
  # an integer beyond 64 bits, 1E5).
  expect_ids_as_written("${SOURCE_DIR}/tests/apps/number_ids.jsonl" 0)

elseif(CASE STREQUAL "missing_file")
  set(missing "${WORK_DIR}/no-such-rims.jsonl")
  file(REMOVE "${missing}")
  run("" "${missing}")
  expect_status(2)
  expect_in("${ERR}" "no-such-rims.jsonl" "stderr")
  if(NOT OUT STREQUAL "")
    fail("wrote to stdout for a missing file:\n${OUT}")
  endif()

elseif(CASE STREQUAL "directory")
  file(MAKE_DIRECTORY "${WORK_DIR}")
  run("" "${WORK_DIR}")
  expect_status(2)
  expect_in("${ERR}" "${WORK_DIR}" "stderr")

elseif(CASE STREQUAL "usage")
  run("" --no-such-option)
  expect_status(2)
  expect_in("${ERR}" "--no-such-option" "stderr")
  expect_in("${ERR}" "usage: clearjoint intersect" "stderr")
  run("" "${EXAMPLE}" "${EXAMPLE}")
  expect_status(2)
  expect_in("${ERR}" "more than one" "stderr")

elseif(CASE STREQUAL "help")
  run("" --help)
  expect_status(0)
  expect_in("${OUT}" "usage: clearjoint intersect [FILE]" "stdout")
  expect_in("${OUT}" "null" "stdout")

else()
  fail("unknown case")
endif()
