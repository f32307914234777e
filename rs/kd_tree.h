// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small kd-tree over poses (x, y, θ) for the RS-decomposition's
// nearest-neighbour look-ups (paper §V-A). The metric is
//   sqrt(dx² + dy² + (w · dθ)²),  dθ wrapped to [-π, π],
// with w (metres per radian) chosen by the caller. Points are inserted one by
// one (the decomposition grows while it queries); random insertion order keeps
// the tree balanced in expectation.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "geometry/pose.h"

namespace hrs::rs {

//! The metric of the decomposition's nearest-sample search, squared, between
//! (x, y, θ) triples with θ in [-π, π]: dx² + dy² + (w · wrapped dθ)².
//! PoseKdTree and PoseGrid both measure with it, so they agree.
inline double pose_metric2(double w, const double* a, const double* b) {
  const double d = std::abs(a[2] - b[2]);
  const double dx = a[0] - b[0], dy = a[1] - b[1];
  const double dt = w * std::min(d, 2.0 * std::numbers::pi - d);
  return dx * dx + dy * dy + dt * dt;
}

class PoseKdTree {
 public:
  //! `heading_weight` w > 0 in metres per radian.
  explicit PoseKdTree(double heading_weight) : w_(heading_weight) {}

  //! Adds a pose; its index is the insertion order.
  void insert(const geometry::Pose2& p) {
    const Node n{{p.x, p.y, geometry::wrap_angle(p.theta)}, -1, -1};
    const auto id = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(n);
    if (id == 0) return;
    std::int32_t cur = 0;
    int axis = 0;
    for (;;) {
      Node& c = nodes_[cur];
      std::int32_t& next = n.p[axis] < c.p[axis] ? c.left : c.right;
      if (next < 0) {
        next = id;
        return;
      }
      cur = next;
      axis = (axis + 1) % 3;
    }
  }

  //! Index of the nearest inserted pose; -1 when empty.
  std::int32_t nearest(const geometry::Pose2& q) const {
    if (nodes_.empty()) return -1;
    const double p[3] = {q.x, q.y, geometry::wrap_angle(q.theta)};
    std::int32_t best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    search(0, 0, p, best, best_d2);
    return best;
  }

  //! Squared metric distance between two poses.
  double distance2(const geometry::Pose2& a, const geometry::Pose2& b) const {
    const double pa[3] = {a.x, a.y, geometry::wrap_angle(a.theta)};
    const double pb[3] = {b.x, b.y, geometry::wrap_angle(b.theta)};
    return dist2(pa, pb);
  }

  std::size_t size() const { return nodes_.size(); }

 private:
  struct Node {
    double p[3];
    std::int32_t left, right;
  };

  double dist2(const double* a, const double* b) const { return pose_metric2(w_, a, b); }
  //! Lower bound on the distance from q to the far side of a split at s on
  //! `axis`. For θ the far side lies within [s, π] (or [-π, s)), which the
  //! wrap-around may reach from the other end.
  double far_gap(int axis, double q, double s) const {
    if (axis < 2) return std::abs(q - s);
    constexpr double kPi = std::numbers::pi;
    return w_ * (q < s ? std::min(s - q, q + kPi) : std::min(q - s, kPi - q));
  }

  void search(std::int32_t id, int axis, const double* q, std::int32_t& best,
              double& best_d2) const {
    const Node& n = nodes_[id];
    const double d2 = dist2(q, n.p);
    if (d2 < best_d2) best_d2 = d2, best = id;
    const bool go_left = q[axis] < n.p[axis];
    const std::int32_t near = go_left ? n.left : n.right;
    const std::int32_t far = go_left ? n.right : n.left;
    const int next_axis = (axis + 1) % 3;
    if (near >= 0) search(near, next_axis, q, best, best_d2);
    if (far >= 0) {
      const double g = far_gap(axis, q[axis], n.p[axis]);
      if (g * g < best_d2) search(far, next_axis, q, best, best_d2);
    }
  }

  double w_;
  std::vector<Node> nodes_;
};

}  // namespace hrs::rs
