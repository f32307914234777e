// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/goals.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"

namespace hrs::planning {

using geometry::Polygon;
using geometry::Pose2;
using geometry::Side;
using geometry::Vec2;

namespace {

//! Chair pose at distance d along `normal` from `q`, facing the origin.
Pose2 facing_origin(Vec2 q, Vec2 normal, double d) {
  const Vec2 c = q + d * normal;
  return {c.x, c.y, std::atan2(-c.y, -c.x)};
}

Side side_of_normal(Vec2 n) {
  if (std::abs(n.x) >= std::abs(n.y)) return n.x > 0 ? Side::kFront : Side::kBack;
  return n.y > 0 ? Side::kLeft : Side::kRight;
}

//! At most this many scan steps per slot (the 2 cm step binds for
//! furniture-sized objects and chairs).
constexpr double kMaxScanSteps = 400.0;

//! Smallest offset d whose chair at facing_origin(q, normal, d) keeps the
//! approach's gap from the footprint `fp`: scan outward, then bisect to
//! `tolerance`. Negative when no offset up to the scan's limit is clear.
double clear_offset(const geometry::Scene& scene, const Polygon& fp, double gap, Vec2 q,
                    Vec2 normal, double tolerance) {
  const double length = scene.wheelchair.length, width = scene.wheelchair.width;
  auto clear = [&](double d) {
    const Polygon chair = geometry::chair_footprint(scene.wheelchair, facing_origin(q, normal, d));
    return geometry::polygon_distance(chair, fp) >= gap;
  };
  const double limit = length + width + gap + 1.0;
  const double kScan = std::max(0.02, limit / kMaxScanSteps);
  double lo = 0.0, hi = -1.0;
  for (double d = 0.0; d <= limit; d += kScan) {
    if (clear(d)) {
      hi = d;
      break;
    }
    lo = d;
  }
  if (hi < 0.0) return hi;
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    (clear(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

Side side_of(const geometry::Object& object, const Pose2& object_pose, Vec2 point) {
  double hx = 0.0, hy = 0.0;
  for (Vec2 v : object.footprint) {
    hx = std::max(hx, std::abs(v.x));
    hy = std::max(hy, std::abs(v.y));
  }
  const Vec2 local = geometry::rotate(point - object_pose.position(), -object_pose.theta);
  return side_of_normal({hx > 0 ? local.x / hx : local.x, hy > 0 ? local.y / hy : local.y});
}

std::vector<GoalPose> goal_poses(const geometry::Scene& scene, const geometry::Object& object,
                                 const Pose2& object_pose, const geometry::CSpace& cspace,
                                 const GoalOptions& options) {
  return place_goal_poses(local_goal_poses(scene, object, options), object_pose, cspace);
}

std::vector<GoalPose> place_goal_poses(const std::vector<GoalPose>& local, const Pose2& object_pose,
                                       const geometry::CSpace& cspace) {
  std::vector<GoalPose> out;
  out.reserve(local.size());
  for (const GoalPose& g : local) {
    const Vec2 world = geometry::to_world(object_pose, g.pose.position());
    const Pose2 pose{world.x, world.y, geometry::wrap_angle(object_pose.theta + g.pose.theta)};
    if (!cspace.is_free(pose)) continue;
    out.push_back({pose, g.side, g.slot});
  }
  return out;
}

std::vector<GoalPose> local_goal_poses(const geometry::Scene& scene, const geometry::Object& object,
                                       const GoalOptions& options, const std::atomic<bool>* stop) {
  const Polygon& fp = object.footprint;
  std::vector<GoalPose> out;
  if (fp.size() < 3) return out;
  const geometry::Approach approach = object.approach_or_default();
  const double width = scene.wheelchair.width;
  double perimeter = 0.0;
  for (std::size_t i = 0; i < fp.size(); ++i)
    perimeter += geometry::norm(fp[(i + 1) % fp.size()] - fp[i]);
  // Bounded work whatever the sizes: at most kMaxSlots slots, each scanned in
  // at most kMaxScanSteps steps (neither bound binds for furniture-sized
  // objects and chairs, where the slots are a chair width apart or closer and
  // the scan steps 2 cm).
  constexpr double kMaxSlots = 256.0;
  const int n = static_cast<int>(
      std::clamp(std::ceil(options.density * perimeter / width - 1e-9), 1.0, kMaxSlots));
  const double spacing = perimeter / n;

  std::size_t edge = 0;
  double edge_start = 0.0;
  for (int slot = 0; slot < n; ++slot) {
    throw_if_stopped(stop, "goal-pose generation");
    const double s = (slot + 0.5) * spacing;
    while (edge + 1 < fp.size() &&
           edge_start + geometry::norm(fp[(edge + 1) % fp.size()] - fp[edge]) < s) {
      edge_start += geometry::norm(fp[(edge + 1) % fp.size()] - fp[edge]);
      ++edge;
    }
    const Vec2 a = fp[edge], b = fp[(edge + 1) % fp.size()];
    const double len = geometry::norm(b - a);
    if (len <= 0.0) continue;
    const Vec2 dir = (1.0 / len) * (b - a);
    const Vec2 normal{dir.y, -dir.x};  // outward for a counter-clockwise outline
    const Side side = side_of_normal(normal);
    if (!approach.sides[static_cast<int>(side)]) continue;
    const Vec2 q = a + std::clamp(s - edge_start, 0.0, len) * dir;
    // The chair faces the centre from the nearest offset that keeps the gap.
    const double d = clear_offset(scene, fp, approach.gap, q, normal, options.gap_tolerance);
    if (d < 0.0) continue;
    out.push_back({facing_origin(q, normal, d), side, slot});
  }
  return out;
}

}  // namespace hrs::planning
