// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Nearest tree nodes for the RRT of §III-B, which first keeps the k nearest
// nodes by a weighted Euclidean distance and then picks the one with the
// shortest RS path among them. The distance is
//   d(a, b) = |(xa, ya) − (xb, yb)| + w · |wrap(θa − θb)|
// with w in metres per radian. Nodes are kept in an incremental bucket
// kd-tree over (x, y, θ): leaves hold up to kBucket poses, contiguously, and
// a leaf that overflows is split at the median of its widest axis (θ scaled
// by w). The θ axis is a circle: the bound used for pruning measures the
// angular gap to a cell the short way round, so poses near ±π are found.
// A leaf's poses are ranked after two cheap lower bounds (the heading term,
// then |dx|), so the square root runs only for poses that may enter the
// answer. The answer is exact: the k smallest distances, ties by insertion
// order (tests/planning/nearest_test.cpp checks it against a linear scan).

#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "geometry/pose.h"

namespace hrs::planning {

class PoseNearest {
 public:
  //! `heading_weight`: metres per radian in the distance (w above).
  explicit PoseNearest(double heading_weight) : weight_(heading_weight) {}

  //! The weighted distance used for ranking.
  double distance(const geometry::Pose2& a, const geometry::Pose2& b) const;
  //! The distance nearest() ranks `pose` by for `query` (headings wrapped
  //! first, exactly as stored), bit for bit.
  double ranking_distance(const geometry::Pose2& query, const geometry::Pose2& pose) const;

  //! Adds a pose with the caller's id (ids need not be dense).
  void insert(const geometry::Pose2& pose, std::int32_t id);
  //! Removes the pose with this id from later answers (a tombstone: the
  //! pose stays in its leaf, and cells with no live pose left are skipped,
  //! so a tree whose poses are mostly removed stays fast). O(depth). Unknown or already removed ids are ignored.
  void remove(std::int32_t id);
  //! Ids of the (at most) k nearest poses to `query`, nearest first; ties are
  //! broken by insertion order, so the answer is deterministic.
  void nearest(const geometry::Pose2& query, std::size_t k, std::vector<std::int32_t>& out) const;

  //! Poses inserted, removed ones included.
  std::size_t size() const { return id_.size(); }
  void clear();
  double heading_weight() const { return weight_; }

  //! Poses per leaf before it is split (a leaf of equal poses may hold more).
  static constexpr std::size_t kBucket = 16;

 private:
  struct Point {
    double x, y, t;       //!< t: heading wrapped to (−pi, pi]
    std::uint32_t order;  //!< insertion index: breaks ties, indexes the per-pose arrays
  };
  //! A kd-tree cell: internal (axis >= 0, two children) or a leaf (points).
  struct Cell {
    int axis = -1;
    double split = 0.0;  //!< internal: coordinate < split goes to child[0]
    std::int32_t child[2] = {-1, -1};
    std::int32_t parent = -1;
    std::int32_t alive = 0;         //!< poses not removed below this cell
    std::size_t split_at = kBucket;  //!< leaf: size that triggers the next split attempt
    std::vector<Point> points;       //!< leaf only
  };
  struct Candidate {
    double d;
    std::uint32_t order;  //!< insertion index, breaks ties
    bool operator<(const Candidate& o) const { return d < o.d || (d == o.d && order < o.order); }
  };
  void search(std::int32_t cell, const double q[3], double lo[3], double hi[3], std::size_t k,
              std::vector<Candidate>& heap) const;
  void scan_leaf(const Cell& leaf, const double q[3], std::size_t k,
                 std::vector<Candidate>& heap) const;
  //! Splits an overflowing leaf in two (no-op when its poses are all equal).
  void split_leaf(std::int32_t cell);
  double point_distance(const double a[3], const double b[3]) const;
  double box_bound(const double q[3], const double lo[3], const double hi[3]) const;

  double weight_;
  std::vector<Cell> cells_;                //!< cells_[0] is the root
  std::vector<std::int32_t> id_;           //!< caller's id per insertion index
  std::vector<std::int32_t> leaf_of_;      //!< leaf cell per insertion index
  std::vector<std::uint8_t> removed_;      //!< per insertion index
  std::vector<std::int32_t> index_of_id_;  //!< insertion index per non-negative id, or -1
};

//! The poses nearest to one fixed query (the RRT's goal), kept in order as
//! poses are inserted and removed, so the k nearest cost O(k) instead of a
//! search. The same answer as PoseNearest::nearest for that query over the
//! same insertions and removals (the same distance, bit for bit) when ids
//! are inserted in increasing order: ties go to the smaller id, which is
//! then PoseNearest's insertion order.
class QueryOrder {
 public:
  explicit QueryOrder(double heading_weight) : metric_(heading_weight) {}

  //! Forgets every pose and ranks by distance to `query` from now on.
  void reset(const geometry::Pose2& query);
  //! Adds a pose with a non-negative id (not present).
  void insert(const geometry::Pose2& pose, std::int32_t id);
  //! Removes the pose with this id; unknown or removed ids are ignored.
  void remove(std::int32_t id);
  //! Ids of the (at most) k nearest poses, nearest first.
  void nearest(std::size_t k, std::vector<std::int32_t>& out) const;

 private:
  PoseNearest metric_;  //!< only its distance is used
  geometry::Pose2 query_{};
  std::set<std::pair<double, std::int32_t>> order_;
  std::vector<double> distance_of_id_;  //!< NaN: absent
};

}  // namespace hrs::planning
