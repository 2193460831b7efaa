# SPDX-License-Identifier: BSD-3-Clause
# CLEARJOINT_BUILD_MATLAB and CLEARJOINT_BUILD_FORTRAN (AUTO, ON or OFF): whether the bindings
# over the C API are built, found out and said at configure time. Sets CLEARJOINT_MATLAB_ENABLED
# (with CLEARJOINT_MKOCTFILE, CLEARJOINT_OCTAVE_CLI) and CLEARJOINT_FORTRAN_ENABLED. Included from
# the top-level CMakeLists.txt: a language enabled there is usable by the tests as well.
set(clearjoint_binding_choices AUTO ON OFF)
set(CLEARJOINT_BUILD_MATLAB AUTO CACHE STRING
    "MEX gateway for MATLAB/Octave, built here with Octave's mkoctfile: AUTO, ON or OFF")
set(CLEARJOINT_BUILD_FORTRAN AUTO CACHE STRING
    "Fortran module (ISO_C_BINDING) over the C API, and its example: AUTO, ON or OFF")
set_property(CACHE CLEARJOINT_BUILD_MATLAB PROPERTY STRINGS ${clearjoint_binding_choices})
set_property(CACHE CLEARJOINT_BUILD_FORTRAN PROPERTY STRINGS ${clearjoint_binding_choices})
foreach(option CLEARJOINT_BUILD_MATLAB CLEARJOINT_BUILD_FORTRAN)
  string(TOUPPER "${${option}}" value)
  if(value STREQUAL "TRUE" OR value STREQUAL "YES" OR value STREQUAL "1")
    set(value ON)
  elseif(value STREQUAL "FALSE" OR value STREQUAL "NO" OR value STREQUAL "0")
    set(value OFF)
  endif()
  if(NOT value IN_LIST clearjoint_binding_choices)
    message(FATAL_ERROR "${option} = ${${option}}: must be AUTO, ON or OFF")
  endif()
  set(${option}_VALUE ${value})
endforeach()

# MATLAB/Octave: the gateway is built with Octave's mkoctfile and tested with octave-cli.
# (MATLAB's own `mex` builds the same source by hand: docs/languages.md.)
set(CLEARJOINT_MATLAB_ENABLED OFF)
if(NOT CLEARJOINT_BUILD_MATLAB_VALUE STREQUAL "OFF")
  find_program(CLEARJOINT_MKOCTFILE mkoctfile)
  find_program(CLEARJOINT_OCTAVE_CLI octave-cli)
  if(NOT BUILD_SHARED_LIBS)
    # A MEX file is a shared object; it would need the static libraries built as PIC.
    if(CLEARJOINT_BUILD_MATLAB_VALUE STREQUAL "ON")
      message(FATAL_ERROR "CLEARJOINT_BUILD_MATLAB=ON needs BUILD_SHARED_LIBS=ON")
    endif()
    message(STATUS "clearjoint: MATLAB/Octave binding: not built (needs BUILD_SHARED_LIBS=ON)")
  elseif(CLEARJOINT_MKOCTFILE AND CLEARJOINT_OCTAVE_CLI)
    set(CLEARJOINT_MATLAB_ENABLED ON)
    message(STATUS "clearjoint: MATLAB/Octave binding: built with ${CLEARJOINT_MKOCTFILE}, "
                   "tested with ${CLEARJOINT_OCTAVE_CLI} (CLEARJOINT_BUILD_MATLAB=${CLEARJOINT_BUILD_MATLAB})")
  elseif(CLEARJOINT_BUILD_MATLAB_VALUE STREQUAL "ON")
    message(FATAL_ERROR "CLEARJOINT_BUILD_MATLAB=ON but mkoctfile or octave-cli was not found "
                        "(Debian: apt-get install octave octave-dev)")
  else()
    message(STATUS "clearjoint: MATLAB/Octave binding: not built (mkoctfile or octave-cli not found; "
                   "Debian: apt-get install octave octave-dev)")
  endif()
else()
  message(STATUS "clearjoint: MATLAB/Octave binding: not built (CLEARJOINT_BUILD_MATLAB=OFF)")
endif()


# Fortran: any compiler CMake knows; Debian's gfortran in CI.
set(CLEARJOINT_FORTRAN_ENABLED OFF)
if(NOT CLEARJOINT_BUILD_FORTRAN_VALUE STREQUAL "OFF")
  include(CheckLanguage)
  check_language(Fortran)
  if(CMAKE_Fortran_COMPILER)
    enable_language(Fortran)
    set(CLEARJOINT_FORTRAN_ENABLED ON)
    message(STATUS "clearjoint: Fortran binding: built with ${CMAKE_Fortran_COMPILER} "
                   "(CLEARJOINT_BUILD_FORTRAN=${CLEARJOINT_BUILD_FORTRAN})")
  elseif(CLEARJOINT_BUILD_FORTRAN_VALUE STREQUAL "ON")
    message(FATAL_ERROR "CLEARJOINT_BUILD_FORTRAN=ON but no Fortran compiler was found "
                        "(Debian: apt-get install gfortran)")
  else()
    message(STATUS "clearjoint: Fortran binding: not built (no Fortran compiler found; "
                   "Debian: apt-get install gfortran)")
  endif()
else()
  message(STATUS "clearjoint: Fortran binding: not built (CLEARJOINT_BUILD_FORTRAN=OFF)")
endif()
