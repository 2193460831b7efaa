#pragma once
/// \file
/// The one vector type of the public API: three doubles, world frame unless a name says otherwise.

#include <Eigen/Core>

namespace clearjoint::geometry {

using Vector3 = Eigen::Vector3d;

}  // namespace clearjoint::geometry
