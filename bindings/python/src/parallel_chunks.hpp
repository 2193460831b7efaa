// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A batch split into chunks of consecutive rows, handed out in increasing order to a few threads.
// Results are written per row or per chunk, so they do not depend on the thread count.
// Hand-written rather than a library pool: std::thread is all it needs, and Debian's TBB or
// OpenMP would add a runtime dependency to the module for one loop.
//
// Threads are a cost under memory pressure, not only a speed-up: each one reserves a stack
// (RLIMIT_STACK, 8 MB by default), on its first allocation its own malloc arena (64 MB of address
// space), and the thread-local storage of the libraries loaded with the module (CGAL's, MPFR's,
// libstdc++'s). glibc cannot report a failure of that last allocation: it ends the process
// ("cannot allocate memory for thread-local data: ABORT", exit status 127). Under an address-space
// limit (ulimit -v) sixteen threads on a two-core machine made that happen; so no more threads
// are started than the process has cores and the batch has chunks, and a thread the system
// refuses to start (std::system_error) leaves its share to the threads that did start. Stacks
// keep their default size: they are reserved, not committed, and the cap bounds their number.

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace clearjoint::python {

/// The cores this process may run on: the size of its affinity mask (what taskset, a cgroup
/// cpuset or a batch scheduler allots), else what std::thread::hardware_concurrency reports;
/// at least 1. Threads beyond it add no speed, only the memory each thread costs.
inline unsigned available_cores() {
#ifdef CPU_COUNT
  cpu_set_t cores;
  if (sched_getaffinity(0, sizeof cores, &cores) == 0 && CPU_COUNT(&cores) > 0) {
    return static_cast<unsigned>(CPU_COUNT(&cores));
  }
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

/// The threads a batch runs on, the caller's among them: the caller's limit, capped at the
/// available cores and at the number of chunks (a thread without a chunk would only cost its
/// memory); at least 1.
inline unsigned worker_count(unsigned threads, std::size_t chunks) {
  const std::size_t workers = std::min<std::size_t>({threads, available_cores(), chunks});
  return static_cast<unsigned>(std::max<std::size_t>(workers, 1));
}

/// Rows per chunk: about eight chunks per thread (balance: a pose in contact costs several times
/// a free one), at least 64 rows (a chunk must outweigh its hand-out), at most 512: the calling
/// thread looks for Ctrl-C between its chunks, and 512 rows at the exact tier's tens of
/// microseconds a pose still end within a few tenths of a second on a loaded machine (4096 took
/// 2.8 s there).
inline std::size_t chunk_rows(std::size_t rows, unsigned threads) {
  const std::size_t workers = std::max(1u, std::min(threads, available_cores()));
  return std::clamp<std::size_t>(rows / (8 * workers), 64, 512);
}

/// Call body(chunk, begin, end) for every chunk [begin, end) of [0, rows), on up to
/// worker_count(threads, chunks) threads (the caller's among them; fewer when the system refuses
/// to start more: then the threads that started, or the caller alone, do every chunk).
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
    const std::size_t helpers = worker_count(threads, chunks) - 1;
    std::vector<std::jthread> pool;
    try {
      pool.reserve(helpers);
      for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(work);
    } catch (const std::exception&) {
      // No more threads to be had (std::system_error: EAGAIN when their stacks or thread
      // descriptors cannot be mapped) or no memory for the list (std::bad_alloc): the threads
      // that started and the caller do the work.
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
