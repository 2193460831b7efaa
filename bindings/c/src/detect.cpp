// SPDX-License-Identifier: BSD-3-Clause
// cj_detect: one detection through the C++ detect_contacts.
#include <new>
#include <type_traits>

#include "conversions.hpp"

using namespace clearjoint::c_api;

namespace {

/// One answer per thread, reused: the in-place overload writes only what the answer has, where a
/// fresh JointContacts would first write 1.4 KB of defaults (detect_contacts.hpp). Raw storage
/// with a flag, constructed on a thread's first call, rather than a `thread_local JointContacts`:
/// this is constant-initialised, so a call looks the thread's block up once and runs no guard
/// or initialisation function (JointContacts is trivially destructible: nothing to run at
/// thread exit).
struct Scratch {
  alignas(geo::JointContacts) unsigned char storage[sizeof(geo::JointContacts)];
  bool constructed = false;

  geo::JointContacts& answer() {
    if (!constructed) {
      ::new (storage) geo::JointContacts();
      constructed = true;
    }
    return *std::launder(reinterpret_cast<geo::JointContacts*>(storage));
  }
};
static_assert(std::is_trivially_destructible_v<geo::JointContacts>);

thread_local Scratch scratch;

}  // namespace

extern "C" cj_status cj_detect(const cj_dimensions* dimensions, const cj_pose* bearing,
                               const cj_pose* journal, const cj_options* options,
                               cj_result* result, char* message, size_t message_capacity) {
  return reporting_failures(message, message_capacity, [&] {
    require_not_null(dimensions, "dimensions", "the joint's dimensions");
    require_not_null(bearing, "bearing", "the bearing's pose");
    require_not_null(journal, "journal", "the journal's pose");
    require_not_null(result, "result", "a cj_result to fill");
    geo::JointContacts& found = scratch.answer();
    geo::detect_contacts(dimensions_of(*dimensions), pose_of(*bearing), pose_of(*journal), found,
                         detection_options_of(options));
    copy_result(found, *result);
  });
}
