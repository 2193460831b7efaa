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

#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "clearjoint/geometry/detect_contacts.hpp"
#include "numpy_views.hpp"
#include "parallel_chunks.hpp"

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

/// The first failure of a chunk: its row and message.
struct RowError {
  std::size_t row = 0;
  std::string message;
  bool invalid_input = false;
};

/// The library's field names in messages, as the Python arguments.
std::string python_message(const RowError& error, const PoseRows& poses) {
  return argument_message(error.message, error.row,
                          {{"bearing.p_WP", "bearing_center", poses.bearing_center.batched()},
                           {"bearing.axis_W", "bearing_axis", poses.bearing_axis.batched()},
                           {"journal.p_WP", "journal_center", poses.journal_center.batched()},
                           {"journal.axis_W", "journal_axis", poses.journal_axis.batched()},
                           {"options.parallel_angle_tolerance", "parallel_angle_tolerance", false}});
}

[[noreturn]] void raise(const RowError& error, const PoseRows& poses) {
  const std::string message = python_message(error, poses);
  if (error.invalid_input) throw py::value_error(message);
  throw std::runtime_error(message);
}

template <typename T>
py::array_t<T> array_of(std::initializer_list<py::ssize_t> shape) {
  return py::array_t<T>(std::vector<py::ssize_t>(shape));
}

/// Per-pose outputs, written by the workers through raw pointers (disjoint rows).
struct PoseColumns {
  py::array_t<std::int8_t> scenario, certificate, contact_count;
  py::array_t<bool> aligned;
  std::int8_t* scenario_out;
  std::int8_t* certificate_out;
  std::int8_t* count_out;
  bool* aligned_out;

  explicit PoseColumns(std::size_t rows)
      : scenario(array_of<std::int8_t>({py::ssize_t(rows)})),
        certificate(array_of<std::int8_t>({py::ssize_t(rows)})),
        contact_count(array_of<std::int8_t>({py::ssize_t(rows)})),
        aligned(array_of<bool>({py::ssize_t(rows)})),
        scenario_out(scenario.mutable_data()),
        certificate_out(certificate.mutable_data()),
        count_out(contact_count.mutable_data()),
        aligned_out(aligned.mutable_data()) {}

  void write(std::size_t n, const geo::JointContacts& r) const {
    scenario_out[n] = static_cast<std::int8_t>(r.scenario);
    certificate_out[n] = static_cast<std::int8_t>(r.certificate.level);
    count_out[n] = static_cast<std::int8_t>(r.contact_count);
    aligned_out[n] = r.aligned;
  }
};

/// The packed contact arrays, filled after the workers from their per-chunk lists.
py::dict contact_columns(const std::vector<std::vector<geo::Contact>>& chunk_contacts,
                         const py::array_t<std::int8_t>& contact_count) {
  std::size_t total = 0;
  for (const auto& list : chunk_contacts) total += list.size();
  const py::ssize_t m = static_cast<py::ssize_t>(total);
  const py::ssize_t rows = contact_count.shape(0);

  auto start = array_of<std::int64_t>({rows + 1});
  auto pose = array_of<std::int64_t>({m});
  {
    std::int64_t* s = start.mutable_data();
    std::int64_t* p = pose.mutable_data();
    const std::int8_t* count = contact_count.data();
    s[0] = 0;
    for (py::ssize_t n = 0; n < rows; ++n) {
      s[n + 1] = s[n] + count[n];
      for (std::int64_t k = s[n]; k < s[n + 1]; ++k) p[k] = n;
    }
  }
  auto type = array_of<std::int8_t>({m});
  auto base = array_of<std::int8_t>({m});
  auto certificate = array_of<std::int8_t>({m});
  auto crossing_count = array_of<std::int8_t>({m});
  auto multiplicity = array_of<std::int8_t>({m, 2});
  auto depth = array_of<double>({m});
  auto point_journal = array_of<double>({m, 3});
  auto point_bearing = array_of<double>({m, 3});
  auto normal = array_of<double>({m, 3});
  auto angle = array_of<double>({m, 2});
  auto angle_error = array_of<double>({m, 2});
  auto crossing_point = array_of<double>({m, 2, 3});
  auto point_error = array_of<double>({m, 2});
  std::int8_t *t = type.mutable_data(), *b = base.mutable_data(), *c = certificate.mutable_data(),
              *cc = crossing_count.mutable_data(), *mu = multiplicity.mutable_data();
  double *d = depth.mutable_data(), *pj = point_journal.mutable_data(),
         *pi = point_bearing.mutable_data(), *nw = normal.mutable_data(), *a = angle.mutable_data(),
         *ae = angle_error.mutable_data(), *xp = crossing_point.mutable_data(),
         *pe = point_error.mutable_data();
  std::size_t k = 0;
  for (const auto& list : chunk_contacts) {
    for (const geo::Contact& contact : list) {
      t[k] = static_cast<std::int8_t>(contact.type);
      b[k] = static_cast<std::int8_t>(contact.base);
      c[k] = static_cast<std::int8_t>(contact.certificate.level);
      cc[k] = static_cast<std::int8_t>(contact.crossing_count);
      d[k] = contact.depth;
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
  }
  py::dict out;
  out["contact_start"] = start;
  out["contact_pose"] = pose;
  out["contact_type"] = type;
  out["contact_base"] = base;
  out["depth"] = depth;
  out["point_journal"] = point_journal;
  out["point_bearing"] = point_bearing;
  out["normal"] = normal;
  out["crossing_count"] = crossing_count;
  out["crossing_angle"] = angle;
  out["crossing_angle_error"] = angle_error;
  out["crossing_point"] = crossing_point;
  out["crossing_point_error"] = point_error;
  out["crossing_multiplicity"] = multiplicity;
  out["contact_certificate"] = certificate;
  return out;
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
  std::vector<std::optional<RowError>> chunk_errors(chunks);
  {
    py::gil_scoped_release release;
    std::atomic<bool> stop{false};
    for_each_chunk(rows, chunk, threads, stop, [&](std::size_t c, std::size_t begin, std::size_t end) {
      geo::JointContacts result;
      std::vector<geo::Contact>& contacts = chunk_contacts[c];
      for (std::size_t n = begin; n < end; ++n) {
        try {
          geo::detect_contacts(dimensions, poses.bearing(n), poses.journal(n), result, options);
        } catch (const geo::InvalidInput& e) {
          chunk_errors[c] = RowError{n, e.what(), true};
        } catch (const std::exception& e) {
          chunk_errors[c] = RowError{n, e.what(), false};
        }
        if (chunk_errors[c]) {
          stop = true;
          return;
        }
        columns.write(n, result);
        contacts.insert(contacts.end(), result.contacts.begin(), result.contacts.begin() + result.contact_count);
      }
    });
  }
  // Chunks are handed out in order and finished once begun: the first error recorded is the
  // first bad row of the batch, whatever the thread count.
  for (const auto& error : chunk_errors) {
    if (error) raise(*error, poses);
  }
  py::dict out;
  out["scenario"] = columns.scenario;
  out["aligned"] = columns.aligned;
  out["certificate"] = columns.certificate;
  out["contact_count"] = columns.contact_count;
  out.attr("update")(contact_columns(chunk_contacts, columns.contact_count));
  return out;
}

py::object detect(const geo::JointDimensions& dimensions, const py::handle& bearing_center,
                  const py::handle& bearing_axis, const py::handle& journal_center,
                  const py::handle& journal_axis, bool certify, double parallel_angle_tolerance,
                  const py::object& threads) {
  const PoseRows poses{VectorRows(bearing_center, "bearing_center"), VectorRows(bearing_axis, "bearing_axis"),
                       VectorRows(journal_center, "journal_center"), VectorRows(journal_axis, "journal_axis")};
  const Broadcast shape =
      broadcast(poses.bearing_center, poses.bearing_axis, poses.journal_center, poses.journal_axis);
  geo::DetectionOptions options;
  options.intersection.certify = certify;
  options.parallel_angle_tolerance = parallel_angle_tolerance;
  const unsigned thread_limit = thread_count(threads);
  if (shape.batched) return detect_batch(dimensions, poses, shape.rows, options, thread_limit);
  geo::JointContacts result;
  try {
    py::gil_scoped_release release;
    geo::detect_contacts(dimensions, poses.bearing(0), poses.journal(0), result, options);
  } catch (const geo::InvalidInput& e) {
    raise(RowError{0, e.what(), true}, poses);
  }
  return py::cast(result);
}

}  // namespace

void bind_detection_batch(py::module_& module) {
  module.def("detect", &detect, py::arg("dims"), py::arg("bearing_center"), py::arg("bearing_axis"),
             py::arg("journal_center"), py::arg("journal_axis"), py::arg("certify"),
             py::arg("parallel_angle_tolerance"), py::arg("threads"),
             "clearjoint.detect's compiled half: a JointContacts, or a dict of arrays for a batch.");
}

}  // namespace clearjoint::python
