// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A detection batch's answers packed into NumPy arrays, for every joint whose answer is a list of
// Contacts (JointContacts, PinInHoleContacts): the poses spread over threads without the GIL,
// Ctrl-C looked for, and the arrays clearjoint.DetectionBatch and clearjoint.PinInHoleBatch wrap.
//
// Layout. Per pose, arrays of shape (N,). The contacts of all poses are packed one after
// another in pose order, arrays of shape (M, ...), M the total count; pose n owns the rows
// contact_start[n] to contact_start[n + 1]. A (N, 6, ...) layout padded to kMaxContacts would
// write ~1 KB per pose, as much time as the detection itself on realistic poses, where about
// half the poses touch at one or two points.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "array_block.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"  // Contact
#include "numpy_views.hpp"
#include "parallel_chunks.hpp"
#include "signal_check.hpp"

namespace clearjoint::python {

namespace geo = clearjoint::geometry;
namespace py = pybind11;

/// Per-pose outputs in one block, written by the workers through raw pointers (disjoint rows).
struct PoseColumns {
  ArrayBlock block;
  std::size_t scenario, certificate, reason, contact_count, aligned;
  std::int8_t* scenario_out;
  std::int8_t* certificate_out;
  std::int8_t* reason_out;
  std::int8_t* count_out;
  bool* aligned_out;

  explicit PoseColumns(std::size_t rows) {
    const auto n = static_cast<py::ssize_t>(rows);
    scenario = block.plan<std::int8_t>({n});
    aligned = block.plan<bool>({n});
    certificate = block.plan<std::int8_t>({n});
    reason = block.plan<std::int8_t>({n});
    contact_count = block.plan<std::int8_t>({n});
    block.allocate();
    scenario_out = block.data<std::int8_t>(scenario);
    certificate_out = block.data<std::int8_t>(certificate);
    reason_out = block.data<std::int8_t>(reason);
    count_out = block.data<std::int8_t>(contact_count);
    aligned_out = block.data<bool>(aligned);
  }

  /// Row n of a JointContacts or a PinInHoleContacts (the members they share).
  template <class Result>
  void write(std::size_t n, const Result& r) const {
    scenario_out[n] = static_cast<std::int8_t>(r.scenario);
    certificate_out[n] = static_cast<std::int8_t>(r.certificate.level);
    reason_out[n] = static_cast<std::int8_t>(r.certificate.reason);
    count_out[n] = static_cast<std::int8_t>(r.contact_count);
    aligned_out[n] = r.aligned;
  }

  void put(py::dict& out) const {
    out["scenario"] = block.array<std::int8_t>(scenario);
    out["aligned"] = block.array<bool>(aligned);
    out["certificate"] = block.array<std::int8_t>(certificate);
    out["certificate_reason"] = block.array<std::int8_t>(reason);
    out["contact_count"] = block.array<std::int8_t>(contact_count);
  }
};

/// The packed contact arrays, in one block, filled after the workers from their per-chunk lists:
/// chunk by chunk on up to `threads` threads without the GIL (a serial copy would bound the
/// speed-up of a batch on several threads). `chunk` is the detection's rows per chunk.
void put_contact_columns(const std::vector<std::vector<geo::Contact>>& chunk_contacts,
                         const PoseColumns& columns, std::size_t rows, std::size_t chunk,
                         unsigned threads, py::dict& out);

/// The per-chunk contact lists, kept from one batch to the next: a batch of 100,000 realistic
/// poses fills ~15 MB of them, and taking fresh memory for them on every call cost more in page
/// faults than the copying (perf: a third of a batch's time in the kernel). Concurrent batches
/// (several Python threads) take fresh lists; the kept ones are at most one batch's worth.
class ContactListCache {
 public:
  std::vector<std::vector<geo::Contact>> take(std::size_t chunks) {
    std::vector<std::vector<geo::Contact>> lists;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      lists.swap(kept_);
    }
    for (auto& list : lists) list.clear();
    lists.resize(chunks);
    return lists;
  }
  void give_back(std::vector<std::vector<geo::Contact>>&& lists) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (lists.size() > kept_.size()) kept_.swap(lists);
  }

 private:
  std::mutex mutex_;
  std::vector<std::vector<geo::Contact>> kept_;
};

ContactListCache& contact_list_cache();

/// The packed arrays of `rows` poses (a dict of arrays by the names of DetectionBatch's fields),
/// `detect(n, result)` answering pose n into `result` (a Result: JointContacts or
/// PinInHoleContacts), on up to `threads` threads without the GIL. A bad pose throws RowError,
/// the first bad row of the batch whatever the thread count (chunks are handed out in order and
/// finished once begun), for the caller to name after its arguments; Ctrl-C raises
/// KeyboardInterrupt within about 50 ms (SignalCheck) and a chunk of rows.
template <class Result, class Detect>
py::dict packed_contacts(std::size_t rows, unsigned threads, const Detect& detect) {
  PoseColumns columns(rows);
  const std::size_t chunk = chunk_rows(rows, threads);
  const std::size_t chunks = (rows + chunk - 1) / chunk;
  std::vector<std::vector<geo::Contact>> chunk_contacts = contact_list_cache().take(chunks);
  struct GiveBack {
    std::vector<std::vector<geo::Contact>>& lists;
    ~GiveBack() { contact_list_cache().give_back(std::move(lists)); }
  } give_back{chunk_contacts};
  {
    py::gil_scoped_release release;
    std::atomic<bool> interrupted{false};
    for_each_chunk(rows, chunk, threads, interrupted, SignalCheck(),
                   [&](std::size_t c, std::size_t begin, std::size_t end) {
      Result result;
      std::vector<geo::Contact>& contacts = chunk_contacts[c];
      for (std::size_t n = begin; n < end && !interrupted.load(std::memory_order_relaxed); ++n) {
        answer_row(n, [&] { detect(n, result); });
        columns.write(n, result);
        contacts.insert(contacts.end(), result.contacts.begin(), result.contacts.begin() + result.contact_count);
      }
    });
  }
  py::dict out;
  columns.put(out);
  put_contact_columns(chunk_contacts, columns, rows, chunk, threads, out);
  return out;
}

}  // namespace clearjoint::python
