# SPDX-License-Identifier: BSD-3-Clause
# dump_answers: every field of 192,000 kernel answers in %a, for bit-for-bit comparisons of two
# builds (docs/verifying-refactors.md). Its printing and input families are a library of their own,
# which the tests in tests/ link too. This file is included by bench/geometry/CMakeLists.txt and by
# the small project scripts/compare-answers.sh builds against each revision's installed library,
# so that both build the tool from one list of sources; paths are relative to this file.
add_library(clearjoint_answer_dump STATIC
  ${CMAKE_CURRENT_LIST_DIR}/answer_text.cpp
  ${CMAKE_CURRENT_LIST_DIR}/answer_families.cpp)
target_include_directories(clearjoint_answer_dump
  PUBLIC ${CMAKE_CURRENT_LIST_DIR} ${CMAKE_CURRENT_LIST_DIR}/../common)
target_link_libraries(clearjoint_answer_dump PUBLIC clearjoint::geometry)
add_executable(dump_answers ${CMAKE_CURRENT_LIST_DIR}/dump_answers.cpp)
target_link_libraries(dump_answers PRIVATE clearjoint_answer_dump)
