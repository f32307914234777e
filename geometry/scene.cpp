// Reader, validator and writer of `hrspace-scene/1` (docs/scene-format.md).
// Every rule of the format is checked here, at the boundary, so inner code can
// assert its preconditions. Errors name the file, the JSON pointer of the field
// and what is wrong, on one line.

#include "geometry/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <utility>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"

namespace hrs::geometry {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr std::string_view kFormat = "hrspace-scene/1";
constexpr double kBoundaryTolerance =
    1e-6;                                  //!< door centre on the boundary, door width on its edge
constexpr double kRowSumTolerance = 1e-6;  //!< AO rows sum to 1
constexpr std::string_view kStartNode = kStartNodeId;
constexpr std::string_view kComment = "comment";
constexpr std::array<std::string_view, 4> kSideNames{"front", "back", "left", "right"};

//! Replaces control characters so that a message stays on one line.
std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (static_cast<unsigned char>(c) < 0x20) {
      out += c == '\n' ? "\\n" : (c == '\t' ? "\\t" : "?");
    } else {
      out += c;
    }
  }
  return out;
}

//! A string as a JSON literal (quoted, escaped), for messages.
std::string literal(std::string_view s) {
  return Json(std::string(s)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

//! A short rendering of a JSON value for messages ("got ...").
std::string shown(const Json& j) {
  std::string text = j.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(j.type_name()) + " " + text;
}

//! Shortest text for a double that reads back to the same value.
std::string num(double v) { return Json(v).dump(); }

//! RFC 6901 escaping of one reference token.
std::string pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string child(const std::string& ptr, std::string_view key) {
  return ptr + "/" + pointer_token(key);
}
std::string child(const std::string& ptr, std::size_t index) {
  return ptr + "/" + std::to_string(index);
}

//! Rectangle [depth, width] centred on the origin, counter-clockwise.
Polygon centred_rectangle(double depth, double width) {
  const double hx = 0.5 * depth, hy = 0.5 * width;
  return {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
}

//! Distance from p to segment [a, b] and the arc-length parameter of its projection.
std::pair<double, double> segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  double t = len2 > 0.0 ? dot(p - a, d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec2 q = a + t * d;
  return {norm(p - q), t * std::sqrt(len2)};
}

//! The room edge holding the door: index i (edge i -> i+1) or -1. Among edges
//! within tolerance of the centre, prefers one on which the opening fits.
int door_edge(const Polygon& room, const Door& door, bool require_fit) {
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

//! Reads one JSON document into a Scene, failing with file/pointer/what.
class Reader {
 public:
  explicit Reader(std::string label) : label_(std::move(label)) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const {
    // The whole document has the empty pointer: then the message names only the file.
    throw InputError(one_line(label_ + ": " + (ptr.empty() ? "" : ptr + ": ") + what));
  }

  Scene read(const Json& root) {
    expect_object(root, "");
    const std::string format = string(require(root, "", "format"), "/format");
    if (format != kFormat) {
      fail("/format", "unsupported format " + literal(format) + ", expected " + literal(kFormat));
    }
    check_keys(root, "",
               {"format", "name", "room", "door", "wheelchair", "objects", "relations", "activity",
                "weights"});
    Scene scene;
    scene.name = string(require(root, "", "name"), "/name");
    if (scene.name.empty()) fail("/name", "must not be empty");
    scene.room = room(require(root, "", "room"), "/room");
    scene.door = door(require(root, "", "door"), "/door", scene.room);
    scene.wheelchair = wheelchair(require(root, "", "wheelchair"), "/wheelchair", scene.room);
    scene.objects = objects(require(root, "", "objects"), "/objects", scene);
    check_start(scene);
    if (const Json* j = optional(root, "relations")) {
      scene.relations = relations(*j, "/relations", scene);
    }
    scene.activity = activity(require(root, "", "activity"), "/activity", scene);
    if (const Json* j = optional(root, "weights")) scene.weights = weights(*j, "/weights");
    return scene;
  }

 private:
  // ---- generic accessors -------------------------------------------------

  void expect_object(const Json& j, const std::string& ptr) const {
    if (!j.is_object()) fail(ptr, "must be a JSON object, got " + shown(j));
  }

  void expect_array(const Json& j, const std::string& ptr) const {
    if (!j.is_array()) fail(ptr, "must be an array, got " + shown(j));
  }

  //! Rejects fields outside `allowed` (and "comment").
  void check_keys(const Json& j, const std::string& ptr,
                  std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : j.items()) {
      if (key == kComment) continue;
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(child(ptr, key), "unknown field (allowed: " + list + ", comment)");
    }
  }

  const Json& require(const Json& j, const std::string& ptr, std::string_view key) const {
    const auto it = j.find(std::string(key));
    if (it == j.end()) fail(child(ptr, key), "missing required field");
    return *it;
  }

  static const Json* optional(const Json& j, std::string_view key) {
    const auto it = j.find(std::string(key));
    return it == j.end() ? nullptr : &*it;
  }

  std::string string(const Json& j, const std::string& ptr) const {
    if (!j.is_string()) fail(ptr, "must be a string, got " + shown(j));
    return j.get<std::string>();
  }

  bool boolean(const Json& j, const std::string& ptr) const {
    if (!j.is_boolean()) fail(ptr, "must be true or false, got " + shown(j));
    return j.get<bool>();
  }

  double number(const Json& j, const std::string& ptr) const {
    if (!j.is_number()) fail(ptr, "must be a number, got " + shown(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(ptr, "must be a finite number, got " + num(v));
    return v;
  }

  //! A finite number in [lo, hi]; `what` names the limit in the message.
  double bounded(const Json& j, const std::string& ptr, double lo, double hi,
                 const char* what) const {
    const double v = number(j, ptr);
    if (!(v >= lo && v <= hi)) {
      fail(ptr, "must be within [" + num(lo) + ", " + num(hi) + "] (" + what + "), got " + num(v));
    }
    return v;
  }

  //! A length > 0: a size, width, depth or radius (limits::kMinLength..kLength).
  double positive(const Json& j, const std::string& ptr) const {
    const double v = number(j, ptr);
    if (!(v > 0.0)) fail(ptr, "must be > 0, got " + num(v));
    return bounded(j, ptr, limits::kMinLength, limits::kLength, "length limits of the format");
  }

  //! A distance >= 0 (at most limits::kLength).
  double non_negative(const Json& j, const std::string& ptr) const {
    const double v = number(j, ptr);
    if (!(v >= 0.0)) fail(ptr, "must be >= 0, got " + num(v));
    return bounded(j, ptr, 0.0, limits::kLength, "length limits of the format");
  }

  //! A weight >= 0 (at most limits::kWeight).
  double weight(const Json& j, const std::string& ptr) const {
    const double v = number(j, ptr);
    if (!(v >= 0.0)) fail(ptr, "must be >= 0, got " + num(v));
    return bounded(j, ptr, 0.0, limits::kWeight, "weight limit of the format");
  }

  double coordinate(const Json& j, const std::string& ptr) const {
    return bounded(j, ptr, -limits::kCoordinate, limits::kCoordinate,
                   "coordinate limit of the format");
  }

  double angle(const Json& j, const std::string& ptr) const {
    return bounded(j, ptr, -limits::kAngle, limits::kAngle, "angle limit of the format");
  }

  int integer_in(const Json& j, const std::string& ptr, int min, int max) const {
    if (!j.is_number_integer()) fail(ptr, "must be an integer, got " + shown(j));
    const bool too_big = j.is_number_unsigned() ? j.get<std::uint64_t>() > std::uint64_t(max)
                                                : j.get<std::int64_t>() > std::int64_t{max};
    if (too_big)
      fail(ptr, "must be <= " + std::to_string(max) + " (limit of the format), got " + j.dump());
    const auto v = j.get<std::int64_t>();
    if (v < min) fail(ptr, "must be >= " + std::to_string(min) + ", got " + std::to_string(v));
    return static_cast<int>(v);
  }

  //! An array of exactly n elements; calls each(element, pointer, index).
  void fixed_array(
      const Json& j, const std::string& ptr, std::size_t n, const char* what,
      const std::function<void(const Json&, const std::string&, std::size_t)>& each) const {
    if (!j.is_array() || j.size() != n) {
      fail(ptr, "must be " + std::string(what) + " (an array of " + std::to_string(n) +
                    " numbers), got " + shown(j));
    }
    for (std::size_t i = 0; i < n; ++i) each(j[i], child(ptr, i), i);
  }

  Vec2 point(const Json& j, const std::string& ptr) const {
    Vec2 p;
    fixed_array(j, ptr, 2, "a point [x, y]",
                [&](const Json& e, const std::string& p2, std::size_t i) {
                  (i == 0 ? p.x : p.y) = coordinate(e, p2);
                });
    return p;
  }

  Pose2 pose(const Json& j, const std::string& ptr) const {
    Pose2 p;
    fixed_array(j, ptr, 3, "a pose [x, y, theta]",
                [&](const Json& e, const std::string& p2, std::size_t i) {
                  const double v = i < 2 ? coordinate(e, p2) : angle(e, p2);
                  (i == 0 ? p.x : i == 1 ? p.y : p.theta) = v;
                });
    return p;
  }

  std::array<double, 2> size2(const Json& j, const std::string& ptr, const char* what) const {
    std::array<double, 2> s{};
    fixed_array(j, ptr, 2, what, [&](const Json& e, const std::string& p2, std::size_t i) {
      s[i] = positive(e, p2);
    });
    return s;
  }

  //! Vertices of a simple counter-clockwise polygon.
  Polygon polygon(const Json& j, const std::string& ptr) const {
    expect_array(j, ptr);
    if (j.size() < 3) fail(ptr, "needs at least 3 vertices, got " + std::to_string(j.size()));
    if (j.size() > limits::kVertices) {
      fail(ptr, "has " + std::to_string(j.size()) + " vertices, more than the format's limit of " +
                    std::to_string(limits::kVertices));
    }
    Polygon poly;
    for (std::size_t i = 0; i < j.size(); ++i) poly.push_back(point(j[i], child(ptr, i)));
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const double edge = norm(poly[(i + 1) % poly.size()] - poly[i]);
      if (!(edge >= limits::kMinLength)) {
        fail(child(ptr, (i + 1) % poly.size()),
             "edge from vertex " + std::to_string(i) + " is " + num(edge) +
                 " m long, shorter than the format's limit of " + num(limits::kMinLength) + " m");
      }
    }
    if (!is_simple(poly)) {
      fail(ptr, "is not a simple polygon (edges cross, touch or repeat a vertex)");
    }
    if (!is_counterclockwise(poly)) {
      fail(ptr, "is clockwise; vertices must be counter-clockwise");
    }
    return poly;
  }

  // ---- sections ----------------------------------------------------------

  Room room(const Json& j, const std::string& ptr) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"polygon", "size"});
    const Json* poly = optional(j, "polygon");
    const Json* size = optional(j, "size");
    if (poly && size) fail(child(ptr, "size"), "give either polygon or size, not both");
    if (!poly && !size) fail(child(ptr, "polygon"), "missing required field (or give size)");
    Room room;
    if (size) {
      const auto s = size2(*size, child(ptr, "size"), "[width, depth]");
      for (std::size_t i = 0; i < 2; ++i) {
        if (s[i] > limits::kCoordinate) {
          fail(child(child(ptr, "size"), i),
               "must be within [" + num(limits::kMinLength) + ", " + num(limits::kCoordinate) +
                   "] (coordinate limit of the format), got " + num(s[i]));
        }
      }
      room.size = s;
      room.polygon = {{0.0, 0.0}, {s[0], 0.0}, {s[0], s[1]}, {0.0, s[1]}};
    } else {
      room.polygon = polygon(*poly, child(ptr, "polygon"));
    }
    return room;
  }

  Door door(const Json& j, const std::string& ptr, const Room& room) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"center", "width", "clear_depth", "start"});
    Door door;
    door.center = point(require(j, ptr, "center"), child(ptr, "center"));
    door.width = positive(require(j, ptr, "width"), child(ptr, "width"));
    if (const Json* d = optional(j, "clear_depth")) {
      door.clear_depth = positive(*d, child(ptr, "clear_depth"));
    }
    if (const Json* s = optional(j, "start")) door.start = pose(*s, child(ptr, "start"));
    if (door_edge(room.polygon, door, false) < 0) {
      fail(child(ptr, "center"),
           "is not on the room boundary (tolerance " + num(kBoundaryTolerance) + ")");
    }
    if (door_edge(room.polygon, door, true) < 0) {
      fail(child(ptr, "width"), "the opening of width " + num(door.width) +
                                    " does not fit on the wall edge holding the door centre");
    }
    return door;
  }

  Wheelchair wheelchair(const Json& j, const std::string& ptr, const Room& room) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"length", "width", "turning_radius"});
    Wheelchair w;
    w.length = positive(require(j, ptr, "length"), child(ptr, "length"));
    w.width = positive(require(j, ptr, "width"), child(ptr, "width"));
    w.turning_radius = positive(require(j, ptr, "turning_radius"), child(ptr, "turning_radius"));
    // The chair must fit in the room's bounding box in some orientation, and
    // a turning circle wider than the room only makes every plan slow.
    Vec2 lo = room.polygon.front(), hi = lo;
    for (Vec2 v : room.polygon) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    }
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    const double diagonal = norm(hi - lo);
    if (std::min(w.length, w.width) > std::min(hi.x - lo.x, hi.y - lo.y) ||
        std::max(w.length, w.width) > diagonal) {
      fail(child(ptr, w.length >= w.width ? "length" : "width"),
           "the wheelchair (" + num(w.length) + " x " + num(w.width) +
               " m) does not fit in the room (bounding box " + num(hi.x - lo.x) + " x " +
               num(hi.y - lo.y) + " m)");
    }
    if (w.turning_radius > 0.5 * extent) {
      fail(child(ptr, "turning_radius"), "must be at most half the room's larger extent (" +
                                             num(0.5 * extent) + " m: a U-turn fits), got " +
                                             num(w.turning_radius));
    }
    return w;
  }

  //! The wheelchair at its start pose lies inside the room and clear of every
  //! fixed object (movable ones are moved by the optimizer); the pointer is
  //! /door/start when given, else /door/center, from which it is derived.
  void check_start(const Scene& scene) const {
    const bool given = scene.door.start.has_value();
    const std::string ptr = given ? "/door/start" : "/door/center";
    const Pose2 start = door_start_pose(scene);
    const double hl = 0.5 * scene.wheelchair.length, hw = 0.5 * scene.wheelchair.width;
    Polygon chair;
    for (Vec2 v : {Vec2{hl, hw}, Vec2{-hl, hw}, Vec2{-hl, -hw}, Vec2{hl, -hw}}) {
      chair.push_back(to_world(start, v));
    }
    const std::string at = std::string(given ? "the start pose " : "the default start pose ") +
                           num(start.x) + "," + num(start.y) + "," + num(start.theta);
    if (!is_simple(chair) || !polygon_inside(chair, scene.room.polygon)) {
      fail(ptr, at + " puts the wheelchair (partly) outside the room");
    }
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      const Object& o = scene.objects[k];
      if (o.fixed && interiors_overlap(chair, world_footprint(o))) {
        fail(ptr, at + " puts the wheelchair into fixed object " + literal(o.id) + " (/objects/" +
                      std::to_string(k) + ")");
      }
    }
  }

  Object object(const Json& j, const std::string& ptr) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"id", "size", "polygon", "pose", "fixed", "wall", "approach"});
    Object o;
    o.id = string(require(j, ptr, "id"), child(ptr, "id"));
    if (o.id.empty()) fail(child(ptr, "id"), "must not be empty");
    if (o.id == kStartNode) fail(child(ptr, "id"), "\"door\" is reserved for the start node");
    if (o.id == kComment) {
      fail(child(ptr, "id"), "\"comment\" is reserved (comment fields are ignored)");
    }
    const Json* size = optional(j, "size");
    const Json* poly = optional(j, "polygon");
    if (size && poly) fail(child(ptr, "polygon"), "give either size or polygon, not both");
    if (!size && !poly) fail(child(ptr, "size"), "missing required field (or give polygon)");
    if (size) {
      o.size = size2(*size, child(ptr, "size"), "[depth, width]");
      o.footprint = centred_rectangle((*o.size)[0], (*o.size)[1]);
    } else {
      o.footprint = polygon(*poly, child(ptr, "polygon"));
    }
    o.pose = pose(require(j, ptr, "pose"), child(ptr, "pose"));
    if (const Json* f = optional(j, "fixed")) o.fixed = boolean(*f, child(ptr, "fixed"));
    if (const Json* w = optional(j, "wall")) o.wall = wall(*w, child(ptr, "wall"));
    if (const Json* a = optional(j, "approach")) o.approach = approach(*a, child(ptr, "approach"));
    return o;
  }

  WallPreference wall(const Json& j, const std::string& ptr) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"distance", "angle"});
    WallPreference w;
    if (const Json* d = optional(j, "distance"))
      w.distance = non_negative(*d, child(ptr, "distance"));
    if (const Json* a = optional(j, "angle")) w.angle = angle(*a, child(ptr, "angle"));
    return w;
  }

  Approach approach(const Json& j, const std::string& ptr) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"sides", "gap"});
    Approach a;
    if (const Json* s = optional(j, "sides")) {
      const std::string sp = child(ptr, "sides");
      expect_array(*s, sp);
      if (s->empty()) fail(sp, "must name at least one side (front, back, left, right)");
      a.sides = {false, false, false, false};
      for (std::size_t i = 0; i < s->size(); ++i) {
        const std::string ep = child(sp, i);
        const std::string name = string((*s)[i], ep);
        const auto it = std::find(kSideNames.begin(), kSideNames.end(), name);
        if (it == kSideNames.end()) {
          fail(ep, "unknown side " + literal(name) + " (allowed: front, back, left, right)");
        }
        const auto index = static_cast<std::size_t>(it - kSideNames.begin());
        if (a.sides[index]) fail(ep, "duplicate side " + literal(name));
        a.sides[index] = true;
      }
    }
    if (const Json* g = optional(j, "gap")) a.gap = non_negative(*g, child(ptr, "gap"));
    return a;
  }

  std::vector<Object> objects(const Json& j, const std::string& ptr, const Scene& scene) const {
    expect_array(j, ptr);
    if (j.size() > limits::kObjects) {
      fail(ptr, "has " + std::to_string(j.size()) + " objects, more than the format's limit of " +
                    std::to_string(limits::kObjects));
    }
    const Room& room = scene.room;
    const Polygon clear_zone = door_clear_zone(scene);
    std::vector<Object> out;
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string op = child(ptr, i);
      Object o = object(j[i], op);
      for (std::size_t k = 0; k < out.size(); ++k) {
        if (out[k].id == o.id) {
          fail(child(op, "id"), "duplicate id " + literal(o.id) + " (also " + child(ptr, k) + ")");
        }
      }
      const Polygon mine = world_footprint(o);
      // Rounding in the placement can collapse or fold a footprint; the exact
      // region tests below need a simple counter-clockwise polygon.
      if (!is_simple(mine) || !is_counterclockwise(mine)) {
        fail(child(op, "pose"), "the footprint of " + literal(o.id) +
                                    " degenerates when placed at this pose (rounding)");
      }
      if (!polygon_inside(mine, room.polygon)) {
        fail(child(op, "pose"), "the footprint of " + literal(o.id) + " is not inside the room");
      }
      if (o.fixed && interiors_overlap(mine, clear_zone)) {
        fail(child(op, "pose"), "fixed object " + literal(o.id) +
                                    " blocks the door's clear zone (no layout could be valid)");
      }
      if (o.fixed) {
        for (std::size_t k = 0; k < out.size(); ++k) {
          if (out[k].fixed && interiors_overlap(mine, world_footprint(out[k]))) {
            fail(child(op, "pose"), "fixed object " + literal(o.id) + " overlaps fixed object " +
                                        literal(out[k].id) + " (" + child(ptr, k) + ")");
          }
        }
      }
      out.push_back(std::move(o));
    }
    return out;
  }

  //! An object id that exists in the scene (the start node only when allowed).
  std::string known_id(const Json& j, const std::string& ptr, const Scene& scene) const {
    const std::string id = string(j, ptr);
    if (scene.find_object(id) < 0) fail(ptr, "unknown object id " + literal(id));
    return id;
  }

  std::vector<Relation> relations(const Json& j, const std::string& ptr, const Scene& scene) const {
    expect_array(j, ptr);
    if (j.size() > limits::kRelations) {
      fail(ptr, "has " + std::to_string(j.size()) + " relations, more than the format's limit of " +
                    std::to_string(limits::kRelations));
    }
    std::vector<Relation> out;
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string rp = child(ptr, i);
      const Json& e = j[i];
      expect_object(e, rp);
      check_keys(e, rp, {"a", "b", "distance", "angle", "weight"});
      Relation r;
      r.a = known_id(require(e, rp, "a"), child(rp, "a"), scene);
      r.b = known_id(require(e, rp, "b"), child(rp, "b"), scene);
      if (r.a == r.b)
        fail(child(rp, "b"),
             "a relation needs two different objects, got " + literal(r.a) + " twice");
      if (const Json* d = optional(e, "distance"))
        r.distance = non_negative(*d, child(rp, "distance"));
      if (const Json* a = optional(e, "angle")) r.angle = angle(*a, child(rp, "angle"));
      if (!r.distance && !r.angle) fail(child(rp, "distance"), "give distance and/or angle");
      if (const Json* w = optional(e, "weight")) r.weight = weight(*w, child(rp, "weight"));
      out.push_back(std::move(r));
    }
    return out;
  }

  Activity activity(const Json& j, const std::string& ptr, const Scene& scene) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"transitions", "sequences", "visits"});
    Activity a;
    const std::string tp = child(ptr, "transitions");
    const Json& t = require(j, ptr, "transitions");
    expect_object(t, tp);
    for (const auto& [from, row] : t.items()) {
      if (from == kComment) continue;
      const std::string rp = child(tp, from);
      if (from != kStartNode && scene.find_object(from) < 0) {
        fail(rp, "unknown object id " + literal(from) + " (rows are \"door\" or object ids)");
      }
      expect_object(row, rp);
      auto& out = a.transitions[from];
      double sum = 0.0;
      for (const auto& [to, p] : row.items()) {
        if (to == kComment) continue;
        const std::string pp = child(rp, to);
        if (to == kStartNode) fail(pp, "\"door\" is the start node, not a destination");
        if (scene.find_object(to) < 0) fail(pp, "unknown object id " + literal(to));
        const double v = number(p, pp);
        if (!(v >= 0.0 && v <= 1.0)) fail(pp, "probability must be in [0, 1], got " + num(v));
        out[to] = v;
        sum += v;
      }
      if (std::abs(sum - 1.0) > kRowSumTolerance) {
        fail(rp, "probabilities must sum to 1 (+-1e-6), got " + num(sum));
      }
    }
    if (!a.transitions.contains(std::string(kStartNode))) {
      fail(child(tp, kStartNode), "missing required row of the start node");
    }
    if (const Json* s = optional(j, "sequences")) {
      a.sequences = integer_in(*s, child(ptr, "sequences"), 1, limits::kSequences);
    }
    if (const Json* v = optional(j, "visits")) {
      a.visits = integer_in(*v, child(ptr, "visits"), 1, limits::kVisits);
    }
    return a;
  }

  Weights weights(const Json& j, const std::string& ptr) const {
    expect_object(j, ptr);
    check_keys(j, ptr, {"path", "interior", "clearance_width"});
    Weights w;
    if (const Json* p = optional(j, "path")) {
      fixed_array(
          *p, child(ptr, "path"), 3, "[length, rotation, clearance]",
          [&](const Json& e, const std::string& ep, std::size_t i) { w.path[i] = weight(e, ep); });
    }
    if (const Json* p = optional(j, "interior")) {
      fixed_array(*p, child(ptr, "interior"), 2, "[distance, rotation]",
                  [&](const Json& e, const std::string& ep, std::size_t i) {
                    w.interior[i] = weight(e, ep);
                  });
    }
    if (const Json* c = optional(j, "clearance_width"))
      w.clearance_width = positive(*c, child(ptr, "clearance_width"));
    return w;
  }

  std::string label_;
};

//! Parser callback that rejects duplicate keys (a typo must not pass silently).
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const Reader& reader) : reader_(reader) {}

  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
        enter_value();
        frames_.push_back({true, {}, "", 0});
        break;
      case Json::parse_event_t::array_start:
        enter_value();
        frames_.push_back({false, {}, "", 0});
        break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end:
        frames_.pop_back();
        break;
      case Json::parse_event_t::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) reader_.fail(pointer(), "duplicate field");
        break;
      }
      case Json::parse_event_t::value:
        enter_value();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;       //!< current key (objects)
    std::size_t next = 0;  //!< index of the next element (arrays)
  };

  //! A value starts inside the current container: advance the array index.
  void enter_value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().next;
  }

  std::string pointer() const {
    std::string ptr;
    for (const Frame& f : frames_) {
      ptr = f.object ? child(ptr, f.key) : child(ptr, f.next - 1);
    }
    return ptr;
  }

  const Reader& reader_;
  std::vector<Frame> frames_;
};

// ---- writer ---------------------------------------------------------------

OrderedJson to_json(Vec2 p) { return OrderedJson::array({p.x, p.y}); }
OrderedJson to_json(const Pose2& p) { return OrderedJson::array({p.x, p.y, p.theta}); }
OrderedJson to_json(const Polygon& poly) {
  OrderedJson out = OrderedJson::array();
  for (Vec2 v : poly) out.push_back(to_json(v));
  return out;
}

bool is_flat(const OrderedJson& j) {
  return std::all_of(j.begin(), j.end(), [](const OrderedJson& e) { return e.is_primitive(); });
}

//! Pretty-prints with objects one field per line and small arrays inline
//! (points, poses, polygons), so scene files stay readable and diffable.
void pretty(const OrderedJson& j, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      if (!first) out += ",\n";
      first = false;
      out += pad + OrderedJson(key).dump() + ": ";
      pretty(value, indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else if (j.is_array() && !j.empty() &&
             !(is_flat(j) || std::all_of(j.begin(), j.end(), [](const OrderedJson& e) {
                 return e.is_array() && is_flat(e);
               }))) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      if (i > 0) out += ",\n";
      out += pad;
      pretty(j[i], indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else {
    std::string text = j.dump();
    // Inline arrays: a space after each comma for readability.
    std::string spaced;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
      const char c = text[i];
      spaced += c;
      if (c == '"' && (i == 0 || text[i - 1] != '\\')) in_string = !in_string;
      if (c == ',' && !in_string) spaced += ' ';
    }
    out += j.is_array() ? spaced : text;
  }
}

}  // namespace

int Scene::find_object(std::string_view id) const {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

Scene parse_scene(std::string_view text, const std::string& label) {
  Reader reader(label);
  if (std::all_of(text.begin(), text.end(),
                  [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; })) {
    reader.fail("", "empty file, expected a JSON object");
  }
  // The parser and the messages recurse into nested values: bound the depth
  // first, with a linear scan that cannot recurse.
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limits::kDepth) {
        reader.fail("", "JSON nested deeper than " + std::to_string(limits::kDepth) +
                            " levels (limit of the format)");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  Json root;
  try {
    root = Json::parse(text.begin(), text.end(), DuplicateKeyCheck(reader));
  } catch (const Json::exception& e) {
    std::string what = e.what();
    if (const auto close = what.find("] ");
        what.rfind("[json.exception.", 0) == 0 && close != std::string::npos) {
      what = what.substr(close + 2);
    }
    reader.fail("", "invalid JSON: " + what);
  }
  try {
    return reader.read(root);
  } catch (const Json::exception& e) {
    // Unreachable if every access above checks its type first; kept so that a
    // missed check still ends as one line and exit status 2, not an abort.
    reader.fail("", std::string("malformed scene: ") + e.what());
  }
}

Scene load_scene(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(one_line(path + ": is a directory, expected a scene file"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(one_line(path + ": cannot open file (missing or unreadable)"));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(one_line(path + ": cannot read file"));
  return parse_scene(buffer.str(), path);
}

std::string write_scene(const Scene& scene) {
  OrderedJson root;
  root["format"] = kFormat;
  root["name"] = scene.name;
  OrderedJson room = OrderedJson::object();
  if (scene.room.size) {
    room["size"] = OrderedJson::array({(*scene.room.size)[0], (*scene.room.size)[1]});
  } else {
    room["polygon"] = to_json(scene.room.polygon);
  }
  root["room"] = room;
  OrderedJson door;
  door["center"] = to_json(scene.door.center);
  door["width"] = scene.door.width;
  door["clear_depth"] = scene.door.clear_depth;
  if (scene.door.start) door["start"] = to_json(*scene.door.start);
  root["door"] = door;
  root["wheelchair"] = {{"length", scene.wheelchair.length},
                        {"width", scene.wheelchair.width},
                        {"turning_radius", scene.wheelchair.turning_radius}};
  OrderedJson objects = OrderedJson::array();
  for (const Object& o : scene.objects) {
    OrderedJson j;
    j["id"] = o.id;
    if (o.size) {
      j["size"] = OrderedJson::array({(*o.size)[0], (*o.size)[1]});
    } else {
      j["polygon"] = to_json(o.footprint);
    }
    j["pose"] = to_json(o.pose);
    if (o.fixed) j["fixed"] = true;
    if (o.wall) {
      OrderedJson w = OrderedJson::object();
      if (o.wall->distance) w["distance"] = *o.wall->distance;
      if (o.wall->angle) w["angle"] = *o.wall->angle;
      j["wall"] = w;
    }
    if (o.approach) {
      OrderedJson sides = OrderedJson::array();
      for (std::size_t i = 0; i < kSideNames.size(); ++i) {
        if (o.approach->sides[i]) sides.push_back(kSideNames[i]);
      }
      j["approach"] = {{"sides", sides}, {"gap", o.approach->gap}};
    }
    objects.push_back(j);
  }
  root["objects"] = objects;
  if (!scene.relations.empty()) {
    OrderedJson relations = OrderedJson::array();
    for (const Relation& r : scene.relations) {
      OrderedJson j;
      j["a"] = r.a;
      j["b"] = r.b;
      if (r.distance) j["distance"] = *r.distance;
      if (r.angle) j["angle"] = *r.angle;
      if (r.weight != 1.0) j["weight"] = r.weight;
      relations.push_back(j);
    }
    root["relations"] = relations;
  }
  OrderedJson transitions = OrderedJson::object();
  // The start row first, then the objects' rows in scene order.
  auto write_row = [&](const std::string& from) {
    const auto it = scene.activity.transitions.find(from);
    if (it == scene.activity.transitions.end()) return;
    OrderedJson row = OrderedJson::object();
    for (const Object& o : scene.objects) {
      if (const auto p = it->second.find(o.id); p != it->second.end()) row[o.id] = p->second;
    }
    for (const auto& [to, p] : it->second) {
      if (!row.contains(to)) row[to] = p;
    }
    transitions[from] = row;
  };
  write_row(std::string(kStartNode));
  for (const Object& o : scene.objects) write_row(o.id);
  for (const auto& [from, row] : scene.activity.transitions) {
    if (!transitions.contains(from)) write_row(from);
  }
  root["activity"] = {{"transitions", transitions},
                      {"sequences", scene.activity.sequences},
                      {"visits", scene.activity.visits}};
  if (scene.weights != Weights{}) {
    root["weights"] = {
        {"path",
         OrderedJson::array({scene.weights.path[0], scene.weights.path[1], scene.weights.path[2]})},
        {"interior", OrderedJson::array({scene.weights.interior[0], scene.weights.interior[1]})}};
    if (scene.weights.clearance_width != Weights{}.clearance_width)
      root["weights"]["clearance_width"] = scene.weights.clearance_width;
  }
  std::string out;
  pretty(root, 0, out);
  out += "\n";
  return out;
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
  std::set<std::string> at{std::string(kStartNode)};
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
    throw InputError(one_line(
        label + ": /activity/visits: no sequence of " + std::to_string(scene.activity.visits) +
        " visits leaves the door (the AO graph's longest has " + std::to_string(longest) + ")"));
  }
}

double signed_area(const Polygon& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) twice += cross(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * twice;
}

}  // namespace hrs::geometry
