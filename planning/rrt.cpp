// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/rrt.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/random.h"
#include "planning/path_ops.h"

namespace hrs::planning {

namespace {

double unit(std::mt19937_64& rng) { return uniform01(rng); }
using geometry::pose_gap;

}  // namespace

rs::Path RrtTree::path_to(std::int32_t index, double radius) const {
  std::vector<std::int32_t> chain;
  for (std::int32_t i = index; i > 0; i = nodes[i].parent) chain.push_back(i);
  rs::Path out;
  out.radius = radius;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    for (const rs::Segment& seg : nodes[*it].edge.segments) append_segment(out.segments, seg);
  }
  return out;
}

UniformSampler UniformSampler::for_room(const geometry::Scene& scene) {
  const geometry::Box b = geometry::bounding_box(scene.room.polygon);
  return UniformSampler(b.xmin, b.ymin, b.xmax, b.ymax);
}

Pose2 UniformSampler::sample(std::mt19937_64& rng) {
  const double x = xmin_ + (xmax_ - xmin_) * unit(rng);
  const double y = ymin_ + (ymax_ - ymin_) * unit(rng);
  const double t = std::numbers::pi * (2.0 * unit(rng) - 1.0);
  return {x, y, t};
}

double ExactSteering::distance(const Pose2& from, const Pose2& to, double radius) {
  return rs::shortest_length(from, to, radius);
}

rs::Path ExactSteering::path(const Pose2& from, const Pose2& to, double radius) {
  return rs::shortest_path(from, to, radius);
}

LegPlanner::LegPlanner(const geometry::Scene& scene, const CSpace& cspace, PlannerOptions options,
                       PlannerHooks hooks)
    : cspace_(&cspace),
      options_(options),
      radius_(scene.wheelchair.turning_radius),
      uniform_(UniformSampler::for_room(scene)),
      hooks_(hooks),
      validator_(cspace, scene.wheelchair.turning_radius),
      nearest_(options.heading_weight),
      goal_order_(options.heading_weight) {}

LegResult LegPlanner::plan(const Pose2& from, const Pose2& to, std::uint64_t seed,
                           const Termination& stop) {
  RrtTree tree;
  tree.nodes.push_back({from, -1, rs::Path{{}, radius_}, 0.0});
  return plan(from, to, seed, tree, stop);
}

std::int32_t LegPlanner::extend(RrtTree& tree, std::int32_t from_node, const Pose2& target,
                                double max_length, bool& reached) {
  reached = false;
  Steering& steering = hooks_.steering ? *hooks_.steering : exact_;
  const Pose2 start = tree.nodes[from_node].pose;
  const rs::Path path = steering.path(start, target, radius_);
  const double total = path.length();
  if (!(total > kMinSegmentLength)) return -1;
  const double limit = std::min(total, max_length);
  const int steps = std::max(1, static_cast<int>(std::ceil(limit / options_.step_length - 1e-9)));
  const double step = limit / steps;
  std::int32_t last = -1;
  std::int32_t parent = from_node;
  Pose2 pose = start;
  for (int i = 0; i < steps; ++i) {
    const double s1 = (i + 1 == steps) ? limit : (i + 1) * step;
    rs::Path piece = subpath(path, i * step, s1);
    if (!validator_.path_free(pose, piece)) break;
    pose = rs::end_pose(pose, piece);
    const double cost = tree.nodes[parent].cost + piece.length();
    tree.nodes.push_back({pose, parent, std::move(piece), cost});
    last = static_cast<std::int32_t>(tree.nodes.size() - 1);
    nearest_.insert(pose, last);
    goal_order_.insert(pose, last);
    parent = last;
    if (i + 1 == steps && limit == total) reached = true;
  }
  return last;
}

void LegPlanner::index_tree(const RrtTree& tree, const Pose2& goal) {
  nearest_.clear();
  goal_order_.reset(goal);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    nearest_.insert(tree.nodes[i].pose, static_cast<std::int32_t>(i));
    goal_order_.insert(tree.nodes[i].pose, static_cast<std::int32_t>(i));
  }
}

std::int32_t LegPlanner::closest_by_steering(const RrtTree& tree, const Pose2& target,
                                             Steering& steering) const {
  if (&steering == static_cast<const Steering*>(&exact_)) return closest_exact(tree, target);
  std::int32_t best = -1;
  double best_length = std::numeric_limits<double>::infinity();
  for (std::int32_t id : knn_) {
    const double d = steering.distance(tree.nodes[id].pose, target, radius_);
    if (d < best_length) {
      best_length = d;
      best = id;
    }
  }
  return best;
}

std::int32_t LegPlanner::closest_exact(const RrtTree& tree, const Pose2& target) const {
  poses_.clear();
  for (std::int32_t id : knn_) poses_.push_back(tree.nodes[id].pose);
  const std::size_t i = rs::first_shortest(poses_, target, radius_, bounds_);
  return i < knn_.size() ? knn_[i] : -1;
}

std::int32_t LegPlanner::try_goal(RrtTree& tree, const Pose2& to, Steering& steering,
                                  std::size_t& tree_size_at_goal_attempt) {
  const std::size_t k = static_cast<std::size_t>(std::max(1, options_.k_nearest));
  if (options_.skip_tried_goal_nodes) {
    goal_order_.nearest(k, knn_);  // the k nearest nodes not yet tried
    if (knn_.empty()) return -1;
  } else {
    // A goal attempt from an unchanged tree repeats the previous one exactly
    // (same nearest node, same curve, same collision), so it is skipped;
    // this changes the work, never the outcome.
    if (tree.nodes.size() == tree_size_at_goal_attempt) return -1;
    goal_order_.nearest(k, knn_);
  }
  const std::int32_t best = closest_by_steering(tree, to, steering);
  if (best < 0) return -1;
  bool reached = false;
  const std::size_t before = tree.nodes.size();
  const std::int32_t last =
      extend(tree, best, to, std::numeric_limits<double>::infinity(), reached);
  tree_size_at_goal_attempt = tree.nodes.size();
  // The chosen node and the nodes along its curve lead to the goal along the
  // same (blocked) curve: a shortest path's suffix is a shortest path.
  if (options_.skip_tried_goal_nodes) {
    goal_order_.remove(best);
    for (std::size_t i = before; i < tree.nodes.size(); ++i)
      goal_order_.remove(static_cast<std::int32_t>(i));
  }
  if (reached && pose_gap(tree.nodes[last].pose, to) <= options_.goal_tolerance) return last;
  return -1;
}

void LegPlanner::try_sample(RrtTree& tree, const Pose2& target, Steering& steering) {
  const std::size_t k = static_cast<std::size_t>(std::max(1, options_.k_nearest));
  nearest_.nearest(target, k, knn_);
  const std::int32_t best = closest_by_steering(tree, target, steering);
  if (best < 0) return;
  bool reached = false;
  extend(tree, best, target, options_.max_steps * options_.step_length, reached);
}

LegResult LegPlanner::plan(const Pose2& from, const Pose2& to, std::uint64_t seed, RrtTree& tree,
                           const Termination& stop) {
  // Documented preconditions (rrt.h): a tree to grow is rooted at `from`.
  assert(tree.nodes.empty() || geometry::pose_gap(tree.nodes.front().pose, from) <= 1e-9);
  const auto t0 = std::chrono::steady_clock::now();
  LegResult result;
  result.path.radius = radius_;
  validator_.reset_checks();
  std::mt19937_64 rng(seed);
  SampleSource& sampler = hooks_.sampler ? *hooks_.sampler : uniform_;
  Steering& steering = hooks_.steering ? *hooks_.steering : exact_;
  if (tree.nodes.empty()) tree.nodes.push_back({from, -1, rs::Path{{}, radius_}, 0.0});
  index_tree(tree, to);

  const bool ends_free = validator_.pose_free(from) && validator_.pose_free(to);
  std::size_t tree_size_at_goal_attempt = 0;
  std::int32_t goal_node = -1;
  if (ends_free && pose_gap(from, to) <= options_.goal_tolerance) goal_node = 0;
  StopRule rule(stop, options_.max_iterations, options_.max_nodes);
  int it = 0;
  while (ends_free && goal_node < 0) {
    result.stopped = rule.before_iteration(it, static_cast<int>(tree.nodes.size()));
    if (result.stopped != StopReason::kNone) break;
    ++it;
    // Goal bias (§III-B): the goal itself, else a sample (one draw each).
    if (unit(rng) < options_.goal_bias) {
      goal_node = try_goal(tree, to, steering, tree_size_at_goal_attempt);
    } else {
      try_sample(tree, sampler.sample(rng), steering);
    }
  }
  if (goal_node < 0) result.stopped = rule.unfound(result.stopped);
  result.found = goal_node >= 0;
  if (result.found) result.path = tree.path_to(goal_node, radius_);
  result.stats.iterations = it;
  result.stats.tree_nodes = static_cast<int>(tree.nodes.size());
  result.stats.collision_checks = validator_.checks();
  result.stats.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace hrs::planning
