// SPDX-License-Identifier: GPL-3.0-or-later
// Preferences met or not, and poses that meet them; see preferences.h.

#include "optimize/preferences.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hrs::optimize {

using geometry::Pose2;
using geometry::Vec2;

namespace {

Pose2 pose_of(const std::vector<Pose2>& poses, int i) { return poses[static_cast<std::size_t>(i)]; }

//! The reference points of object `o` (heading `theta`) whose footprint lies
//! `distance` from room edge `edge`'s line, inside the edge's extent: the
//! segment p + t·u + k·n, t in [lo, hi].
struct WallLine {
  Vec2 p, u, n;
  double k = 0.0, lo = 0.0, hi = 0.0;
  double theta = 0.0;
  Pose2 at(double t) const {
    const Vec2 c = p + std::clamp(t, lo, hi) * u + k * n;
    return {c.x, c.y, geometry::wrap_angle(theta)};
  }
};

//! nullopt when the footprint is wider than the edge.
std::optional<WallLine> wall_line(const geometry::Scene& scene, const geometry::Object& o, int edge,
                                  double theta, double distance) {
  const auto& room = scene.room.polygon;
  const Vec2 p = room[static_cast<std::size_t>(edge)];
  const Vec2 q = room[(static_cast<std::size_t>(edge) + 1) % room.size()];
  const double length = geometry::norm(q - p);
  if (!(length > 0.0)) return std::nullopt;
  WallLine line;
  line.p = p;
  line.u = (1.0 / length) * (q - p);
  line.n = Vec2{-line.u.y, line.u.x};  // inward: the room is counter-clockwise
  line.theta = theta;
  double min_n = std::numeric_limits<double>::infinity();
  double min_u = min_n, max_u = -min_n;
  for (const Vec2& v : o.footprint) {
    const Vec2 w = geometry::rotate(v, theta);
    min_n = std::min(min_n, geometry::dot(w, line.n));
    min_u = std::min(min_u, geometry::dot(w, line.u));
    max_u = std::max(max_u, geometry::dot(w, line.u));
  }
  if (max_u - min_u > length) return std::nullopt;
  line.k = distance - min_n;
  line.lo = -min_u;
  line.hi = length - max_u;
  return line;
}

//! The pose against `edge` nearest the position `near` (wall_line()).
std::optional<Pose2> against_edge(const geometry::Scene& scene, const geometry::Object& o,
                                  int edge, double theta, double distance, const Vec2& near) {
  const auto line = wall_line(scene, o, edge, theta, distance);
  if (!line) return std::nullopt;
  return line->at(geometry::dot(near - line->p, line->u));
}

//! The points of `line` at distance `d` from `centre` (0, 1 or 2 poses), or
//! when the line stays farther, its point nearest `centre`.
void at_distance(const WallLine& line, const Vec2& centre, double d, std::vector<Pose2>& out) {
  const double t0 = geometry::dot(centre - line.p, line.u);
  const double off = line.k - geometry::dot(centre - line.p, line.n);
  const double s = d * d - off * off;
  if (s < 0.0) {
    out.push_back(line.at(t0));  // as near as the wall gets
    return;
  }
  for (const double t : {t0 - std::sqrt(s), t0 + std::sqrt(s)})
    if (t >= line.lo - 1e-12 && t <= line.hi + 1e-12) out.push_back(line.at(t));
}

void add(PreferenceReport& report, PreferenceCheck check) {
  check.met = check.residual <= check.tolerance;
  report.total += 1;
  report.met += check.met ? 1 : 0;
  if (check.angular()) report.worst_angle = std::max(report.worst_angle, check.residual);
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
    if (r.faces) {
      const double e = facing_error(pa, pb);
      add(report, {"relation_faces", r.a, r.b, -1, 0.0, e, std::abs(e), tol.relation_angle});
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
      const auto line = wall_line(scene, o, e, theta, *o.wall->distance);
      if (!line) continue;
      out.push_back(line->at(geometry::dot(now.position() - line->p, line->u)));
      // Along the wall where a relation's distance is met too.
      for (const geometry::Relation& r : scene.relations) {
        const int a = scene.find_object(r.a), b = scene.find_object(r.b);
        if (a < 0 || b < 0 || (a != object && b != object)) continue;
        const Vec2 partner = pose_of(poses, a == object ? b : a).position();
        if (r.distance) at_distance(*line, partner, *r.distance, out);
        // Facing the partner from the wall: straight across from it.
        if (r.faces && a == object) out.push_back(line->at(geometry::dot(partner - line->p, line->u)));
      }
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
    if (r.faces && a == object)
      to.theta = geometry::wrap_angle(now.theta + facing_error(now, other));
    if (r.distance) {
      Vec2 dir = now.position() - other.position();
      const double len = geometry::norm(dir);
      dir = len > 1e-9 ? (1.0 / len) * dir : Vec2{1.0, 0.0};
      const Vec2 c = other.position() + *r.distance * dir;
      to.x = c.x;
      to.y = c.y;
    }
    out.push_back(to);
    // In front of the partner at the distance (a table before a sofa, a TV
    // across from it), turned as the relation asks.
    if (r.distance) {
      const Vec2 front{std::cos(other.theta), std::sin(other.theta)};
      const Vec2 c = other.position() + *r.distance * front;
      const double theta = r.faces && a == object ? std::atan2(other.y - c.y, other.x - c.x) : to.theta;
      out.push_back({c.x, c.y, theta});
    }
  }
  return out;
}

std::vector<Pose2> wall_slides(const geometry::Scene& scene, const CostModel& model,
                               const std::vector<Pose2>& poses, int object, double step) {
  std::vector<Pose2> out;
  const geometry::Object& o = scene.objects[static_cast<std::size_t>(object)];
  if (!o.wall || !o.wall->distance || !(step > 0.0)) return out;
  const Pose2 now = pose_of(poses, object);
  std::vector<std::pair<double, Pose2>> ranked;
  for (int e = 0; e < static_cast<int>(scene.room.polygon.size()); ++e) {
    const double theta =
        o.wall->angle ? model.wall_normal_angle(e) + *o.wall->angle : now.theta;
    const auto line = wall_line(scene, o, e, theta, *o.wall->distance);
    if (!line) continue;
    // Every step from the line's start, and its end unless a step landed
    // on it (within a micrometre).
    const int n = static_cast<int>(std::floor((line->hi - line->lo) / step));
    const bool end_apart = line->hi - (line->lo + n * step) > 1e-6;
    for (int j = 0; j <= n + (end_apart ? 1 : 0); ++j) {
      const Pose2 at = line->at(j <= n ? line->lo + j * step : line->hi);
      ranked.emplace_back(geometry::norm(at.position() - now.position()), at);
    }
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& r : ranked) out.push_back(r.second);
  return out;
}

std::vector<Pose2> relation_slides(const geometry::Scene& scene, const std::vector<Pose2>& poses,
                                   int object, double step) {
  std::vector<Pose2> out;
  const geometry::Object& o = scene.objects[static_cast<std::size_t>(object)];
  if ((o.wall && o.wall->distance) || !(step > 0.0)) return out;
  const Pose2 now = pose_of(poses, object);
  const geometry::Box box = geometry::bounding_box(scene.room.polygon);
  std::vector<std::pair<double, Pose2>> ranked;
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (a < 0 || b < 0 || (a != object && b != object) || !r.distance || !(*r.distance > 0.0))
      continue;
    const Pose2 other = pose_of(poses, a == object ? b : a);
    const double d = *r.distance;
    // At least eight places, and at most one per centimetre of arc.
    const int n = std::clamp(static_cast<int>(std::ceil(2.0 * std::numbers::pi * d / step)), 8,
                             std::max(8, static_cast<int>(2.0 * std::numbers::pi * d * 100.0)));
    for (int j = 0; j < n; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / n;
      const Vec2 c{other.x + d * std::cos(phi), other.y + d * std::sin(phi)};
      if (c.x < box.xmin || c.x > box.xmax || c.y < box.ymin || c.y > box.ymax) continue;
      double theta = now.theta;
      if (r.angle) theta = a == object ? other.theta + *r.angle : other.theta - *r.angle;
      if (r.faces && a == object) theta = std::atan2(other.y - c.y, other.x - c.x);
      ranked.emplace_back(geometry::norm(c - now.position()),
                          Pose2{c.x, c.y, geometry::wrap_angle(theta)});
    }
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& r : ranked) out.push_back(r.second);
  return out;
}

namespace {

//! The middle of the back edge of `o`'s footprint's bounding box, in its
//! local frame (the front is local +x).
Vec2 back_middle(const geometry::Object& o) {
  double x = std::numeric_limits<double>::infinity();
  double y0 = x, y1 = -x;
  for (const Vec2& v : o.footprint) {
    x = std::min(x, v.x);
    y0 = std::min(y0, v.y);
    y1 = std::max(y1, v.y);
  }
  return {x, 0.5 * (y0 + y1)};
}

Vec2 rotated(const Vec2& v, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

}  // namespace

std::vector<GroupMove> swaps(const geometry::Scene& scene, const std::vector<Pose2>& poses, int a,
                             int b) {
  const geometry::Object& oa = scene.objects[static_cast<std::size_t>(a)];
  const geometry::Object& ob = scene.objects[static_cast<std::size_t>(b)];
  const Pose2 pa = pose_of(poses, a), pb = pose_of(poses, b);
  // Object `o` with its back middle where `at`'s object (back middle `m`) has its own.
  const auto back_to = [](const geometry::Object& o, const Pose2& at, const Vec2& m) {
    const Vec2 back = at.position() + rotated(m, at.theta);
    const Vec2 c = back - rotated(back_middle(o), at.theta);
    return Pose2{c.x, c.y, at.theta};
  };
  std::vector<GroupMove> out;
  out.push_back({{a, back_to(oa, pb, back_middle(ob))}, {b, back_to(ob, pa, back_middle(oa))}});
  out.push_back({{a, {pb.x, pb.y, pa.theta}}, {b, {pa.x, pa.y, pb.theta}}});
  return out;
}

std::vector<std::vector<int>> heading_groups(const geometry::Scene& scene) {
  const int n = static_cast<int>(scene.objects.size());
  std::vector<int> parent(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) parent[static_cast<std::size_t>(i)] = i;
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)];
    return i;
  };
  for (const geometry::Relation& r : scene.relations) {
    const int a = scene.find_object(r.a), b = scene.find_object(r.b);
    if (a < 0 || b < 0 || !r.angle || a == b) continue;
    const int ra = root(a), rb = root(b);
    if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
  std::vector<std::vector<int>> groups(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) groups[static_cast<std::size_t>(root(i))].push_back(i);
  std::vector<std::vector<int>> out;
  for (auto& g : groups)
    if (g.size() >= 2) out.push_back(std::move(g));
  return out;
}

std::vector<GroupMove> group_turns(const geometry::Scene& scene, const CostModel& model,
                                   const std::vector<Pose2>& poses, const std::vector<bool>& movable,
                                   const std::vector<int>& group) {
  // offset[m]: the member's heading minus the group's first one, along a
  // spanning tree (relation: theta_a − theta_b = angle).
  std::vector<std::optional<double>> offset(scene.objects.size());
  offset[static_cast<std::size_t>(group.front())] = 0.0;
  for (bool grew = true; grew;) {
    grew = false;
    for (const geometry::Relation& r : scene.relations) {
      const int a = scene.find_object(r.a), b = scene.find_object(r.b);
      if (a < 0 || b < 0 || !r.angle) continue;
      auto &oa = offset[static_cast<std::size_t>(a)], &ob = offset[static_cast<std::size_t>(b)];
      if (oa && !ob) ob = *oa - *r.angle, grew = true;
      if (ob && !oa) oa = *ob + *r.angle, grew = true;
    }
  }
  const auto wall_heading = [&](int m, int edge) {
    return model.wall_normal_angle(edge) + *scene.objects[static_cast<std::size_t>(m)].wall->angle;
  };
  std::vector<double> rotations;
  for (const int m : group) {
    const geometry::Object& o = scene.objects[static_cast<std::size_t>(m)];
    const Pose2 p = pose_of(poses, m);
    const double anchor = movable[static_cast<std::size_t>(m)] && o.wall && o.wall->angle
                              ? wall_heading(m, model.nearest_wall(m, p))
                              : p.theta;
    const double phi = geometry::wrap_angle(anchor - *offset[static_cast<std::size_t>(m)]);
    if (std::none_of(rotations.begin(), rotations.end(), [&](double x) {
          return std::abs(geometry::wrap_angle(x - phi)) < 1e-9;
        }))
      rotations.push_back(phi);
  }
  std::vector<GroupMove> out;
  const int edges = static_cast<int>(scene.room.polygon.size());
  for (const double phi : rotations) {
    GroupMove move;
    bool ok = true;
    for (const int m : group) {
      if (!movable[static_cast<std::size_t>(m)]) continue;
      const geometry::Object& o = scene.objects[static_cast<std::size_t>(m)];
      const Pose2 now = pose_of(poses, m);
      const double h = geometry::wrap_angle(phi + *offset[static_cast<std::size_t>(m)]);
      if (std::abs(geometry::wrap_angle(h - now.theta)) < 1e-9) continue;
      if (o.wall && o.wall->angle && o.wall->distance) {
        // The wall whose normal gives the heading; nearest the position.
        std::optional<Pose2> best;
        double best_d = std::numeric_limits<double>::infinity();
        for (int e = 0; e < edges; ++e) {
          if (std::abs(geometry::wrap_angle(wall_heading(m, e) - h)) > 1e-6) continue;
          const auto at = against_edge(scene, o, e, h, *o.wall->distance, now.position());
          if (!at) continue;
          const double d = geometry::norm(at->position() - now.position());
          if (d < best_d) best_d = d, best = at;
        }
        if (!best) {
          ok = false;
          break;
        }
        move.emplace_back(m, *best);
      } else {
        move.emplace_back(m, Pose2{now.x, now.y, h});
      }
    }
    if (ok && !move.empty()) out.push_back(std::move(move));
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
