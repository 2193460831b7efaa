// SPDX-License-Identifier: BSD-3-Clause
// The C++ API's answers for the equivalence test (README.md): detect_contacts on every record,
// one call each (the batch records in a plain loop). The reference the other languages' answers
// must equal byte for byte.
//
// usage: answers_cpp INPUT OUTPUT

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "clearjoint/clearjoint.h"  // the C codes the lines are written in
#include "clearjoint/geometry/detect_contacts.hpp"

namespace {

namespace geo = clearjoint::geometry;

constexpr std::size_t kRecord = 18;

std::string hex(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  char text[24];
  std::snprintf(text, sizeof text, " %016llX", static_cast<unsigned long long>(bits));
  return text;
}

std::string hex(const geo::Vector3& v) { return hex(v.x()) + hex(v.y()) + hex(v.z()); }

// The C API's codes, written out here from the header's enums rather than through the C
// library's own conversion, so that a wrong mapping there shows up as a difference.
int code(geo::ContactScenario s) {
  using S = geo::ContactScenario;
  switch (s) {
    case S::none: return CJ_SCENARIO_NONE;
    case S::single_radial: return CJ_SCENARIO_SINGLE_RADIAL;
    case S::single_axial: return CJ_SCENARIO_SINGLE_AXIAL;
    case S::radial_at_both_bases: return CJ_SCENARIO_RADIAL_AT_BOTH_BASES;
    case S::axial_at_both_bases: return CJ_SCENARIO_AXIAL_AT_BOTH_BASES;
    case S::radial_and_axial_same_base: return CJ_SCENARIO_RADIAL_AND_AXIAL_SAME_BASE;
    case S::radial_and_axial_opposite_bases: return CJ_SCENARIO_RADIAL_AND_AXIAL_OPPOSITE_BASES;
    case S::two_radial_one_axial: return CJ_SCENARIO_TWO_RADIAL_ONE_AXIAL;
    case S::one_radial_two_axial: return CJ_SCENARIO_ONE_RADIAL_TWO_AXIAL;
    case S::all_four: return CJ_SCENARIO_ALL_FOUR;
    case S::line: return CJ_SCENARIO_LINE;
    case S::face: return CJ_SCENARIO_FACE;
    case S::line_and_face: return CJ_SCENARIO_LINE_AND_FACE;
    case S::beyond_model: return CJ_SCENARIO_BEYOND_MODEL;
  }
  return -1;
}

int code(geo::Certainty c) {
  switch (c) {
    case geo::Certainty::exact: return CJ_CERTAINTY_EXACT;
    case geo::Certainty::certified: return CJ_CERTAINTY_CERTIFIED;
    case geo::Certainty::uncertain: return CJ_CERTAINTY_UNCERTAIN;
  }
  return -1;
}

int reason_code(const geo::Certificate& c) {
  using R = geo::CertificateReason;
  switch (c.reason) {
    case R::none: return CJ_REASON_NONE;
    case R::not_decided: return CJ_REASON_NOT_DECIDED;
    case R::certificate_switched_off: return CJ_REASON_CERTIFICATE_SWITCHED_OFF;
    case R::plane_filter_undecided: return CJ_REASON_PLANE_FILTER_UNDECIDED;
    case R::plane_filter_undecided_exact_fallback_off: return CJ_REASON_PLANE_FILTER_UNDECIDED_EXACT_FALLBACK_OFF;
    case R::plane_results_not_representable: return CJ_REASON_PLANE_RESULTS_NOT_REPRESENTABLE;
    case R::subdivision_budget_exhausted: return CJ_REASON_SUBDIVISION_BUDGET_EXHAUSTED;
    case R::more_than_four_roots: return CJ_REASON_MORE_THAN_FOUR_ROOTS;
    case R::interval_proof_failed_near_multiple_root: return CJ_REASON_INTERVAL_PROOF_FAILED_NEAR_MULTIPLE_ROOT;
    case R::coefficient_overflow: return CJ_REASON_COEFFICIENT_OVERFLOW;
    case R::cylinder_points_not_representable: return CJ_REASON_CYLINDER_POINTS_NOT_REPRESENTABLE;
    case R::exact_root_isolation_budget_exhausted: return CJ_REASON_EXACT_ROOT_ISOLATION_BUDGET_EXHAUSTED;
    case R::exact_coefficients_too_large: return CJ_REASON_EXACT_COEFFICIENTS_TOO_LARGE;
    case R::exact_intermediate_beyond_double_range: return CJ_REASON_EXACT_INTERMEDIATE_BEYOND_DOUBLE_RANGE;
    case R::contact_not_representable_in_world: return CJ_REASON_CONTACT_NOT_REPRESENTABLE_IN_WORLD;
    case R::axes_parallel_within_tolerance: return CJ_REASON_AXES_PARALLEL_WITHIN_TOLERANCE;
    case R::beyond_model_undecided: return CJ_REASON_BEYOND_MODEL_UNDECIDED;
  }
  return -1;
}

int code(geo::ContactType t) { return t == geo::ContactType::radial ? CJ_CONTACT_RADIAL : CJ_CONTACT_AXIAL; }

int code(geo::ContactBase b) {
  switch (b) {
    case geo::ContactBase::a: return CJ_BASE_A;
    case geo::ContactBase::b: return CJ_BASE_B;
    case geo::ContactBase::mid: return CJ_BASE_MID;
  }
  return -1;
}

std::string line_of(char tag, std::size_t index, const geo::JointContacts& r) {
  const bool text = tag == 'S';
  std::string line = std::string(1, tag) + ' ' + std::to_string(index) + " ok " + std::to_string(code(r.scenario)) +
                     ' ' + std::to_string(r.aligned ? 1 : 0) + ' ' + std::to_string(code(r.certificate.level)) +
                     ' ' + std::to_string(reason_code(r.certificate));
  if (text) line += " \"" + std::string(r.certificate.reason_text()) + '"';
  line += ' ' + std::to_string(r.contact_count);
  for (int k = 0; k < r.contact_count; ++k) {
    const geo::Contact& c = r.contacts[k];
    line += " | " + std::to_string(code(c.type)) + ' ' + std::to_string(code(c.base)) + hex(c.depth) + hex(c.p_WCj) +
            hex(c.p_WCi) + hex(c.normal_W) + hex(c.depth_error) + hex(c.p_WCj_error) + hex(c.p_WCi_error) + ' ' +
            std::to_string(c.crossing_count);
    for (int m = 0; m < c.crossing_count; ++m) {
      const geo::RimCrossing& x = c.crossings[m];
      line += hex(x.angle) + hex(x.angle_error) + hex(x.point) + hex(x.point_error) + ' ' +
              std::to_string(x.multiplicity);
    }
    line += ' ' + std::to_string(code(c.certificate.level)) + ' ' + std::to_string(reason_code(c.certificate));
    if (text) line += " \"" + std::string(c.certificate.reason_text()) + '"';
  }
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s INPUT OUTPUT\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<double> data(bytes.size() / sizeof(double));
  std::memcpy(data.data(), bytes.data(), data.size() * sizeof(double));
  if (data.size() < kRecord) {
    std::fprintf(stderr, "%s: cannot read %s\n", argv[0], argv[1]);
    return 2;
  }
  const std::size_t count = static_cast<std::size_t>(data[0]), singles = static_cast<std::size_t>(data[1]);
  std::FILE* out = std::fopen(argv[2], "w");
  if (out == nullptr) return 2;
  for (std::size_t i = 0; i < count; ++i) {
    const double* r = data.data() + (i + 1) * kRecord;
    const geo::JointDimensions dims{r[0], r[1], r[2], r[3]};
    const geo::PartPose bearing{{r[4], r[5], r[6]}, {r[7], r[8], r[9]}};
    const geo::PartPose journal{{r[10], r[11], r[12]}, {r[13], r[14], r[15]}};
    geo::DetectionOptions options;
    options.intersection.certify = r[16] != 0.0;
    options.parallel_angle_tolerance = r[17];
    const char tag = i < singles ? 'S' : 'B';
    try {
      std::fprintf(out, "%s\n", line_of(tag, i, geo::detect_contacts(dims, bearing, journal, options)).c_str());
    } catch (const geo::InvalidInput& e) {
      std::fprintf(out, "%c %zu error %d %s\n", tag, i, static_cast<int>(CJ_INVALID_INPUT), e.what());
    }
  }
  return std::fclose(out) == 0 ? 0 : 2;
}
