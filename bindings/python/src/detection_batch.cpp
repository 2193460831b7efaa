// SPDX-License-Identifier: BSD-3-Clause
// clearjoint._core.detect: detect_contacts on one pose (a JointContacts) or on a batch of poses
// given as NumPy arrays (a dict of arrays, which clearjoint/_detect.py wraps), without the GIL
// and spread over threads.
//
// Batch layout. Per pose, arrays of shape (N,). The contacts of all poses are packed one after
// another in pose order, arrays of shape (M, ...), M the total count; pose n owns the rows
// contact_start[n] to contact_start[n + 1]. A (N, 6, ...) layout padded to kMaxContacts would
// write ~1 KB per pose, as much time as the detection itself on realistic poses, where about
// half the poses touch at one or two points.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "bindings.hpp"
#include "clearjoint/geometry/joint/detect_contacts.hpp"
#include "clearjoint/geometry/model/option_fields.hpp"
#include "array_block.hpp"
#include "numpy_views.hpp"
#include "parallel_chunks.hpp"
#include "signal_check.hpp"

namespace py = pybind11;

namespace clearjoint::python {

namespace {

namespace geo = clearjoint::geometry;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The pose arguments, read once.
struct PoseRows {
  VectorRows bearing_center;
  VectorRows bearing_axis;
  VectorRows journal_center;
  VectorRows journal_axis;

  geo::PartPose bearing(std::size_t n) const { return {bearing_center[n], bearing_axis[n]}; }
  geo::PartPose journal(std::size_t n) const { return {journal_center[n], journal_axis[n]}; }
};

/// The library's field paths, as the Python arguments.
[[noreturn]] void raise(const RowError& error, const PoseRows& poses) {
  raise(error, {{"bearing.p_WP", "bearing_center", poses.bearing_center.batched()},
                {"bearing.axis_W", "bearing_axis", poses.bearing_axis.batched()},
                {"journal.p_WP", "journal_center", poses.journal_center.batched()},
                {"journal.axis_W", "journal_axis", poses.journal_axis.batched()},
                {"options.parallel_angle_tolerance", "parallel_angle_tolerance", false}});
}

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

  void write(std::size_t n, const geo::JointContacts& r) const {
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
                         unsigned threads, py::dict& out) {
  // First contact row of each chunk.
  std::vector<std::size_t> first(chunk_contacts.size() + 1, 0);
  for (std::size_t c = 0; c < chunk_contacts.size(); ++c) first[c + 1] = first[c] + chunk_contacts[c].size();
  const std::size_t total = first.back();
  const auto m = static_cast<py::ssize_t>(total);
  const auto n = static_cast<py::ssize_t>(rows);

  ArrayBlock block;
  // Widest elements first; each array starts on its own cache line anyway.
  const std::size_t depth = block.plan<double>({m}), depth_error = block.plan<double>({m}),
                    point_journal_error = block.plan<double>({m}),
                    point_bearing_error = block.plan<double>({m}),
                    point_journal = block.plan<double>({m, 3}),
                    point_bearing = block.plan<double>({m, 3}), normal = block.plan<double>({m, 3}),
                    angle = block.plan<double>({m, 2}), angle_error = block.plan<double>({m, 2}),
                    crossing_point = block.plan<double>({m, 2, 3}), point_error = block.plan<double>({m, 2}),
                    start = block.plan<std::int64_t>({n + 1}), pose = block.plan<std::int64_t>({m}),
                    type = block.plan<std::int8_t>({m}), base = block.plan<std::int8_t>({m}),
                    crossing_count = block.plan<std::int8_t>({m}),
                    multiplicity = block.plan<std::int8_t>({m, 2}),
                    certificate = block.plan<std::int8_t>({m}),
                    reason = block.plan<std::int8_t>({m});
  block.allocate();
  std::int64_t* s = block.data<std::int64_t>(start);
  std::int64_t* p = block.data<std::int64_t>(pose);
  const std::int8_t* count = columns.count_out;
  std::int8_t *t = block.data<std::int8_t>(type), *b = block.data<std::int8_t>(base),
              *c = block.data<std::int8_t>(certificate), *cr = block.data<std::int8_t>(reason),
              *cc = block.data<std::int8_t>(crossing_count), *mu = block.data<std::int8_t>(multiplicity);
  double *d = block.data<double>(depth), *de = block.data<double>(depth_error),
         *pje = block.data<double>(point_journal_error), *pie = block.data<double>(point_bearing_error),
         *pj = block.data<double>(point_journal), *pi = block.data<double>(point_bearing),
         *nw = block.data<double>(normal), *a = block.data<double>(angle),
         *ae = block.data<double>(angle_error), *xp = block.data<double>(crossing_point),
         *pe = block.data<double>(point_error);
  s[0] = 0;
  {
    py::gil_scoped_release release;
    for_each_chunk(chunk_contacts.size(), 1, threads, [&](std::size_t h, std::size_t, std::size_t) {
      // This chunk's poses, rows [h * chunk, ...), own contact rows [first[h], first[h + 1]).
      std::size_t k = first[h];
      for (std::size_t r = h * chunk; r < std::min(rows, (h + 1) * chunk); ++r) {
        for (int j = 0; j < count[r]; ++j) p[k++] = static_cast<std::int64_t>(r);
        s[r + 1] = static_cast<std::int64_t>(k);
      }
      k = first[h];
      for (const geo::Contact& contact : chunk_contacts[h]) {
        t[k] = static_cast<std::int8_t>(contact.type);
        b[k] = static_cast<std::int8_t>(contact.base);
        c[k] = static_cast<std::int8_t>(contact.certificate.level);
        cr[k] = static_cast<std::int8_t>(contact.certificate.reason);
        cc[k] = static_cast<std::int8_t>(contact.crossing_count);
        d[k] = contact.depth;
        de[k] = contact.depth_error;
        pje[k] = contact.p_WCj_error;
        pie[k] = contact.p_WCi_error;
        for (int i = 0; i < 3; ++i) {
          pj[3 * k + i] = contact.p_WCj[i];
          pi[3 * k + i] = contact.p_WCi[i];
          nw[3 * k + i] = contact.normal_W[i];
        }
        for (int x = 0; x < 2; ++x) {
          const bool used = x < contact.crossing_count;
          const geo::RimCrossing& crossing = contact.crossings[x];
          mu[2 * k + x] = used ? static_cast<std::int8_t>(crossing.multiplicity) : 0;
          a[2 * k + x] = used ? crossing.angle : kNaN;
          ae[2 * k + x] = used ? crossing.angle_error : kNaN;
          pe[2 * k + x] = used ? crossing.point_error : kNaN;
          for (int i = 0; i < 3; ++i) xp[6 * k + 3 * x + i] = used ? crossing.point[i] : kNaN;
        }
        ++k;
      }
    });
  }
  out["contact_start"] = block.array<std::int64_t>(start);
  out["contact_pose"] = block.array<std::int64_t>(pose);
  out["contact_type"] = block.array<std::int8_t>(type);
  out["contact_base"] = block.array<std::int8_t>(base);
  out["depth"] = block.array<double>(depth);
  out["depth_error"] = block.array<double>(depth_error);
  out["point_journal"] = block.array<double>(point_journal);
  out["point_journal_error"] = block.array<double>(point_journal_error);
  out["point_bearing"] = block.array<double>(point_bearing);
  out["point_bearing_error"] = block.array<double>(point_bearing_error);
  out["normal"] = block.array<double>(normal);
  out["crossing_count"] = block.array<std::int8_t>(crossing_count);
  out["crossing_angle"] = block.array<double>(angle);
  out["crossing_angle_error"] = block.array<double>(angle_error);
  out["crossing_point"] = block.array<double>(crossing_point);
  out["crossing_point_error"] = block.array<double>(point_error);
  out["crossing_multiplicity"] = block.array<std::int8_t>(multiplicity);
  out["contact_certificate"] = block.array<std::int8_t>(certificate);
  out["contact_certificate_reason"] = block.array<std::int8_t>(reason);
}

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

ContactListCache& contact_list_cache() {
  static ContactListCache cache;
  return cache;
}

py::dict detect_batch(const geo::JointDimensions& dimensions, const PoseRows& poses,
                      std::size_t rows, const geo::DetectionOptions& options, unsigned threads) {
  PoseColumns columns(rows);
  const std::size_t chunk = chunk_rows(rows, threads);
  const std::size_t chunks = (rows + chunk - 1) / chunk;
  std::vector<std::vector<geo::Contact>> chunk_contacts = contact_list_cache().take(chunks);
  struct GiveBack {
    std::vector<std::vector<geo::Contact>>& lists;
    ~GiveBack() { contact_list_cache().give_back(std::move(lists)); }
  } give_back{chunk_contacts};
  try {
    py::gil_scoped_release release;
    std::atomic<bool> interrupted{false};
    for_each_chunk(rows, chunk, threads, interrupted, SignalCheck(),
                   [&](std::size_t c, std::size_t begin, std::size_t end) {
      geo::JointContacts result;
      std::vector<geo::Contact>& contacts = chunk_contacts[c];
      for (std::size_t n = begin; n < end && !interrupted.load(std::memory_order_relaxed); ++n) {
        answer_row(n, [&] { geo::detect_contacts(dimensions, poses.bearing(n), poses.journal(n), result, options); });
        columns.write(n, result);
        contacts.insert(contacts.end(), result.contacts.begin(), result.contacts.begin() + result.contact_count);
      }
    });
  } catch (const RowError& error) {
    // Chunks are handed out in order and finished once begun: the error rethrown is the first
    // bad row of the batch, whatever the thread count.
    raise(error, poses);
  }
  py::dict out;
  columns.put(out);
  put_contact_columns(chunk_contacts, columns, rows, chunk, threads, out);
  return out;
}

}  // namespace

/// The options clearjoint.detect passes by their keys in the option list (option_fields.hpp),
/// each checked as its keyword argument. A key it does not pass is an error of the package, not
/// of the caller: tests/test_detect.py checks that detect has a keyword for each.
geo::DetectionOptions detection_options(const py::dict& given) {
  geo::DetectionOptions options;
  geo::visit_options(options, [&given](std::string_view key, auto& value) {
    const std::string name(key);
    if (!given.contains(name)) throw std::logic_error("clearjoint.detect passes no option " + name);
    const py::handle argument = given[py::str(name)];
    if constexpr (std::is_same_v<std::remove_reference_t<decltype(value)>, bool>) {
      value = flag_argument(argument, name.c_str());
    } else {
      value = number_argument(argument, name);
    }
  });
  return options;
}

namespace {

/// Every option's default by its key, for the check of detect's keywords.
py::dict detection_option_defaults() {
  py::dict defaults;
  const geo::DetectionOptions options;
  geo::visit_options(options, [&defaults](std::string_view key, const auto& value) {
    defaults[py::str(std::string(key))] = value;
  });
  return defaults;
}

py::object detect(const geo::JointDimensions& dimensions, const py::handle& bearing_center,
                  const py::handle& bearing_axis, const py::handle& journal_center,
                  const py::handle& journal_axis, const py::dict& option_arguments, const py::object& threads) {
  const PoseRows poses{VectorRows(bearing_center, "bearing_center"), VectorRows(bearing_axis, "bearing_axis"),
                       VectorRows(journal_center, "journal_center"), VectorRows(journal_axis, "journal_axis")};
  const Broadcast shape =
      broadcast(poses.bearing_center, poses.bearing_axis, poses.journal_center, poses.journal_axis);
  const geo::DetectionOptions options = detection_options(option_arguments);
  const unsigned thread_limit = thread_count(threads);
  if (shape.batched) {
    return within_memory("detect", shape.rows, "poses",
                         [&]() -> py::object { return detect_batch(dimensions, poses, shape.rows, options, thread_limit); });
  }
  geo::JointContacts result;
  try {
    py::gil_scoped_release release;
    geo::detect_contacts(dimensions, poses.bearing(0), poses.journal(0), result, options);
  } catch (const ValidationError& e) {
    raise(RowError::invalid(0, e), poses);
  }
  return py::cast(result);
}

}  // namespace

void bind_detection_batch(py::module_& module) {
  module.def("detect", &detect, py::arg("dims"), py::arg("bearing_center"), py::arg("bearing_axis"),
             py::arg("journal_center"), py::arg("journal_axis"), py::arg("options"), py::arg("threads"),
             "clearjoint.detect's compiled half: a JointContacts, or a dict of arrays for a batch.");
  module.def("_detection_option_defaults", &detection_option_defaults,
             "Each detection option's default by its key (the library's option list).");
}

}  // namespace clearjoint::python
