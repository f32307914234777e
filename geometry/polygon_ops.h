// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Exact polygon predicates and decompositions (CGAL with exact predicates,
// confined to polygon_ops.cpp). Input coordinates are doubles, taken exactly.
// The furniture checks (scene reader, design loop) use the contact-tolerant
// predicates protrusion() and overlap_depth() with kContactTolerance; the
// exact ones serve the wheelchair, whose C-space answers are certified.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::geometry {

//! True if the polygon has >= 3 vertices and no two non-adjacent edges meet.
bool is_simple(const Polygon& polygon);
//! True if counter-clockwise (positive orientation); polygon must be simple.
bool is_counterclockwise(const Polygon& polygon);
//! True if `inner` lies in the closed region of `outer` (both simple).
bool polygon_inside(const Polygon& inner, const Polygon& outer);
//! True if the open interiors of two simple polygons intersect.
bool interiors_overlap(const Polygon& a, const Polygon& b);
//! Euclidean distance between two simple polygons as closed regions: 0 when
//! their boundaries cross or one contains the other, else the smallest
//! vertex-to-edge distance either way (where the distance of two disjoint
//! polygons is attained). Floating point, for clearances and "near" tests.
double polygon_distance(const Polygon& a, const Polygon& b);

//! Contact tolerance of furniture, m: a footprint may stick out of the room,
//! or into another footprint or the door's clear zone, by at most this much
//! and still count as inside, or as touching. Furniture placed flush with a
//! wall at a heading typed to 4-5 digits (1.5708 for pi/2) moves a corner
//! (half-extent x angle error) a few micrometres past the wall; this absorbs
//! it for half-extents up to about 2.5 m. The door centre and opening use the
//! same tolerance. The wheelchair's own checks (start pose, C-space,
//! collisions) stay exact.
inline constexpr double kContactTolerance = 1e-5;

//! How a footprint leaves a region: `amount` (m, a lower bound of the
//! largest distance of a point of it from the region, exact for corners
//! that stick out) and the edge i (from vertex i to i + 1) of the region
//! nearest to where it is largest.
struct Protrusion {
  double amount = 0.0;
  std::size_t edge = 0;
};

//! Empty if `inner` lies in `outer` but for points within `tolerance` of
//! `outer` (both simple, counter-clockwise); else how far it sticks out.
//! Exact: no point farther than `tolerance` passes; every point within
//! 0.98 x `tolerance` does (the corners of the allowance are 16-gons).
std::optional<Protrusion> protrusion(const Polygon& inner, const Polygon& outer,
                                     double tolerance = kContactTolerance);
//! Empty if the two footprints (simple, counter-clockwise) overlap at most
//! by contact: every common point within `tolerance` of the boundary of
//! each; else the depth of the overlap (m, a lower bound, exact for a corner
//! of one inside the other).
std::optional<double> overlap_depth(const Polygon& a, const Polygon& b,
                                    double tolerance = kContactTolerance);
//! "sticks out 0.012 m past the wall from (0,0) to (5,0)": the amount (3
//! significant digits) and the edge of `room` named by its end points.
std::string sticks_out_text(const Protrusion& protrusion, const Polygon& room);
//! A length in metres for messages, 3 significant digits ("0.012").
std::string metres_text(double metres);
//! polygon_inside within kContactTolerance (furniture in the room).
inline bool inside_with_contact(const Polygon& inner, const Polygon& outer) {
  return !protrusion(inner, outer).has_value();
}
//! overlap_depth(a, b, tolerance).has_value(), the same answer for every
//! input: furniture against furniture beyond contact. For two convex
//! footprints a common point deeper than the tolerance (checked with exact
//! side tests) answers without the Boolean operation.
bool overlap_beyond_contact(const Polygon& a, const Polygon& b,
                            double tolerance = kContactTolerance);

//! Convex pieces whose union is the simple counter-clockwise polygon: CGAL's
//! optimal convex partition (fewest pieces; Greene's dynamic program, O(n⁴)
//! for n vertices, cheap for furniture outlines); a convex input is returned
//! as is.
std::vector<Polygon> convex_partition(const Polygon& polygon);
//! Convex hull in doubles (monotone chain), counter-clockwise, of at least 3
//! points. Its vertices are input points and rounding in the orientation
//! tests can only drop points within rounding of the hull, so it never
//! exceeds the true hull; callers needing a cover take supports over all the
//! points instead.
std::vector<Vec2> convex_hull_doubles(std::vector<Vec2> points);
//! Separating-axis scan in doubles: for each edge normal of `a`, then of
//! `b` (edges of zero length skipped), calls `found(overlap)` with the
//! length the two polygons' projections on it share (negative: the gap
//! between them) and returns true at the first call that returns true. For
//! convex polygons, an axis with a negative overlap separates them (the
//! separating axis theorem); callers that need an exact answer use it only
//! as a shortcut whose margin covers the rounding.
template <class Found>
bool any_edge_axis(const Polygon& a, const Polygon& b, Found&& found) {
  for (const Polygon* p : {&a, &b}) {
    const std::size_t n = p->size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 e = (*p)[(i + 1) % n] - (*p)[i];
      const double len = std::hypot(e.x, e.y);
      if (!(len > 0.0)) continue;
      const Vec2 axis{-e.y / len, e.x / len};
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (const Vec2& v : a) {
        const double d = v.x * axis.x + v.y * axis.y;
        amin = std::min(amin, d);
        amax = std::max(amax, d);
      }
      for (const Vec2& v : b) {
        const double d = v.x * axis.x + v.y * axis.y;
        bmin = std::min(bmin, d);
        bmax = std::max(bmax, d);
      }
      if (found(std::min(amax, bmax) - std::max(amin, bmin))) return true;
    }
  }
  return false;
}

//! Convex pieces covering (room bounding box grown by `margin`) minus the room.
std::vector<Polygon> complement_pieces(const Polygon& room, double margin);

}  // namespace hrs::geometry
