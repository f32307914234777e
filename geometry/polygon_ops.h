#pragma once
// Exact polygon predicates and decompositions (CGAL with exact predicates,
// confined to polygon_ops.cpp). Input coordinates are doubles, taken exactly.

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
//! Convex pieces covering (room bounding box grown by `margin`) minus the room.
std::vector<Polygon> complement_pieces(const Polygon& room, double margin);

}  // namespace hrs::geometry
