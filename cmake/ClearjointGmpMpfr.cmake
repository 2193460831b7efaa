# SPDX-License-Identifier: BSD-3-Clause
# The GMP and MPFR libraries as the imported targets GMP::GMP and MPFR::MPFR.
#
# A static clearjoint::geometry needs both at the final link: its exact tiers use CGAL's Gmpq
# (GMP rationals) and CGAL converts them to double through MPFR. A shared library carries them
# itself. CGAL's target brings them in the build tree, but exporting it would ask consumers for
# CGAL's whole package (and CMake writes it as a bare `CGAL`, its aliased name); CGAL's find
# modules set variables only, and Debian ships no CMake package for GMP or MPFR. Hence these few
# lines, used by geometry/CMakeLists.txt and, installed, by clearjointConfig.cmake. Not named
# FindGMP.cmake on purpose: CGAL's configuration runs find_package(GMP) and expects its own
# module's variables. Targets a project has already defined under these names are kept.
foreach(clearjoint_number_library GMP MPFR)
  string(TOLOWER ${clearjoint_number_library} clearjoint_name)
  if(NOT TARGET ${clearjoint_number_library}::${clearjoint_number_library})
    find_path(CLEARJOINT_${clearjoint_number_library}_INCLUDE_DIR NAMES ${clearjoint_name}.h)
    find_library(CLEARJOINT_${clearjoint_number_library}_LIBRARY NAMES ${clearjoint_name})
    mark_as_advanced(CLEARJOINT_${clearjoint_number_library}_INCLUDE_DIR
                     CLEARJOINT_${clearjoint_number_library}_LIBRARY)
    if(NOT CLEARJOINT_${clearjoint_number_library}_LIBRARY OR
       NOT CLEARJOINT_${clearjoint_number_library}_INCLUDE_DIR)
      set(CLEARJOINT_GMP_MPFR_MISSING ${clearjoint_number_library})
      break()
    endif()
    add_library(${clearjoint_number_library}::${clearjoint_number_library} UNKNOWN IMPORTED)
    set_target_properties(${clearjoint_number_library}::${clearjoint_number_library} PROPERTIES
      IMPORTED_LOCATION "${CLEARJOINT_${clearjoint_number_library}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${CLEARJOINT_${clearjoint_number_library}_INCLUDE_DIR}")
  endif()
endforeach()
unset(clearjoint_number_library)
unset(clearjoint_name)
