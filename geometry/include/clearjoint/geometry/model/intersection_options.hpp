// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// Switches shared by the intersection queries.

namespace clearjoint::geometry {

struct IntersectionOptions {
  /// Prove every answer (topology, root counts, enclosures). Off: plain double-precision
  /// pipeline, every answer `uncertain` with reason "certificate switched off".
  bool certify = true;
  /// When the floating-point proof fails (near tangency), decide with exact rational
  /// arithmetic. Off: such answers come back `uncertain` with the reason.
  bool exact_fallback = true;
};

}  // namespace clearjoint::geometry
