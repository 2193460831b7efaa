# SPDX-License-Identifier: BSD-3-Clause
# clearjoint_add_pkg_config(TARGET NAME DESCRIPTION [REQUIRES ...] [LIBS_PRIVATE ...])
#
# Writes and installs NAME.pc (into ${CMAKE_INSTALL_LIBDIR}/pkgconfig) for the library TARGET, so
# that a build without CMake can use it:
#
#     c++ -std=c++20 app.cpp $(pkg-config --cflags --libs NAME)            # shared install
#     c++ -std=c++20 app.cpp $(pkg-config --static --cflags --libs NAME)   # static install
#
#   REQUIRES      pkg-config modules the headers or the library need (e.g. eigen3,
#                 clearjoint-geometry); they go into "Requires:".
#   LIBS_PRIVATE  what a static link of TARGET needs beyond it (e.g. -lgmp); "Libs.private:",
#                 which pkg-config adds only with --static. Written only when TARGET is a static
#                 library: a shared library carries its own dependencies.
#
# The file locates the install by its own place (${pcfiledir}), not by an absolute prefix: the
# prefix is chosen at install time (`cmake --install build --prefix P`, CPack's /usr), after this
# file is generated, and an installed tree may be moved.
include_guard(GLOBAL)
include(GNUInstallDirs)

function(clearjoint_add_pkg_config)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;NAME;DESCRIPTION" "REQUIRES;LIBS_PRIVATE")
  foreach(required TARGET NAME DESCRIPTION)
    if(NOT arg_${required})
      message(FATAL_ERROR "clearjoint_add_pkg_config: ${required} is required")
    endif()
  endforeach()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "clearjoint_add_pkg_config: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()

  # The prefix seen from the .pc file's folder: "../.." for lib/pkgconfig, "../../.." for
  # lib/x86_64-linux-gnu/pkgconfig.
  file(RELATIVE_PATH to_prefix "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  string(REGEX REPLACE "/$" "" to_prefix "${to_prefix}")
  list(JOIN arg_REQUIRES ", " requires)
  list(JOIN arg_LIBS_PRIVATE " " libs_private)

  get_target_property(type ${arg_TARGET} TYPE)
  set(libs_private_line "")
  if(type STREQUAL "STATIC_LIBRARY" AND libs_private)
    set(libs_private_line "Libs.private: ${libs_private}\n")
  endif()
  set(requires_line "")
  if(requires)
    set(requires_line "Requires: ${requires}\n")
  endif()

  # file(GENERATE) resolves the library's file name (OUTPUT_NAME, without "lib" and suffix).
  file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${arg_NAME}.pc CONTENT
"prefix=\${pcfiledir}/${to_prefix}
libdir=\${prefix}/${CMAKE_INSTALL_LIBDIR}
includedir=\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}

Name: ${arg_NAME}
Description: ${arg_DESCRIPTION}
Version: ${PROJECT_VERSION}
${requires_line}Cflags: -I\${includedir}
Libs: -L\${libdir} -l$<TARGET_FILE_BASE_NAME:${arg_TARGET}>
${libs_private_line}")
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${arg_NAME}.pc
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endfunction()
