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
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <list>

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

}  // namespace hrs::geometry
