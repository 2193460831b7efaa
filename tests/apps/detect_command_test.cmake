# SPDX-License-Identifier: BSD-3-Clause
# Checks of `clearjoint detect` (apps/clearjoint/detect_command.cpp) against
# docs/command-line.md. Run by ctest, one case per test:
#   cmake -DCLEARJOINT=<program> -DSOURCE_DIR=<repository> -DWORK_DIR=<scratch dir> -DCASE=<case>
#         -P detect_command_test.cmake
# Cases: example, scenarios, stdin, exact, bad_lines, number_ids, missing_file, usage, help,
# pin_in_hole, pin_in_hole_bad_lines, pin_in_hole_scenarios.
# Any failed check ends the script with FATAL_ERROR, which fails the test. The checks themselves
# are in json_lines_checks.cmake.

cmake_minimum_required(VERSION 3.20)  # string(JSON)

foreach(var CLEARJOINT SOURCE_DIR WORK_DIR CASE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "detect_command_test: -D${var}=... is required")
  endif()
endforeach()

set(EXAMPLE "${SOURCE_DIR}/examples/joints.jsonl")
set(SCENARIOS "${SOURCE_DIR}/examples/scenarios.jsonl")
set(EXACT "${SOURCE_DIR}/tests/apps/detect_exact.jsonl")
set(BAD_LINES "${SOURCE_DIR}/tests/apps/detect_bad_lines.jsonl")
set(PIN_IN_HOLE "${SOURCE_DIR}/tests/apps/detect_pin_in_hole.jsonl")
set(PIN_IN_HOLE_SCENARIOS "${SOURCE_DIR}/examples/pin_in_hole_scenarios.jsonl")
set(PIN_IN_HOLE_BAD_LINES "${SOURCE_DIR}/tests/apps/detect_pin_in_hole_bad_lines.jsonl")

set(SUBCOMMAND detect)
set(TEST_NAME detect_command_test)
include(${CMAKE_CURRENT_LIST_DIR}/json_lines_checks.cmake)

# expect_joint(id scenario aligned [type:base ...]): the answer's scenario, aligned flag, and its
# contacts, in order (radial before axial, base A before B; docs/command-line.md).
function(expect_joint id scenario aligned)
  expect_member(${id} "${scenario}" scenario)
  # string(JSON GET) gives a JSON boolean as ON or OFF.
  if(aligned STREQUAL "true")
    expect_member(${id} "ON" aligned)
  else()
    expect_member(${id} "OFF" aligned)
  endif()
  list(LENGTH ARGN count)
  expect_length(${id} ${count} contacts)
  set(k 0)
  foreach(contact IN LISTS ARGN)
    string(REPLACE ":" ";" parts "${contact}")
    list(GET parts 0 type)
    list(GET parts 1 base)
    expect_member(${id} "${type}" contacts ${k} type)
    expect_member(${id} "${base}" contacts ${k} base)
    math(EXPR k "${k} + 1")
  endforeach()
endfunction()

# Every line answered, with no velocities unless both motions are given.
# Needs ANSWER_LINE_* (split_lines) in the caller's scope.
function(expect_all_answered_without_velocities)
  math(EXPR last "${ANSWER_LINE_COUNT} - 1")
  foreach(k RANGE ${last})
    expect_no_error(${k})
    string(FIND "${ANSWER_LINE_${k}}" "velocity" at)
    string(FIND "${ANSWER_LINE_${k}}" "-with-motions" has_motions)
    if(NOT at EQUAL -1 AND has_motions EQUAL -1)
      fail("output line ${k} has velocities without motions: ${ANSWER_LINE_${k}}")
    endif()
  endforeach()
endfunction()

# The example (metres, paper Table 2 unless the id names other dimensions). Scenarios and contacts
# from the closed forms of tests/geometry/joint/test_detect_contacts.cpp (journal centred at
# (0, y0, z0), tilted by t = atan(k) in the y-z plane, bearing on the z axis): radial depth at A
# and B = +-y0 + S, axial at A and B = +-z0 + T, S = (Lj/2) sin t + Rj cos t - Ri,
# T = (Lj/2) cos t + Rj sin t - Li/2; with Table 2, S = T = -5.0624e-5 at k = 0.005 and
# +2.7853e-5 at k = 0.013.
function(check_example_answers)
  split_lines("${OUT}" ANSWER_LINE)
  expect_all_answered_without_velocities()
  expect_joint(none-aligned none true)
  expect_joint(none-tilted none false)
  expect_joint(a a false radial:a)
  expect_joint(a-at-B a false radial:b)
  expect_joint(a-moved a false radial:a)
  expect_joint(b b false axial:a)
  expect_joint(b-at-B b false axial:b)
  expect_joint(c-long-axial-clearance c false radial:a radial:b)
  expect_joint(d-wide-radial-clearance d false axial:a axial:b)
  expect_joint(e e false radial:a axial:a)
  expect_joint(f f false radial:a axial:b)
  expect_joint(g g false radial:a radial:b axial:a)
  expect_joint(h h false radial:a axial:a axial:b)
  expect_joint(i i false radial:a radial:b axial:a axial:b)
  expect_joint(j j true radial:mid)
  expect_joint(k k true axial:a)
  expect_joint(l-journal-axis-reversed l true radial:mid axial:b)
  # y0 = 2e-4: rim B is on the +y side too (c_y = y0 - (Lj/2) sin t > 0), depth 5.04e-5; rim A
  # is 1.49e-4 deep, more than cr = 1e-4.
  expect_joint(beyond-radial-deeper-than-clearance beyond_model false radial:a radial:b)
  expect_joint(beyond-aligned-deeper-than-clearance beyond_model true radial:mid)
  # Two penetration arcs on rim A (see the example table in docs/command-line.md).
  expect_joint(beyond-rim-crosses-wall-four-times beyond_model false radial:a radial:a)
  expect_length(beyond-rim-crosses-wall-four-times 2 contacts 0 crossings)
  expect_length(beyond-rim-crosses-wall-four-times 2 contacts 1 crossings)
  expect_joint(e-with-motions e false radial:a axial:a)
  expect_joint(i-uncertified i false radial:a radial:b axial:a axial:b)
  expect_joint(nearly-aligned-exact c false radial:a radial:b)
  expect_joint(nearly-aligned-tolerance j true radial:mid)

  # Depths against the closed forms above, evaluated in 30-digit arithmetic (mpmath), to 9
  # significant digits: the program's depths are differences of numbers ~0.01 computed in double,
  # good to ~1e-17 m absolute, so 9 digits of a 3e-5 depth leave four orders of margin.
  expect_match(a "^2\\.93756335[0-9]*e-05$" contacts 0 depth)          # y0 + S
  expect_match(a-moved "^2\\.93756335[0-9]*e-05$" contacts 0 depth)
  expect_match(c-long-axial-clearance "^4\\.13704093[0-9]*e-05$" contacts 0 depth)
  expect_match(d-wide-radial-clearance "^7\\.79846045[0-9]*e-05$" contacts 1 depth)
  expect_match(g "^6\\.78526822[0-9]*e-05$" contacts 2 depth)          # z0 + T
  expect_match(i "^2\\.78526822[0-9]*e-05$" contacts 3 depth)          # T
  expect_match(beyond-radial-deeper-than-clearance "^0\\.000149375633[0-9]*$" contacts 0 depth)
  # Aligned: eccentricity - cr = 1.5e-4 - 1e-4 (cr = 0.01 - 0.0099 is 1e-4 only to ~1e-16 m).
  expect_match(j "^(5\\.00000000|4\\.99999999)[0-9]*e-05$" contacts 0 depth)

  # The jump between the misaligned and the aligned formulas (docs/contact-detection.md): tilt
  # t = atan(1e-6), y0 = 1.5e-4. Exactly: two radial contacts, rims at c_y = y0 +- (Lj/2) sin t,
  # depths c_y + Rj cos t - Ri = 5.00099e-5 and 4.99901e-5 (total 1.0e-4). Treated as aligned: one
  # line contact of depth y0 - cr = 5e-5 (total halved).
  expect_match(nearly-aligned-exact "^5\\.00098999[0-9]*e-05$" contacts 0 depth)
  expect_match(nearly-aligned-exact "^4\\.99900999[0-9]*e-05$" contacts 1 depth)
  expect_match(nearly-aligned-tolerance "^(5\\.00000000|4\\.99999999)[0-9]*e-05$" contacts 0 depth)

  # Certificates: certified throughout, except where the options say otherwise.
  expect_member(a "certified" certificate)
  expect_member(a "certified" contacts 0 certificate)
  expect_member(i-uncertified "uncertain" certificate)
  expect_member(i-uncertified "uncertain" contacts 3 certificate)
  expect_member(nearly-aligned-exact "certified" certificate)
  expect_member(nearly-aligned-tolerance "uncertain" certificate)
  expect_match(nearly-aligned-tolerance "parallel_angle_tolerance" contacts 0 certificate_reason)

  # Velocities only with motions. e-with-motions: the journal moves at (0.1, -0.5, 0.2) m/s and
  # spins at 2 pi rad/s about the z axis through its mass centre (0, 8e-5, 0.1); the bearing
  # translates at (0.1, 0, 0). Both contact points lie in the plane x = 0 (mirror symmetry), so
  # the spin adds only an x component: approach speed -0.5 along +y (radial A, separating),
  # +0.2 along +z (axial A, penetrating).
  expect_absent(e contacts 0 approach_velocity)
  expect_match(e-with-motions "^-0\\.5(0000000[0-9]*)?$|^-0\\.49999999" contacts 0 approach_velocity)
  expect_match(e-with-motions "^0\\.2(0000000[0-9]*)?$|^0\\.19999999" contacts 1 approach_velocity)
  expect_length(e-with-motions 3 contacts 0 tangential_velocity)
endfunction()

if(CASE STREQUAL "example")
  run("" "${EXAMPLE}")
  expect_status(0)
  file(READ "${EXAMPLE}" input)
  expect_ids_in_order("${input}" "${OUT}")
  check_example_answers()

elseif(CASE STREQUAL "scenarios")
  # The configurations drawn in docs/figures (exaggerated clearances): one per scenario.
  run("" "${SCENARIOS}")
  expect_status(0)
  file(READ "${SCENARIOS}" input)
  expect_ids_in_order("${input}" "${OUT}")
  split_lines("${OUT}" ANSWER_LINE)
  foreach(scenario a b c d e f g h i j k l none beyond_model)
    expect_member(${scenario} "${scenario}" scenario)
    expect_member(${scenario} "certified" certificate)
  endforeach()

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

elseif(CASE STREQUAL "exact")
  # Dimensions and poses that are dyadic rationals (Ri = 0.5, Rj = 0.375, Li = 1, Lj = 0.75,
  # cr = ca = 0.125): every depth, point and velocity below is exact in double, so the text must
  # be exactly this (shortest round-trip form; string(JSON GET) returns a number as written, so
  # a double with an integer value reads "1.0").
  run("" "${EXACT}")
  expect_status(0)
  split_lines("${OUT}" ANSWER_LINE)
  # Aligned, eccentricity 0.25: line contact of depth 0.25 - cr (eqs. 6-8, 23).
  expect_joint(line-with-motions j true radial:mid)
  expect_member(line-with-motions "0.125" contacts 0 depth)
  expect_member(line-with-motions "0.625" contacts 0 point_journal 1)
  expect_member(line-with-motions "0.5" contacts 0 point_bearing 1)
  expect_member(line-with-motions "1.0" contacts 0 normal 1)
  # eq. (25): journal point velocity (0, 1, 0) + (0, 0, 2) x (0, 0.375, 0) = (-0.75, 1, 0);
  # bearing point (0.5, 0.25, 0). Relative (-1.25, 0.75, 0): eq. (24) 0.75, eq. (26) (-1.25, 0, 0).
  expect_member(line-with-motions "0.75" contacts 0 approach_velocity)
  expect_member(line-with-motions "-1.25" contacts 0 tangential_velocity 0)
  expect_member(line-with-motions "0.0" contacts 0 tangential_velocity 1)
  # Eccentricity exactly cr: the journal touches the wall without penetrating. No contact, and
  # without the exact fallback the tangency cannot be proved.
  expect_joint(line-tangent none true)
  expect_member(line-tangent "certified" certificate)
  expect_joint(line-tangent-no-fallback none true)
  expect_member(line-tangent-no-fallback "uncertain" certificate)
  expect_match(line-tangent-no-fallback "tangency" certificate_reason)
  # Journal base A at 0.25 + 0.375 = 0.625, bearing base A at 0.5 (eqs. 9-10); axis of length 2.
  expect_joint(face-non-unit-axis k true axial:a)
  expect_member(face-non-unit-axis "0.125" contacts 0 depth)
  expect_member(face-non-unit-axis "0.0625" contacts 0 point_journal 0)
  expect_member(face-non-unit-axis "0.625" contacts 0 point_journal 2)
  expect_member(face-non-unit-axis "0.5" contacts 0 point_bearing 2)
  # The journal axis points down: labels follow the bearing, the face contact is at B.
  expect_joint(line-and-face-reversed-journal l true radial:mid axial:b)
  expect_member(line-and-face-reversed-journal "-0.625" contacts 1 point_journal 2)
  expect_member(line-and-face-reversed-journal "-1.0" contacts 1 normal 2)
  # eq. (5) decided exactly: (1, 3, 7) and (-0.5, -1.5, -3.5) are parallel; one ulp off is not.
  expect_joint(parallel-non-unit-axes none true)
  expect_joint(one-ulp-from-parallel none false)
  expect_joint(line-deeper-than-clearance beyond_model true radial:mid)
  expect_member(line-deeper-than-clearance "0.25" contacts 0 depth)

elseif(CASE STREQUAL "bad_lines")
  run("" "${BAD_LINES}")
  expect_status(1)
  file(READ "${BAD_LINES}" input)
  expect_ids_in_order("${input}" "${OUT}")
  split_lines("${OUT}" ANSWER_LINE)
  # Indices are output lines; detect_bad_lines.jsonl has one blank line (line 5), skipped.
  expect_no_error(0)
  expect_error(1 "line 2" "malformed JSON")
  expect_error(2 "line 3" "journal.length" "missing")
  expect_error(3 "bearing.radius" "\"NaN\"" "number")
  expect_error(4 "line 6" "1e999")
  expect_error(5 "journal.center" "[1,2]" "3 numbers")
  expect_error(6 "bearing.axis" "\"z\"")
  expect_error(7 "journal.radius = -0.0099: must be positive")
  expect_error(8 "journal.radius = 0.01: must be smaller than bearing.radius = 0.01" "eq. 1")
  expect_error(9 "journal.length" "0.025" "smaller than bearing.length")
  expect_error(10 "bearing.axis = [0, 0, 0]: must not be the zero vector")
  expect_error(11 "journal.centre" "unknown field")
  expect_error(12 "clearance" "unknown field")
  expect_error(13 "options.certify" "\"yes\"")
  expect_error(14 "options.certfy" "unknown field")
  expect_error(15 "options.parallel_angle_tolerance" "-1")  # InvalidInput from the library
  expect_error(16 "journal_motion" "missing" "bearing_motion is given")
  expect_error(17 "journal_motion.angular_velocity" "missing")
  expect_error(18 "line 20" "[1,2,3]" "object")
  expect_error(19 "bearing.length" "0" "positive")
  expect_error(20 "bearing" "must be a JSON object")
  expect_error(21 "approach_velocity" "infinite")           # 1e308 - (-1e308) overflows
  # The kernel's own range check (validate(PartPose)), its message naming the field as in the line.
  expect_error(22 "journal.center = [0, 1e+300, 0]: a magnitude outside [1e-150, 1e150], the range of lengths")
  expect_error(23 "bearing.radius" "1e-300" "[1e-150, 1e150]")
  expect_no_error(24)
  # An axis may be any finite non-zero vector (the kernel's rule): no range of its own here.
  expect_no_error(25)
  expect_in("${ERR}" "detect_bad_lines.jsonl" "stderr")
  expect_in("${ERR}" "23 line(s)" "stderr")

elseif(CASE STREQUAL "pin_in_hole")
  # "joint": "pin_in_hole" (docs/command-line.md). Hole Rh = 0.5, L = 1; pin Rp = 0.375 (cr =
  # 0.125), stops at -+0.625 of outer radius 1 (ca = 0.125): dyadic, so the aligned answers below
  # are exact in double and their text must be exactly this. The closed forms are those of
  # tests/geometry/joint/test_detect_pin_in_hole_contacts.cpp.
  run("" "${PIN_IN_HOLE}")
  expect_status(0)
  file(READ "${PIN_IN_HOLE}" input)
  expect_ids_in_order("${input}" "${OUT}")
  split_lines("${OUT}" ANSWER_LINE)
  expect_member(centred "pin_in_hole" joint)
  expect_joint(centred none true)
  expect_member(centred "certified" certificate)
  # Aligned, offset 0.1875 along y: the hole's mid circle point (0, 0.5, 0) is 0.3125 from the
  # pin's axis, a line contact of depth offset - cr = 0.0625 along +y.
  expect_joint(line line true radial:mid)
  expect_member(line "certified" certificate)
  expect_member(line "0.0625" contacts 0 depth)
  expect_member(line "0.5625" contacts 0 point_journal 1)
  expect_member(line "0.5" contacts 0 point_bearing 1)
  expect_member(line "1.0" contacts 0 normal 1)
  # eq. (25): pin point velocity (0, 1, 0) + (0, 0, 2) x (0, 0.375, 0) = (-0.75, 1, 0); link
  # point (0.5, 0.25, 0). Relative (-1.25, 0.75, 0): eq. (24) 0.75, eq. (26) (-1.25, 0, 0).
  expect_joint(line-with-motions line true radial:mid)
  expect_member(line-with-motions "0.75" contacts 0 approach_velocity)
  expect_member(line-with-motions "-1.25" contacts 0 tangential_velocity 0)
  expect_absent(line contacts 0 approach_velocity)
  # Pushed 0.1875 along +z: the stop at -0.625 comes to -0.4375, 0.0625 beyond face B (z = -0.5).
  expect_joint(face face true axial:b)
  expect_member(face "0.0625" contacts 0 depth)
  expect_member(face "-0.4375" contacts 0 point_journal 2)
  expect_member(face "-0.5" contacts 0 point_bearing 2)
  expect_member(face "1.0" contacts 0 normal 2)
  # The same push without stops: a free sliding pin touches nothing.
  expect_joint(free-pin-pushed none true)
  # Rh = 10, L = 20, Rp = 9.9, tilted by t = 0.0125 about the hole's centre: both edges, at
  # opposite sides, each 9.9 - 10 sqrt(1 - sin 2t) = 0.0257779846446... deep (mpmath, 40 digits).
  expect_joint(tilted both_edges_opposite false radial:a radial:b)
  expect_member(tilted "certified" certificate)
  expect_match(tilted "^0\\.0257779846[0-9]*$" contacts 0 depth)
  expect_match(tilted "^0\\.0257779846[0-9]*$" contacts 1 depth)
  # "journal_bearing" names the paper's joint, the default: its answer has no "joint".
  expect_joint(paper-joint-by-name j true radial:mid)
  expect_absent(paper-joint-by-name joint)

elseif(CASE STREQUAL "pin_in_hole_scenarios")
  # The pin-in-hole configurations drawn in docs/figures: one per scenario of the table, the id
  # "pin-<scenario>", each answer certified.
  run("" "${PIN_IN_HOLE_SCENARIOS}")
  expect_status(0)
  file(READ "${PIN_IN_HOLE_SCENARIOS}" input)
  expect_ids_in_order("${input}" "${OUT}")
  split_lines("${OUT}" ANSWER_LINE)
  foreach(scenario none one_edge both_edges_opposite both_edges_same_side line one_stop both_stops face
                   edges_and_stops line_and_face beyond_model)
    expect_member(pin-${scenario} "${scenario}" scenario)
    expect_member(pin-${scenario} "certified" certificate)
  endforeach()

elseif(CASE STREQUAL "pin_in_hole_bad_lines")
  run("" "${PIN_IN_HOLE_BAD_LINES}")
  expect_status(1)
  file(READ "${PIN_IN_HOLE_BAD_LINES}" input)
  expect_ids_in_order("${input}" "${OUT}")
  split_lines("${OUT}" ANSWER_LINE)
  expect_error(0 "line 1" "joint = \"screw\"" "pin_in_hole")
  expect_error(1 "joint = 2: must be a string")
  # The kernel's validate(PinInHoleDimensions), its messages naming the fields as in the line.
  expect_error(2 "pin.radius = 0.625: must be smaller than hole.radius = 0.5")
  expect_error(3 "pin.stops[1].position = 0.25" "inside the hole")
  expect_error(4 "pin.stops = " "at most 2 stops")
  expect_error(5 "hole.length = -1: must be positive")
  expect_error(6 "pin.stops: missing")
  expect_error(7 "pin.length: unknown field")
  expect_error(8 "pin.stops[0].outer_radius = \"NaN\": must be a number")
  expect_error(9 "pin_motion: missing (hole_motion is given")
  expect_error(10 "journal: unknown field")
  expect_error(11 "pin.axis = [0, 0, 0]: must not be the zero vector")
  expect_error(12 "pin.stops[0].outer_radius = 0.5: must be larger than hole.radius = 0.5")
  expect_in("${ERR}" "13 line(s)" "stderr")

elseif(CASE STREQUAL "number_ids")
  # As for intersect: a number id comes back as the text it was written in, also where no double
  # prints that text (1.23e29, an integer beyond 64 bits, -0) and on an error line.
  expect_ids_as_written("${SOURCE_DIR}/tests/apps/detect_number_ids.jsonl" 1)

elseif(CASE STREQUAL "missing_file")
  set(missing "${WORK_DIR}/no-such-joints.jsonl")
  file(REMOVE "${missing}")
  run("" "${missing}")
  expect_status(2)
  expect_in("${ERR}" "no-such-joints.jsonl" "stderr")
  if(NOT OUT STREQUAL "")
    fail("wrote to stdout for a missing file:\n${OUT}")
  endif()

elseif(CASE STREQUAL "usage")
  run("" --no-such-option)
  expect_status(2)
  expect_in("${ERR}" "--no-such-option" "stderr")
  expect_in("${ERR}" "usage: clearjoint detect" "stderr")
  run("" "${EXAMPLE}" "${EXAMPLE}")
  expect_status(2)
  expect_in("${ERR}" "more than one" "stderr")

elseif(CASE STREQUAL "help")
  run("" --help)
  expect_status(0)
  expect_in("${OUT}" "usage: clearjoint detect [FILE]" "stdout")
  expect_in("${OUT}" "journal_motion" "stdout")
  expect_in("${OUT}" "parallel_angle_tolerance" "stdout")
  # The program's own list of commands names it.
  execute_process(COMMAND "${CLEARJOINT}" --help RESULT_VARIABLE RC OUTPUT_VARIABLE OUT
                  ERROR_VARIABLE ERR)
  expect_status(0)
  expect_in("${OUT}" "detect" "clearjoint --help")

else()
  fail("unknown case")
endif()
