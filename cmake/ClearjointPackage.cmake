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
# A static clearjoint::nonsmooth carries Siconos Numerics to its consumers' link.
if(TARGET clearjoint_nonsmooth AND CLEARJOINT_STATIC_LIBRARIES)
  set(CLEARJOINT_STATIC_NONSMOOTH TRUE)
else()
  set(CLEARJOINT_STATIC_NONSMOOTH FALSE)
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

# The licence, README, change log, documentation and examples in the documentation folder
# (share/doc/clearjoint); the JSON Schemas of the command line's formats where `clearjoint --help`
# says they are.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md
              ${PROJECT_SOURCE_DIR}/CHANGELOG.md ${PROJECT_SOURCE_DIR}/CITATION.cff
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        PATTERN "Doxyfile.in" EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)
if(EXISTS ${PROJECT_SOURCE_DIR}/docs/schema)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/schema/
          DESTINATION ${CMAKE_INSTALL_DATADIR}/clearjoint/schema FILES_MATCHING PATTERN "*.json")
endif()

# Debian packages of this build (`cpack -G DEB` in a build folder configured with the prefix /usr;
# scripts/check-deb.sh builds them, runs lintian on them, installs and checks them):
#   clearjoint           the libraries, headers, CMake and pkg-config files, the program, docs
#   python3-clearjoint   the Python package (component "python", bindings/python)
#   octave-clearjoint    the MEX files and their help text (component "octave", bindings/matlab:
#                        each gateway it builds)
#   clearjoint-engines   the Simbody and MuJoCo adapters (component "engines")
# Depends: the run-time libraries as dpkg-shlibdeps finds them, the package the others build on,
# and what the Python package imports. Each package has its documentation folder with the
# machine-readable copyright file (cmake/debian/copyright) and a Debian change log.
set(CPACK_PACKAGE_NAME clearjoint)
set(CPACK_PACKAGE_VENDOR "The clearjoint developers")
# Debian wants a Maintainer with an address; the project publishes none, so this placeholder is a
# cache variable, to be set to a real address for packages given to others.
set(CLEARJOINT_DEB_MAINTAINER "The clearjoint developers <clearjoint@example.org>" CACHE STRING
    "Maintainer field of the Debian packages (Name <address>)")
set(CPACK_PACKAGE_CONTACT "${CLEARJOINT_DEB_MAINTAINER}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# A Debian revision: the packaging of upstream version ${PROJECT_VERSION}, not a native package.
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(clearjoint_deb_version "${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# A shlibs file for the libraries (exact version: before 1.0 a minor release may break the ABI),
# stripped binaries, and ldconfig run by a trigger (CPack's postinst and postrm call it as well).
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY "=")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# Compressed with xz, as the packages of the Debian archive are.
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)

# The main package, component Unspecified (every install rule without a COMPONENT).
set(clearjoint_deb_components Unspecified)
set(CPACK_DEBIAN_UNSPECIFIED_PACKAGE_NAME clearjoint)
# Descriptions: the first line is the synopsis, then lines of at most 80 characters.
set(CPACK_DEBIAN_UNSPECIFIED_DESCRIPTION "${PROJECT_DESCRIPTION}
clearjoint finds every rim/wall crossing of a spatial revolute joint
with radial and axial clearance, proves each one, and decides tangencies
exactly (CGAL rationals); a multibody dynamics module uses it for the
clearance joint's contact forces. This package holds the libraries, their
C++ headers, CMake and pkg-config files, the C API, the clearjoint
program, the documentation and the examples.")
set(CPACK_DEBIAN_UNSPECIFIED_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/cmake/debian/triggers)
# Eigen's headers: the public headers include them. The tools of a consumer's build (a C++20
# compiler, CMake or pkg-config) are the user's choice.
set(CPACK_DEBIAN_UNSPECIFIED_PACKAGE_DEPENDS "libeigen3-dev (>= 3.3)")
set(CPACK_DEBIAN_UNSPECIFIED_PACKAGE_SUGGESTS "cmake, pkgconf, g++")
set(clearjoint_deb_UNSPECIFIED_package clearjoint)

if(TARGET clearjoint_python_core)
  list(APPEND clearjoint_deb_components python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-clearjoint)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_DESCRIPTION
"Python 3 package of clearjoint, certified joint contact detection
The clearjoint package for Python 3: contact detection on one pose or on
NumPy batches of poses, the certified kernel queries, simulations that
return their time series as arrays, the study runner, figures and a
browser viewer of runs.")
  # The module is built for this interpreter's ABI (python3.X): that version, and NumPy.
  execute_process(COMMAND ${Python3_EXECUTABLE} -c
                          "import sys; print('%d.%d %d.%d' % (*sys.version_info[:2], sys.version_info[0], sys.version_info[1] + 1))"
                  OUTPUT_VARIABLE python_versions OUTPUT_STRIP_TRAILING_WHITESPACE)
  separate_arguments(python_versions)
  list(GET python_versions 0 python_this)
  list(GET python_versions 1 python_next)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "clearjoint (= ${clearjoint_deb_version}), python3 (>= ${python_this}~), python3 (<< ${python_next}), python3-numpy")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS
      "python3-pandas, python3-matplotlib, python3-h5py, python3-jsonschema, python3-scipy, python3-distributed, python3-tqdm")
  set(clearjoint_deb_PYTHON_package python3-clearjoint)
endif()
if(CLEARJOINT_MATLAB_ENABLED)
  list(APPEND clearjoint_deb_components octave)
  set(CPACK_DEBIAN_OCTAVE_PACKAGE_NAME octave-clearjoint)
  set(CPACK_DEBIAN_OCTAVE_PACKAGE_SECTION math)
  set(CPACK_DEBIAN_OCTAVE_DESCRIPTION
"Octave MEX files of clearjoint, certified joint contact detection
The MEX gateways for GNU Octave, over clearjoint's C API, with their help
text (help cj_detect): cj_detect and cj_detect_many for the paper's
journal in its bearing, cj_detect_pin_in_hole and
cj_detect_pin_in_hole_many for a pin through a hole, on one pose or on
many.")
  set(CPACK_DEBIAN_OCTAVE_PACKAGE_DEPENDS "clearjoint (= ${clearjoint_deb_version}), octave")
  set(clearjoint_deb_OCTAVE_package octave-clearjoint)
endif()
if(TARGET clearjoint_simbody OR TARGET clearjoint_mujoco)
  list(APPEND clearjoint_deb_components engines)
  set(CPACK_DEBIAN_ENGINES_PACKAGE_NAME clearjoint-engines)
  set(CPACK_DEBIAN_ENGINES_DESCRIPTION
"Simbody and MuJoCo adapters of clearjoint's clearance revolute joint
The clearance revolute joint inside Simbody and MuJoCo: the libraries
clearjoint::simbody and clearjoint::mujoco, their headers and CMake files.")
  set(CPACK_DEBIAN_ENGINES_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/cmake/debian/triggers)
  set(CPACK_DEBIAN_ENGINES_PACKAGE_DEPENDS "clearjoint (= ${clearjoint_deb_version})")
  set(clearjoint_deb_ENGINES_package clearjoint-engines)
endif()
set(CPACK_COMPONENTS_ALL ${clearjoint_deb_components})

# Each package's documentation folder: copyright and changelog.Debian.gz (whose date is
# SOURCE_DATE_EPOCH's when set, for a reproducible package). Only in a build for /usr, the
# packages' prefix: another install has no Debian packages to describe.
string(TIMESTAMP clearjoint_deb_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(clearjoint_deb_doc_components)
else()
  set(clearjoint_deb_doc_components ${clearjoint_deb_components})
endif()
foreach(component IN LISTS clearjoint_deb_doc_components)
  string(TOUPPER ${component} upper)
  set(package ${clearjoint_deb_${upper}_package})
  set(changelog ${PROJECT_BINARY_DIR}/debian/${package}/changelog.Debian)
  file(WRITE ${changelog}
"${package} (${clearjoint_deb_version}) unstable; urgency=medium

  * Package of clearjoint ${PROJECT_VERSION}, built with CPack. The changes of the
    software are in /usr/share/doc/clearjoint/CHANGELOG.md.

 -- ${CLEARJOINT_DEB_MAINTAINER}  ${clearjoint_deb_date}
")
  install(CODE "execute_process(COMMAND gzip -9nf \"${changelog}\" -c
                                OUTPUT_FILE \"${changelog}.gz\" COMMAND_ERROR_IS_FATAL ANY)"
          COMPONENT ${component})
  install(FILES ${changelog}.gz ${PROJECT_SOURCE_DIR}/cmake/debian/copyright
          DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${package} COMPONENT ${component})
endforeach()

# A package for /usr only: the multiarch library folder (GNUInstallDirs chooses it for that prefix),
# no run paths, Octave's and Python's own folders. A build configured for another prefix stops here.
set(CPACK_CLEARJOINT_INSTALL_PREFIX "${CMAKE_INSTALL_PREFIX}")
set(CPACK_CLEARJOINT_LIBDIR "${CMAKE_INSTALL_LIBDIR}")
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_SOURCE_DIR}/cmake/ClearjointCPackOptions.cmake)
include(CPack)
