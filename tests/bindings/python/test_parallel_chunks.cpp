// SPDX-License-Identifier: BSD-3-Clause
// The Python package's batch runner (bindings/python/src/parallel_chunks.hpp) from C++, where
// ThreadSanitizer can watch it (scripts/run-sanitizers.sh, lane tsan): every chunk done once,
// the first failure reported, no more threads than cores, and a batch detection spread over
// threads giving the answers of one thread.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "parallel_chunks.hpp"
#include "tilted_journal_scenarios.hpp"

namespace {

using clearjoint::python::available_cores;
using clearjoint::python::for_each_chunk;
namespace geo = clearjoint::geometry;

#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer) || __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

TEST(ForEachChunk, RunsEveryChunkExactlyOnceWhateverTheThreadCount) {
  constexpr std::size_t kRows = 10000, kChunk = 64;  // 157 chunks, the last one short
  for (unsigned threads : {1u, 2u, 3u, 16u, 1024u}) {
    std::vector<std::atomic<int>> visits(kRows);
    for_each_chunk(kRows, kChunk, threads, [&](std::size_t c, std::size_t begin, std::size_t end) {
      EXPECT_EQ(begin, c * kChunk);
      for (std::size_t n = begin; n < end; ++n) ++visits[n];
    });
    for (std::size_t n = 0; n < kRows; ++n) ASSERT_EQ(visits[n].load(), 1) << "row " << n << ", threads " << threads;
  }
}

TEST(ForEachChunk, StartsNoMoreThreadsThanTheProcessHasCores) {
  // 64 threads asked for, 512 chunks of a few hundred microseconds: every thread started would
  // get chunks. The threads seen are the caller's and the helpers it started.
  std::mutex mutex;
  std::set<std::thread::id> seen;
  for_each_chunk(512, 1, 64, [&](std::size_t, std::size_t, std::size_t) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      seen.insert(std::this_thread::get_id());
    }
    volatile double sink = 0;
    for (int k = 0; k < 100000; ++k) sink = sink + std::sqrt(static_cast<double>(k));
  });
  EXPECT_GE(seen.size(), 1u);
  EXPECT_LE(seen.size(), available_cores());
}

TEST(ForEachChunk, StartsNoMoreThreadsThanThereAreChunks) {
  std::mutex mutex;
  std::set<std::thread::id> seen;
  for_each_chunk(1, 1, 16, [&](std::size_t, std::size_t, std::size_t) {
    const std::lock_guard<std::mutex> lock(mutex);
    seen.insert(std::this_thread::get_id());
  });
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(*seen.begin(), std::this_thread::get_id());  // the caller's: nothing else was started
}

TEST(ForEachChunk, RethrowsTheEarliestFailedChunksErrorWhateverTheThreadCount) {
  for (unsigned threads : {1u, 2u, 4u}) {
    try {
      for_each_chunk(4000, 10, threads, [](std::size_t c, std::size_t, std::size_t) {
        if (c == 37 || c == 250) throw std::runtime_error("chunk " + std::to_string(c));
      });
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "chunk 37") << threads << " threads";
    }
  }
}

TEST(ForEachChunkDeathTest, DoesEveryChunkOnTheCallerWhenNoThreadCanBeStarted) {
  if (kSanitized) GTEST_SKIP() << "a sanitizer's runtime maps memory of its own under the limit";
  // In a child: an address-space limit 4 MB above what the process holds leaves no room for a
  // thread's stack (8 MB by default), so std::thread's constructor fails (std::system_error).
  EXPECT_EXIT(
      {
        rlimit limit{};
        getrlimit(RLIMIT_AS, &limit);
        std::size_t held = 0;
        if (FILE* status = std::fopen("/proc/self/status", "r")) {
          char line[256];
          while (std::fgets(line, sizeof line, status)) {
            if (std::sscanf(line, "VmSize: %zu kB", &held) == 1) break;
          }
          std::fclose(status);
        }
        limit.rlim_cur = (held + 4096) * 1024;
        setrlimit(RLIMIT_AS, &limit);
        std::atomic<std::size_t> rows_done{0};
        std::atomic<bool> elsewhere{false};
        const std::thread::id caller = std::this_thread::get_id();
        for_each_chunk(1000, 10, 8, [&](std::size_t, std::size_t begin, std::size_t end) {
          rows_done += end - begin;
          if (std::this_thread::get_id() != caller) elsewhere = true;
        });
        std::exit(rows_done == 1000 && !elsewhere ? 0 : 1);
      },
      testing::ExitedWithCode(0), "");
}

/// A journal of Table 2 (mm) for row n: free, sliding on the wall, tilted into rim contacts and
/// into a base, and near-tangent tilts that the exact tier decides (GMP, CGAL, MPFR: libraries
/// with thread-local state of their own).
geo::PartPose journal_pose(std::size_t n) {
  const double tilt[] = {0.0, 0.005, 0.013, 1e-140};
  const double y0[] = {0.0, 0.1, 0.05, 0.1};
  const double z0[] = {0.0, 0.0, 0.02, 0.1};
  return geo::testing::TiltedJournal{y0[n % 4], z0[(n / 4) % 4], tilt[(n / 16) % 4]}.pose();
}

void expect_same_answer(const geo::JointContacts& a, const geo::JointContacts& b, std::size_t row) {
  ASSERT_EQ(a.scenario, b.scenario) << "row " << row;
  ASSERT_EQ(a.certificate.level, b.certificate.level) << "row " << row;
  ASSERT_EQ(a.contact_count, b.contact_count) << "row " << row;
  for (int k = 0; k < a.contact_count; ++k) {
    EXPECT_EQ(a.contacts[k].depth, b.contacts[k].depth) << "row " << row << ", contact " << k;
    EXPECT_EQ(a.contacts[k].p_WCj, b.contacts[k].p_WCj) << "row " << row << ", contact " << k;
    EXPECT_EQ(a.contacts[k].normal_W, b.contacts[k].normal_W) << "row " << row << ", contact " << k;
  }
}

TEST(ForEachChunk, DetectsABatchOnSeveralThreadsAsOneThreadDoes) {
  // What clearjoint.detect's batch does (detection_batch.cpp): each chunk detects its rows into
  // one reused answer, writes its rows, and appends its contacts to the chunk's own list.
  constexpr std::size_t kRows = 640, kChunk = 16;
  const geo::JointDimensions dims = geo::testing::kTable2;
  const geo::PartPose bearing = geo::testing::bearing_on_z();
  std::vector<geo::JointContacts> alone(kRows);
  for (std::size_t n = 0; n < kRows; ++n) geo::detect_contacts(dims, bearing, journal_pose(n), alone[n]);

  for (unsigned threads : {2u, 4u}) {
    std::vector<geo::JointContacts> rows(kRows);
    std::vector<std::vector<geo::Contact>> lists(kRows / kChunk);
    std::atomic<bool> interrupted{false};
    for_each_chunk(kRows, kChunk, threads, interrupted, [] {}, [&](std::size_t c, std::size_t begin, std::size_t end) {
      geo::JointContacts result;
      for (std::size_t n = begin; n < end; ++n) {
        geo::detect_contacts(dims, bearing, journal_pose(n), result);
        rows[n] = result;
        lists[c].insert(lists[c].end(), result.contacts.begin(), result.contacts.begin() + result.contact_count);
      }
    });
    std::size_t listed = 0, expected = 0;
    for (std::size_t n = 0; n < kRows; ++n) {
      expect_same_answer(rows[n], alone[n], n);
      expected += static_cast<std::size_t>(alone[n].contact_count);
    }
    for (const auto& list : lists) listed += list.size();
    EXPECT_EQ(listed, expected) << threads << " threads";
    EXPECT_GT(expected, 0u);
  }
}

}  // namespace
