// SPDX-License-Identifier: GPL-3.0-or-later
// Square headings; see squaring.h.

#include "optimize/squaring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/polygon_ops.h"
#include "optimize/rearrange.h"

namespace hrs::optimize {

bool heading_fixed(const geometry::Scene& scene, int object) {
  const geometry::Object& o = scene.objects[static_cast<std::size_t>(object)];
  if (o.wall && o.wall->angle) return true;
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (r.angle && (a == object || b == object)) return true;
    if (r.faces && a == object) return true;
  }
  return false;
}

std::vector<SquarePlace> square_places(
    const geometry::Scene& scene, const CostModel& model, const std::vector<geometry::Pose2>& poses,
    int object, const PreferenceReport& report,
    const std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)>& valid) {
  std::vector<SquarePlace> out;
  const std::size_t i = static_cast<std::size_t>(object);
  const int wall = model.nearest_wall(object, poses[i]);
  const double normal = model.wall_normal_angle(wall);
  const double off = geometry::wrap_angle(poses[i].theta - normal);
  const double quarter = std::numbers::pi / 2;
  if (std::abs(off - std::round(off / quarter) * quarter) < kSquareTolerance) return out;
  // Quarter turns from the wall's normal, nearest `off` first; the stable
  // sort keeps the lower multiple first on a tie.
  std::vector<double> squares;
  for (int k = -2; k <= 1; ++k) squares.push_back(k * quarter);
  std::stable_sort(squares.begin(), squares.end(), [&](double a, double b) {
    return std::abs(geometry::wrap_angle(off - a)) < std::abs(geometry::wrap_angle(off - b));
  });
  // The footprint's reach towards the wall: the least signed distance of
  // its corners from the wall's line, negative beyond it (a quarter turn
  // can push a long object through the wall, which a clamped distance
  // would not show).
  const geometry::Vec2 wall_at = scene.room.polygon[static_cast<std::size_t>(wall)];
  const geometry::Vec2 inward{std::cos(normal), std::sin(normal)};
  const auto gap = [&](const geometry::Pose2& at) {
    geometry::Object o = scene.objects[i];
    o.pose = at;
    double reach = std::numeric_limits<double>::infinity();
    for (const geometry::Vec2& c : geometry::world_footprint(o))
      reach = std::min(reach, (c.x - wall_at.x) * inward.x + (c.y - wall_at.y) * inward.y);
    return reach;
  };
  const double gap_was = gap(poses[i]);
  const int score = polish_score(report);
  for (const double square : squares) {
    geometry::Pose2 turned = poses[i];
    turned.theta = geometry::wrap_angle(normal + square);
    const double shift = gap(turned) - gap_was;  // > 0: the turn took it off the wall
    std::vector<geometry::Pose2> tries{turned};
    if (std::abs(shift) > 1e-9)
      tries.push_back(
          {turned.x - shift * std::cos(normal), turned.y - shift * std::sin(normal), turned.theta});
    for (const geometry::Pose2& to : tries) {
      std::vector<geometry::Pose2> p = poses;
      p[i] = to;
      if (!valid(p, object)) continue;
      PreferenceReport next = check_preferences(scene, model, p);
      if (polish_score(next) >= score) {
        out.push_back({to, std::move(next)});
        break;
      }
    }
  }
  return out;
}

}  // namespace hrs::optimize
