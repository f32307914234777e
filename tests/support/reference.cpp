// SPDX-License-Identifier: GPL-3.0-or-later
#include "tests/support/reference.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <cmath>
#include <iterator>
#include <list>
#include <numbers>

namespace hrs::test_support {
namespace {
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using Point = K::Point_2;
using Poly = CGAL::Polygon_2<K>;
using geometry::Vec2;

//! Distance from p to segment ab in doubles (used only for safe prefilters
//! with a 1e-6 m margin, far above the error of these formulas).
double seg_dist(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = geometry::dot(ab, ab);
  double t = l2 > 0 ? geometry::dot(p - a, ab) / l2 : 0;
  t = std::max(0.0, std::min(1.0, t));
  return geometry::norm(p - (a + t * ab));
}

bool inside_doubles(Vec2 p, const geometry::Polygon& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}
}  // namespace

struct ExactReference::Impl {
  geometry::Polygon room;
  Poly room_exact;
  double half_length, half_width, reach;
  struct Obj {
    Poly exact;
    Vec2 centre;
    double radius;
    double xmin, ymin, xmax, ymax;  //!< world bounding box (doubles)
  };
  std::vector<Obj> objects;
};

ExactReference::ExactReference(const geometry::Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->room = scene.room.polygon;
  for (const Vec2& v : scene.room.polygon) impl_->room_exact.push_back(Point(v.x, v.y));
  impl_->half_length = 0.5 * scene.wheelchair.length;
  impl_->half_width = 0.5 * scene.wheelchair.width;
  impl_->reach = std::hypot(impl_->half_length, impl_->half_width);
  for (const auto& o : scene.objects) {
    Impl::Obj ob;
    // Canonical object geometry: rotated vertices (doubles) plus the position, exactly.
    double r = 0;
    ob.xmin = ob.ymin = 1e300, ob.xmax = ob.ymax = -1e300;
    for (const Vec2& v : geometry::rotated_footprint(o)) {
      ob.exact.push_back(Point(FT(v.x) + FT(o.pose.x), FT(v.y) + FT(o.pose.y)));
      r = std::max(r, geometry::norm(v));
      ob.xmin = std::min(ob.xmin, v.x + o.pose.x), ob.xmax = std::max(ob.xmax, v.x + o.pose.x);
      ob.ymin = std::min(ob.ymin, v.y + o.pose.y), ob.ymax = std::max(ob.ymax, v.y + o.pose.y);
    }
    ob.centre = o.pose.position();
    ob.radius = r;
    impl_->objects.push_back(std::move(ob));
  }
}

ExactReference::~ExactReference() = default;
ExactReference::ExactReference(ExactReference&&) noexcept = default;

bool ExactReference::pose_free(const geometry::Pose2& pose) const {
  const Impl& m = *impl_;
  const Vec2 p = pose.position();
  constexpr double kSafe = 1e-6;
  bool need_room = true;
  if (inside_doubles(p, m.room)) {
    double d = 1e300;
    for (std::size_t i = 0; i < m.room.size(); ++i)
      d = std::min(d, seg_dist(p, m.room[i], m.room[(i + 1) % m.room.size()]));
    if (d > m.reach + kSafe) need_room = false;  // the chair's disk is inside
  }
  // Exact rational rotation: cos = (1-t^2)/(1+t^2), sin = 2t/(1+t^2).
  double th = geometry::wrap_angle(pose.theta);
  bool flip = false;
  if (std::abs(th) > std::numbers::pi / 2) {
    th -= th > 0 ? std::numbers::pi : -std::numbers::pi;
    flip = true;
  }
  const FT t(std::tan(th / 2));
  const FT den = FT(1) + t * t;
  FT c = (FT(1) - t * t) / den, s = FT(2) * t / den;
  if (flip) c = -c, s = -s;
  Poly chair;
  const double lx[4] = {m.half_length, -m.half_length, -m.half_length, m.half_length};
  const double ly[4] = {m.half_width, m.half_width, -m.half_width, -m.half_width};
  bool built = false;
  auto build = [&] {
    if (built) return;
    for (int i = 0; i < 4; ++i)
      chair.push_back(Point(FT(pose.x) + c * FT(lx[i]) - s * FT(ly[i]),
                            FT(pose.y) + s * FT(lx[i]) + c * FT(ly[i])));
    built = true;
  };
  if (need_room) {
    build();
    std::list<CGAL::Polygon_with_holes_2<K>> outside;
    CGAL::difference(chair, m.room_exact, std::back_inserter(outside));
    if (!outside.empty()) return false;
  }
  // Chair bounding box in doubles, grown by kSafe (far above rounding).
  const double cth = std::cos(pose.theta), sth = std::sin(pose.theta);
  const double ex = std::abs(cth) * m.half_length + std::abs(sth) * m.half_width + kSafe;
  const double ey = std::abs(sth) * m.half_length + std::abs(cth) * m.half_width + kSafe;
  for (const auto& o : m.objects) {
    if (geometry::norm(p - o.centre) > m.reach + o.radius + kSafe) continue;
    if (p.x + ex < o.xmin || p.x - ex > o.xmax || p.y + ey < o.ymin || p.y - ey > o.ymax) continue;
    build();
    std::list<CGAL::Polygon_with_holes_2<K>> common;
    CGAL::intersection(chair, o.exact, std::back_inserter(common));
    if (!common.empty()) return false;
  }
  return true;
}

}  // namespace hrs::test_support
