// SPDX-License-Identifier: BSD-3-Clause
#include "clearjoint/geometry/model/certificate.hpp"

namespace clearjoint::geometry {

std::string_view to_string(Certainty level) noexcept { return key_of(level); }

std::string_view to_string(CertificateReason reason) noexcept { return label_of(reason); }

std::string_view Certificate::reason_text() const noexcept { return label_of(reason); }

}  // namespace clearjoint::geometry
