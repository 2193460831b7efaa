// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Simbody's headers, made to compile as C++20. Include this instead of SimTKsimbody.h.
///
/// Why: Simbody 3.7's index types (SimTK_DEFINE_UNIQUE_INDEX_TYPE) compare with an int through
/// members operator==(int), operator==(short), ... and convert to int. C++20 also considers each
/// member with its operands reversed, so `a == b` between two indices has two equally good
/// candidates and GCC 12 rejects it (in inline code of simmath's ContactGeometry.h, and in
/// std::pair's comparison of State's cache keys). The macro is redefined here, right after
/// SimTKcommon/internal/common.h defines it and before any index type is declared, to add an
/// exact-match operator== and operator!= beside each such type: the same comparison of the int
/// values, now unambiguous. The classes themselves are unchanged.

#include "SimTKcommon/internal/common.h"

#undef SimTK_DEFINE_UNIQUE_INDEX_TYPE
#define SimTK_DEFINE_UNIQUE_INDEX_TYPE(NAME)                                             \
  SimTK_DEFINE_AND_EXPORT_UNIQUE_LOCAL_INDEX_TYPE(, , , NAME)                            \
  static const NAME Invalid##NAME;                                                       \
  inline bool operator==(const NAME& a, const NAME& b) { return int(a) == int(b); }      \
  inline bool operator!=(const NAME& a, const NAME& b) { return int(a) != int(b); }

#include "SimTKsimbody.h"
