# SPDX-License-Identifier: BSD-3-Clause
# The study runner (clearjoint.study, docs/studies.md): its Python files (apps/python/study/) and
# the study schema go into the package in the build tree and are installed with it; the clearjoint
# program gets its `study` subcommand, which runs clearjoint.study with this interpreter. Included
# from bindings/python/CMakeLists.txt after the package is set up, with plot_view.cmake.

file(GLOB clearjoint_study_files RELATIVE ${CMAKE_CURRENT_LIST_DIR}/study CONFIGURE_DEPENDS
     ${CMAKE_CURRENT_LIST_DIR}/study/*.py)
foreach(file ${clearjoint_study_files})
  configure_file(${CMAKE_CURRENT_LIST_DIR}/study/${file} ${clearjoint_python_package}/study/${file} COPYONLY)
endforeach()
set(clearjoint_study_schema ${PROJECT_SOURCE_DIR}/docs/schema/study-v1.schema.json)
configure_file(${clearjoint_study_schema} ${clearjoint_python_package}/study/study-v1.schema.json COPYONLY)
list(TRANSFORM clearjoint_study_files PREPEND ${CMAKE_CURRENT_LIST_DIR}/study/)
install(FILES ${clearjoint_study_files} ${clearjoint_study_schema}
        DESTINATION ${clearjoint_python_destination}/study)

if(TARGET clearjoint)
  # The subcommand hands over through apps/clearjoint/python_handover.cpp, which plot_view.cmake
  # adds with the interpreter and the package's location.
  target_sources(clearjoint PRIVATE ${PROJECT_SOURCE_DIR}/apps/clearjoint/study_command.cpp)
  target_compile_definitions(clearjoint PRIVATE CLEARJOINT_WITH_STUDY)
endif()
