// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/nearest.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace hrs::planning {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

//! Short-way angular gap between two angles in (−pi, pi]: equal, bit for
//! bit, to |wrap_angle(a − b)|. a − b lies in (−2pi, 2pi), where wrap_angle
//! adds or subtracts 2pi once; 2pi − |a − b| is that sum's magnitude, and the
//! rounding of x − 2pi and 2pi − x is the same up to sign.
double angle_gap(double a, double b) {
  const double g = std::abs(a - b);
  return g > kPi ? kTwoPi - g : g;
}

//! Keeps the k best candidates in a max-heap (worst at the front).
template <class Candidate>
void offer(std::vector<Candidate>& heap, std::size_t k, const Candidate& c) {
  if (heap.size() < k) {
    heap.push_back(c);
    std::push_heap(heap.begin(), heap.end());
  } else if (c < heap.front()) {
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = c;
    std::push_heap(heap.begin(), heap.end());
  }
}
}  // namespace

// sqrt(dx² + dy²) rather than std::hypot: the coordinates are metres in a
// room, far from overflow, and hypot's scaling made it the planner's hottest
// function.
double PoseNearest::distance(const geometry::Pose2& a, const geometry::Pose2& b) const {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy) + weight_ * std::abs(geometry::wrap_angle(a.theta - b.theta));
}

double PoseNearest::ranking_distance(const geometry::Pose2& query,
                                     const geometry::Pose2& pose) const {
  const double q[3] = {query.x, query.y, geometry::wrap_angle(query.theta)};
  const double p[3] = {pose.x, pose.y, geometry::wrap_angle(pose.theta)};
  return point_distance(q, p);
}

double PoseNearest::point_distance(const double a[3], const double b[3]) const {
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  return std::sqrt(dx * dx + dy * dy) + weight_ * angle_gap(a[2], b[2]);
}

double PoseNearest::box_bound(const double q[3], const double lo[3], const double hi[3]) const {
  const double dx = q[0] < lo[0] ? lo[0] - q[0] : q[0] > hi[0] ? q[0] - hi[0] : 0.0;
  const double dy = q[1] < lo[1] ? lo[1] - q[1] : q[1] > hi[1] ? q[1] - hi[1] : 0.0;
  double dt = 0.0;
  if (q[2] < lo[2] || q[2] > hi[2]) dt = std::min(angle_gap(q[2], lo[2]), angle_gap(q[2], hi[2]));
  return std::sqrt(dx * dx + dy * dy) + weight_ * dt;
}

void PoseNearest::clear() {
  cells_.clear();
  id_.clear();
  leaf_of_.clear();
  removed_.clear();
  index_of_id_.clear();
}

void PoseNearest::insert(const geometry::Pose2& pose, std::int32_t id) {
  const auto order = static_cast<std::uint32_t>(id_.size());
  const Point point{pose.x, pose.y, geometry::wrap_angle(pose.theta), order};
  id_.push_back(id);
  removed_.push_back(0);
  if (id >= 0) {
    if (index_of_id_.size() <= static_cast<std::size_t>(id)) index_of_id_.resize(id + 1, -1);
    index_of_id_[id] = static_cast<std::int32_t>(order);
  }
  if (cells_.empty()) cells_.emplace_back();
  std::int32_t cur = 0;
  const double p[3] = {point.x, point.y, point.t};
  for (;;) {
    Cell& c = cells_[cur];
    ++c.alive;
    if (c.axis < 0) break;
    cur = c.child[p[c.axis] < c.split ? 0 : 1];
  }
  cells_[cur].points.push_back(point);
  leaf_of_.push_back(cur);
  if (cells_[cur].points.size() > cells_[cur].split_at) split_leaf(cur);
}

void PoseNearest::split_leaf(std::int32_t cell) {
  std::vector<Point> points = std::move(cells_[cell].points);
  const auto coord = [](const Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.t; };
  // The widest axis, θ measured in metres (w · radians) like the distance.
  int axis = 0;
  double widest = -1.0;
  for (int a = 0; a < 3; ++a) {
    double lo = kInf, hi = -kInf;
    for (const Point& p : points) {
      lo = std::min(lo, coord(p, a));
      hi = std::max(hi, coord(p, a));
    }
    const double width = (hi - lo) * (a == 2 ? weight_ : 1.0);
    if (width > widest) {
      widest = width;
      axis = a;
    }
  }
  std::vector<double> values;
  values.reserve(points.size());
  for (const Point& p : points) values.push_back(coord(p, axis));
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  double split = values[values.size() / 2];
  // Coordinates below the split go left: a median equal to the minimum would
  // leave the left side empty, so the split moves to the next larger value.
  if (std::none_of(points.begin(), points.end(),
                   [&](const Point& p) { return coord(p, axis) < split; })) {
    double next = kInf;
    for (const Point& p : points)
      if (coord(p, axis) > split) next = std::min(next, coord(p, axis));
    split = next;
  }
  if (!(split < kInf)) {  // every pose equal on the widest axis: all equal
    cells_[cell].points = std::move(points);
    cells_[cell].split_at = 2 * cells_[cell].points.size();
    return;
  }
  Cell left, right;
  left.parent = right.parent = cell;
  for (const Point& p : points) {
    Cell& side = coord(p, axis) < split ? left : right;
    side.points.push_back(p);
    if (!removed_[p.order]) ++side.alive;
  }
  const auto l = static_cast<std::int32_t>(cells_.size());
  cells_.push_back(std::move(left));
  cells_.push_back(std::move(right));
  for (int s = 0; s < 2; ++s)
    for (const Point& p : cells_[l + s].points) leaf_of_[p.order] = l + s;
  Cell& c = cells_[cell];
  c.axis = axis;
  c.split = split;
  c.child[0] = l;
  c.child[1] = l + 1;
}

void PoseNearest::remove(std::int32_t id) {
  if (id < 0 || static_cast<std::size_t>(id) >= index_of_id_.size()) return;
  const std::int32_t i = index_of_id_[id];
  if (i < 0 || removed_[i]) return;
  removed_[i] = 1;
  for (std::int32_t c = leaf_of_[i]; c >= 0; c = cells_[c].parent) --cells_[c].alive;
}

void PoseNearest::scan_leaf(const Cell& leaf, const double q[3], std::size_t k,
                            std::vector<Candidate>& heap) const {
  for (const Point& p : leaf.points) {
    if (removed_[p.order]) continue;
    const double dx = q[0] - p.x, dy = q[1] - p.y;
    const double turn = weight_ * angle_gap(q[2], p.t);
    if (heap.size() == k) {
      // Lower bounds of the distance below: sqrt(dx² + dy²) rounds to at
      // least |dx| and |dy|, and adding a non-negative term to `turn` rounds
      // to at least `turn`. A pose above the worst kept one cannot enter.
      const double worst = heap.front().d;
      if (turn > worst || std::abs(dx) > worst || std::abs(dy) > worst) continue;
    }
    offer(heap, k, Candidate{std::sqrt(dx * dx + dy * dy) + turn, p.order});
  }
}

void PoseNearest::search(std::int32_t cell, const double q[3], double lo[3], double hi[3],
                         std::size_t k, std::vector<Candidate>& heap) const {
  const Cell& c = cells_[cell];
  if (c.axis < 0) {
    scan_leaf(c, q, k, heap);
    return;
  }
  const int axis = c.axis;
  const int first = q[axis] < c.split ? 0 : 1;
  for (int pass = 0; pass < 2; ++pass) {
    const int side = pass == 0 ? first : 1 - first;
    const std::int32_t child = c.child[side];
    if (cells_[child].alive == 0) continue;
    // The child's cell: this cell cut at the split.
    double* bound = side == 0 ? &hi[axis] : &lo[axis];
    const double saved = *bound;
    *bound = c.split;
    if (heap.size() < k || box_bound(q, lo, hi) <= heap.front().d)
      search(child, q, lo, hi, k, heap);
    *bound = saved;
  }
}

void PoseNearest::nearest(const geometry::Pose2& query, std::size_t k,
                          std::vector<std::int32_t>& out) const {
  out.clear();
  if (cells_.empty() || k == 0) return;
  const double q[3] = {query.x, query.y, geometry::wrap_angle(query.theta)};
  std::vector<Candidate> heap;
  heap.reserve(k + 1);
  double lo[3] = {-kInf, -kInf, -kPi};
  double hi[3] = {kInf, kInf, kPi};
  search(0, q, lo, hi, k, heap);
  std::sort_heap(heap.begin(), heap.end());
  for (const Candidate& c : heap) out.push_back(id_[c.order]);
}

void QueryOrder::reset(const geometry::Pose2& query) {
  query_ = query;
  order_.clear();
  distance_of_id_.clear();
}

void QueryOrder::insert(const geometry::Pose2& pose, std::int32_t id) {
  assert(id >= 0);
  const auto slot = static_cast<std::size_t>(id);
  if (distance_of_id_.size() <= slot)
    distance_of_id_.resize(slot + 1, std::numeric_limits<double>::quiet_NaN());
  assert(std::isnan(distance_of_id_[slot]));
  const double d = metric_.ranking_distance(query_, pose);
  distance_of_id_[slot] = d;
  order_.emplace(d, id);
}

void QueryOrder::remove(std::int32_t id) {
  if (id < 0 || static_cast<std::size_t>(id) >= distance_of_id_.size()) return;
  double& d = distance_of_id_[static_cast<std::size_t>(id)];
  if (std::isnan(d)) return;
  order_.erase({d, id});
  d = std::numeric_limits<double>::quiet_NaN();
}

void QueryOrder::nearest(std::size_t k, std::vector<std::int32_t>& out) const {
  out.clear();
  for (auto it = order_.begin(); it != order_.end() && out.size() < k; ++it)
    out.push_back(it->second);
}

}  // namespace hrs::planning
