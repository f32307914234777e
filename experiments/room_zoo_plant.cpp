// SPDX-License-Identifier: GPL-3.0-or-later
// The plant and the scramble of the room zoo (experiments/room_zoo_plant.h):
// rejection sampling of rectangles against the room (exact predicates after
// cheap double filters) and against each other and the kept-free zones.

#include "experiments/room_zoo_plant.h"

#include <algorithm>
#include <numbers>

#include "geometry/polygon_ops.h"

namespace hrs::experiments::zoo::detail {

namespace {

using geometry::Object;
using geometry::Polygon;
using geometry::Pose2;
using geometry::Scene;
using geometry::Side;
using geometry::Vec2;
using geometry::wrap_angle;

constexpr double kPi = std::numbers::pi;
//! Wall objects stand this far off their wall: their footprints stay inside
//! the room under the rounding of the rotation (about 1e-15 m), and the wall
//! distance is 0 up to 1e-9.
constexpr double kWallInset = 2e-10;
//! Tries to place one object in a plant, and to scramble one.
constexpr int kPlaceTries = 400;
constexpr int kScrambleTries = 300;

struct Rect {
  double xmin, ymin, xmax, ymax;
};
Rect rect_of(const Polygon& p) {
  const geometry::Box b = geometry::bounding_box(p);
  return {b.xmin, b.ymin, b.xmax, b.ymax};
}
bool boxes_meet(const Rect& a, const Rect& b) {
  return a.xmin < b.xmax && b.xmin < a.xmax && a.ymin < b.ymax && b.ymin < a.ymax;
}

//! Separating axes of two convex polygons in doubles: +1 when an axis
//! separates them by more than 1e-9 m, -1 when every axis overlaps by more
//! than 1e-9 m (the interiors meet), 0 when too close to tell (then the exact
//! predicate decides).
int convex_overlap(const Polygon& a, const Polygon& b) {
  bool deep = true;
  for (const Polygon* p : {&a, &b}) {
    for (std::size_t i = 0; i < p->size(); ++i) {
      const Vec2 e = (*p)[(i + 1) % p->size()] - (*p)[i];
      const Vec2 axis = (1.0 / norm(e)) * Vec2{-e.y, e.x};
      double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
      for (Vec2 v : a) amin = std::min(amin, dot(v, axis)), amax = std::max(amax, dot(v, axis));
      for (Vec2 v : b) bmin = std::min(bmin, dot(v, axis)), bmax = std::max(bmax, dot(v, axis));
      const double gap = std::max(bmin - amax, amin - bmax);
      if (gap > 1e-9) return +1;
      if (gap > -1e-9) deep = false;
    }
  }
  return deep ? -1 : 0;
}

//! Obstacles of a plant: footprints (objects) and zones kept free, all
//! rectangles (convex).
struct Occupancy {
  std::vector<Polygon> solids, zones;
  std::vector<Rect> solid_boxes, zone_boxes;
  static bool hits(const Polygon& p, const std::vector<Polygon>& list,
                   const std::vector<Rect>& boxes) {
    const Rect r = rect_of(p);
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!boxes_meet(r, boxes[i])) continue;
      const int sat = convex_overlap(p, list[i]);
      if (sat < 0 || (sat == 0 && geometry::interiors_overlap(p, list[i]))) return true;
    }
    return false;
  }
  void add_solid(Polygon p) {
    solid_boxes.push_back(rect_of(p));
    solids.push_back(std::move(p));
  }
  void add_zone(Polygon p) {
    zone_boxes.push_back(rect_of(p));
    zones.push_back(std::move(p));
  }
};

//! Exact "inside the room", after a cheap rejection of polygons with a
//! vertex clearly outside it.
bool inside_room(const Polygon& p, const Polygon& room) {
  for (Vec2 v : p) {
    if (geometry::point_in_polygon(v, room)) continue;
    double d = 1e300;
    for (std::size_t i = 0; i < room.size(); ++i)
      d = std::min(d, geometry::point_segment_distance(v, room[i], room[(i + 1) % room.size()]));
    if (d > 1e-9) return false;
  }
  return geometry::polygon_inside(p, room);
}

Polygon local_rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

//! The stopping zone kept free beside side `side` of an object: as deep as
//! the approach gap, the chair's length and 0.3 m, 0.6 m wider than the chair.
Polygon approach_zone(const Object& o, double depth, double width, Side side,
                      const geometry::Wheelchair& chair) {
  const double reach = o.approach_or_default().gap + chair.length + 0.3;
  const double h = 0.5 * chair.width + 0.3, hd = 0.5 * depth, hw = 0.5 * width;
  Polygon local;
  switch (side) {
    case Side::kFront: local = local_rect(hd, -h, hd + reach, h); break;
    case Side::kBack: local = local_rect(-hd - reach, -h, -hd, h); break;
    case Side::kLeft: local = local_rect(-h, hw, h, hw + reach); break;
    case Side::kRight: local = local_rect(-h, -hw - reach, h, -hw); break;
  }
  for (Vec2& v : local) v = geometry::to_world(o.pose, v);
  return local;
}

Object make_object(const Item& it) {
  Object o;
  o.id = it.id;
  o.size = std::array<double, 2>{it.depth, it.width};
  const double hx = 0.5 * it.depth, hy = 0.5 * it.width;
  o.footprint = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  o.fixed = it.fixed;
  if (it.kind->wall) o.wall = geometry::WallPreference{0.0, 0.0};
  geometry::Approach a{{false, false, false, false}, 0.1};
  for (int s = 0; s < 4; ++s) a.sides[s] = (it.kind->sides >> s) & 1u;
  o.approach = a;
  return o;
}

//! A pose for `o` against a wall (its back to it) or in the open.
Pose2 draw_pose(const Polygon& room, const Item& it, std::mt19937_64& rng) {
  if (it.kind->wall) {
    std::vector<double> lengths;
    double total = 0.0;
    const std::size_t n = room.size();
    for (std::size_t e = 0; e < n; ++e) {
      const double len = norm(room[(e + 1) % n] - room[e]);
      lengths.push_back(len >= it.width + 1e-8 ? len : 0.0);
      total += lengths.back();
    }
    if (total <= 0.0) return {0, 0, 0};
    double u = uniform01(rng) * total;
    std::size_t e = 0;
    while (e + 1 < n && (u -= lengths[e]) >= 0.0) ++e;
    while (lengths[e] == 0.0) e = (e + 1) % n;
    const Vec2 a = room[e], b = room[(e + 1) % n];
    const double len = lengths[e];
    const Vec2 d = (1.0 / len) * (b - a), nrm{-d.y, d.x};
    const double lo = 0.5 * it.width + 1e-9, hi = len - 0.5 * it.width - 1e-9;
    const double c = uniform01(rng);
    const double t = c < 0.15 ? lo : c < 0.3 ? hi : draw(rng, lo, hi);  // corners are common
    const Vec2 p = a + t * d + (0.5 * it.depth + kWallInset) * nrm;
    return {p.x, p.y, std::atan2(nrm.y, nrm.x)};
  }
  const geometry::Box box = geometry::bounding_box(room);
  if (!it.toured && uniform01(rng) < 0.7) {
    // Most furniture that is not toured stands near a wall, out of the way.
    const std::size_t n = room.size(), e = uniform_index(rng, n);
    const Vec2 a = room[e], b = room[(e + 1) % n];
    const Vec2 d = (1.0 / norm(b - a)) * (b - a), nrm{-d.y, d.x};
    const double reach = 0.5 * std::max(it.depth, it.width) + draw(rng, 0.0, 0.3);
    const Vec2 p = a + draw(rng, 0.0, norm(b - a)) * d + reach * nrm;
    return {p.x, p.y, wrap_angle(draw(rng, -kPi, kPi))};
  }
  const double theta = uniform01(rng) < 0.5 ? draw(rng, -kPi, kPi)
                                            : kPi / 2 * static_cast<double>(uniform_index(rng, 4));
  return {draw(rng, box.xmin + 0.2, box.xmax - 0.2), draw(rng, box.ymin + 0.2, box.ymax - 0.2),
          wrap_angle(theta)};
}

}  // namespace

bool plant(Scene& scene, const std::vector<Item>& items, std::mt19937_64& rng) {
  Occupancy occ;
  for (const Object& p : scene.objects) occ.add_solid(geometry::world_footprint(p));
  occ.add_zone(geometry::door_clear_zone(scene));
  // Room to turn inside the door: 2.4 m wide, 2.2 m deep (kept free in the
  // plant only, not a rule of the scene).
  {
    const Vec2 n = geometry::door_inward_normal(scene), d{n.y, -n.x}, c = scene.door.center;
    occ.add_zone({c - 1.2 * d, c + 1.2 * d, c + 1.2 * d + 2.2 * n, c - 1.2 * d + 2.2 * n});
  }
  // Toured objects first (they need their stopping zones), wall objects
  // before the others, larger first.
  std::vector<std::size_t> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (items[a].toured != items[b].toured) return items[a].toured;
    if (items[a].kind->wall != items[b].kind->wall) return items[a].kind->wall;
    return items[a].depth * items[a].width > items[b].depth * items[b].width;
  });
  std::vector<Object> placed(items.size());
  for (std::size_t i : order) {
    const Item& it = items[i];
    Object o = make_object(it);
    bool ok = false;
    for (int tr = 0; tr < kPlaceTries && !ok; ++tr) {
      o.pose = draw_pose(scene.room.polygon, it, rng);
      const Polygon fp = geometry::world_footprint(o);
      if (!inside_room(fp, scene.room.polygon)) continue;
      if (Occupancy::hits(fp, occ.solids, occ.solid_boxes) ||
          Occupancy::hits(fp, occ.zones, occ.zone_boxes))
        continue;
      if (!it.toured) {
        occ.add_solid(fp);
        ok = true;
        break;
      }
      // One allowed side, tried in random order, must have its stopping zone.
      std::vector<Side> sides;
      for (int s = 0; s < 4; ++s)
        if (o.approach->sides[s]) sides.push_back(static_cast<Side>(s));
      shuffle(sides, rng);
      for (Side s : sides) {
        Polygon zone = approach_zone(o, it.depth, it.width, s, scene.wheelchair);
        if (!inside_room(zone, scene.room.polygon)) continue;
        if (Occupancy::hits(zone, occ.solids, occ.solid_boxes)) continue;
        occ.add_zone(std::move(zone));
        occ.add_solid(fp);
        ok = true;
        break;
      }
    }
    if (!ok) return false;
    placed[i] = std::move(o);
  }
  for (auto& o : placed) scene.objects.push_back(std::move(o));
  return true;
}

void scramble(Scene& scene, std::mt19937_64& rng) {
  const Polygon& room = scene.room.polygon;
  const geometry::Box box = geometry::bounding_box(room);
  Occupancy occ;
  occ.add_zone(geometry::door_clear_zone(scene));
  for (const Object& o : scene.objects)
    if (o.fixed) occ.add_solid(geometry::world_footprint(o));
  for (Object& o : scene.objects) {
    if (o.fixed) continue;
    const Pose2 planted = o.pose;
    bool placed = false;
    // Without overlap when possible, else anywhere inside, else where planted.
    for (int pass = 0; pass < 2 && !placed; ++pass) {
      for (int tr = 0; tr < kScrambleTries && !placed; ++tr) {
        o.pose = {draw(rng, box.xmin, box.xmax), draw(rng, box.ymin, box.ymax),
                  draw(rng, -kPi, kPi)};
        const Polygon fp = geometry::world_footprint(o);
        if (!inside_room(fp, room)) continue;
        if (pass == 0 && (Occupancy::hits(fp, occ.solids, occ.solid_boxes) ||
                          Occupancy::hits(fp, occ.zones, occ.zone_boxes)))
          continue;
        occ.add_solid(fp);
        placed = true;
      }
    }
    if (!placed) {
      o.pose = planted;
      occ.add_solid(geometry::world_footprint(o));
    }
  }
}

}  // namespace hrs::experiments::zoo::detail
