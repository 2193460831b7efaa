// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Three coordinates of any number type: the vectors of the predicates written once over the
// number type (plane_terms.hpp), whose instances run on Bounded, on a value and its twin
// (twinned.hpp) and on CGAL's rationals. Eigen's Matrix would need NumTraits for each of them and
// brings expression templates the predicates do not want (each operation must round where it is
// written).

namespace clearjoint::geometry::detail {

template <class T>
struct Vector3Of {
  T x, y, z;
};

}  // namespace clearjoint::geometry::detail
