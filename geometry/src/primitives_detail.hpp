#pragma once
#include "clearjoint/geometry/primitives.hpp"

namespace clearjoint::geometry {
/// Index k of the smallest |normal_k| (first on ties): the frame uses u' = normal x e_k.
int frame_axis_index(const Vector3& normal);
}  // namespace clearjoint::geometry
