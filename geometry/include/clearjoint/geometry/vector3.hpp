// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Forwarding header, kept for one release: the header is clearjoint/geometry/arithmetic/vector3.hpp
/// (docs/architecture.md, "Public headers of the kernel").
#include "clearjoint/geometry/arithmetic/vector3.hpp"
