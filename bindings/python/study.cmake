# SPDX-License-Identifier: BSD-3-Clause
# The study runner (clearjoint.study, docs/studies.md): its Python files and the study schema go
# into the package in the build tree and are installed with it; the clearjoint program gets its
# `study` subcommand, which runs `python3 -m clearjoint.study` with this interpreter.
# Included from bindings/python/CMakeLists.txt after the package is set up.

file(GLOB clearjoint_study_files RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/clearjoint/study CONFIGURE_DEPENDS
     ${CMAKE_CURRENT_SOURCE_DIR}/clearjoint/study/*.py)
foreach(file ${clearjoint_study_files})
  configure_file(clearjoint/study/${file} ${clearjoint_python_package}/study/${file} COPYONLY)
endforeach()
set(clearjoint_study_schema ${PROJECT_SOURCE_DIR}/docs/schema/study-v1.schema.json)
configure_file(${clearjoint_study_schema} ${clearjoint_python_package}/study/study-v1.schema.json COPYONLY)
list(TRANSFORM clearjoint_study_files PREPEND clearjoint/study/)
install(FILES ${clearjoint_study_files} ${clearjoint_study_schema}
        DESTINATION ${clearjoint_python_destination}/study)

if(TARGET clearjoint)
  # From the installed program (PREFIX/bin) up to the prefix, for a relative package directory.
  file(RELATIVE_PATH clearjoint_study_bin_to_prefix "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix")
  if(clearjoint_study_bin_to_prefix STREQUAL "")
    set(clearjoint_study_bin_to_prefix ".")
  endif()
  target_sources(clearjoint PRIVATE ${PROJECT_SOURCE_DIR}/apps/clearjoint/study_command.cpp)
  target_compile_definitions(clearjoint PRIVATE
    CLEARJOINT_WITH_STUDY
    CLEARJOINT_STUDY_PYTHON="${Python3_EXECUTABLE}"
    CLEARJOINT_STUDY_BUILD_PROGRAM_DIR="$<TARGET_FILE_DIR:clearjoint>"
    CLEARJOINT_STUDY_BUILD_PYTHONPATH="${CMAKE_CURRENT_BINARY_DIR}"
    CLEARJOINT_STUDY_INSTALL_PYTHONPATH="${CLEARJOINT_PYTHON_INSTALL_DIR}"
    CLEARJOINT_STUDY_INSTALL_PREFIX_FROM_BINDIR="${clearjoint_study_bin_to_prefix}")
endif()
