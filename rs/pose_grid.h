// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A bucket grid over poses (x, y, θ) for the RS-decomposition's nearest-
// neighbour look-ups (paper §V-A), with the metric of PoseKdTree (pose_metric2):
//   sqrt(dx² + dy² + (w · dθ)²),  dθ wrapped to [-π, π].
// The decomposition's samples are uniform in a box, so equal cells (about
// two samples each, re-bucketed as the set grows) answer a query from the
// query's cell and one or two rings of cells around it: a ring search stops
// once the nearest point found is closer than any cell outside the rings can
// be. Same answers as PoseKdTree (ties: the lowest index), fewer visits.
// Large sets (a 40 m room's decomposition keeps ~10^6 samples) are bound by
// memory, not arithmetic: each cell stores its poses in one array, a column
// of heading cells is contiguous, and a ring's cells are prefetched before
// they are read.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "geometry/pose.h"
#include "rs/kd_tree.h"

namespace hrs::rs {

class PoseGrid {
 public:
  //! `heading_weight` w > 0 in metres per radian; cells cover the box
  //! [xmin, xmax] × [ymin, ymax] × [-π, π) (queries and points outside the
  //! box are allowed: they fall in the border cells).
  PoseGrid(double heading_weight, double xmin, double xmax, double ymin, double ymax)
      : w_(heading_weight),
        x0_(xmin),
        x1_(std::max(xmax, xmin + 1e-9)),
        y0_(ymin),
        y1_(std::max(ymax, ymin + 1e-9)) {
    rebucket(64);
  }

  //! Adds a pose; its index is the insertion order.
  void insert(const geometry::Pose2& p) {
    const auto id = static_cast<std::int32_t>(points_.size());
    points_.push_back({p.x, p.y, geometry::wrap_angle(p.theta)});
    if (points_.size() > 2 * cells_.size()) {
      rebucket(points_.size());
    } else {
      link(id);
    }
  }

  //! Index of the nearest inserted pose (the lowest index among equally
  //! near ones); -1 when empty.
  std::int32_t nearest(const geometry::Pose2& query) const {
    if (points_.empty()) return -1;
    const std::array<double, 3> q{query.x, query.y, geometry::wrap_angle(query.theta)};
    const int cx = cell(q[0], x0_, hx_, nx_), cy = cell(q[1], y0_, hy_, ny_);
    const int ct = cell(q[2], -std::numbers::pi, ht_, nt_);
    std::int32_t best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int r = 0;; ++r) {
      const bool all_t = 2 * r + 1 >= nt_;
      const bool prev_all_t = r > 0 && 2 * (r - 1) + 1 >= nt_;
      const int t_count = all_t ? nt_ : 2 * r + 1;
      const int t_first = all_t ? 0 : (ct - r < 0 ? ct - r + nt_ : ct - r);
      // The ring's cells are listed first and their memory asked for at
      // once, so that the cache misses of a large grid overlap.
      std::size_t ring[kRingBuffer];
      int listed = 0;
      auto visit = [&](std::size_t c) {
        for (const Entry& e : cells_[c]) {
          const double d2 = dist2(q, e.pose);
          if (d2 < best_d2 || (d2 == best_d2 && e.id < best)) best_d2 = d2, best = e.id;
        }
      };
      auto flush = [&] {
        for (int n = 0; n < listed; ++n) {
          const auto& v = cells_[ring[n]];
          if (!v.empty()) __builtin_prefetch(v.data());
        }
        for (int n = 0; n < listed; ++n) visit(ring[n]);
        listed = 0;
      };
      for (int j = std::max(0, cy - r); j <= std::min(ny_ - 1, cy + r); ++j) {
        for (int i = std::max(0, cx - r); i <= std::min(nx_ - 1, cx + r); ++i) {
          const bool inner_xy = r > 0 && std::abs(i - cx) <= r - 1 && std::abs(j - cy) <= r - 1;
          if (inner_xy && prev_all_t) continue;  // every heading seen
          const std::size_t base = index(i, j, 0);
          for (int o = 0, k = t_first; o < t_count; ++o, k = k + 1 == nt_ ? 0 : k + 1) {
            if (inner_xy && circular(k, ct) <= r - 1) continue;  // seen
            const std::size_t c = base + static_cast<std::size_t>(k);
            __builtin_prefetch(&cells_[c]);
            ring[listed++] = c;
            if (listed == kRingBuffer) flush();
          }
        }
      }
      flush();
      // Every point outside the rings is at least `gap` away.
      double gap = std::numeric_limits<double>::infinity();
      if (cx - r > 0) gap = std::min(gap, q[0] - (x0_ + (cx - r) * hx_));
      if (cx + r < nx_ - 1) gap = std::min(gap, x0_ + (cx + r + 1) * hx_ - q[0]);
      if (cy - r > 0) gap = std::min(gap, q[1] - (y0_ + (cy - r) * hy_));
      if (cy + r < ny_ - 1) gap = std::min(gap, y0_ + (cy + r + 1) * hy_ - q[1]);
      if (!all_t) {
        const double lo = -std::numbers::pi + (ct - r) * ht_;
        const double hi = -std::numbers::pi + (ct + r + 1) * ht_;
        gap = std::min(gap, w_ * std::min(q[2] - lo, hi - q[2]));
      }
      if (!std::isfinite(gap)) break;  // every cell visited
      gap = std::max(0.0, gap);
      if (best >= 0 && best_d2 < gap * gap) break;
    }
    return best;
  }

  //! Squared metric distance between two poses.
  double distance2(const geometry::Pose2& a, const geometry::Pose2& b) const {
    return dist2({a.x, a.y, geometry::wrap_angle(a.theta)},
                 {b.x, b.y, geometry::wrap_angle(b.theta)});
  }

  std::size_t size() const { return points_.size(); }

 private:
  double dist2(const std::array<double, 3>& a, const std::array<double, 3>& b) const {
    return pose_metric2(w_, a.data(), b.data());
  }
  static int cell(double v, double origin, double size, int count) {
    const double f = std::floor((v - origin) / size);
    if (!(f >= 0.0)) return 0;  // below the box, or NaN
    return f >= count - 1 ? count - 1 : static_cast<int>(f);
  }
  //! Steps between heading cells a and b around the circle.
  int circular(int a, int b) const {
    const int d = std::abs(a - b);
    return std::min(d, nt_ - d);
  }
  //! Heading innermost: a column of heading cells is one run of memory.
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(j) * nx_ + i) * nt_ + k;
  }
  void link(std::int32_t id) {
    const auto& p = points_[id];
    const std::size_t c = index(cell(p[0], x0_, hx_, nx_), cell(p[1], y0_, hy_, ny_),
                                cell(p[2], -std::numbers::pi, ht_, nt_));
    cells_[c].push_back({p, id});
  }
  //! Cells of equal metric extent, about `wanted` of them; every point re-linked.
  void rebucket(std::size_t wanted) {
    const double tx = x1_ - x0_, ty = y1_ - y0_, tt = 2.0 * std::numbers::pi * w_;
    const double h =
        std::cbrt(tx * ty * tt / static_cast<double>(std::max<std::size_t>(wanted, 1)));
    nx_ = std::max(1, static_cast<int>(std::ceil(tx / h)));
    ny_ = std::max(1, static_cast<int>(std::ceil(ty / h)));
    nt_ = std::max(1, static_cast<int>(std::ceil(tt / h)));
    hx_ = tx / nx_;
    hy_ = ty / ny_;
    ht_ = 2.0 * std::numbers::pi / nt_;
    cells_.assign(static_cast<std::size_t>(nx_) * ny_ * nt_, {});
    for (std::size_t id = 0; id < points_.size(); ++id) link(static_cast<std::int32_t>(id));
  }

  double w_, x0_, x1_, y0_, y1_;
  int nx_ = 1, ny_ = 1, nt_ = 1;
  double hx_ = 1, hy_ = 1, ht_ = 1;
  //! A pose stored in its cell, so that a cell's poses are read in one run
  //! of memory (at 10^5–10^6 poses, chasing per-pose links missed the cache
  //! on most visits).
  static constexpr int kRingBuffer = 32;
  struct Entry {
    std::array<double, 3> pose;
    std::int32_t id;
  };
  std::vector<std::array<double, 3>> points_;
  std::vector<std::vector<Entry>> cells_;
};

}  // namespace hrs::rs
