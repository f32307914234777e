// SPDX-License-Identifier: GPL-3.0-or-later
// Exact, conservative C-space: see cspace.h for the construction.
//
// Certification argument. Every C-obstacle piece is P = A ⊕ (−S_k) for a
// convex obstacle piece A and the convex cover S_k of the swept chair. P is the
// intersection of the half-planes {x : n·x <= h_A(n) + h_S(−n)} over the edge
// normals n of A and of −S_k (support functions; exact for any unit vector n,
// whatever rounding made n). Values are computed in doubles; every support
// value is raised by kMargin, which bounds the accumulated rounding error of
// the dot products and sums by several orders of magnitude for coordinates up
// to kMaxCoordinate (error <= ~8 u |n| |x| ≈ 2e-12 m at 1 km). A point (or a
// segment/triangle by separating axes) is reported outside P only when it is
// beyond a raised half-plane, so the true footprint cannot touch A. Slices
// overlap by kSliceOverlap radians so rounding of the heading cannot put a pose
// into the wrong slice.

#include "geometry/cspace.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geometry/polygon_ops.h"

namespace hrs::geometry {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMargin = 1e-9;        // metres, see the certification argument
constexpr double kSliceOverlap = 1e-9;  // radians
constexpr double kMaxCoordinate = 1e3;  // metres
constexpr int kRefineDepth = 4;         // arcs: slice pieces split down to 5°/16

Vec2 unit(Vec2 v) {
  const double l = norm(v);
  return {v.x / l, v.y / l};
}

//! Convex hull of 12 points into a fixed array (no allocation); returns the
//! vertex count. Same algorithm and caveat as convex_hull_doubles(); rounding
//! only affects tightness: supports are always taken over all the points.
int hull_fixed(const Vec2 (&in)[12], Vec2 (&out)[12]) {
  Vec2 pts[12];
  std::copy(in, in + 12, pts);
  std::sort(pts, pts + 12, [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  Vec2 h[24];
  int k = 0;
  for (int i = 0; i < 12; ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (int i = 10, t = k + 1; i >= 0; --i) {
    while (k >= t && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
    h[k++] = pts[i];
  }
  const int n = std::min(k - 1, 12);
  std::copy(h, h + n, out);
  return n;
}

//! Outward unit normals of a counter-clockwise convex polygon's edges.
std::vector<Vec2> edge_normals(const std::vector<Vec2>& poly) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 e = poly[(i + 1) % poly.size()] - poly[i];
    if (norm(e) > 0) out.push_back(unit({e.y, -e.x}));
  }
  return out;
}

double support(const std::vector<Vec2>& pts, Vec2 n) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec2& p : pts) best = std::max(best, dot(n, p));
  return best;
}

double support(const Vec2* pts, int n, Vec2 m) {
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) best = std::max(best, dot(m, pts[i]));
  return best;
}

//! Points whose hull covers the chair (corners `corners`) rotating over
//! headings [a, b] (b − a < π): each corner at both ends, and the meeting
//! point of the tangents at its arc's ends, at radius r / cos((b − a) / 2).
void swept_cover(const Vec2 (&corners)[4], double a, double b, Vec2 (&out)[12]) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  for (int i = 0; i < 4; ++i) {
    const Vec2 c = corners[i];
    const double r = norm(c), phi = std::atan2(c.y, c.x);
    out[3 * i] = r * Vec2{std::cos(phi + a), std::sin(phi + a)};
    out[3 * i + 1] = r * Vec2{std::cos(phi + b), std::sin(phi + b)};
    out[3 * i + 2] = (r / std::cos(half)) * Vec2{std::cos(phi + mid), std::sin(phi + mid)};
  }
}

}  // namespace

CSpace::CSpace(const Scene& scene, CSpaceOptions options) : slices_(options.slices) {
  if (slices_ < 4) throw std::invalid_argument("CSpace: at least 4 orientation slices");
  room_ = scene.room.polygon;
  room_box_ = bounding_box(room_);
  for (const Vec2& v : room_) {
    if (std::abs(v.x) > kMaxCoordinate || std::abs(v.y) > kMaxCoordinate)
      throw std::invalid_argument("CSpace: room coordinates beyond 1 km");
  }
  build_slice_shapes(scene.wheelchair);
  build_walls(room_, 0.5 * std::hypot(scene.wheelchair.length, scene.wheelchair.width));
  for (const Object& o : scene.objects) {
    ObjectState s;
    s.pose = o.pose;
    s.footprint = o.footprint;
    s.local_pieces = convex_partition(o.footprint);
    objects_.push_back(std::move(s));
  }
  // Slice layout: wall pieces first, then each object's pieces in order. The
  // number of half-planes of a piece never changes, so ranges stay fixed.
  for (Slice& sl : slice_data_) {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      SlicePiece sp{-1, static_cast<std::int32_t>(w), 0, 0, {}, {}};
      fill_piece(sl, walls_[w], sp, sl.base);
      sl.pieces.push_back(sp);
    }
  }
  for (int i = 0; i < object_count(); ++i) {
    rebuild_object_pieces(i);
    for (Slice& sl : slice_data_) {
      for (std::size_t p = 0; p < objects_[i].pieces.size(); ++p) {
        SlicePiece sp{i, static_cast<std::int32_t>(p), 0, 0, {}, {}};
        fill_piece(sl, objects_[i].pieces[p], sp, sl.base);
        sl.pieces.push_back(sp);
      }
    }
  }
  for (Slice& sl : slice_data_) {
    sl.world = sl.base;
    for (SlicePiece& sp : sl.pieces) sp.box = sp.base_box;
  }
  for (int i = 0; i < object_count(); ++i) place_object(i);
  // Walls sit at the origin: only the margin is added.
  for (Slice& sl : slice_data_) {
    for (SlicePiece& sp : sl.pieces) {
      if (sp.owner >= 0) continue;
      for (std::uint32_t h = sp.first; h < sp.first + sp.count; ++h) sl.world[h].c += kMargin;
      sp.box = {sp.base_box.xmin - kMargin, sp.base_box.ymin - kMargin, sp.base_box.xmax + kMargin,
                sp.base_box.ymax + kMargin};
    }
  }
}

void CSpace::build_slice_shapes(const Wheelchair& chair) {
  const double hl = 0.5 * chair.length, hw = 0.5 * chair.width;
  corners_[0] = {hl, hw}, corners_[1] = {-hl, hw}, corners_[2] = {-hl, -hw},
  corners_[3] = {hl, -hw};
  const double step = 2.0 * kPi / slices_;
  slice_data_.assign(slices_, Slice{});
  for (int k = 0; k < slices_; ++k) {
    const double a = -kPi + k * step - kSliceOverlap;
    const double b = -kPi + (k + 1) * step + kSliceOverlap;
    Vec2 pts[12];
    swept_cover(corners_, a, b, pts);
    slice_data_[k].swept = convex_hull_doubles(std::vector<Vec2>(pts, pts + 12));
    slice_data_[k].swept_normals = edge_normals(slice_data_[k].swept);
  }
}

void CSpace::build_walls(const Polygon& room, double reach) {
  // The chair centre is kept inside the room's bounding box, so its footprint
  // stays within that box grown by the chair's reach (plus the slice cover's
  // sub-millimetre bulge): wall pieces must cover at least that band.
  for (const Polygon& p : complement_pieces(room, reach + 0.5)) {
    ConvexPiece piece;
    piece.local = p;
    piece.normals = edge_normals(p);
    walls_.push_back(std::move(piece));
  }
}

void CSpace::rebuild_object_pieces(int index) {
  ObjectState& s = objects_[index];
  s.pieces.clear();
  for (const Polygon& lp : s.local_pieces) {
    ConvexPiece piece;
    for (const Vec2& v : lp) piece.local.push_back(rotate(v, s.pose.theta));
    piece.normals = edge_normals(piece.local);
    s.pieces.push_back(std::move(piece));
  }
  set_world_boundary(s);
}

void CSpace::fill_piece(const Slice& slice, const ConvexPiece& shape, SlicePiece& out,
                        std::vector<Halfplane>& base) const {
  const bool fresh = out.count == 0;
  if (fresh) out.first = static_cast<std::uint32_t>(base.size());
  std::uint32_t h = out.first;
  auto put = [&](Vec2 n) {
    const double c = support(shape.local, n) + support(slice.swept, {-n.x, -n.y});
    if (fresh) {
      base.push_back({n.x, n.y, c});
    } else {
      base[h] = {n.x, n.y, c};
    }
    ++h;
  };
  for (const Vec2& n : shape.normals) put(n);
  for (const Vec2& n : slice.swept_normals) put({-n.x, -n.y});
  if (fresh) out.count = h - out.first;
  // Box of A ⊕ (−S): supports along the axes.
  out.base_box = {-support(shape.local, {-1, 0}) - support(slice.swept, {1, 0}),
                  -support(shape.local, {0, -1}) - support(slice.swept, {0, 1}),
                  support(shape.local, {1, 0}) + support(slice.swept, {-1, 0}),
                  support(shape.local, {0, 1}) + support(slice.swept, {0, -1})};
}

void CSpace::place_object(int index) {
  const Vec2 t = objects_[index].pose.position();
  for (Slice& sl : slice_data_) {
    for (SlicePiece& sp : sl.pieces) {
      if (sp.owner != index) continue;
      for (std::uint32_t h = sp.first; h < sp.first + sp.count; ++h) {
        const Halfplane& b = sl.base[h];
        sl.world[h] = {b.nx, b.ny, b.c + (b.nx * t.x + b.ny * t.y) + kMargin};
      }
      sp.box = {sp.base_box.xmin + t.x - kMargin, sp.base_box.ymin + t.y - kMargin,
                sp.base_box.xmax + t.x + kMargin, sp.base_box.ymax + t.y + kMargin};
    }
  }
}

void CSpace::move_object(int index, const Pose2& pose) {
  assert(index >= 0 && index < object_count() && "move_object: no such object");
  assert(std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.theta));
  ObjectState& s = objects_.at(index);
  const bool rotated = pose.theta != s.pose.theta;
  s.pose = pose;
  if (rotated) {
    rebuild_object_pieces(index);
    for (Slice& sl : slice_data_) {
      for (SlicePiece& sp : sl.pieces) {
        if (sp.owner == index) fill_piece(sl, s.pieces[sp.piece], sp, sl.base);
      }
    }
  } else {
    set_world_boundary(s);
  }
  place_object(index);
}

int CSpace::slice_of(double theta) const {
  const double u = (wrap_angle(theta) + kPi) * (slices_ / (2.0 * kPi));
  const int k = static_cast<int>(std::floor(u));
  return std::clamp(k, 0, slices_ - 1);
}

const CSpace::ConvexPiece& CSpace::shape_of(const SlicePiece& piece) const {
  return piece.owner < 0 ? walls_[piece.piece] : objects_[piece.owner].pieces[piece.piece];
}

bool CSpace::hits(const Slice& slice, const SlicePiece& piece, const Vec2* pts, int n,
                  const Vec2* axes, int naxes) const {
  // Bounding boxes.
  double xmin = pts[0].x, xmax = pts[0].x, ymin = pts[0].y, ymax = pts[0].y;
  for (int i = 1; i < n; ++i) {
    xmin = std::min(xmin, pts[i].x), xmax = std::max(xmax, pts[i].x);
    ymin = std::min(ymin, pts[i].y), ymax = std::max(ymax, pts[i].y);
  }
  if (xmin > piece.box.xmax || xmax < piece.box.xmin || ymin > piece.box.ymax ||
      ymax < piece.box.ymin)
    return false;
  // The piece's own facets.
  const Halfplane* hp = slice.world.data() + piece.first;
  for (std::uint32_t h = 0; h < piece.count; ++h) {
    double lo = hp[h].nx * pts[0].x + hp[h].ny * pts[0].y;
    for (int i = 1; i < n; ++i) lo = std::min(lo, hp[h].nx * pts[i].x + hp[h].ny * pts[i].y);
    if (lo > hp[h].c) return false;
  }
  if (naxes == 0) return true;
  // The motion's own edge normals: supports of P = A + t ⊕ (−S).
  const ConvexPiece& shape = shape_of(piece);
  const Vec2 t = piece.owner < 0 ? Vec2{} : objects_[piece.owner].pose.position();
  for (int a = 0; a < naxes; ++a) {
    const Vec2 m = axes[a];
    double lo = dot(m, pts[0]), hi = lo;
    for (int i = 1; i < n; ++i) {
      const double v = dot(m, pts[i]);
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double tm = dot(m, t);
    const double p_hi = support(shape.local, m) + tm + support(slice.swept, {-m.x, -m.y}) + kMargin;
    const double p_lo =
        -support(shape.local, {-m.x, -m.y}) + tm - support(slice.swept, m) - kMargin;
    if (lo > p_hi || hi < p_lo) return false;
  }
  return true;
}

namespace {

//! Certified separating-axis test between the convex piece `shape` (placed
//! at `t`) and a convex set Q given by its support function and its edge
//! normals `q_axes`: true when an axis separates them by more than kMargin.
template <class Shape, class Support>
bool separated(const Shape& shape, Vec2 t, Support&& q_support, const Vec2* q_axes, int nq) {
  auto test = [&](Vec2 m) {
    const double tm = dot(m, t);
    const double a_hi = support(shape.local, m) + tm;
    const double a_lo = -support(shape.local, {-m.x, -m.y}) + tm;
    return q_support(m) < a_lo - kMargin || -q_support(Vec2{-m.x, -m.y}) > a_hi + kMargin;
  };
  for (const Vec2& m : shape.normals)
    if (test(m)) return true;
  for (int i = 0; i < nq; ++i)
    if (test(q_axes[i])) return true;
  return false;
}

}  // namespace

bool CSpace::refine_hits(const SlicePiece& piece, const Motion& motion, int depth) const {
  return motion.kind == Motion::kArc ? arc_hits(piece, motion, depth)
                                     : straight_hits(piece, motion);
}

bool CSpace::straight_hits(const SlicePiece& piece, const Motion& motion) const {
  // The footprint at its exact heading, swept along a straight line: a
  // rectangle's corners at both ends (the same point twice for a pose).
  const Vec2 t = piece.owner < 0 ? Vec2{} : objects_[piece.owner].pose.position();
  const Vec2 u{std::cos(motion.start.theta), std::sin(motion.start.theta)};
  const Vec2 v{-u.y, u.x};
  const Vec2 p0 = motion.start.position(), p1 = p0 + motion.length * u;
  Vec2 q[8];
  for (int i = 0; i < 4; ++i) {
    const Vec2 c = corners_[i].x * u + corners_[i].y * v;
    q[i] = p0 + c, q[i + 4] = p1 + c;
  }
  const Vec2 axes[2] = {u, v};
  return !separated(shape_of(piece), t, [&](Vec2 m) { return support(q, 8, m); }, axes, 2);
}

bool CSpace::arc_hits(const SlicePiece& piece, const Motion& motion, int depth) const {
  // A sub-arc whose end (or middle) pose truly overlaps the piece is a
  // certain hit; otherwise test the cover: centre positions in the triangle T
  // and the footprint inside the swept cover of the heading range, T ⊕ cover,
  // whose normals are those of T and of the cover. Split while undecided.
  auto pose_hits = [&](double h) {
    const double phi = h - motion.side * 0.5 * kPi;
    const Pose2 at{motion.centre.x + motion.radius * std::cos(phi),
                   motion.centre.y + motion.radius * std::sin(phi), h};
    return straight_hits(piece, Motion{Motion::kPose, at, 0.0, {}, 0.0, 0.0, 0.0, 0.0});
  };
  if (depth == 0 && (pose_hits(motion.ha) || pose_hits(motion.hb))) return true;
  Vec2 cover[12];
  swept_cover(corners_, std::min(motion.ha, motion.hb), std::max(motion.ha, motion.hb), cover);
  Vec2 cover_hull[12];
  const int nh = hull_fixed(cover, cover_hull);
  Vec2 tri[3];
  Vec2 axes[16];
  int naxes = arc_triangle(motion, motion.ha, motion.hb, tri, axes);
  for (int i = 0; i < nh && naxes < 16; ++i) {
    const Vec2 e = cover_hull[(i + 1) % nh] - cover_hull[i];
    const double l = norm(e);
    if (l > 1e-12) axes[naxes++] = {e.y / l, -e.x / l};
  }
  const Vec2 t = piece.owner < 0 ? Vec2{} : objects_[piece.owner].pose.position();
  const auto q_support = [&](Vec2 m) { return support(tri, 3, m) + support(cover_hull, nh, m); };
  if (separated(shape_of(piece), t, q_support, axes, naxes)) return false;
  if (depth >= kRefineDepth) return true;
  const double mid = 0.5 * (motion.ha + motion.hb);
  if (pose_hits(mid)) return true;
  Motion lo = motion, hi = motion;
  lo.hb = hi.ha = mid;
  return arc_hits(piece, lo, depth + 1) || arc_hits(piece, hi, depth + 1);
}

int CSpace::arc_triangle(const Motion& m, double ha, double hb, Vec2 (&tri)[3], Vec2* axes) const {
  const double pa = ha - m.side * 0.5 * kPi, pb = hb - m.side * 0.5 * kPi;
  const double pm = 0.5 * (pa + pb), half = 0.5 * std::abs(pb - pa);
  tri[0] = m.centre + m.radius * Vec2{std::cos(pa), std::sin(pa)};
  tri[1] = m.centre + m.radius * Vec2{std::cos(pb), std::sin(pb)};
  tri[2] = m.centre + (m.radius / std::cos(half)) * Vec2{std::cos(pm), std::sin(pm)};
  int naxes = 0;
  for (int e = 0; e < 3; ++e) {
    const Vec2 d = tri[(e + 1) % 3] - tri[e];
    const double l = norm(d);
    if (l > 1e-12) axes[naxes++] = {-d.y / l, d.x / l};
  }
  return naxes;
}

bool CSpace::points_free(int slice, const Vec2* pts, int n, const Vec2* axes, int naxes,
                         const Motion& motion) const {
  for (int i = 0; i < n; ++i) {
    if (!(pts[i].x >= room_box_.xmin && pts[i].x <= room_box_.xmax && pts[i].y >= room_box_.ymin &&
          pts[i].y <= room_box_.ymax))
      return false;
  }
  const Slice& sl = slice_data_[slice];
  for (const SlicePiece& sp : sl.pieces) {
    // The slice test is fast but as loose as the slice is wide; a hit is
    // confirmed against the piece with the motion's own headings.
    if (hits(sl, sp, pts, n, axes, naxes) && refine_hits(sp, motion, 0)) return false;
  }
  return true;
}

bool CSpace::is_free(const Pose2& pose) const {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) return false;
  const Vec2 p = pose.position();
  const Motion motion{Motion::kPose, pose, 0.0, {}, 0.0, 0.0, 0.0, 0.0};
  return points_free(slice_of(pose.theta), &p, 1, nullptr, 0, motion);
}

bool CSpace::straight_free(const Pose2& start, double length) const {
  if (!std::isfinite(length)) return false;
  const Vec2 dir{std::cos(start.theta), std::sin(start.theta)};
  const Vec2 pts[2] = {start.position(), start.position() + length * dir};
  if (!std::isfinite(pts[0].x) || !std::isfinite(pts[0].y) || !std::isfinite(start.theta))
    return false;
  const Vec2 axis{-dir.y, dir.x};  // the segment's normal
  const Motion motion{Motion::kStraight, start, length, {}, 0.0, 0.0, 0.0, 0.0};
  return points_free(slice_of(start.theta), pts, 2, &axis, std::abs(length) > 0 ? 1 : 0, motion);
}

bool CSpace::arc_free(const Pose2& start, double radius, double turn, int gear) const {
  if (!std::isfinite(turn) || !(radius > 0) || !std::isfinite(radius)) return false;
  if (turn == 0.0) return is_free(start);
  const double side = turn > 0 ? 1.0 : -1.0;          // +1: centre on the left
  const double dh = (gear >= 0 ? 1.0 : -1.0) * turn;  // signed heading change
  const double h0 = start.theta, h1 = start.theta + dh;
  // Centre of rotation and the position angle at heading h: phi = h - side·π/2.
  const Vec2 centre = start.position() + (side * radius) * Vec2{-std::sin(h0), std::cos(h0)};
  const double step = 2.0 * kPi / slices_;
  const double dir = dh > 0 ? 1.0 : -1.0;
  // Cut at slice borders (-π + j·step, continued periodically).
  double ha = h0;
  for (int guard = 0; guard < 4 * slices_ + 8; ++guard) {
    const double u = (ha + kPi) / step;
    double border =
        dir > 0 ? (std::floor(u) + 1.0) * step - kPi : (std::ceil(u) - 1.0) * step - kPi;
    // ha already on a border (to rounding): move to the next one.
    if (std::abs(border - ha) < 1e-12) border += dir * step;
    const bool last = dir > 0 ? border >= h1 : border <= h1;
    const double hb = last ? h1 : border;
    const Motion motion{Motion::kArc, start, 0.0, centre, radius, side, ha, hb};
    Vec2 tri[3];
    Vec2 axes[3];
    const int naxes = arc_triangle(motion, ha, hb, tri, axes);
    if (!points_free(slice_of(0.5 * (ha + hb)), tri, 3, axes, naxes, motion)) return false;
    if (last) return true;
    ha = hb;
  }
  return false;  // unreachable for finite input
}

namespace {

//! Squared distance from `p` to the segment [a, b] (no hypot: metres in a
//! room are far from overflow, and the square root is taken once per side).
double squared_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  const Vec2 d = p - (a + t * ab);
  return dot(d, d);
}

//! Folds the squared distances from `p` to the closed polygon `ring`, each
//! edge clipped to the closed half-plane left (side 0) or right (side 1) of
//! heading `left`, into `best`, recording `owner` on each side it lowers.
void visit_ring(const std::vector<Vec2>& ring, Vec2 p, Vec2 left, int owner, double best[2],
                int owners[2]) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const double sa = dot(a - p, left), sb = dot(b - p, left);
    for (int side = 0; side < 2; ++side) {
      const double sgn = side == 0 ? 1.0 : -1.0;
      const double da = sgn * sa, db = sgn * sb;
      if (da < 0 && db < 0) continue;
      Vec2 ca = a, cb = b;
      if (da < 0) ca = a + (da / (da - db)) * (b - a);
      if (db < 0) cb = b + (db / (db - da)) * (a - b);
      const double d = squared_distance(p, ca, cb);
      if (d < best[side]) {
        best[side] = d;
        owners[side] = owner;
      }
    }
  }
}

Vec2 left_of(const Pose2& pose) { return {-std::sin(pose.theta), std::cos(pose.theta)}; }

}  // namespace

void CSpace::set_world_boundary(ObjectState& s) {
  s.world_boundary.clear();
  for (const Vec2& v : s.footprint) s.world_boundary.push_back(to_world(s.pose, v));
  Box& b = s.world_box;
  b = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
       -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Vec2& v : s.world_boundary)
    b = {std::min(b.xmin, v.x), std::min(b.ymin, v.y), std::max(b.xmax, v.x),
         std::max(b.ymax, v.y)};
}

CSpace::NearestObstacles CSpace::nearest_obstacles(const Pose2& pose) const {
  const Vec2 p = pose.position(), left = left_of(pose);
  double best[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
  int owners[2] = {kNothing, kNothing};
  visit_ring(room_, p, left, kWalls, best, owners);
  for (std::size_t k = 0; k < objects_.size(); ++k) {
    // Every boundary point is in the object's box: when the box is farther
    // than both sides' best (with a margin far above the rounding of these
    // squared distances), no edge can lower either side.
    const Box& b = objects_[k].world_box;
    const double dx = std::max({b.xmin - p.x, 0.0, p.x - b.xmax});
    const double dy = std::max({b.ymin - p.y, 0.0, p.y - b.ymax});
    if ((dx * dx + dy * dy) * (1.0 - 1e-9) > std::max(best[0], best[1])) continue;
    visit_ring(objects_[k].world_boundary, p, left, static_cast<int>(k), best, owners);
  }
  return {{std::sqrt(best[0]), std::sqrt(best[1])}, owners[0], owners[1]};
}

Clearance CSpace::clearance(const Pose2& pose) const { return nearest_obstacles(pose).clearance; }

double CSpace::object_reach(int index) const {
  double r2 = 0.0;
  for (const Vec2& v : objects_[index].footprint) r2 = std::max(r2, dot(v, v));
  return std::sqrt(r2);
}

double CSpace::swept_reach() const {
  double r2 = 0.0;
  for (const Slice& s : slice_data_)
    for (const Vec2& v : s.swept) r2 = std::max(r2, dot(v, v));
  return std::sqrt(r2);
}

Clearance CSpace::object_clearance(const Pose2& pose, int index) const {
  double best[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
  int owners[2] = {kNothing, kNothing};
  visit_ring(objects_[index].world_boundary, pose.position(), left_of(pose), index, best, owners);
  return {std::sqrt(best[0]), std::sqrt(best[1])};
}

std::size_t CSpace::piece_count() const {
  std::size_t n = 0;
  for (const Slice& sl : slice_data_) n += sl.pieces.size();
  return n;
}

}  // namespace hrs::geometry
