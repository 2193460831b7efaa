// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A batch split into chunks of consecutive rows, handed out in increasing order to a few threads.
// Results are written per row or per chunk, so they do not depend on the thread count.
// Hand-written rather than a library pool: std::thread is all it needs, and Debian's TBB or
// OpenMP would add a runtime dependency to the module for one loop.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace clearjoint::python {

/// Rows per chunk: about eight chunks per thread (balance: a pose in contact costs several times
/// a free one), at least 64 rows (a chunk must outweigh its hand-out), at most 512: the calling
/// thread looks for Ctrl-C between its chunks, and 512 rows at the exact tier's tens of
/// microseconds a pose still end within a few tenths of a second on a loaded machine (4096 took
/// 2.8 s there).
inline std::size_t chunk_rows(std::size_t rows, unsigned threads) {
  return std::clamp<std::size_t>(rows / (8 * std::size_t{threads}), 64, 512);
}

/// Call body(chunk, begin, end) for every chunk [begin, end) of [0, rows), on up to `threads`
/// threads (the caller's among them; fewer when the system refuses to start more).
///
/// A body that throws stops the hand-out: the chunks already handed out, which include every
/// chunk before the failed one, finish, and once every thread is done the exception of the
/// earliest failed chunk is rethrown in the caller. So the first bad row of a batch is reported
/// whatever the thread count, and a failure in a worker (std::bad_alloc) reaches the caller
/// instead of std::terminate.
///
/// Between its chunks the calling thread calls `poll()` (which may look for Ctrl-C). When poll
/// throws, `abandon` is set, no chunk is handed out any more, bodies that watch `abandon` stop
/// within a row, and poll's exception is rethrown once every thread is done.
template <typename Body, typename Poll>
void for_each_chunk(std::size_t rows, std::size_t chunk, unsigned threads, std::atomic<bool>& abandon,
                    Poll&& poll, const Body& body) {
  const std::size_t chunks = (rows + chunk - 1) / chunk;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::vector<std::exception_ptr> failures(chunks);  // one slot per chunk: no two writers
  auto run = [&](std::size_t c) {
    try {
      body(c, c * chunk, std::min(rows, (c + 1) * chunk));
    } catch (...) {
      failures[c] = std::current_exception();
      stop = true;
    }
  };
  auto work = [&] {
    while (!stop.load(std::memory_order_relaxed)) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks) return;
      run(c);
    }
  };
  std::exception_ptr interrupt;
  {
    const std::size_t helpers = std::min<std::size_t>(threads, chunks) - (chunks > 0 ? 1 : 0);
    std::vector<std::jthread> pool;
    pool.reserve(helpers);
    for (std::size_t t = 0; t < helpers; ++t) {
      try {
        pool.emplace_back(work);
      } catch (const std::exception&) {
        break;  // no more threads to be had (std::system_error): the ones running do the work
      }
    }
    while (!stop.load(std::memory_order_relaxed)) {
      try {
        poll();
      } catch (...) {
        interrupt = std::current_exception();
        abandon = true;
        stop = true;
        break;
      }
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks) break;
      run(c);
    }
  }  // the jthreads join here
  if (interrupt) std::rethrow_exception(interrupt);
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

/// for_each_chunk without a poll, for work too short to be worth interrupting.
template <typename Body>
void for_each_chunk(std::size_t rows, std::size_t chunk, unsigned threads, const Body& body) {
  std::atomic<bool> abandon{false};
  for_each_chunk(rows, chunk, threads, abandon, [] {}, body);
}

}  // namespace clearjoint::python
