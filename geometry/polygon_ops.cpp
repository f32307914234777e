// SPDX-License-Identifier: GPL-3.0-or-later
// Exact polygon predicates and decompositions. Predicates use CGAL's
// exact-predicates kernel (double input taken exactly); region tests that need
// new points (containment, overlap) use the exact-constructions kernel.

#include "geometry/polygon_ops.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <list>
#include <numbers>

namespace hrs::geometry {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class K>
CGAL::Polygon_2<K> to_cgal(const Polygon& p) {
  CGAL::Polygon_2<K> out;
  for (const Vec2& v : p) out.push_back(typename K::Point_2(v.x, v.y));
  return out;
}

Epick::Point_2 pt(Vec2 v) { return {v.x, v.y}; }

bool is_convex_ccw(const Polygon& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (CGAL::orientation(pt(p[i]), pt(p[(i + 1) % n]), pt(p[(i + 2) % n])) == CGAL::RIGHT_TURN)
      return false;
  }
  return true;
}

//! Greedy Hertel–Mehlhorn: merge pieces across shared edges while convex.
std::vector<Polygon> merge_convex(std::vector<Polygon> pieces) {
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t a = 0; a < pieces.size() && !merged; ++a) {
      for (std::size_t b = a + 1; b < pieces.size() && !merged; ++b) {
        const Polygon& A = pieces[a];
        const Polygon& B = pieces[b];
        for (std::size_t i = 0; i < A.size() && !merged; ++i) {
          const Vec2 u = A[i], v = A[(i + 1) % A.size()];
          for (std::size_t j = 0; j < B.size(); ++j) {
            if (!(B[j] == v && B[(j + 1) % B.size()] == u)) continue;
            // Merged boundary: A from v around to u, then B from u around to v.
            Polygon m;
            for (std::size_t k = 0; k < A.size(); ++k) m.push_back(A[(i + 1 + k) % A.size()]);
            for (std::size_t k = 2; k < B.size(); ++k) m.push_back(B[(j + k) % B.size()]);
            if (is_convex_ccw(m)) {
              // Drop collinear vertices left at the former diagonal's ends.
              Polygon clean;
              for (std::size_t k = 0; k < m.size(); ++k) {
                const Vec2 prev = m[(k + m.size() - 1) % m.size()], next = m[(k + 1) % m.size()];
                if (CGAL::orientation(pt(prev), pt(m[k]), pt(next)) != CGAL::COLLINEAR)
                  clean.push_back(m[k]);
              }
              pieces[a] = clean;
              pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(b));
              merged = true;
            }
            break;
          }
        }
      }
    }
  }
  return pieces;
}

using EpeckPolygon = CGAL::Polygon_2<Epeck>;
using EpeckSet = CGAL::Polygon_set_2<Epeck>;

//! Distance from p to the boundary of the polygon and the nearest edge.
std::pair<double, std::size_t> boundary_distance(Vec2 p, const Polygon& poly) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t edge = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const double d = point_segment_distance(p, poly[i], poly[(i + 1) % poly.size()]);
    if (d < best) {
      best = d;
      edge = i;
    }
  }
  return {best, edge};
}

//! The largest boundary distance (and its edge) of the vertices of `points`
//! that lie on the given side of `poly` (exact side tests).
std::pair<double, std::size_t> deepest(const Polygon& points, const Polygon& poly,
                                       CGAL::Bounded_side side) {
  const auto p = to_cgal<Epick>(poly);
  std::pair<double, std::size_t> best{0.0, 0};
  for (const Vec2& v : points) {
    if (p.bounded_side(pt(v)) != side) continue;
    const auto d = boundary_distance(v, poly);
    if (d.first > best.first) best = d;
  }
  return best;
}

Vec2 to_vec(const Epeck::Point_2& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

//! The allowance of `tolerance` along the boundary of a counter-clockwise
//! polygon, on its outer (`outward`) or inner side: a band of that width
//! on each edge and a 16-gon inscribed in the circle of that radius at each
//! vertex. Every piece lies within `tolerance` of the boundary; together
//! they cover every point on that side within 0.98 x `tolerance` of it.
std::vector<EpeckPolygon> allowance(const Polygon& poly, double tolerance, bool outward) {
  std::vector<EpeckPolygon> pieces;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % n];
    const Vec2 d = (1.0 / norm(b - a)) * (b - a);
    const Vec2 left{-d.y, d.x};
    Polygon band;
    if (outward) {
      band = {a, a - tolerance * left, b - tolerance * left, b};
    } else {
      band = {a, b, b + tolerance * left, a + tolerance * left};
    }
    pieces.push_back(to_cgal<Epeck>(band));
    Polygon cap;
    for (int k = 0; k < 16; ++k) {
      const double phi = k * std::numbers::pi / 8.0;
      cap.push_back({a.x + tolerance * std::cos(phi), a.y + tolerance * std::sin(phi)});
    }
    pieces.push_back(to_cgal<Epeck>(cap));
  }
  return pieces;
}

//! True if the region is covered by the pieces (exact Boolean operations;
//! pieces away from the region's box are skipped).
bool covered(EpeckSet region, const std::vector<EpeckPolygon>& pieces) {
  std::list<CGAL::Polygon_with_holes_2<Epeck>> parts;
  region.polygons_with_holes(std::back_inserter(parts));
  if (parts.empty()) return true;
  CGAL::Bbox_2 box = parts.front().outer_boundary().bbox();
  for (const auto& part : parts) box += part.outer_boundary().bbox();
  for (const auto& piece : pieces) {
    if (!CGAL::do_overlap(box, piece.bbox())) continue;
    region.difference(piece);
    if (region.is_empty()) return true;
  }
  return region.is_empty();
}

//! The largest boundary distance from `poly` (and its edge) of the points
//! of what is left of `region`: its vertices and 64 points along each of its
//! edges (doubles; for messages: the largest can lie inside an edge, as
//! where a footprint's edge passes between two walls).
std::pair<double, std::size_t> deepest_left(const EpeckSet& region, const Polygon& poly) {
  std::list<CGAL::Polygon_with_holes_2<Epeck>> parts;
  region.polygons_with_holes(std::back_inserter(parts));
  std::pair<double, std::size_t> best{0.0, 0};
  const auto visit = [&](const EpeckPolygon& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = to_vec(ring[i]), b = to_vec(ring[(i + 1) % n]);
      for (int k = 0; k < 64; ++k) {
        const auto d = boundary_distance(a + (k / 64.0) * (b - a), poly);
        if (d.first > best.first) best = d;
      }
    }
  };
  for (const auto& part : parts) {
    visit(part.outer_boundary());
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h) visit(*h);
  }
  return best;
}

//! The part of the convex counter-clockwise polygon `subject` inside the
//! convex counter-clockwise `clip` (Sutherland–Hodgman, floating point).
Polygon clip_convex(const Polygon& subject, const Polygon& clip) {
  Polygon out = subject;
  for (std::size_t i = 0; i < clip.size() && !out.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % clip.size()];
    const auto side = [&](Vec2 v) { return (b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x); };
    Polygon in;
    for (std::size_t k = 0; k < out.size(); ++k) {
      const Vec2 p = out[k], q = out[(k + 1) % out.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0.0) in.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) in.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    out = std::move(in);
  }
  return out;
}

//! True when a point is found strictly inside both polygons (exact side
//! tests) and more than `tolerance` (plus 1 nm for rounding) from the
//! boundary of one of them; the candidate, for two convex polygons, is the
//! vertex mean of their intersection clipped in floating point. Such a point
//! lies in the intersection and outside every allowance piece of that
//! polygon, so overlap_depth() returns a depth. False proves nothing.
bool deep_common_point(const Polygon& a, const Polygon& b, double tolerance) {
  const double need = tolerance + 1e-9;
  const auto ca = to_cgal<Epick>(a), cb = to_cgal<Epick>(b);
  const auto deep = [&](Vec2 v) {
    return ca.bounded_side(pt(v)) == CGAL::ON_BOUNDED_SIDE &&
           cb.bounded_side(pt(v)) == CGAL::ON_BOUNDED_SIDE &&
           (boundary_distance(v, a).first > need || boundary_distance(v, b).first > need);
  };
  if (!is_convex_ccw(a) || !is_convex_ccw(b)) return false;
  const Polygon common = clip_convex(a, b);
  if (common.size() < 3) return false;
  Vec2 mean{0.0, 0.0};
  for (const Vec2& v : common) mean = mean + (1.0 / static_cast<double>(common.size())) * v;
  return deep(mean);
}

}  // namespace

bool is_simple(const Polygon& polygon) {
  if (polygon.size() < 3) return false;
  for (const Vec2& v : polygon)
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return false;
  const auto p = to_cgal<Epick>(polygon);
  return p.is_simple() && p.orientation() != CGAL::COLLINEAR;
}

bool is_counterclockwise(const Polygon& polygon) {
  return to_cgal<Epick>(polygon).orientation() == CGAL::COUNTERCLOCKWISE;
}

bool polygon_inside(const Polygon& inner, const Polygon& outer) {
  const auto a = to_cgal<Epeck>(inner);
  const auto b = to_cgal<Epeck>(outer);
  std::list<CGAL::Polygon_with_holes_2<Epeck>> rest;
  CGAL::difference(a, b, std::back_inserter(rest));
  return rest.empty();
}

bool interiors_overlap(const Polygon& a, const Polygon& b) {
  const auto pa = to_cgal<Epeck>(a);
  const auto pb = to_cgal<Epeck>(b);
  if (CGAL::do_overlap(pa.bbox(), pb.bbox()) == false) return false;
  std::list<CGAL::Polygon_with_holes_2<Epeck>> common;
  CGAL::intersection(pa, pb, std::back_inserter(common));
  return !common.empty();
}

std::optional<Protrusion> protrusion(const Polygon& inner, const Polygon& outer,
                                     double tolerance) {
  const auto a = to_cgal<Epeck>(inner);
  const auto b = to_cgal<Epeck>(outer);
  std::list<CGAL::Polygon_with_holes_2<Epeck>> rest;
  CGAL::difference(a, b, std::back_inserter(rest));
  if (rest.empty()) return std::nullopt;
  // A corner farther out than the tolerance settles it.
  const auto corner = deepest(inner, outer, CGAL::ON_UNBOUNDED_SIDE);
  if (corner.first > tolerance) return Protrusion{corner.first, corner.second};
  EpeckSet region;
  for (const auto& part : rest) region.join(part);
  const auto pieces = allowance(outer, tolerance, true);
  if (covered(region, pieces)) return std::nullopt;
  // Where it sticks out beyond the allowance (a wall's corner poking into
  // the footprint leaves no vertex out: the region's edges are sampled).
  for (const auto& piece : pieces) region.difference(piece);
  Protrusion worst{std::max(tolerance, corner.first), corner.second};
  if (const auto left = deepest_left(region, outer); left.first > worst.amount)
    worst = {left.first, left.second};
  return worst;
}

std::string metres_text(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", metres);
  return buf;
}

std::string sticks_out_text(const Protrusion& protrusion, const Polygon& room) {
  const auto point = [](Vec2 v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.6g,%.6g)", v.x, v.y);
    return std::string(buf);
  };
  const std::size_t i = protrusion.edge % room.size();
  return "sticks out " + metres_text(protrusion.amount) + " m past the wall from " +
         point(room[i]) + " to " + point(room[(i + 1) % room.size()]);
}

std::optional<double> overlap_depth(const Polygon& a, const Polygon& b, double tolerance) {
  const auto pa = to_cgal<Epeck>(a);
  const auto pb = to_cgal<Epeck>(b);
  if (CGAL::do_overlap(pa.bbox(), pb.bbox()) == false) return std::nullopt;
  // A corner of one strictly inside the other (an exact predicate) and
  // deeper than the tolerance: the interiors meet, so the intersection
  // below would be non-empty and the answer is this corner. Taken first, it
  // spares the Boolean operation, the costly part, with the same answer.
  const double corner = std::max(deepest(a, b, CGAL::ON_BOUNDED_SIDE).first,
                                 deepest(b, a, CGAL::ON_BOUNDED_SIDE).first);
  if (corner > tolerance) return corner;
  std::list<CGAL::Polygon_with_holes_2<Epeck>> common;
  CGAL::intersection(pa, pb, std::back_inserter(common));
  if (common.empty()) return std::nullopt;
  EpeckSet region;
  for (const auto& part : common) region.join(part);
  const auto near_b = allowance(b, tolerance, false);
  const auto near_a = allowance(a, tolerance, false);
  if (covered(region, near_b) && covered(region, near_a)) return std::nullopt;
  EpeckSet deep_b = region, deep_a = region;
  for (const auto& piece : near_b) deep_b.difference(piece);
  for (const auto& piece : near_a) deep_a.difference(piece);
  return std::max({corner, deepest_left(deep_b, b).first, deepest_left(deep_a, a).first,
                   tolerance});
}

bool overlap_beyond_contact(const Polygon& a, const Polygon& b, double tolerance) {
  return deep_common_point(a, b, tolerance) || overlap_depth(a, b, tolerance).has_value();
}

std::vector<Polygon> convex_partition(const Polygon& polygon) {
  if (is_convex_ccw(polygon)) return {polygon};
  using Traits = CGAL::Partition_traits_2<Epick>;
  Traits::Polygon_2 in;
  for (const Vec2& v : polygon) in.push_back(Traits::Point_2(v.x, v.y));
  std::list<Traits::Polygon_2> parts;
  CGAL::optimal_convex_partition_2(in.vertices_begin(), in.vertices_end(),
                                   std::back_inserter(parts), Traits());
  std::vector<Polygon> out;
  for (const auto& part : parts) {
    Polygon q;
    for (auto it = part.vertices_begin(); it != part.vertices_end(); ++it)
      q.push_back({it->x(), it->y()});  // original vertices: exact copies
    out.push_back(q);
  }
  return out;
}

std::vector<Polygon> complement_pieces(const Polygon& room, double margin) {
  using Fb =
      CGAL::Triangulation_face_base_with_info_2<int, Epick,
                                                CGAL::Constrained_triangulation_face_base_2<Epick>>;
  using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<Epick>, Fb>;
  using Cdt =
      CGAL::Constrained_Delaunay_triangulation_2<Epick, Tds, CGAL::No_constraint_intersection_tag>;

  const Box b = bounding_box(room);
  const Polygon box = {{b.xmin - margin, b.ymin - margin},
                       {b.xmax + margin, b.ymin - margin},
                       {b.xmax + margin, b.ymax + margin},
                       {b.xmin - margin, b.ymax + margin}};
  Cdt cdt;
  for (const Polygon* ring : {&box, &room}) {
    for (std::size_t i = 0; i < ring->size(); ++i)
      cdt.insert_constraint(pt((*ring)[i]), pt((*ring)[(i + 1) % ring->size()]));
  }
  // Nesting depth by flood fill across constrained edges: 0 outside the box,
  // 1 between box and room (the walls), 2 inside the room.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::list<Cdt::Face_handle> frontier{cdt.infinite_face()};
  cdt.infinite_face()->info() = 0;
  for (int depth = 0; !frontier.empty(); ++depth) {
    std::list<Cdt::Face_handle> next;
    while (!frontier.empty()) {
      auto f = frontier.front();
      frontier.pop_front();
      for (int i = 0; i < 3; ++i) {
        auto g = f->neighbor(i);
        if (g->info() != -1) continue;
        if (cdt.is_constrained({f, i})) {
          g->info() = depth + 1;
          next.push_back(g);
        } else {
          g->info() = depth;
          frontier.push_back(g);
        }
      }
    }
    frontier.swap(next);
  }
  std::vector<Polygon> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() != 1) continue;
    Polygon t;
    for (int i = 0; i < 3; ++i) t.push_back({f->vertex(i)->point().x(), f->vertex(i)->point().y()});
    triangles.push_back(t);  // CGAL faces are counter-clockwise
  }
  return merge_convex(std::move(triangles));
}

std::vector<Vec2> convex_hull_doubles(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (pts.size() < 3) return pts;
  std::vector<Vec2> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

double polygon_distance(const Polygon& a, const Polygon& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  if (point_in_polygon(a.front(), b) || point_in_polygon(b.front(), a)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 a0 = a[i], a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 b0 = b[j], b1 = b[(j + 1) % b.size()];
      if (segments_cross(a0, a1, b0, b1)) return 0.0;
      best =
          std::min({best, point_segment_distance(a0, b0, b1), point_segment_distance(b0, a0, a1)});
    }
  }
  return best;
}

}  // namespace hrs::geometry
