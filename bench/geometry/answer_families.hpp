// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file
/// The inputs dump_answers prints answers for, in families, each drawn from its own fixed seed
/// (UniformSource), so that a family prints the same lines alone (`--family`) as in the whole
/// run, and the text is a function of the library build only.
///
/// Every input gives two lines, `<family> <input> <query>` followed by the answer
/// (answer_text.hpp), where the query is
///   detect               detect_contacts with the default options (certified), into a result
///                        reused from input to input as a simulation does;
///   detect_uncertified   detect_contacts with `.intersection.certify = false`, fresh result;
///   circle_cylinder      intersect_circle_cylinder;
///   circle_plane         intersect_circle_plane.
/// The detection families print `detect` and `detect_uncertified`, the random kernel family
/// `circle_cylinder` and `circle_plane` on one rim, the near-tangent family `circle_cylinder` on a
/// rim touching a wall and `detect` on the joint made of them.

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string_view>
#include <variant>

#include "clearjoint/geometry/model/joint_geometry.hpp"

namespace clearjoint::bench {

/// Random journal poses in a joint (the detection families). cr = Ri - Rj, ca = (Li - Lj) / 2.
struct JointPoses {
  geometry::JointDimensions dimensions;  ///< before scaling
  double offset_in_cr;  ///< journal centre off the bearing axis by up to this many cr
  double shift_in_ca;   ///< and along it by up to this many ca, either way
  double tilt_share;    ///< journal tilt up to this share of min(2 cr / Lj, 0.5) rad
  /// The joint rotated and translated by up to 1 (times `scale`) along each world axis, and 30 %
  /// of journal axes given length 1.7; otherwise the bearing sits at the origin along +z.
  bool moved_in_world;
  double scale;  ///< every length multiplied by this
};

/// Random rims, walls and planes at scales 2^-20..2^20 (the kernel family).
struct RandomRims {};

/// Rims of radius r in [0.2, 0.9] inside the unit wall about z, centred at 1 - r moved by -4..4
/// ulps (touching the wall to within rounding), a third of them untilted and the rest tilted by up
/// to 1e-3 rad; the joint Ri = 1, Li = 2, Rj = r, Lj = 1.8 of the same journal. These reach the
/// exact tier.
struct NearTangentRims {};

struct AnswerFamily {
  std::string_view name;
  std::string_view description;
  std::uint64_t seed;
  int input_count;
  std::variant<JointPoses, RandomRims, NearTangentRims> inputs;
};

/// Lines printed per input.
inline constexpr int kLinesPerInput = 2;

/// Every family, in print order.
std::span<const AnswerFamily> answer_families();

/// The family of that name, or nullptr.
const AnswerFamily* find_answer_family(std::string_view name);

/// Receives one line, without its newline.
using LineSink = std::function<void(std::string_view line)>;

/// Prints the answers to the family's first `input_limit` inputs (all of them by default), two
/// lines per input. The first n inputs are the same whatever the limit.
void print_family(const AnswerFamily& family, const LineSink& sink,
                  int input_limit = std::numeric_limits<int>::max());

}  // namespace clearjoint::bench
