// SPDX-License-Identifier: GPL-3.0-or-later
// What the scene model derives from its data (geometry/scene.h): object
// footprints in the world, the door's wall, clear zone and start pose, the
// longest walk of the AO graph, polygon areas. The reader and writer of the
// format are geometry/scene_reader.cpp and geometry/scene_writer.cpp.

#include "geometry/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <limits>
#include <set>
#include <utility>

#include "geometry/error.h"
#include "geometry/scene_json.h"

namespace hrs::geometry {
namespace {

using scene_io::door_edge;

//! Distance from p to segment [a, b] and the arc-length parameter of its projection.
std::pair<double, double> segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  double t = len2 > 0.0 ? dot(p - a, d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 q = a + t * d;
  return {norm(p - q), t * std::sqrt(len2)};
}

}  // namespace

int scene_io::door_edge(const Polygon& room, const Door& door, bool require_fit) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  const std::size_t n = room.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = room[i], b = room[(i + 1) % n];
    const auto [distance, along] = segment_distance(door.center, a, b);
    if (distance > kBoundaryTolerance) continue;
    const double length = norm(b - a);
    const bool fits = along - 0.5 * door.width >= -kBoundaryTolerance &&
                      along + 0.5 * door.width <= length + kBoundaryTolerance;
    if (require_fit && !fits) continue;
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(i);
    }
  }
  return best;
}

int Scene::find_object(std::string_view id) const {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

Polygon rotated_footprint(const Object& object) {
  const double c = std::cos(object.pose.theta), s = std::sin(object.pose.theta);
  Polygon out;
  out.reserve(object.footprint.size());
  for (Vec2 v : object.footprint) out.push_back({c * v.x - s * v.y, s * v.x + c * v.y});
  return out;
}

Polygon world_footprint(const Object& object) {
  Polygon out = rotated_footprint(object);
  const Vec2 t = object.pose.position();
  for (Vec2& v : out) v = v + t;
  return out;
}

Vec2 door_inward_normal(const Scene& scene) {
  const Polygon& room = scene.room.polygon;
  int edge = door_edge(room, scene.door, true);
  if (edge < 0) edge = door_edge(room, scene.door, false);
  if (edge < 0) return {0.0, 0.0};  // not a validated scene
  const Vec2 a = room[static_cast<std::size_t>(edge)];
  const Vec2 b = room[(static_cast<std::size_t>(edge) + 1) % room.size()];
  const Vec2 d = (1.0 / norm(b - a)) * (b - a);
  return {-d.y, d.x};  // counter-clockwise room: the interior is on the left
}

Polygon door_clear_zone(const Scene& scene) {
  const Vec2 n = door_inward_normal(scene);
  const Vec2 d{n.y, -n.x};  // along the wall, in the room's edge direction
  const Vec2 c = scene.door.center;
  const double h = 0.5 * scene.door.width, depth = scene.door.clear_depth;
  return {c - h * d, c + h * d, c + h * d + depth * n, c - h * d + depth * n};
}

Pose2 door_start_pose(const Scene& scene) {
  if (scene.door.start) return *scene.door.start;
  const Vec2 n = door_inward_normal(scene);
  const Vec2 p = scene.door.center + (0.5 * scene.wheelchair.length + 0.05) * n;
  return {p.x, p.y, std::atan2(n.y, n.x)};
}

int longest_walk(const Activity& activity, int cap) {
  std::set<std::string> at{std::string(kStartNodeId)};
  for (int step = 0; step < cap; ++step) {
    std::set<std::string> next;
    for (const std::string& from : at) {
      const auto row = activity.transitions.find(from);
      if (row == activity.transitions.end()) continue;
      for (const auto& [to, p] : row->second) {
        if (to != from && p > 0.0) next.insert(to);
      }
    }
    if (next.empty()) return step;
    at = std::move(next);
  }
  return cap;
}

void require_sequences(const Scene& scene, const std::string& label) {
  const int longest = longest_walk(scene.activity, scene.activity.visits);
  if (longest < scene.activity.visits) {
    throw InputError(scene_io::one_line(
        label + ": /activity/visits: no sequence of " + std::to_string(scene.activity.visits) +
        " visits leaves the door (the AO graph's longest has " + std::to_string(longest) + ")"));
  }
}

std::vector<std::string> degree_like_angles(const Scene& scene, const std::string& label) {
  std::vector<std::string> out;
  const auto check = [&](double angle, const std::string& ptr) {
    if (!(std::abs(angle) > 2.0 * std::numbers::pi)) return;
    char given[32], radians[32];
    std::snprintf(given, sizeof given, "%.10g", angle);
    std::snprintf(radians, sizeof radians, "%.5g", angle * std::numbers::pi / 180.0);
    out.push_back(scene_io::one_line(label + ": " + ptr + ": angle " + given +
                                     " is larger than 2π in magnitude: radians are expected (" +
                                     given + "° would be " + radians + ")"));
  };
  if (scene.door.start) check(scene.door.start->theta, "/door/start/2");
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    const std::string ptr = "/objects/" + std::to_string(i);
    check(o.pose.theta, ptr + "/pose/2");
    if (o.wall && o.wall->angle) check(*o.wall->angle, ptr + "/wall/angle");
  }
  for (std::size_t i = 0; i < scene.relations.size(); ++i) {
    if (scene.relations[i].angle)
      check(*scene.relations[i].angle, "/relations/" + std::to_string(i) + "/angle");
  }
  return out;
}

double signed_area(const Polygon& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) twice += cross(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * twice;
}

}  // namespace hrs::geometry
