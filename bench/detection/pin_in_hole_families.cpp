// SPDX-License-Identifier: BSD-3-Clause
#include "pin_in_hole_families.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "clearjoint/geometry/joint/detect_pin_in_hole_contacts.hpp"

namespace clearjoint::bench {
namespace {

using geometry::PartPose;
using geometry::PinInHoleDimensions;
using geometry::Vector3;

class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : engine_(seed) {}
  double operator()(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  double log(double lo, double hi) { return std::pow(10.0, (*this)(std::log10(lo), std::log10(hi))); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  Vector3 direction() {
    for (;;) {
      const Vector3 v((*this)(-1, 1), (*this)(-1, 1), (*this)(-1, 1));
      if (v.norm() > 0.1 && v.norm() <= 1.0) return v.normalized();
    }
  }

 private:
  std::mt19937_64 engine_;
};

PinInHoleDimensions random_dimensions(Uniform& uniform) {
  PinInHoleDimensions d;
  d.hole_radius = uniform(0.005, 0.05);
  const double cr = d.hole_radius * uniform.log(1e-3, 1e-1);
  d.pin_radius = d.hole_radius - cr;
  d.hole_length = d.hole_radius * uniform(0.5, 3.0);
  d.stop_count = uniform.integer(0, 2);
  const double ca = cr * uniform(0.5, 3.0);
  const double side = uniform(0, 1) < 0.5 ? -1.0 : 1.0;
  for (int k = 0; k < d.stop_count; ++k) {
    const double sign = k == 0 ? side : -side;
    d.stops[k] = {sign * (0.5 * d.hole_length + ca * uniform(0.5, 1.5)), d.hole_radius * uniform(1.2, 2.5)};
  }
  return d;
}

/// The hole's frame: its axis and two directions across it.
struct Frame {
  Vector3 u, v, a;
};
Frame random_frame(Uniform& uniform) {
  Frame f;
  f.a = uniform.direction();
  f.u = f.a.unitOrthogonal();
  f.v = f.a.cross(f.u);
  return f;
}

/// The pin's displacement from the centred pose in the hole's frame: offset (x, y, z) and tilt
/// (tx, ty), the axis being (tx, ty, 1) normalised.
struct Displacement {
  double x = 0, y = 0, z = 0, tx = 0, ty = 0;
  Displacement scaled(double s) const { return {s * x, s * y, s * z, s * tx, s * ty}; }
};

Displacement random_displacement(Uniform& uniform, const PinInHoleDimensions& d, double radial, double axial,
                                  double tilt) {
  const double cr = d.radial_clearance();
  const double ca = d.stop_count == 2 ? d.axial_clearance() : cr;
  const double phi = uniform(0, 2 * M_PI), psi = uniform(0, 2 * M_PI);
  const double r = cr * uniform(0, radial), t = (cr / d.hole_length) * uniform(0, tilt);
  return {r * std::cos(phi), r * std::sin(phi), ca * uniform(-axial, axial), t * std::cos(psi), t * std::sin(psi)};
}

struct Placed {
  PartPose hole, pin;
};
Placed place(const Frame& f, const Vector3& centre, double hole_axis_length, double pin_axis_length,
             const Displacement& p) {
  Placed out;
  out.hole = PartPose{centre, hole_axis_length * f.a};
  out.pin.p_WP = centre + p.x * f.u + p.y * f.v + p.z * f.a;
  const Vector3 local = Vector3(p.tx, p.ty, 1.0).normalized();
  out.pin.axis_W = pin_axis_length * (local.x() * f.u + local.y() * f.v + local.z() * f.a);
  return out;
}

PinInHoleInput input(const std::string& id, const PinInHoleDimensions& d, const Placed& placed) {
  return {id, d, placed.hole, placed.pin};
}

bool touches(const PinInHoleDimensions& d, const Placed& placed) {
  return geometry::detect_pin_in_hole_contacts(d, placed.hole, placed.pin).contact_count > 0;
}

}  // namespace

std::vector<PinInHoleInput> generate_pin_in_hole_family(const std::string& family, int count, std::uint64_t seed) {
  Uniform uniform(seed);
  std::vector<PinInHoleInput> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int n = 0; static_cast<int>(out.size()) < count; ++n) {
    const PinInHoleDimensions d = random_dimensions(uniform);
    const Frame f = random_frame(uniform);
    const Vector3 centre = 0.2 * uniform(0, 1) * uniform.direction();
    const double hole_length = uniform(0.5, 2.0), pin_length = uniform(0.5, 2.0);
    const std::string id = family + "/" + std::to_string(n);
    if (family == "random") {
      out.push_back(input(id, d, place(f, centre, hole_length, pin_length, random_displacement(uniform, d, 1.3, 1.5, 2.5))));
    } else if (family == "near_tangent") {
      // Scale a displacement that touches down to the first touch: lo never touches, hi does.
      const Displacement p = random_displacement(uniform, d, 1.3, 1.5, 2.5);
      double lo = 0.0, hi = 1.0;
      if (!touches(d, place(f, centre, hole_length, pin_length, p.scaled(hi)))) continue;
      if (touches(d, place(f, centre, hole_length, pin_length, p.scaled(lo)))) continue;
      for (int step = 0; step < 64 && lo < hi; ++step) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (touches(d, place(f, centre, hole_length, pin_length, p.scaled(mid))) ? hi : lo) = mid;
      }
      out.push_back(input(id, d, place(f, centre, hole_length, pin_length, p.scaled(uniform(0, 1) < 0.5 ? lo : hi))));
    } else if (family == "near_parallel") {
      // An offset within 1e-6 (relative) of cr, a tilt of 10^-k rad (k = 8..16) or none.
      Displacement p = random_displacement(uniform, d, 1.0, 1.5, 0.0);
      const double phi = uniform(0, 2 * M_PI);
      const double e = d.radial_clearance() * (1.0 + uniform(-1e-6, 1e-6));
      p.x = e * std::cos(phi);
      p.y = e * std::sin(phi);
      const int k = uniform.integer(7, 16);
      if (k > 7) {
        const double psi = uniform(0, 2 * M_PI);
        p.tx = std::pow(10.0, -k) * std::cos(psi);
        p.ty = std::pow(10.0, -k) * std::sin(psi);
        out.push_back(input(id, d, place(f, centre, hole_length, pin_length, p)));
      } else {
        // Exactly parallel stored axes: the pin's axis a power of two times the hole's.
        Placed placed = place(f, centre, hole_length, pin_length, p);
        placed.pin.axis_W = (uniform(0, 1) < 0.5 ? 2.0 : -0.5) * placed.hole.axis_W;
        out.push_back(input(id + "/parallel", d, placed));
      }
    } else if (family == "near_flush") {
      // A pin held against one of its heads, tilted by 10^-k rad (k = 4..14): the stop's centre
      // d beyond its face, d from half to a hundred times Ro sin(tilt) (mostly beyond the face all
      // round, the rest crossing it) and below the axial limit.
      PinInHoleDimensions held = d;
      if (held.stop_count == 0) {
        held.stop_count = 1;
        held.stops[0] = {(uniform(0, 1) < 0.5 ? -1.0 : 1.0) * (0.5 * held.hole_length + held.radial_clearance()),
                         held.hole_radius * uniform(1.2, 2.5)};
      }
      Displacement p = random_displacement(uniform, held, 0.8, 0.0, 0.0);
      const double tilt = std::pow(10.0, -uniform.integer(4, 14)), psi = uniform(0, 2 * M_PI);
      p.tx = tilt * std::cos(psi);
      p.ty = tilt * std::sin(psi);
      const geometry::AxialStop& stop = held.stops[uniform.integer(0, held.stop_count - 1)];
      const double limit = held.stop_count == 2 ? held.axial_clearance() : 0.5 * held.hole_length;
      const double depth = std::min(0.9 * limit, stop.outer_radius * tilt * uniform.log(0.5, 100.0));
      const double cosine = 1.0 / std::sqrt(1.0 + tilt * tilt);
      // The stop's centre along the hole's axis is p.z + s cos(tilt); face A at +L/2 for a head on
      // the positive side, face B at -L/2 otherwise.
      p.z = stop.position > 0.0 ? 0.5 * held.hole_length - stop.position * cosine - depth
                                : depth - 0.5 * held.hole_length - stop.position * cosine;
      out.push_back(input(id, held, place(f, centre, hole_length, pin_length, p)));
    } else if (family == "small_heads") {
      // Heads barely larger than the hole on a tilted, off-centre pin pressed against one of
      // them. In the hole's frame, with the tilt t towards tau, w = sign(s) tau the side where the
      // stop's outer circle is deepest into the link, yS = -(S . w) the stop centre's offset away
      // from it and g its depth beyond the face: the circle's deepest point m lies over the hole
      // when yS > Ro cos t - Rh, and the hole's edge's deepest point q, (Rh + yS) cos t - g sin t
      // from the pin's axis, lies within the head's rim when yS <= (Ro + g sin t) / cos t - Rh.
      // A third of the poses each: m over the link (1), yS between the two (2: a sliver about
      // t (g + Ro sin t) wide), q beyond the rim (3); the first and last also off the line.
      PinInHoleDimensions small = d;
      const double cr = small.radial_clearance();
      if (small.stop_count == 0) {
        small.stop_count = 1;
        small.stops[0].position = (uniform(0, 1) < 0.5 ? -1.0 : 1.0) * (0.5 * small.hole_length + cr * uniform(0.5, 3.0));
      }
      for (int k = 0; k < small.stop_count; ++k) small.stops[k].outer_radius = small.hole_radius + cr * uniform(0.02, 3.0);
      const geometry::AxialStop& stop = small.stops[uniform.integer(0, small.stop_count - 1)];
      const double ro = stop.outer_radius, rh = small.hole_radius;
      const double tangent = (cr / small.hole_length) * uniform(0.2, 2.5), psi = uniform(0, 2 * M_PI);
      const double sine = tangent / std::sqrt(1.0 + tangent * tangent), cosine = 1.0 / std::sqrt(1.0 + tangent * tangent);
      const double limit = small.stop_count == 2 ? small.axial_clearance() : 0.5 * small.hole_length;
      const double g = std::min(0.9 * limit, ro * sine * uniform(-0.5, 2.0));
      const double lower = ro * cosine - rh, upper = (ro + g * sine) / cosine - rh;
      const int mode = n % 3;
      const double ys = mode == 0   ? lower - 2.0 * cr * uniform(0, 1)
                        : mode == 1 ? lower + (upper - lower) * uniform(0.02, 0.98)
                                    : upper + 2.0 * cr * uniform(0, 1);
      const double across = mode == 1 ? 0.0 : cr * uniform(-0.5, 0.5);
      const double side = stop.position > 0.0 ? 1.0 : -1.0;
      const double tau_x = std::cos(psi), tau_y = std::sin(psi);
      // S = -yS w + across (w rotated a quarter turn), and the pin's point P = S - s a_hat.
      const double sx = -ys * side * tau_x - across * tau_y, sy = -ys * side * tau_y + across * tau_x;
      const double sz = side * (0.5 * small.hole_length - g);
      Displacement p;
      p.tx = tangent * tau_x;
      p.ty = tangent * tau_y;
      p.x = sx - stop.position * sine * tau_x;
      p.y = sy - stop.position * sine * tau_y;
      p.z = sz - stop.position * cosine;
      out.push_back(input(id, small, place(f, centre, hole_length, pin_length, p)));
    } else {
      throw std::invalid_argument("unknown pin-in-hole family: " + family);
    }
  }
  return out;
}

}  // namespace clearjoint::bench
