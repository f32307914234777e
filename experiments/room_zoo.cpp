// The room zoo (experiments/room_zoo.h): shapes, furniture, the planted
// layout, preferences read off it, the AO graph, the scramble and the
// witness check.

#include "experiments/room_zoo.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <map>
#include <set>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/random.h"
#include "optimize/design.h"

namespace hrs::experiments::zoo {

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
constexpr double kPartitionDepth = 0.1;
constexpr char kPartitionPrefix[] = "partition_";
//! Tries to place one object in a plant, and to scramble one.
constexpr int kPlaceTries = 400;
constexpr int kScrambleTries = 300;

// ---- furniture ---------------------------------------------------------------

constexpr unsigned kFront = 1u << static_cast<int>(Side::kFront);
constexpr unsigned kBack = 1u << static_cast<int>(Side::kBack);
constexpr unsigned kLeft = 1u << static_cast<int>(Side::kLeft);
constexpr unsigned kRight = 1u << static_cast<int>(Side::kRight);
constexpr unsigned kAll = kFront | kBack | kLeft | kRight;

struct Kind {
  const char* name;
  double depth, width;  //!< m, before a ±10 % jitter
  bool wall;            //!< back against a wall, with a wall preference
  unsigned sides;       //!< approach sides
  double fixed_share;   //!< probability of being fixed
  double weight;        //!< how often it is drawn
};

constexpr Kind kKinds[] = {
    {"bed", 2.0, 1.4, true, kLeft | kRight, 0.0, 1.0},
    {"single_bed", 2.0, 0.9, true, kLeft | kRight, 0.0, 1.0},
    {"wardrobe", 0.6, 1.2, true, kFront, 0.5, 1.5},
    {"dresser", 0.5, 1.0, true, kFront, 0.0, 1.5},
    {"desk", 0.6, 1.2, true, kFront, 0.0, 1.5},
    {"bookshelf", 0.35, 0.9, true, kFront, 0.2, 1.5},
    {"tv", 0.4, 1.2, true, kFront, 0.0, 1.0},
    {"sofa", 0.9, 2.0, true, kFront, 0.0, 1.0},
    {"nightstand", 0.4, 0.45, true, kFront, 0.0, 2.0},
    {"cabinet", 0.45, 0.8, true, kFront, 0.3, 1.5},
    {"radiator", 0.15, 1.0, true, kFront, 1.0, 0.5},
    {"armchair", 0.8, 0.8, false, kFront, 0.0, 1.0},
    {"chair", 0.5, 0.5, false, kFront | kLeft | kRight, 0.0, 3.0},
    {"table", 0.8, 1.2, false, kAll, 0.0, 1.0},
    {"coffee_table", 0.5, 0.9, false, kAll, 0.0, 1.0},
    {"lamp", 0.35, 0.35, false, kAll, 0.0, 2.0},
    {"plant", 0.4, 0.4, false, kAll, 0.0, 1.5},
    {"stool", 0.4, 0.4, false, kAll, 0.0, 1.5},
};

//! Fisher–Yates with uniform_index (std::shuffle's draws differ between
//! standard libraries).
template <class T>
void shuffle(std::vector<T>& v, std::mt19937_64& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[uniform_index(rng, i)]);
}

double draw(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }
double cm(double x) { return std::round(100.0 * x) / 100.0; }

//! One piece of furniture of the room (drawn once per room).
struct Item {
  const Kind* kind;
  double depth, width;
  bool fixed;
  std::string id;
  bool toured = false;  //!< a node of the AO graph: gets a stopping zone
};

std::vector<Item> draw_furniture(std::mt19937_64& rng, int count) {
  double total = 0.0;
  for (const Kind& k : kKinds) total += k.weight;
  std::vector<Item> items;
  std::map<std::string, int> used;
  int large = 0;  // beds and sofas: at most one per 8 items (and one)
  while (static_cast<int>(items.size()) < count) {
    double u = uniform01(rng) * total;
    const Kind* kind = &kKinds[0];
    for (const Kind& k : kKinds) {
      kind = &k;
      if ((u -= k.weight) < 0.0) break;
    }
    const bool is_large = kind->depth * kind->width > 1.5;
    if (is_large && large >= std::max(1, count / 8)) continue;
    large += is_large;
    Item it{kind, cm(kind->depth * draw(rng, 0.9, 1.1)), cm(kind->width * draw(rng, 0.9, 1.1)),
            uniform01(rng) < kind->fixed_share, "", false};
    it.id = std::string(kind->name) + "_" + std::to_string(++used[kind->name]);
    items.push_back(std::move(it));
  }
  return items;
}

// ---- rooms -------------------------------------------------------------------

//! A drawn room: the polygon, the door and the partition walls of a flat.
struct Floor {
  Polygon polygon;
  geometry::Door door;
  std::vector<Object> partitions;
};

//! The room-level choices (kept across plants): shape, rooms of a flat and
//! whether each partition's opening is at an end (one piece) or not (two).
struct Plan {
  Shape shape;
  int flat_rooms = 2;
  std::vector<bool> two_pieces;
  double area = 9.0;
};

Object partition_piece(const std::string& id, double x, double y0, double y1) {
  Object o;
  o.id = id;
  o.size = std::array<double, 2>{kPartitionDepth, y1 - y0};
  const double hx = 0.5 * kPartitionDepth, hy = 0.5 * (y1 - y0);
  o.footprint = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  o.pose = {x + hx, 0.5 * (y0 + y1), 0.0};
  o.fixed = true;
  return o;
}

//! Width and depth of a box of `area` with aspect in [1, 1.8], shorter side
//! at least `min_side`.
std::pair<double, double> box_of(std::mt19937_64& rng, double area, double min_side) {
  double w = std::sqrt(area * draw(rng, 1.0, 1.8));
  double d = area / w;
  if (d < min_side) d = min_side, w = std::max(area / d, min_side);
  return {cm(w), cm(d)};
}

Floor draw_floor(const Plan& plan, double area, std::mt19937_64& rng) {
  Floor f;
  switch (plan.shape) {
    case Shape::kRect: {
      const auto [w, d] = box_of(rng, area, 3.0);
      f.polygon = {{0, 0}, {w, 0}, {w, d}, {0, d}};
      break;
    }
    case Shape::kL: {
      const double fx = draw(rng, 0.35, 0.5), fy = draw(rng, 0.35, 0.5);
      const auto [w, d] = box_of(rng, area / (1.0 - fx * fy), 4.8);
      const double cw = cm(std::min(fx * w, w - 2.6)), cd = cm(std::min(fy * d, d - 2.6));
      f.polygon = {{0, 0}, {w, 0}, {w, d - cd}, {w - cw, d - cd}, {w - cw, d}, {0, d}};
      break;
    }
    case Shape::kU: {
      const double fx = draw(rng, 0.25, 0.4), fy = draw(rng, 0.3, 0.5);
      // Arms at least 2.4 m wide, the base at least 2.6 m deep.
      auto [w, d] = box_of(rng, area / (1.0 - fx * fy), 4.6);
      w = std::max(w, 5.8);
      const double nw = cm(std::clamp(fx * w, 1.0, w - 4.8));
      const double nd = cm(std::min(fy * d, d - 2.6));
      const double x1 = cm(draw(rng, 2.4, w - 2.4 - nw)), x2 = x1 + nw;
      f.polygon = {{0, 0}, {w, 0}, {w, d}, {x2, d}, {x2, d - nd}, {x1, d - nd}, {x1, d}, {0, d}};
      break;
    }
    case Shape::kFlat: {
      const int k = plan.flat_rooms;
      const double d = cm(draw(rng, 3.0, 5.0));
      const double w = cm(std::max(area / d, k * 2.8 + (k - 1) * kPartitionDepth));
      // Partition walls at x = s_i, each room at least 2.6 m wide.
      const double spare = w - k * 2.6 - (k - 1) * kPartitionDepth;
      std::vector<double> share(k);
      double sum = 0.0;
      for (double& s : share) sum += (s = draw(rng, 0.5, 1.5));
      double x = 0.0;
      for (int i = 0; i + 1 < k; ++i) {
        x = cm(x + 2.6 + spare * share[i] / sum);
        const double opening = cm(draw(rng, 1.2, 1.5));
        const std::string id = kPartitionPrefix + std::to_string(i + 1);
        // 1e-9 m off the walls, so that rounding keeps the pieces inside.
        if (plan.two_pieces[i]) {
          const double y0 = cm(draw(rng, 0.5, d - opening - 0.5));
          f.partitions.push_back(partition_piece(id + "a", x, 1e-9, y0));
          f.partitions.push_back(partition_piece(id + "b", x, y0 + opening, d - 1e-9));
        } else if (uniform01(rng) < 0.5) {
          f.partitions.push_back(partition_piece(id, x, opening, d - 1e-9));
        } else {
          f.partitions.push_back(partition_piece(id, x, 1e-9, d - opening));
        }
        x += kPartitionDepth;
      }
      f.polygon = {{0, 0}, {w, 0}, {w, d}, {0, d}};
      // The door on the outer wall of the first room.
      const double first = f.partitions.front().pose.x - 0.5 * kPartitionDepth;
      f.door.center = {cm(draw(rng, 0.8, first - 0.8)), 0.0};
      break;
    }
  }
  if (plan.shape != Shape::kFlat) {
    // The door on an edge at least 2 m long, 0.8 m or more from its ends.
    std::vector<int> edges;
    const std::size_t n = f.polygon.size();
    for (std::size_t e = 0; e < n; ++e)
      if (norm(f.polygon[(e + 1) % n] - f.polygon[e]) >= 2.0) edges.push_back(static_cast<int>(e));
    const int e = edges[uniform_index(rng, edges.size())];
    const Vec2 a = f.polygon[e], b = f.polygon[(e + 1) % n];
    const double len = norm(b - a), t = cm(draw(rng, 0.8, len - 0.8));
    f.door.center = a + (t / len) * (b - a);
    // Axis-aligned edges: snap the constant coordinate exactly onto the edge.
    if (a.x == b.x) f.door.center.x = a.x;
    if (a.y == b.y) f.door.center.y = a.y;
  }
  f.door.width = 0.9;
  f.door.clear_depth = 1.2;
  return f;
}

// ---- planting ----------------------------------------------------------------

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

//! Places every item: false when one found no place.
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

// ---- preferences and the AO graph -------------------------------------------

void add_relations(Scene& scene, std::mt19937_64& rng) {
  std::vector<int> furniture;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (!is_partition(scene.objects[i])) furniture.push_back(static_cast<int>(i));
  const int count = static_cast<int>(furniture.size()) / 3;
  std::set<std::pair<int, int>> used;
  for (int r = 0; r < count; ++r) {
    const int a = furniture[uniform_index(rng, furniture.size())];
    const Pose2& pa = scene.objects[a].pose;
    int best = -1;
    double best_d = 0.0;
    for (int b : furniture) {
      if (b == a || used.count({std::min(a, b), std::max(a, b)})) continue;
      const Pose2& pb = scene.objects[b].pose;
      const double d = std::hypot(pa.x - pb.x, pa.y - pb.y);
      if (best < 0 || d < best_d) best = b, best_d = d;
    }
    if (best < 0) continue;
    used.insert({std::min(a, best), std::max(a, best)});
    const Pose2& pb = scene.objects[best].pose;
    geometry::Relation rel;
    rel.a = scene.objects[a].id;
    rel.b = scene.objects[best].id;
    rel.distance = std::hypot(pa.x - pb.x, pa.y - pb.y);
    rel.angle = wrap_angle(pa.theta - pb.theta);
    scene.relations.push_back(rel);
  }
}

//! `count` probabilities of whole percents, each at least 1 %, summing to 1.
std::vector<double> percents(std::mt19937_64& rng, std::size_t count) {
  std::vector<int> w(count);
  int sum = 0;
  for (int& x : w) sum += (x = 1 + static_cast<int>(uniform_index(rng, 10)));
  std::vector<int> pct(count);
  int given = 0;
  for (std::size_t i = 0; i < count; ++i) given += (pct[i] = std::max(1, 100 * w[i] / sum));
  *std::max_element(pct.begin(), pct.end()) += 100 - given;
  std::vector<double> p;
  for (int x : pct) p.push_back(x / 100.0);
  return p;
}

//! The AO graph over the toured items.
void add_activity(Scene& scene, const std::vector<Item>& items, std::mt19937_64& rng) {
  std::vector<std::string> ids;
  for (const Item& it : items)
    if (it.toured) ids.push_back(it.id);
  auto row = [&](std::size_t outs, const std::string* self) {
    std::vector<std::string> to;
    for (const auto& id : ids)
      if (!self || id != *self) to.push_back(id);
    shuffle(to, rng);
    to.resize(std::min(outs, to.size()));
    if (self && uniform01(rng) < 0.25) to.push_back(*self);  // staying
    std::map<std::string, double> r;
    const auto p = percents(rng, to.size());
    for (std::size_t i = 0; i < to.size(); ++i) r[to[i]] = p[i];
    return r;
  };
  // At least 3 ways out of the door and 2 out of every node: >= 12 sequences.
  scene.activity.transitions[std::string(geometry::kStartNodeId)] =
      row(3 + uniform_index(rng, 3), nullptr);
  for (const auto& id : ids) scene.activity.transitions[id] = row(2 + uniform_index(rng, 3), &id);
  scene.activity.sequences = 10;
  scene.activity.visits = 3;
}

// ---- scramble ----------------------------------------------------------------

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

std::uint64_t mix(std::uint64_t a, std::uint64_t b) { return splitmix64(splitmix64(a) ^ b); }

}  // namespace

std::string shape_name(Shape shape) {
  switch (shape) {
    case Shape::kRect: return "rect";
    case Shape::kL: return "l";
    case Shape::kU: return "u";
    case Shape::kFlat: return "flat";
  }
  return "?";
}

std::optional<Shape> parse_shape(const std::string& name) {
  for (Shape s : {Shape::kRect, Shape::kL, Shape::kU, Shape::kFlat})
    if (name == shape_name(s)) return s;
  return std::nullopt;
}

bool is_partition(const Object& object) { return object.id.rfind(kPartitionPrefix, 0) == 0; }

WitnessCheck check_layout(const Scene& scene, int threads) {
  optimize::DesignOptions o;
  o.seed = 1;
  o.iterations = 0;
  o.threads = threads;
  const optimize::DesignResult r = optimize::design(scene, o);
  return {r.initial.tours_found, r.initial.tours_total, r.initial.total()};
}

ZooRoom generate_room(const ZooOptions& options, int index) {
  if (options.min_objects < 4 || options.max_objects < options.min_objects ||
      options.max_objects > static_cast<int>(geometry::limits::kObjects))
    throw InputError("zoo: object counts must satisfy 4 <= min <= max <= 100");
  const auto t0 = std::chrono::steady_clock::now();
  const std::uint64_t base = mix(options.seed, static_cast<std::uint64_t>(index));
  std::mt19937_64 rng(base);
  ZooRoom room;
  room.name = "zoo_" + std::to_string(options.seed) + "_" + std::to_string(index);
  // Room-level choices: shape, object count, partitions, furniture, openness.
  Plan plan;
  plan.shape = options.shape ? *options.shape : static_cast<Shape>(uniform_index(rng, 4));
  const int objects =
      options.min_objects +
      static_cast<int>(uniform_index(rng, options.max_objects - options.min_objects + 1));
  int pieces = 0;
  if (plan.shape == Shape::kFlat) {
    plan.flat_rooms = objects >= 12 && uniform01(rng) < 0.5 ? 3 : 2;
    for (int i = 0; i + 1 < plan.flat_rooms; ++i) {
      plan.two_pieces.push_back(objects - pieces >= 6 && uniform01(rng) < 0.5);
      pieces += plan.two_pieces.back() ? 2 : 1;
    }
  }
  std::vector<Item> items = draw_furniture(rng, objects - pieces);
  {  // 3 to 10 of them are nodes of the AO graph
    std::vector<std::size_t> pick(items.size());
    for (std::size_t i = 0; i < pick.size(); ++i) pick[i] = i;
    shuffle(pick, rng);
    pick.resize(std::min(items.size(), 3 + uniform_index(rng, 8)));
    for (std::size_t i : pick) items[i].toured = true;
  }
  double footprint = 0.0;
  for (const Item& it : items) footprint += it.depth * it.width;
  // From cramped (2.6 times the furniture) to open (4.5 times).
  const double base_area = std::clamp(footprint * draw(rng, 2.6, 4.5), 9.0, 60.0);
  room.shape = plan.shape;

  for (int attempt = 1; attempt <= options.max_plants; ++attempt) {
    room.plant_attempts = attempt;
    std::mt19937_64 arng(mix(base, static_cast<std::uint64_t>(attempt)));
    const double area = base_area * std::pow(1.1, (attempt - 1) / 4);
    Floor floor = draw_floor(plan, area, arng);
    Scene s;
    s.name = room.name;
    s.room.polygon = floor.polygon;
    s.door = floor.door;
    s.wheelchair = {1.1, 0.65, 0.7};
    s.objects = floor.partitions;
    if (!plant(s, items, arng)) {
      ++room.unplaced;
      continue;
    }
    add_relations(s, arng);
    add_activity(s, items, arng);
    Scene input = s;
    scramble(input, arng);
    // Both files must pass the reader (they always should: this is a guard).
    try {
      geometry::parse_scene(geometry::write_scene(s), room.name + ".witness.json");
      geometry::parse_scene(geometry::write_scene(input), room.name + ".json");
    } catch (const InputError&) {
      continue;
    }
    room.scene = std::move(input);
    room.witness = std::move(s);
    room.area = geometry::signed_area(room.scene.room.polygon);
    room.feasible = true;
    if (options.check_tours) {
      const WitnessCheck c = check_layout(room.witness, options.threads);
      room.tours_found = c.tours_found;
      room.tours_total = c.tours_total;
      room.witness_cost = c.cost;
      room.feasible = c.tours_total > 0 && c.tours_found == c.tours_total;
      room.untourable += !room.feasible;
    }
    if (room.feasible) break;
  }
  room.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return room;
}

}  // namespace hrs::experiments::zoo
