# SPDX-License-Identifier: BSD-3-Clause
# Checks shared by the end-to-end tests of the JSON Lines commands (intersect_command_test.cmake,
# detect_command_test.cmake). Before include(), the including script sets SUBCOMMAND (the
# clearjoint subcommand to run), TEST_NAME (for messages) and CLEARJOINT, CASE.
#
# Output lines are split by hand (string(FIND) and SUBSTRING), never turned into CMake lists:
# JSON text holds brackets and semicolons, which list splitting would mangle.

function(fail message)
  message(FATAL_ERROR "${TEST_NAME} [${CASE}]: ${message}")
endfunction()

# run(<stdin file or "">, args...): runs `clearjoint SUBCOMMAND args...`, sets RC, OUT, ERR.
macro(run input)
  if("${input}" STREQUAL "")
    execute_process(COMMAND "${CLEARJOINT}" ${SUBCOMMAND} ${ARGN}
                    RESULT_VARIABLE RC OUTPUT_VARIABLE OUT ERROR_VARIABLE ERR)
  else()
    execute_process(COMMAND "${CLEARJOINT}" ${SUBCOMMAND} ${ARGN} INPUT_FILE "${input}"
                    RESULT_VARIABLE RC OUTPUT_VARIABLE OUT ERROR_VARIABLE ERR)
  endif()
endmacro()

# split_lines(text prefix [SKIP_BLANK]): sets <prefix>_COUNT and <prefix>_0, <prefix>_1, ...
function(split_lines text prefix)
  set(count 0)
  while(NOT "${text}" STREQUAL "")
    string(FIND "${text}" "\n" end)
    if(end EQUAL -1)
      set(line "${text}")
      set(text "")
    else()
      string(SUBSTRING "${text}" 0 ${end} line)
      math(EXPR rest "${end} + 1")
      string(SUBSTRING "${text}" ${rest} -1 text)
    endif()
    string(STRIP "${line}" stripped)
    if("SKIP_BLANK" IN_LIST ARGN AND stripped STREQUAL "")
      continue()
    endif()
    set(${prefix}_${count} "${line}" PARENT_SCOPE)
    math(EXPR count "${count} + 1")
  endwhile()
  set(${prefix}_COUNT ${count} PARENT_SCOPE)
endfunction()

# json_get(out line member...): the member, failing the test if the line is not JSON or lacks it.
function(json_get out line)
  string(JSON value ERROR_VARIABLE error GET "${line}" ${ARGN})
  if(error)
    fail("cannot read ${ARGN} from output line ${line}: ${error}")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

function(json_type out line)
  string(JSON value ERROR_VARIABLE error TYPE "${line}" ${ARGN})
  if(error)
    fail("cannot read ${ARGN} from output line ${line}: ${error}")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

# expect_ids_as_written(file status): runs the command on `file`, whose lines start with
# {"id": ID, expects the exit status `status`, and checks that each answer (or error line) starts
# with {"v":1,"id":ID, with ID character for character.
function(expect_ids_as_written input_file status)
  run("" "${input_file}")
  expect_status(${status})
  file(READ "${input_file}" input)
  split_lines("${input}" IN SKIP_BLANK)
  split_lines("${OUT}" OUT_LINE)
  if(NOT OUT_LINE_COUNT EQUAL IN_COUNT OR IN_COUNT EQUAL 0)
    fail("${OUT_LINE_COUNT} output lines for ${IN_COUNT} input lines")
  endif()
  math(EXPR last "${IN_COUNT} - 1")
  foreach(k RANGE ${last})
    string(REGEX MATCH "^{\"id\": ([^,]+)," matched "${IN_${k}}")
    set(written "${CMAKE_MATCH_1}")
    # Every output line starts with the format version, then the id.
    string(REGEX MATCH "^{\"v\":1,\"id\":([^,]+)," matched "${OUT_LINE_${k}}")
    if(NOT "${CMAKE_MATCH_1}" STREQUAL "${written}")
      fail("id ${written} came back as '${CMAKE_MATCH_1}': ${OUT_LINE_${k}}")
    endif()
  endforeach()
endfunction()

function(expect_status expected)
  if(NOT "${RC}" STREQUAL "${expected}")
    fail("exit status ${RC}, expected ${expected}\nstdout:\n${OUT}\nstderr:\n${ERR}")
  endif()
endfunction()

# Each output line answers the input line with the same index: ids equal, in order.
function(expect_ids_in_order input_text output_text)
  split_lines("${input_text}" IN SKIP_BLANK)
  split_lines("${output_text}" OUT_LINE)
  if(NOT OUT_LINE_COUNT EQUAL IN_COUNT)
    fail("${OUT_LINE_COUNT} output lines for ${IN_COUNT} non-empty input lines:\n${output_text}")
  endif()
  math(EXPR last "${IN_COUNT} - 1")
  foreach(k RANGE ${last})
    json_get(out_id "${OUT_LINE_${k}}" id)
    string(JSON in_id ERROR_VARIABLE unreadable GET "${IN_${k}}" id)
    if(unreadable)  # a malformed input line: its id is not readable, the answer says null
      json_type(out_type "${OUT_LINE_${k}}" id)
      if(NOT out_type STREQUAL "NULL")
        fail("line ${k}: unreadable input answered with id ${out_id}, expected null")
      endif()
    elseif(NOT "${in_id}" STREQUAL "${out_id}")
      fail("output line ${k} has id '${out_id}', input line has '${in_id}'")
    endif()
  endforeach()
endfunction()

# The answer whose id is `id` (a string), in <prefix>_<k> lines; sets ANSWER.
function(find_answer id)
  math(EXPR last "${ANSWER_LINE_COUNT} - 1")
  foreach(k RANGE ${last})
    string(JSON line_id ERROR_VARIABLE ignored GET "${ANSWER_LINE_${k}}" id)
    if("${line_id}" STREQUAL "${id}")
      set(ANSWER "${ANSWER_LINE_${k}}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  fail("no answer with id ${id}")
endfunction()

function(expect_member id expected)
  find_answer("${id}")
  json_get(value "${ANSWER}" ${ARGN})
  if(NOT "${value}" STREQUAL "${expected}")
    fail("${id}: ${ARGN} is '${value}', expected '${expected}'\n${ANSWER}")
  endif()
endfunction()

function(expect_length id expected)
  find_answer("${id}")
  string(JSON value ERROR_VARIABLE error LENGTH "${ANSWER}" ${ARGN})
  if(error OR NOT "${value}" STREQUAL "${expected}")
    fail("${id}: ${ARGN} has length '${value}', expected ${expected}\n${ANSWER}")
  endif()
endfunction()

# The error line at output index k names the field: every `needle` occurs in its message.
function(expect_error k)
  json_get(message "${ANSWER_LINE_${k}}" error)
  foreach(needle IN LISTS ARGN)
    string(FIND "${message}" "${needle}" at)
    if(at EQUAL -1)
      fail("error of output line ${k} does not mention '${needle}': ${message}")
    endif()
  endforeach()
endfunction()

function(expect_no_error k)
  string(JSON message ERROR_VARIABLE missing GET "${ANSWER_LINE_${k}}" error)
  if(NOT missing)
    fail("output line ${k} is an error: ${message}")
  endif()
endfunction()

function(expect_in text needle where)
  string(FIND "${text}" "${needle}" at)
  if(at EQUAL -1)
    fail("${where} does not mention '${needle}':\n${text}")
  endif()
endfunction()


# The member of the answer with this id matches the regular expression `pattern` (used for
# numbers: CMake has no floating-point comparison, so a value is checked digit by digit).
function(expect_match id pattern)
  find_answer("${id}")
  json_get(value "${ANSWER}" ${ARGN})
  if(NOT "${value}" MATCHES "${pattern}")
    fail("${id}: ${ARGN} is '${value}', expected a match of '${pattern}'\n${ANSWER}")
  endif()
endfunction()

# The answer with this id has no such member.
function(expect_absent id)
  find_answer("${id}")
  string(JSON value ERROR_VARIABLE missing GET "${ANSWER}" ${ARGN})
  if(NOT missing)
    fail("${id}: ${ARGN} is present ('${value}'), expected absent\n${ANSWER}")
  endif()
endfunction()
