# SPDX-License-Identifier: BSD-3-Clause
# clearjoint.lubrication (docs/lubrication.md): its Python files go into the package in the build
# tree and are installed with it; the compiled half is src/lubrication.cpp in _core.
# Included from bindings/python/CMakeLists.txt after the package is set up.

file(GLOB clearjoint_lubrication_files RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/clearjoint CONFIGURE_DEPENDS
     ${CMAKE_CURRENT_SOURCE_DIR}/clearjoint/lubrication/*.py)
foreach(file ${clearjoint_lubrication_files})
  configure_file(clearjoint/${file} ${clearjoint_python_package}/${file} COPYONLY)
  install(FILES clearjoint/${file} DESTINATION ${clearjoint_python_destination}/lubrication)
endforeach()
