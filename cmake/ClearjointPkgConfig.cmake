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
#
# A shared library's Libs carry -Wl,-rpath,${libdir}, so that a program linked with them runs
# without LD_LIBRARY_PATH, as programs built with the CMake package do; except when the install
# prefix is /usr, whose library folder the dynamic loader searches anyway (Debian's policy forbids
# a run path there). The prefix is known only when installing: the install step writes the file.
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

  set(rpath_placeholder "")
  if(type STREQUAL "SHARED_LIBRARY")
    set(rpath_placeholder "%CLEARJOINT_PKG_CONFIG_RPATH%")
  endif()

  # file(GENERATE) resolves the library's file name (OUTPUT_NAME, without "lib" and suffix).
  set(template ${CMAKE_CURRENT_BINARY_DIR}/pkgconfig/${arg_NAME}.pc.in)
  file(GENERATE OUTPUT ${template} CONTENT
"prefix=\${pcfiledir}/${to_prefix}
libdir=\${prefix}/${CMAKE_INSTALL_LIBDIR}
includedir=\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}

Name: ${arg_NAME}
Description: ${arg_DESCRIPTION}
Version: ${PROJECT_VERSION}
${requires_line}Cflags: -I\${includedir}
Libs: -L\${libdir} -l$<TARGET_FILE_BASE_NAME:${arg_TARGET}>${rpath_placeholder}
${libs_private_line}")
  # At install time, CMAKE_INSTALL_PREFIX is the prefix installed into (--prefix, CPack's). The
  # placeholder is not @...@: the install script runs under CMake's old policy CMP0053, which
  # would expand such a reference in the script's own text.
  set(staged ${CMAKE_CURRENT_BINARY_DIR}/pkgconfig/install/${arg_NAME}.pc)
  install(CODE "
    if(CMAKE_INSTALL_PREFIX STREQUAL \"/usr\" OR CMAKE_INSTALL_PREFIX STREQUAL \"/usr/\")
      set(CLEARJOINT_PKG_CONFIG_RPATH \"\")
    else()
      set(CLEARJOINT_PKG_CONFIG_RPATH \" -Wl,-rpath,\\\${libdir}\")
    endif()
    file(READ \"${template}\" content)
    string(REPLACE \"%CLEARJOINT_PKG_CONFIG_RPATH%\" \"\${CLEARJOINT_PKG_CONFIG_RPATH}\" content \"\${content}\")
    file(WRITE \"${staged}\" \"\${content}\")
    file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig\"
         TYPE FILE FILES \"${staged}\")")
endfunction()
