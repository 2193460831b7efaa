// SPDX-License-Identifier: BSD-3-Clause
// The C++ API's answers for the equivalence test (README.md): detect_contacts on every record,
// one call each (the batch records in a plain loop). The reference the other languages' answers
// must equal byte for byte.
//
// usage: answers_cpp INPUT OUTPUT

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "clearjoint/clearjoint.h"  // CJ_INVALID_INPUT
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "equivalence_line.hpp"

namespace {

namespace geo = clearjoint::geometry;
using clearjoint::equivalence::line_of;

constexpr std::size_t kRecord = 19;

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
    options.intersection.exact_fallback = r[18] != 0.0;
    const char tag = i < singles ? 'S' : 'B';
    try {
      std::fprintf(out, "%s\n", line_of(tag, i, geo::detect_contacts(dims, bearing, journal, options)).c_str());
    } catch (const geo::InvalidInput& e) {
      std::fprintf(out, "%c %zu error %d %s\n", tag, i, static_cast<int>(CJ_INVALID_INPUT), e.what());
    }
  }
  return std::fclose(out) == 0 ? 0 : 2;
}
