// SPDX-License-Identifier: GPL-3.0-or-later
// The room zoo (experiments/room_zoo.h): furniture, shapes, preferences
// read off the planted layout, the AO graph, the witness check and the
// attempts loop. The plant and the scramble are in room_zoo_plant.cpp.

#include "experiments/room_zoo.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "experiments/room_zoo_plant.h"
#include "geometry/error.h"
#include "geometry/random.h"
#include "optimize/design.h"

namespace hrs::experiments::zoo {

namespace {

using detail::cm;
using detail::draw;
using detail::Item;
using detail::Kind;
using detail::shuffle;
using geometry::Object;
using geometry::Polygon;
using geometry::Pose2;
using geometry::Scene;
using geometry::Side;
using geometry::Vec2;
using geometry::wrap_angle;

constexpr double kPartitionDepth = 0.1;
constexpr char kPartitionPrefix[] = "partition_";

// ---- furniture ---------------------------------------------------------------

constexpr unsigned kFront = 1u << static_cast<int>(Side::kFront);
constexpr unsigned kBack = 1u << static_cast<int>(Side::kBack);
constexpr unsigned kLeft = 1u << static_cast<int>(Side::kLeft);
constexpr unsigned kRight = 1u << static_cast<int>(Side::kRight);
constexpr unsigned kAll = kFront | kBack | kLeft | kRight;

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
  o.planner = optimize::PlannerConfig::from_preset("baseline");
  o.seed = 1;
  o.iterations = 0;
  o.threads = threads;
  const optimize::DesignResult r = optimize::design(scene, o);
  return {r.initial.tours_found, r.initial.tours_total, r.initial.total()};
}

namespace {

//! One draw of room `index`: the room-level choices from `base`, then up to
//! max_plants plants. Adds its counts to `room`; true when a plant passed.
bool draw_room(const ZooOptions& options, std::uint64_t base, ZooRoom& room) {
  std::mt19937_64 rng(base);
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
  room.feasible = false;

  for (int attempt = 1; attempt <= options.max_plants; ++attempt) {
    ++room.plant_attempts;
    std::mt19937_64 arng(mix(base, static_cast<std::uint64_t>(attempt)));
    const double area = base_area * std::pow(1.1, (attempt - 1) / 4);
    Floor floor = draw_floor(plan, area, arng);
    Scene s;
    s.name = room.name;
    s.room.polygon = floor.polygon;
    s.door = floor.door;
    s.wheelchair = {1.1, 0.65, 0.7};
    s.objects = floor.partitions;
    if (!detail::plant(s, items, arng)) {
      ++room.unplaced;
      continue;
    }
    add_relations(s, arng);
    add_activity(s, items, arng);
    Scene input = s;
    detail::scramble(input, arng);
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
    if (room.feasible) return true;
  }
  return false;
}

}  // namespace

ZooRoom generate_room(const ZooOptions& options, int index) {
  if (options.min_objects < 4 || options.max_objects < options.min_objects ||
      options.max_objects > static_cast<int>(geometry::limits::kObjects))
    throw InputError("zoo: object counts must satisfy 4 <= min <= max <= 100");
  if (options.max_plants < 1 || options.max_draws < 1)
    throw InputError("zoo: max_plants and max_draws must be at least 1");
  const auto t0 = std::chrono::steady_clock::now();
  ZooRoom room;
  room.name = "zoo_" + std::to_string(options.seed) + "_" + std::to_string(index);
  // The first draw's stream is the room's own (seed, index); a room whose
  // plants all fail is drawn again from a stream derived from it, so rooms
  // that pass at the first draw do not depend on max_draws.
  const std::uint64_t base = mix(options.seed, static_cast<std::uint64_t>(index));
  for (int d = 1; d <= options.max_draws; ++d) {
    room.room_draws = d;
    if (draw_room(options, d == 1 ? base : mix(base, 0x9e3779b97f4a7c15ULL + d), room)) break;
  }
  room.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return room;
}

}  // namespace hrs::experiments::zoo
