// SPDX-License-Identifier: GPL-3.0-or-later
// Preferences met or not, and poses that meet them; see preferences.h.

#include "optimize/preferences.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hrs::optimize {

using geometry::Pose2;
using geometry::Vec2;

namespace {

Pose2 pose_of(const std::vector<Pose2>& poses, int i) { return poses[static_cast<std::size_t>(i)]; }

//! The pose of object `o` against room edge `edge` with heading `theta`, its
//! footprint `distance` from the edge's line, as near as the edge allows to
//! the position `near`; nullopt when the footprint is wider than the edge.
std::optional<Pose2> against_edge(const geometry::Scene& scene, const geometry::Object& o,
                                  int edge, double theta, double distance, const Vec2& near) {
  const auto& room = scene.room.polygon;
  const Vec2 p = room[static_cast<std::size_t>(edge)];
  const Vec2 q = room[(static_cast<std::size_t>(edge) + 1) % room.size()];
  const double length = geometry::norm(q - p);
  if (!(length > 0.0)) return std::nullopt;
  const Vec2 u = (1.0 / length) * (q - p);
  const Vec2 n{-u.y, u.x};  // inward: the room is counter-clockwise
  double min_n = std::numeric_limits<double>::infinity();
  double min_u = min_n, max_u = -min_n;
  for (const Vec2& v : o.footprint) {
    const Vec2 w = geometry::rotate(v, theta);
    min_n = std::min(min_n, geometry::dot(w, n));
    min_u = std::min(min_u, geometry::dot(w, u));
    max_u = std::max(max_u, geometry::dot(w, u));
  }
  if (max_u - min_u > length) return std::nullopt;
  const double along = std::clamp(geometry::dot(near - p, u), -min_u, length - max_u);
  const Vec2 c = p + along * u + (distance - min_n) * n;
  return Pose2{c.x, c.y, geometry::wrap_angle(theta)};
}

void add(PreferenceReport& report, PreferenceCheck check) {
  check.met = check.residual <= check.tolerance;
  report.total += 1;
  report.met += check.met ? 1 : 0;
  if (check.kind.ends_with("angle")) report.worst_angle = std::max(report.worst_angle, check.residual);
  report.checks.push_back(std::move(check));
}

}  // namespace

PreferenceReport check_preferences(const geometry::Scene& scene, const CostModel& model,
                                   const std::vector<Pose2>& poses,
                                   const PreferenceTolerances& tol) {
  PreferenceReport report;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const geometry::Object& o = scene.objects[i];
    if (o.fixed || !o.wall) continue;
    const int idx = static_cast<int>(i);
    const int e = model.nearest_wall(idx, poses[i]);
    if (o.wall->distance) {
      geometry::Object at = o;
      at.pose = poses[i];
      const double d = model.wall_distance(geometry::world_footprint(at), e);
      add(report, {"wall_distance", o.id, "", e, *o.wall->distance, d,
                   std::abs(d - *o.wall->distance), tol.wall_distance});
    }
    if (o.wall->angle) {
      const double achieved = geometry::wrap_angle(poses[i].theta - model.wall_normal_angle(e));
      add(report, {"wall_angle", o.id, "", e, *o.wall->angle, achieved,
                   std::abs(geometry::wrap_angle(achieved - *o.wall->angle)), tol.wall_angle});
    }
  }
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (a < 0 || b < 0) continue;
    if (scene.objects[static_cast<std::size_t>(a)].fixed &&
        scene.objects[static_cast<std::size_t>(b)].fixed)
      continue;
    const Pose2 pa = pose_of(poses, a), pb = pose_of(poses, b);
    if (r.distance) {
      const double d = geometry::norm(pa.position() - pb.position());
      add(report, {"relation_distance", r.a, r.b, -1, *r.distance, d, std::abs(d - *r.distance),
                   std::max(tol.relation_distance, tol.relation_distance_share * *r.distance)});
    }
    if (r.angle) {
      const double achieved = geometry::wrap_angle(pa.theta - pb.theta);
      add(report, {"relation_angle", r.a, r.b, -1, *r.angle, achieved,
                   std::abs(geometry::wrap_angle(achieved - *r.angle)), tol.relation_angle});
    }
  }
  return report;
}

std::vector<Pose2> preferred_poses(const geometry::Scene& scene, const CostModel& model,
                                   const std::vector<Pose2>& poses, int object) {
  std::vector<Pose2> out;
  const geometry::Object& o = scene.objects[static_cast<std::size_t>(object)];
  const Pose2 now = pose_of(poses, object);
  if (o.wall && (o.wall->distance || o.wall->angle)) {
    // Against the nearest wall first, then every other wall.
    const int nearest = model.nearest_wall(object, now);
    const int edges = static_cast<int>(scene.room.polygon.size());
    for (int k = 0; k < edges; ++k) {
      const int e = (nearest + k) % edges;
      const double theta =
          o.wall->angle ? model.wall_normal_angle(e) + *o.wall->angle : now.theta;
      if (!o.wall->distance) {
        if (k == 0) out.push_back({now.x, now.y, geometry::wrap_angle(theta)});
        continue;
      }
      if (auto p = against_edge(scene, o, e, theta, *o.wall->distance, now.position()))
        out.push_back(*p);
    }
  }
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (a < 0 || b < 0 || (a != object && b != object)) continue;
    const int partner = a == object ? b : a;
    const Pose2 other = pose_of(poses, partner);
    Pose2 to = now;
    if (r.angle) to.theta = geometry::wrap_angle(a == object ? other.theta + *r.angle
                                                             : other.theta - *r.angle);
    if (r.distance) {
      Vec2 dir = now.position() - other.position();
      const double len = geometry::norm(dir);
      dir = len > 1e-9 ? (1.0 / len) * dir : Vec2{1.0, 0.0};
      const Vec2 c = other.position() + *r.distance * dir;
      to.x = c.x;
      to.y = c.y;
    }
    out.push_back(to);
  }
  return out;
}

std::optional<Pose2> wall_slot(const geometry::Scene& scene, int object, std::mt19937_64& rng) {
  const geometry::Object& o = scene.objects[static_cast<std::size_t>(object)];
  if (!o.wall || !o.wall->distance) return std::nullopt;
  const auto& room = scene.room.polygon;
  std::uniform_int_distribution<std::size_t> pick(0, room.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t e = pick(rng);
  const Vec2 p = room[e], q = room[(e + 1) % room.size()];
  const Vec2 u = q - p;
  const double normal = std::atan2(u.x, -u.y);  // inward normal of a counter-clockwise room
  const double theta = normal + (o.wall->angle ? *o.wall->angle : 0.0);
  return against_edge(scene, o, static_cast<int>(e), theta, *o.wall->distance, p + unit(rng) * u);
}

}  // namespace hrs::optimize
