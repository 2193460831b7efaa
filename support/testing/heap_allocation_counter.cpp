// SPDX-License-Identifier: BSD-3-Clause
#include "heap_allocation_counter.hpp"

#include <atomic>
#include <cstddef>
#include <cstdlib>

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define CLEARJOINT_TEST_UNDER_ASAN 1
#elif defined(__has_feature)  // Clang
#if __has_feature(address_sanitizer)
#define CLEARJOINT_TEST_UNDER_ASAN 1
#endif
#endif

#ifdef CLEARJOINT_TEST_UNDER_ASAN
#include <sanitizer/allocator_interface.h>
#endif

namespace {
std::atomic<long> allocations{0};
}  // namespace

#ifdef CLEARJOINT_TEST_UNDER_ASAN
namespace {
void count_allocation(const volatile void*, std::size_t) { allocations.fetch_add(1, std::memory_order_relaxed); }
void ignore_release(const volatile void*) {}
// Installed before main, so before any test runs (the runtime takes both hooks or none).
const bool hooks_installed = __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_release) != 0;
}  // namespace
#else
namespace {
constexpr bool hooks_installed = true;
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);

void* malloc(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(pointer, size);
}
}
#endif

namespace clearjoint::testing {

long heap_allocations() noexcept { return allocations.load(std::memory_order_relaxed); }

bool heap_allocations_are_counted() noexcept {
  if (!hooks_installed) return false;
  const long before = heap_allocations();
  // Through a volatile pointer, so that the compiler cannot omit the allocation and its release.
  void* volatile probe = std::malloc(64);
  std::free(probe);
  return heap_allocations() - before == 1;
}

}  // namespace clearjoint::testing
