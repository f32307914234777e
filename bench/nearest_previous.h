// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The RRT's nearest-node index as it was at commit 96959f3 (one pose per
// kd-tree node, angle gaps through wrap_angle), frozen here so that
// planning_bench times planning::PoseNearest against its previous version in
// the same run (issue #32 item 4). Not used by the product.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "geometry/pose.h"

namespace hrs::bench {

class PreviousPoseNearest {
 public:
  //! `heading_weight`: metres per radian in the distance (w above).
  explicit PreviousPoseNearest(double heading_weight) : weight_(heading_weight) {}

  //! The weighted distance used for ranking.
  double distance(const geometry::Pose2& a, const geometry::Pose2& b) const;
  //! The distance nearest() ranks `pose` by for `query` (headings wrapped
  //! first, exactly as stored), bit for bit.
  double ranking_distance(const geometry::Pose2& query, const geometry::Pose2& pose) const;

  //! Adds a pose with the caller's id (ids need not be dense).
  void insert(const geometry::Pose2& pose, std::int32_t id);
  //! Removes the pose with this id from later answers (a tombstone: the
  //! node still guides the search, and subtrees with no live pose left are
  //! skipped, so a tree whose nodes are mostly removed stays fast).
  //! O(depth). Unknown or already removed ids are ignored.
  void remove(std::int32_t id);
  //! Ids of the (at most) k nearest poses to `query`, nearest first; ties are
  //! broken by insertion order, so the answer is deterministic.
  void nearest(const geometry::Pose2& query, std::size_t k, std::vector<std::int32_t>& out) const;

  //! Poses inserted, removed ones included.
  std::size_t size() const { return nodes_.size(); }
  void clear() {
    nodes_.clear();
    index_of_id_.clear();
  }
  double heading_weight() const { return weight_; }

  //! Below this many poses a linear scan answers queries.
  static constexpr std::size_t kLinearScanBelow = 32;

 private:
  struct Node {
    double p[3];  //!< x, y, theta wrapped to (−pi, pi]
    std::int32_t id;
    std::int32_t child[2] = {-1, -1};
    std::int32_t parent = -1;
    std::int32_t alive = 1;  //!< poses not removed in this subtree (itself included)
    bool removed = false;
  };
  struct Candidate {
    double d;
    std::uint32_t order;  //!< insertion index, breaks ties
    bool operator<(const Candidate& o) const { return d < o.d || (d == o.d && order < o.order); }
  };
  void search(std::int32_t node, int depth, const double q[3], double lo[3], double hi[3],
              std::size_t k, std::vector<Candidate>& heap) const;
  double point_distance(const double a[3], const double b[3]) const;
  double box_bound(const double q[3], const double lo[3], const double hi[3]) const;

  double weight_;
  std::vector<Node> nodes_;                //!< nodes_[0] is the kd-tree root
  std::vector<std::int32_t> index_of_id_;  //!< node index per non-negative id, or -1
};

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

//! Short-way angular gap between two wrapped angles.
double angle_gap(double a, double b) { return std::abs(geometry::wrap_angle(a - b)); }
}  // namespace

// sqrt(dx² + dy²) rather than std::hypot: the coordinates are metres in a
// room, far from overflow, and hypot's scaling made it the planner's hottest
// function.
inline double PreviousPoseNearest::distance(const geometry::Pose2& a, const geometry::Pose2& b) const {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy) + weight_ * angle_gap(a.theta, b.theta);
}

inline double PreviousPoseNearest::ranking_distance(const geometry::Pose2& query,
                                     const geometry::Pose2& pose) const {
  const double q[3] = {query.x, query.y, geometry::wrap_angle(query.theta)};
  const double p[3] = {pose.x, pose.y, geometry::wrap_angle(pose.theta)};
  return point_distance(q, p);
}

inline double PreviousPoseNearest::point_distance(const double a[3], const double b[3]) const {
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  return std::sqrt(dx * dx + dy * dy) + weight_ * angle_gap(a[2], b[2]);
}

inline double PreviousPoseNearest::box_bound(const double q[3], const double lo[3], const double hi[3]) const {
  const double dx = std::max({0.0, lo[0] - q[0], q[0] - hi[0]});
  const double dy = std::max({0.0, lo[1] - q[1], q[1] - hi[1]});
  double dt = 0.0;
  if (q[2] < lo[2] || q[2] > hi[2]) dt = std::min(angle_gap(q[2], lo[2]), angle_gap(q[2], hi[2]));
  return std::sqrt(dx * dx + dy * dy) + weight_ * dt;
}

inline void PreviousPoseNearest::insert(const geometry::Pose2& pose, std::int32_t id) {
  Node n;
  n.p[0] = pose.x;
  n.p[1] = pose.y;
  n.p[2] = geometry::wrap_angle(pose.theta);
  n.id = id;
  const auto index = static_cast<std::int32_t>(nodes_.size());
  nodes_.push_back(n);
  if (id >= 0) {
    if (index_of_id_.size() <= static_cast<std::size_t>(id)) index_of_id_.resize(id + 1, -1);
    index_of_id_[id] = index;
  }
  if (index == 0) return;
  std::int32_t cur = 0;
  int depth = 0;
  for (;;) {
    Node& c = nodes_[cur];
    ++c.alive;
    const int axis = depth % 3;
    const int side = n.p[axis] < c.p[axis] ? 0 : 1;
    if (c.child[side] < 0) {
      c.child[side] = index;
      nodes_[index].parent = cur;
      return;
    }
    cur = c.child[side];
    ++depth;
  }
}

inline void PreviousPoseNearest::remove(std::int32_t id) {
  if (id < 0 || static_cast<std::size_t>(id) >= index_of_id_.size()) return;
  std::int32_t i = index_of_id_[id];
  if (i < 0 || nodes_[i].removed) return;
  nodes_[i].removed = true;
  for (; i >= 0; i = nodes_[i].parent) --nodes_[i].alive;
}

namespace {
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

inline void PreviousPoseNearest::search(std::int32_t node, int depth, const double q[3], double lo[3],
                         double hi[3], std::size_t k, std::vector<Candidate>& heap) const {
  const Node& n = nodes_[node];
  const Candidate c{point_distance(q, n.p), static_cast<std::uint32_t>(node)};
  if (!n.removed) offer(heap, k, c);  // removed nodes only guide the descent
  const int axis = depth % 3;
  const int first = q[axis] < n.p[axis] ? 0 : 1;
  for (int pass = 0; pass < 2; ++pass) {
    const int side = pass == 0 ? first : 1 - first;
    const std::int32_t child = n.child[side];
    if (child < 0 || nodes_[child].alive == 0) continue;
    // The child's cell: this cell cut at the node's coordinate.
    double* bound = side == 0 ? &hi[axis] : &lo[axis];
    const double saved = *bound;
    *bound = n.p[axis];
    if (heap.size() < k || box_bound(q, lo, hi) <= heap.front().d) {
      search(child, depth + 1, q, lo, hi, k, heap);
    }
    *bound = saved;
  }
}

inline void PreviousPoseNearest::nearest(const geometry::Pose2& query, std::size_t k,
                          std::vector<std::int32_t>& out) const {
  out.clear();
  if (nodes_.empty() || k == 0) return;
  const double q[3] = {query.x, query.y, geometry::wrap_angle(query.theta)};
  std::vector<Candidate> heap;
  heap.reserve(k + 1);
  if (nodes_.size() < kLinearScanBelow) {
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      if (nodes_[i].removed) continue;
      offer(heap, k, Candidate{point_distance(q, nodes_[i].p), static_cast<std::uint32_t>(i)});
    }
  } else {
    double lo[3] = {-kInf, -kInf, -kPi};
    double hi[3] = {kInf, kInf, kPi};
    search(0, 0, q, lo, hi, k, heap);
  }
  std::sort_heap(heap.begin(), heap.end());
  for (const Candidate& c : heap) out.push_back(nodes_[c.order].id);
}

}  // namespace hrs::bench
