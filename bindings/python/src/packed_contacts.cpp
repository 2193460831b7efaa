// SPDX-License-Identifier: BSD-3-Clause
// The packed contact arrays of a detection batch (packed_contacts.hpp): the copy of the workers'
// per-chunk contact lists into one block of arrays, and the lists kept from batch to batch.

#include "packed_contacts.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace clearjoint::python {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

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

ContactListCache& contact_list_cache() {
  static ContactListCache cache;
  return cache;
}


}  // namespace clearjoint::python
