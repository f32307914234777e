// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/moved_objects.h"

#include <algorithm>

namespace hrs::planning {

namespace {

//! True when the footprint `local` placed at `pose` lies farther than `m`
//! from every point; `world` is scratch.
bool footprint_clear(const geometry::Polygon& local, const geometry::Pose2& pose,
                     std::span<const geometry::Vec2> points, double m, geometry::Polygon& world) {
  if (local.empty()) return true;
  world.clear();
  for (const geometry::Vec2& v : local) world.push_back(geometry::to_world(pose, v));
  const geometry::Box b = geometry::bounding_box(world);
  for (const geometry::Vec2& p : points) {
    // Outside the box grown by m, a point is farther than m from the footprint.
    if (p.x < b.xmin - m || p.x > b.xmax + m || p.y < b.ymin - m || p.y > b.ymax + m) continue;
    if (geometry::point_in_polygon(p, world)) return false;
    for (std::size_t k = 0, j = world.size() - 1; k < world.size(); j = k++)
      if (geometry::point_segment_distance(p, world[j], world[k]) <= m) return false;
  }
  return true;
}

}  // namespace

std::vector<geometry::Pose2> layout_of(const geometry::CSpace& cspace) {
  std::vector<geometry::Pose2> poses;
  poses.reserve(static_cast<std::size_t>(cspace.object_count()));
  for (int i = 0; i < cspace.object_count(); ++i) poses.push_back(cspace.object_pose(i));
  return poses;
}

bool moved_objects_clear(const geometry::Scene& scene, std::span<const geometry::Pose2> then,
                         std::span<const geometry::Pose2> now,
                         std::span<const geometry::Vec2> points, double margin,
                         bool old_poses_too) {
  if (then.size() != now.size() || now.size() != scene.objects.size()) return false;
  geometry::Polygon world;
  for (std::size_t i = 0; i < now.size(); ++i) {
    if (now[i] == then[i]) continue;
    const geometry::Polygon& fp = scene.objects[i].footprint;
    if (!footprint_clear(fp, now[i], points, margin, world)) return false;
    if (old_poses_too && !footprint_clear(fp, then[i], points, margin, world)) return false;
  }
  return true;
}

}  // namespace hrs::planning
