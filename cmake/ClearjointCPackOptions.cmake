# SPDX-License-Identifier: BSD-3-Clause
# Read by cpack for each generator (CPACK_PROJECT_CONFIG_FILE, cmake/ClearjointPackage.cmake).
# A Debian package installs into /usr: from a build configured for another prefix, its libraries
# would miss the multiarch folder and its programs would carry run paths to that prefix.
if(CPACK_GENERATOR STREQUAL "DEB" AND NOT CPACK_CLEARJOINT_INSTALL_PREFIX STREQUAL "/usr")
  message(FATAL_ERROR "clearjoint: a Debian package needs a build configured with "
                      "-DCMAKE_INSTALL_PREFIX=/usr (this one: ${CPACK_CLEARJOINT_INSTALL_PREFIX}); "
                      "scripts/check-deb.sh builds and checks one")
endif()

# The packages other than clearjoint link its libraries: dpkg-shlibdeps finds them in clearjoint's
# staging folder (their dependency is written out: "clearjoint (= version)"). Each package's
# description starts with its own synopsis: no summary for CPack to put before it.
if(CPACK_GENERATOR STREQUAL "DEB")
  unset(CPACK_PACKAGE_DESCRIPTION_SUMMARY)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS
      "${CPACK_PACKAGE_DIRECTORY}/_CPack_Packages/${CPACK_SYSTEM_NAME}/DEB/${CPACK_PACKAGE_FILE_NAME}/Unspecified/usr/${CPACK_CLEARJOINT_LIBDIR}")
endif()
