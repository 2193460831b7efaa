// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/version.hpp"

namespace clearjoint {

// Compiled into the library (not inline), so that it reports the library's version, not the
// version of the headers the caller was compiled with.
const char* version_string() noexcept { return CLEARJOINT_VERSION_STRING; }

}  // namespace clearjoint
