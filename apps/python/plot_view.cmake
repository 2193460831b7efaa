# SPDX-License-Identifier: BSD-3-Clause
# Figures and the browser viewer of a run (clearjoint.plot, clearjoint.view; docs/viewing-runs.md):
# their Python files (apps/python/plot/, apps/python/view/) and the viewer's web page with its
# vendored three.js go into the package in the build tree and are installed with it, so the page
# works offline from any install; the clearjoint program gets its `plot` and `view` subcommands,
# which hand over to this interpreter. Included from bindings/python/CMakeLists.txt after the
# package is set up.

foreach(subpackage plot view)
  file(GLOB_RECURSE clearjoint_${subpackage}_files RELATIVE ${CMAKE_CURRENT_LIST_DIR}
       CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/${subpackage}/*.py
       ${CMAKE_CURRENT_LIST_DIR}/${subpackage}/web/*)
  foreach(file ${clearjoint_${subpackage}_files})
    configure_file(${CMAKE_CURRENT_LIST_DIR}/${file} ${clearjoint_python_package}/${file} COPYONLY)
    get_filename_component(directory ${file} DIRECTORY)
    install(FILES ${CMAKE_CURRENT_LIST_DIR}/${file} DESTINATION ${clearjoint_python_destination}/${directory})
  endforeach()
endforeach()

if(TARGET clearjoint)
  # From the installed program (PREFIX/bin) up to the prefix, for a relative package directory.
  file(RELATIVE_PATH clearjoint_python_bin_to_prefix "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix")
  if(clearjoint_python_bin_to_prefix STREQUAL "")
    set(clearjoint_python_bin_to_prefix ".")
  endif()
  target_sources(clearjoint PRIVATE ${PROJECT_SOURCE_DIR}/apps/clearjoint/python_handover.cpp)
  target_compile_definitions(clearjoint PRIVATE
    CLEARJOINT_WITH_PLOT_VIEW
    CLEARJOINT_PYTHON_EXECUTABLE="${Python3_EXECUTABLE}"
    CLEARJOINT_PYTHON_BUILD_PROGRAM_DIR="$<TARGET_FILE_DIR:clearjoint>"
    CLEARJOINT_PYTHON_BUILD_PYTHONPATH="${CMAKE_CURRENT_BINARY_DIR}"
    CLEARJOINT_PYTHON_INSTALL_PYTHONPATH="${CLEARJOINT_PYTHON_INSTALL_DIR}"
    CLEARJOINT_PYTHON_INSTALL_PREFIX_FROM_BINDIR="${clearjoint_python_bin_to_prefix}")
endif()
