// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/lattice.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace hrs::planning {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
//! A start join or an edge longer than this many times the motion it
//! stands for is dropped: the snap made it a manoeuvre, not a step.
constexpr double kEdgeStretch = 4.0;
//! Start joins longer than this (metres) are not tried.
constexpr double kStartJoin = 1.5;
//! The start joins the nodes of the cells up to this many cells away, at
//! its nearest heading and up to this many headings beside it.
constexpr int kJoinCells = 2;
constexpr int kJoinHeadings = 2;
//! The assembled path's end must be this close to the goal (metres +
//! radians); the edges' rounding adds about 1e-15 per edge.
constexpr double kEndTolerance = 1e-9;
}  // namespace

LatticePlanner::LatticePlanner(const geometry::Scene& scene, const geometry::CSpace& cspace,
                               double radius, LatticeOptions options)
    : cspace_(&cspace), radius_(radius), options_(options), validator_(cspace, radius) {
  if (!(options_.cell > 0.0) || options_.headings < 4 || !(options_.straight > 0.0) ||
      options_.turn_steps < 1)
    throw std::invalid_argument(
        "LatticePlanner: cell, straight > 0, headings >= 4, turn_steps >= 1");
  double x1 = -kInf, y1 = -kInf;
  x0_ = y0_ = kInf;
  for (const geometry::Vec2& v : scene.room.polygon) {
    x0_ = std::min(x0_, v.x);
    y0_ = std::min(y0_, v.y);
    x1 = std::max(x1, v.x);
    y1 = std::max(y1, v.y);
  }
  nx_ = std::max(1, static_cast<int>(std::ceil((x1 - x0_) / options_.cell)));
  ny_ = std::max(1, static_cast<int>(std::ceil((y1 - y0_) / options_.cell)));
  if (node_count() > 64'000'000)
    throw std::invalid_argument("LatticePlanner: more than 64 M nodes; use a coarser cell");

  // The edges of each heading, between canonical poses relative to the
  // source's cell centre (translation-invariant).
  const int k_count = options_.headings;
  const double step = 2.0 * std::numbers::pi / k_count;
  const double h = options_.cell;
  edges_.resize(static_cast<std::size_t>(k_count));
  for (int k = 0; k < k_count; ++k) {
    const geometry::Pose2 p0{0.0, 0.0, geometry::wrap_angle(k * step)};
    const double arc = radius_ * options_.turn_steps * step;
    const rs::Segment motions[] = {
        {rs::Steer::kStraight, 1, options_.straight}, {rs::Steer::kLeft, 1, arc},
        {rs::Steer::kRight, 1, arc},                  {rs::Steer::kStraight, -1, options_.straight},
        {rs::Steer::kLeft, -1, arc},                  {rs::Steer::kRight, -1, arc}};
    for (const rs::Segment& m : motions) {
      const geometry::Pose2 end = rs::advance(p0, m, radius_);
      Edge e;
      e.dx = static_cast<int>(std::lround(end.x / h));
      e.dy = static_cast<int>(std::lround(end.y / h));
      e.heading = static_cast<int>(std::lround(end.theta / step)) % k_count;
      if (e.heading < 0) e.heading += k_count;
      if (e.dx == 0 && e.dy == 0 && e.heading == k) continue;
      const geometry::Pose2 target{e.dx * h, e.dy * h, geometry::wrap_angle(e.heading * step)};
      e.path = rs::shortest_path(p0, target, radius_);
      if (e.path.length() > kEdgeStretch * m.length) continue;
      const bool repeated = std::any_of(
          edges_[k].begin(), edges_[k].end(), [&](const Edge& o) {
            return o.dx == e.dx && o.dy == e.dy && o.heading == e.heading;
          });
      if (!repeated) edges_[k].push_back(std::move(e));
    }
  }
}

geometry::Pose2 LatticePlanner::node_pose(std::size_t node) const {
  const int k_count = options_.headings;
  const auto k = static_cast<int>(node % k_count);
  const std::size_t column = node / k_count;
  const auto ix = static_cast<int>(column % nx_);
  const auto iy = static_cast<int>(column / nx_);
  return {x0_ + (ix + 0.5) * options_.cell, y0_ + (iy + 0.5) * options_.cell,
          geometry::wrap_angle(k * 2.0 * std::numbers::pi / k_count)};
}

std::int64_t LatticePlanner::node_of(const geometry::Pose2& pose) const {
  const auto ix = static_cast<std::int64_t>(std::floor((pose.x - x0_) / options_.cell));
  const auto iy = static_cast<std::int64_t>(std::floor((pose.y - y0_) / options_.cell));
  if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return -1;
  const int k_count = options_.headings;
  auto k = static_cast<std::int64_t>(
      std::lround(geometry::wrap_angle(pose.theta) / (2.0 * std::numbers::pi / k_count)));
  k = ((k % k_count) + k_count) % k_count;
  return (iy * nx_ + ix) * k_count + k;
}

rs::Path LatticePlanner::assemble(std::int64_t last, const rs::Path& shot) const {
  std::vector<const rs::Path*> pieces{&shot};
  const Visit* v = &visits_.at(last);
  while (v->parent >= 0) {
    const auto k = static_cast<std::size_t>(v->parent % options_.headings);
    pieces.push_back(&edges_[k][static_cast<std::size_t>(v->via)].path);
    v = &visits_.at(v->parent);
  }
  pieces.push_back(&start_paths_[static_cast<std::size_t>(v->via)]);
  rs::Path out{{}, radius_};
  for (auto it = pieces.rbegin(); it != pieces.rend(); ++it) out = rs::concatenate(out, **it);
  return out;
}

LatticeResult LatticePlanner::plan(const geometry::Pose2& from, const geometry::Pose2& to) {
  LatticeResult result;
  validator_.reset_checks();
  const auto finish = [&](LatticeAnswer answer) {
    result.answer = answer;
    result.checks = validator_.checks();
    return result;
  };
  if (!validator_.pose_free(from) || !validator_.pose_free(to))
    return finish(LatticeAnswer::kNoPath);
  {
    rs::Path direct = rs::shortest_path(from, to, radius_);
    if (validator_.path_free(from, direct)) {
      result.path = std::move(direct);
      return finish(LatticeAnswer::kFound);
    }
  }
  visits_.clear();
  start_paths_.clear();
  const auto cost_of = [&](std::int64_t node) {
    const auto it = visits_.find(node);
    return it == visits_.end() ? kInf : it->second.cost;
  };

  // Open list: (priority, node). A* orders by cost + w · RS estimate; the
  // breadth-first mode by discovery (a FIFO).
  using Entry = std::pair<double, std::int64_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  std::deque<std::int64_t> fifo;
  const auto push = [&](std::int64_t node, double cost) {
    ++result.reached;
    if (options_.breadth_first) {
      fifo.push_back(node);
    } else {
      const double estimate =
          options_.heuristic_weight > 0.0
              ? options_.heuristic_weight * rs::shortest_length(node_pose(node), to, radius_)
              : 0.0;
      open.emplace(cost + estimate, node);
    }
  };

  // Start joins: the cells around the start at the headings beside its own.
  const std::int64_t start_node = node_of(from);
  if (start_node >= 0) {
    const int k_count = options_.headings;
    const auto column = start_node / k_count;
    const auto k0 = static_cast<int>(start_node % k_count);
    const auto cx = static_cast<int>(column % nx_), cy = static_cast<int>(column / nx_);
    for (int diy = -kJoinCells; diy <= kJoinCells; ++diy)
      for (int dix = -kJoinCells; dix <= kJoinCells; ++dix)
        for (int dk = -kJoinHeadings; dk <= kJoinHeadings; ++dk) {
          const int ix = cx + dix, iy = cy + diy;
          if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) continue;
          const int k = ((k0 + dk) % k_count + k_count) % k_count;
          const std::int64_t node = (static_cast<std::int64_t>(iy) * nx_ + ix) * k_count + k;
          rs::Path join = rs::shortest_path(from, node_pose(node), radius_);
          const double length = join.length();
          if (length > kStartJoin || !(length < cost_of(node))) continue;
          if (!validator_.path_free(from, join)) continue;
          if (cost_of(node) == kInf) push(node, length);
          visits_[node] = {length, -1, static_cast<std::int32_t>(start_paths_.size()), false};
          start_paths_.push_back(std::move(join));
        }
  }

  while (options_.breadth_first ? !fifo.empty() : !open.empty()) {
    std::int64_t n;
    if (options_.breadth_first) {
      n = fifo.front();
      fifo.pop_front();
    } else {
      n = open.top().second;
      open.pop();
    }
    Visit& here = visits_.at(n);
    if (here.settled) continue;
    here.settled = true;
    const double here_cost = here.cost;
    if (++result.expansions > options_.max_expansions) return finish(LatticeAnswer::kBudget);
    const geometry::Pose2 pose = node_pose(static_cast<std::size_t>(n));
    if (std::hypot(pose.x - to.x, pose.y - to.y) <= options_.shot_radius) {
      const rs::Path shot = rs::shortest_path(pose, to, radius_);
      if (validator_.path_free(pose, shot)) {
        rs::Path whole = assemble(n, shot);
        // The pieces were certified from canonical poses; the whole path is
        // certified again as driven from the start.
        if (geometry::pose_gap(rs::end_pose(from, whole), to) <= kEndTolerance &&
            validator_.path_free(from, whole)) {
          result.path = std::move(whole);
          return finish(LatticeAnswer::kFound);
        }
      }
    }
    const int k_count = options_.headings;
    const auto column = n / k_count;
    const auto k = static_cast<int>(n % k_count);
    const auto cx = static_cast<int>(column % nx_), cy = static_cast<int>(column / nx_);
    const std::vector<Edge>& edges = edges_[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const Edge& e = edges[i];
      const int ix = cx + e.dx, iy = cy + e.dy;
      if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) continue;
      const std::int64_t m = (static_cast<std::int64_t>(iy) * nx_ + ix) * k_count + e.heading;
      const auto it = visits_.find(m);
      if (it != visits_.end() && it->second.settled) continue;
      const double cost = here_cost + e.path.length();
      const double known = it == visits_.end() ? kInf : it->second.cost;
      if (!(cost < known)) continue;
      if (!validator_.path_free(pose, e.path)) continue;
      // Queued already (breadth-first): only the cheaper link is kept.
      if (!(options_.breadth_first && known < kInf)) push(m, cost);
      visits_[m] = {cost, n, static_cast<std::int32_t>(i), false};
    }
  }
  return finish(LatticeAnswer::kNoPath);
}

}  // namespace hrs::planning
