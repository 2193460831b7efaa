# SPDX-License-Identifier: BSD-3-Clause
# clearjoint_position_independent_link_closure(TARGET)
#
# Compiles every static and object library of this project that TARGET links, directly or through
# other libraries, as position-independent code. For a shared object built with static libraries
# inside it (the Python extension module of `pip install .`, which setup.py builds with
# BUILD_SHARED_LIBS=OFF): each object that goes into it must be PIC, or the link fails with
# "relocation R_X86_64_TPOFF32 ... recompile with -fPIC" (the exact tier's thread-local CGAL
# objects were the ones that did).
#
# POSITION_INDEPENDENT_CODE is a property of the library that is compiled, not of the one that
# links it, and CMake does not carry it along the link: a list kept by hand goes stale when a
# library gains a dependency (the object library of the exact tier was left out of one). The walk
# follows LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES, looks inside $<BUILD_INTERFACE:...> and
# $<LINK_ONLY:...>, and skips imported targets (their code is built elsewhere). Call it after
# every library TARGET links has its link libraries (the top-level CMakeLists.txt adds the Python
# package after the libraries).
include_guard(GLOBAL)

function(clearjoint_position_independent_link_closure target)
  set(pending ${target})
  set(seen)
  while(pending)
    list(POP_FRONT pending current)
    if(NOT TARGET ${current})
      continue()
    endif()
    get_target_property(aliased ${current} ALIASED_TARGET)
    if(aliased)
      set(current ${aliased})
    endif()
    if(current IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${current})
    get_target_property(imported ${current} IMPORTED)
    if(imported)
      continue()
    endif()
    get_target_property(type ${current} TYPE)
    if(type STREQUAL "STATIC_LIBRARY" OR type STREQUAL "OBJECT_LIBRARY")
      set_target_properties(${current} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    endif()
    set(links)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(direct ${current} LINK_LIBRARIES)
      if(direct)
        list(APPEND links ${direct})
      endif()
    endif()
    get_target_property(interface ${current} INTERFACE_LINK_LIBRARIES)
    if(interface)
      list(APPEND links ${interface})
    endif()
    foreach(link IN LISTS links)
      # $<BUILD_INTERFACE:x>, $<LINK_ONLY:x>, nested: the target inside. Other generator
      # expressions (install-only or conditional entries) name nothing built here.
      while(link MATCHES "^\\$<(BUILD_INTERFACE|LINK_ONLY):(.*)>$")
        set(link "${CMAKE_MATCH_2}")
      endwhile()
      if(NOT link MATCHES "^\\$<" AND TARGET "${link}")
        list(APPEND pending "${link}")
      endif()
    endforeach()
  endwhile()
endfunction()
