# SPDX-License-Identifier: BSD-3-Clause
# What `cmake --install` and `cpack` ship besides the targets themselves: the CMake package
# (find_package(clearjoint)), pkg-config files, licence and format schemas, and the .deb
# configuration. Included at the end of the top-level CMakeLists.txt, after every target exists.
include(CMakePackageConfigHelpers)

# find_package(clearjoint) then target_link_libraries(app clearjoint::geometry).
get_target_property(clearjoint_geometry_type clearjoint_geometry TYPE)
if(clearjoint_geometry_type STREQUAL "STATIC_LIBRARY")
  set(CLEARJOINT_STATIC_LIBRARIES TRUE)
else()
  set(CLEARJOINT_STATIC_LIBRARIES FALSE)
endif()
configure_package_config_file(cmake/clearjointConfig.cmake.in
  ${PROJECT_BINARY_DIR}/clearjointConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/clearjoint)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/clearjointConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/clearjointConfig.cmake
              ${PROJECT_BINARY_DIR}/clearjointConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/ClearjointGmpMpfr.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/clearjoint)
install(EXPORT clearjointTargets NAMESPACE clearjoint::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/clearjoint)

# pkg-config: clearjoint-geometry.pc, clearjoint-dynamics.pc. A static geometry library leaves
# GMP and MPFR to the final link (its exact tiers; cmake/ClearjointGmpMpfr.cmake).
clearjoint_add_pkg_config(TARGET clearjoint_geometry NAME clearjoint-geometry
  DESCRIPTION "Certified circle-plane and circle-cylinder intersection and joint contact detection (C++20)"
  REQUIRES eigen3
  LIBS_PRIVATE -lmpfr -lgmp)
if(TARGET clearjoint_dynamics)
  clearjoint_add_pkg_config(TARGET clearjoint_dynamics NAME clearjoint-dynamics
    DESCRIPTION "Spatial multibody dynamics with clearance revolute joints (C++20)"
    REQUIRES clearjoint-geometry eigen3)
endif()

# The licence beside the documentation; the JSON Schemas of the command line's formats where
# `clearjoint --help` says they are.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
if(EXISTS ${PROJECT_SOURCE_DIR}/docs/schema)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/schema/
          DESTINATION ${CMAKE_INSTALL_DATADIR}/clearjoint/schema FILES_MATCHING PATTERN "*.json")
endif()

# A Debian package of this build (`cpack -G DEB` in the build folder; scripts/check-deb.sh builds
# one with the prefix /usr and checks it on this system). Depends: the libraries' run-time
# dependencies as dpkg-shlibdeps finds them (GMP, MPFR, the C++ run time), and Eigen's headers,
# which the public headers include.
set(CPACK_PACKAGE_NAME clearjoint)
set(CPACK_PACKAGE_VENDOR "The clearjoint developers")
set(CPACK_PACKAGE_CONTACT "The clearjoint developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
  "clearjoint finds every rim/wall crossing of a spatial revolute joint with radial and axial\n\
clearance, proves each one, and decides tangencies exactly (CGAL rationals); a multibody\n\
dynamics module uses it for the clearance joint's contact forces. This package holds the\n\
libraries, their C++ headers, CMake and pkg-config files, and the clearjoint program.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libeigen3-dev (>= 3.3)")
# The tools of a consumer's build (a C++20 compiler, CMake or pkg-config) are the user's choice:
# suggested, not required.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "cmake, pkgconf, g++")
include(CPack)
