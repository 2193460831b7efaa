// SPDX-License-Identifier: BSD-3-Clause
// The field lists are header-only; compiling them here makes the library's own build check them
// (result_fields.hpp's static_asserts: every member of every public result is listed), not only
// the front-ends that include them.
#include "clearjoint/geometry/joint/result_fields.hpp"
