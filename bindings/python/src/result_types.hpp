// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Text for reprs and conversions shared by the result bindings (detection.cpp, kernel.cpp).

#include <string>

#include "clearjoint/geometry/model/certificate.hpp"
#include "clearjoint/geometry/arithmetic/vector3.hpp"
#include "enum_codes.hpp"  // every file that binds results converts their enums the same way

namespace clearjoint::python {

std::string repr_number(double x);              ///< round-trip precision
std::string repr_vector(const geometry::Vector3& v);
std::string repr_certificate(const geometry::Certificate& c);  ///< "uncertain (why)"

}  // namespace clearjoint::python
