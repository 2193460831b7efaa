// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// One answer of the geometry kernel as text, every field of it: doubles in C's `%a` (hexadecimal,
/// the exact bits; `-0x0p+0`, `inf` and `nan` included), integers and enums in decimal,
/// certificates as their level and reason. Two builds that print the same text gave the same
/// answers bit for bit. dump_answers prints one answer a line (docs/verifying-refactors.md).
///
/// Fields are separated by one space. Only the counted entries are printed
/// (contacts[0, contact_count), crossings[0, crossing_count), penetration_arcs[0, arc_count)):
/// the API leaves the others unspecified (a reused JointContacts keeps old contacts past the
/// count). Integer fields carry a short tag glued to the number (`n2` is a count of 2):
///
///   certificate   c<level> "<reason>"      level: Certainty (0 exact, 1 certified, 2 uncertain);
///                                          the reason is the only field with spaces in it
///   crossing      x <angle> <angle_error> <point x y z> <point_error> m<multiplicity>
///   arc           arc <begin> <end> f<full>
///
///   JointContacts               s<scenario> al<aligned> n<contact_count> <certificate>
///                               and per contact:
///                               | t<type> b<base> <p_WCj x y z> <p_WCi x y z> <normal_W x y z>
///                                 <depth> e <p_WCj_error> <p_WCi_error> <depth_error>
///                                 nc<crossing_count> <crossing>... <certificate>
///                               (the `e` group only from the revision that added the bounds)
///   CircleCylinderIntersection  t<topology> n<crossing_count> a<arc_count> <certificate>
///                               <crossing>... <arc>...
///   CirclePlaneIntersection     t<topology> s<side> n<crossing_count> <certificate>
///                               pen<has_penetration> <arc: penetration>
///                               msd <max_signed_distance> <max_signed_distance_error>
///                               <crossing>...
///   a query that threw          threw <what()>   (the rest of the line)

#include <exception>
#include <string>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/queries/intersect_circle_cylinder.hpp"
#include "clearjoint/geometry/queries/intersect_circle_plane.hpp"

namespace clearjoint::bench {

/// Appends a space, then every field of `answer` in the grammar above.
void append_answer(std::string& line, const geometry::JointContacts& answer);
void append_answer(std::string& line, const geometry::CircleCylinderIntersection& answer);
void append_answer(std::string& line, const geometry::CirclePlaneIntersection& answer);
/// Appends " threw " and the exception's message, for a query that threw instead of answering.
void append_exception(std::string& line, const std::exception& error);

}  // namespace clearjoint::bench
