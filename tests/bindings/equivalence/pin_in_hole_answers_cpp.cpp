// SPDX-License-Identifier: BSD-3-Clause
// The C++ API's answers for the pin-in-hole equivalence test (README.md):
// detect_pin_in_hole_contacts on every record. The reference the other languages' answers must
// equal byte for byte.
//
// usage: pin_in_hole_answers_cpp INPUT OUTPUT

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "clearjoint/clearjoint.h"  // CJ_INVALID_INPUT
#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"
#include "equivalence_line.hpp"

namespace {

namespace geo = clearjoint::geometry;
using clearjoint::equivalence::line_of;

constexpr std::size_t kRecord = 23;

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
  const std::size_t count = static_cast<std::size_t>(data[0]);
  std::FILE* out = std::fopen(argv[2], "w");
  if (out == nullptr) return 2;
  for (std::size_t i = 0; i < count; ++i) {
    const double* r = data.data() + (i + 1) * kRecord;
    geo::PinInHoleDimensions dims;
    dims.hole_radius = r[0];
    dims.hole_length = r[1];
    dims.pin_radius = r[2];
    dims.stop_count = static_cast<int>(r[3]);
    dims.stops[0] = {r[4], r[5]};
    dims.stops[1] = {r[6], r[7]};
    const geo::PartPose hole{{r[8], r[9], r[10]}, {r[11], r[12], r[13]}};
    const geo::PartPose pin{{r[14], r[15], r[16]}, {r[17], r[18], r[19]}};
    geo::DetectionOptions options;
    options.intersection.certify = r[20] != 0.0;
    options.parallel_angle_tolerance = r[21];
    options.intersection.exact_fallback = r[22] != 0.0;
    try {
      std::fprintf(out, "%s\n", line_of('S', i, geo::detect_pin_in_hole_contacts(dims, hole, pin, options)).c_str());
    } catch (const geo::InvalidInput& e) {
      std::fprintf(out, "S %zu error %d %s\n", i, static_cast<int>(CJ_INVALID_INPUT), e.what());
    }
  }
  return std::fclose(out) == 0 ? 0 : 2;
}
