// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Forwarding header, kept for one release: the header is clearjoint/geometry/model/option_fields.hpp
/// (docs/architecture.md, "Public headers of the kernel").
#include "clearjoint/geometry/model/option_fields.hpp"
