// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Counts every heap allocation of the test program that links clearjoint_heap_allocation_counter
// (an object library: its malloc must be in the program itself). It replaces malloc, calloc and
// realloc by counting wrappers around glibc's own (__libc_malloc etc.); operator new, Eigen's
// dynamic storage and GMP's default allocator all end in malloc. Under AddressSanitizer
// (scripts/run-sanitizers.sh) malloc belongs to the sanitizer's runtime, which aborts at start-up
// when a program replaces it; there the sanitizer's allocation hook, which every malloc, calloc,
// realloc and operator new of its allocator calls, counts instead.

namespace clearjoint::testing {

/// Heap allocations since the program started.
long heap_allocations() noexcept;

/// True when one allocation made now is counted once: false when the sanitizer refused its hook,
/// or when the program was linked without this counter's malloc.
bool heap_allocations_are_counted() noexcept;

}  // namespace clearjoint::testing
