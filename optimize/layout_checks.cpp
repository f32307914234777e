// SPDX-License-Identifier: GPL-3.0-or-later
// The exact validity of a layout (declared in optimize/design.h): inside the
// room, clear of the door's clear zone, no overlap beyond contact.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "geometry/polygon_ops.h"
#include "optimize/design.h"

namespace hrs::optimize {

namespace {

using geometry::Vec2;

double point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double l2 = d.x * d.x + d.y * d.y;
  double t = l2 > 0.0 ? ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * d.x), p.y - (a.y + t * d.y));
}

//! Whether segments ab and cd cross or touch (orientation signs).
bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const auto orient = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c),
               d4 = orient(a, b, d);
  return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) &&
         ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0);
}

bool point_inside(const Vec2& p, const geometry::Polygon& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      in = !in;
  }
  return in;
}

//! A sufficient test, in floating point with a margin far above its
//! rounding, that `inner` lies strictly inside `outer` (simple polygons):
//! no edge of one comes within kMargin of an edge of the other, and a
//! vertex of `inner` is inside `outer`. Then the boundaries do not meet, so
//! `inner` is wholly inside. False means "ask the exact test".
bool clearly_inside(const geometry::Polygon& inner, const geometry::Polygon& outer) {
  constexpr double kMargin = 1e-7;
  for (std::size_t i = 0; i < inner.size(); ++i) {
    const Vec2& a = inner[i];
    const Vec2& b = inner[(i + 1) % inner.size()];
    for (std::size_t j = 0; j < outer.size(); ++j) {
      const Vec2& c = outer[j];
      const Vec2& d = outer[(j + 1) % outer.size()];
      if (segments_meet(a, b, c, d)) return false;
      if (std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                    point_segment(d, a, b)}) <= kMargin)
        return false;
    }
  }
  return !inner.empty() && point_inside(inner[0], outer);
}

//! Slack of the floating-point shortcuts below: a quarter of the contact
//! tolerance, far above their rounding (about 1e-15 m), far below what the
//! exact predicates allow (geometry::kContactTolerance).
constexpr double kSlack = 0.25 * geometry::kContactTolerance;

//! True when `room` is convex and every vertex of `fp` is inside each of its
//! edges' half-planes, or out by at most kSlack: then nothing sticks out by
//! more than the tolerance, and protrusion() would say so.
bool inside_convex_room(const geometry::Polygon& fp, const geometry::Polygon& room) {
  const std::size_t n = room.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = room[i];
    const Vec2& b = room[(i + 1) % n];
    const Vec2& c = room[(i + 2) % n];
    if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0.0) return false;  // reflex
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = room[i];
    const Vec2 e = room[(i + 1) % n] - a;
    const double len = std::hypot(e.x, e.y);
    if (!(len > 0.0)) return false;
    const Vec2 inward{-e.y / len, e.x / len};  // the room is counter-clockwise
    for (const Vec2& v : fp)
      if ((v.x - a.x) * inward.x + (v.y - a.y) * inward.y < -kSlack) return false;
  }
  return true;
}

//! True when, along some edge normal of `a` or `b`, their projections
//! overlap by at most kSlack: every common point then lies within kSlack of
//! both boundaries (it leaves one polygon's projection, so the polygon,
//! within that distance), so overlap_depth() finds no overlap beyond contact.
bool contact_at_most(const geometry::Polygon& a, const geometry::Polygon& b) {
  return geometry::any_edge_axis(a, b, [](double overlap) { return overlap <= kSlack; });
}

bool boxes_apart(const geometry::Box& a, const geometry::Box& b) {
  return b.xmin > a.xmax || b.xmax < a.xmin || b.ymin > a.ymax || b.ymax < a.ymin;
}

//! The first violation of object `index`: its text when `describe`, else
//! "x" (the same verdict, with the quicker predicates that give no amount).
std::string violation(const geometry::Scene& scene, int index, bool describe) {
  // Contact is allowed within geometry::kContactTolerance, as in the reader.
  const auto& o = scene.objects[index];
  // Cheap tests that only skip an exact test whose answer they prove (a
  // footprint clearly inside the room, polygons apart or in contact along an
  // axis) come first; they never change an answer.
  const auto fp = geometry::world_footprint(o);
  const geometry::Box box = geometry::bounding_box(fp);
  if (!inside_convex_room(fp, scene.room.polygon) && !clearly_inside(fp, scene.room.polygon))
    if (const auto out = geometry::protrusion(fp, scene.room.polygon))
      return describe ? o.id + " " + geometry::sticks_out_text(*out, scene.room.polygon) : "x";
  const auto overlap = [&](const geometry::Polygon& other) -> std::optional<double> {
    if (describe) return geometry::overlap_depth(fp, other);
    return geometry::overlap_beyond_contact(fp, other) ? std::optional<double>(0.0) : std::nullopt;
  };
  const geometry::Polygon door = geometry::door_clear_zone(scene);
  if (!boxes_apart(box, geometry::bounding_box(door)) && !contact_at_most(fp, door))
    if (const auto depth = overlap(door))
      return describe ? o.id + " enters the door's clear zone by " + geometry::metres_text(*depth) +
                            " m"
                      : "x";
  for (std::size_t j = 0; j < scene.objects.size(); ++j) {
    if (static_cast<int>(j) == index) continue;
    const auto other = geometry::world_footprint(scene.objects[j]);
    // Disjoint bounding boxes: no overlap, without the exact test.
    if (boxes_apart(box, geometry::bounding_box(other)) || contact_at_most(fp, other)) continue;
    if (const auto depth = overlap(other))
      return describe ? o.id + " overlaps " + scene.objects[j].id + " by " +
                            geometry::metres_text(*depth) + " m"
                      : "x";
  }
  return "";
}

}  // namespace

std::string object_violation(const geometry::Scene& scene, int index) {
  return violation(scene, index, true);
}

bool object_fits(const geometry::Scene& scene, int index) {
  return violation(scene, index, false).empty();
}

std::string layout_violation(const geometry::Scene& scene) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    auto v = object_violation(scene, static_cast<int>(i));
    if (!v.empty()) return v;
  }
  return "";
}

}  // namespace hrs::optimize
