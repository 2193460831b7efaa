// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A batch split into chunks of consecutive rows, handed out in increasing order to a few threads.
// Results are written per row or per chunk, so they do not depend on the thread count.
// Hand-written rather than a library pool: std::thread is all it needs, and Debian's TBB or
// OpenMP would add a runtime dependency to the module for one loop.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace clearjoint::python {

/// Rows per chunk: about eight chunks per thread (balance: a pose in contact costs several times
/// a free one), at least 64 rows (a chunk must outweigh its hand-out), at most 4096.
inline std::size_t chunk_rows(std::size_t rows, unsigned threads) {
  return std::clamp<std::size_t>(rows / (8 * std::size_t{threads}), 64, 4096);
}

/// Call body(chunk, begin, end) for every chunk [begin, end) of [0, rows), on up to `threads`
/// threads (the caller's among them). `stop` set by a body hands out no further chunks; every
/// chunk already handed out, which includes every chunk before the one that set it, is finished.
/// The body must not throw.
template <typename Body>
void for_each_chunk(std::size_t rows, std::size_t chunk, unsigned threads, std::atomic<bool>& stop,
                    const Body& body) {
  const std::size_t chunks = (rows + chunk - 1) / chunk;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    while (!stop.load(std::memory_order_relaxed)) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks) return;
      body(c, c * chunk, std::min(rows, (c + 1) * chunk));
    }
  };
  const std::size_t helpers = std::min<std::size_t>(threads, chunks) - (chunks > 0 ? 1 : 0);
  std::vector<std::jthread> pool;
  pool.reserve(helpers);
  for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(work);
  work();
}  // the jthreads join here

}  // namespace clearjoint::python
