// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The one vector type of the public API: three doubles, world frame unless a name says otherwise.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace clearjoint::geometry {

using Vector3 = Eigen::Vector3d;

}  // namespace clearjoint::geometry
