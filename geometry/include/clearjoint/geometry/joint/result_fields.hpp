// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Every public result with its field list. Each list is written right after its struct (as an
/// enum's table after its enum): one line per field, in the order the outputs write the fields,
/// with the key each front-end spells it by and a doc. A field is added to a result by one edit
/// in one file: its member and its line, side by side.
///
/// The command line's JSON and Python's result dicts and attributes are written (and read back)
/// through visit_fields; the stubs are generated from the lists (scripts/projections); the
/// front-ends that cannot be (the C structs, the equivalence writers, the answer dumps of
/// bench/geometry) are checked against them by tests that change one field at a time and require
/// the output to change.
///
/// The lists are checked by the compiler: a static_assert after each counts its struct's members,
/// so a member added without its line does not build.
///
/// The kinds of field a visitor sees, and visit_fields itself: model/field_lists.hpp.

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/model/field_lists.hpp"
#include "clearjoint/geometry/model/rim_arc.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"
