// SPDX-License-Identifier: GPL-3.0-or-later
// Reader and validator of `hrspace-scene/1` (docs/scene-format.md): the
// document section by section (room, door, wheelchair, objects, relations,
// activity, weights). Every rule of the format is checked here, at the
// boundary, so inner code can assert its preconditions. Errors name the file,
// the JSON pointer of the field and what is wrong, on one line.

#include "geometry/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <utility>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/scene_json.h"

namespace hrs::geometry {
namespace {

//! Empty when `s` (valid UTF-8) holds only printable characters; else what
//! the first other one is. Ids and the name go into SVG (XML 1.0 has no
//! C0 controls but tab and newline, nor U+FFFE, U+FFFF), CSV cells and the
//! terminal, so the reader admits no control characters there.
std::string unprintable(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    char hex[16];
    if (c < 0x20 || c == 0x7f) {
      std::snprintf(hex, sizeof hex, "U+%04X", c);
      return std::string("the control character ") + hex;
    }
    if (c == 0xc2 && i + 1 < s.size()) {
      const auto d = static_cast<unsigned char>(s[i + 1]);
      if (d >= 0x80 && d <= 0x9f) {
        std::snprintf(hex, sizeof hex, "U+%04X", d);
        return std::string("the control character ") + hex;
      }
    }
    if (c == 0xef && i + 2 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0xbf &&
        (static_cast<unsigned char>(s[i + 2]) & 0xfe) == 0xbe)
      return static_cast<unsigned char>(s[i + 2]) == 0xbe ? "the non-character U+FFFE"
                                                           : "the non-character U+FFFF";
  }
  return {};
}

using scene_io::child;
using scene_io::door_edge;
using scene_io::Json;
using scene_io::kBoundaryTolerance;
using scene_io::kComment;
using scene_io::kFormat;
using scene_io::kSideNames;
using scene_io::literal;
using scene_io::num;
using scene_io::one_line;

constexpr double kRowSumTolerance = 1e-6;  //!< AO rows sum to 1 within this, both ways
//! Slack for the rounding of decimal probabilities to doubles and of their
//! sum: without it 0.999999 passed and 1.000001 failed (1.000001 - 1 is
//! 1.00000000003e-6 in doubles, 1 - 0.999999 is 0.99999999992e-6).
constexpr double kRowSumRounding = 1e-12;

//! For a refused pose: a hint when its heading looks like degrees.
std::string degrees_hint(double theta) {
  if (!(std::abs(theta) > 2.0 * std::numbers::pi)) return "";
  return "; its heading " + num(theta) + " is larger than 2π: radians are expected";
}

//! Rectangle [depth, width] centred on the origin, counter-clockwise.
Polygon centred_rectangle(double depth, double width) {
  const double hx = 0.5 * depth, hy = 0.5 * width;
  return {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
}

//! Reads one JSON document into a Scene, failing with file/pointer/what.
class SceneReader : public scene_io::FieldReader {
 public:
  using FieldReader::FieldReader;

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
    if (const std::string bad = unprintable(scene.name); !bad.empty())
      fail("/name", "holds " + bad + " (names and ids are printable text)");
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
    const Polygon chair = chair_footprint(scene.wheelchair, start);
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
    if (const std::string bad = unprintable(o.id); !bad.empty())
      fail(child(ptr, "id"), "holds " + bad + " (names and ids are printable text)");
    if (o.id == kStartNodeId) fail(child(ptr, "id"), "\"door\" is reserved for the start node");
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
      // Contact (with walls, the clear zone, other objects) is allowed
      // within kContactTolerance: flush furniture at a rounded heading.
      if (const auto out_of_room = protrusion(mine, room.polygon)) {
        fail(child(op, "pose"), "the footprint of " + literal(o.id) + " " +
                                    sticks_out_text(*out_of_room, room.polygon) +
                                    " (contact tolerance " + num(kContactTolerance) + " m)" +
                                    degrees_hint(o.pose.theta));
      }
      if (o.fixed) {
        if (const auto depth = overlap_depth(mine, clear_zone)) {
          fail(child(op, "pose"), "fixed object " + literal(o.id) +
                                      " enters the door's clear zone by " + metres_text(*depth) +
                                      " m (no layout could be valid)" +
                                      degrees_hint(o.pose.theta));
        }
      }
      if (o.fixed) {
        for (std::size_t k = 0; k < out.size(); ++k) {
          if (!out[k].fixed) continue;
          if (const auto depth = overlap_depth(mine, world_footprint(out[k]))) {
            fail(child(op, "pose"), "fixed object " + literal(o.id) + " overlaps fixed object " +
                                        literal(out[k].id) + " (" + child(ptr, k) + ") by " +
                                        metres_text(*depth) + " m" + degrees_hint(o.pose.theta));
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
      check_keys(e, rp, {"a", "b", "distance", "angle", "faces", "weight"});
      Relation r;
      r.a = known_id(require(e, rp, "a"), child(rp, "a"), scene);
      r.b = known_id(require(e, rp, "b"), child(rp, "b"), scene);
      if (r.a == r.b)
        fail(child(rp, "b"),
             "a relation needs two different objects, got " + literal(r.a) + " twice");
      if (const Json* d = optional(e, "distance"))
        r.distance = non_negative(*d, child(rp, "distance"));
      if (const Json* a = optional(e, "angle")) r.angle = angle(*a, child(rp, "angle"));
      if (const Json* f = optional(e, "faces")) r.faces = boolean(*f, child(rp, "faces"));
      if (!r.distance && !r.angle && !r.faces)
        fail(child(rp, "distance"), "give distance, angle and/or faces");
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
      if (from != kStartNodeId && scene.find_object(from) < 0) {
        fail(rp, "unknown object id " + literal(from) + " (rows are \"door\" or object ids)");
      }
      expect_object(row, rp);
      auto& out = a.transitions[from];
      double sum = 0.0;
      for (const auto& [to, p] : row.items()) {
        if (to == kComment) continue;
        const std::string pp = child(rp, to);
        if (to == kStartNodeId) fail(pp, "\"door\" is the start node, not a destination");
        if (scene.find_object(to) < 0) fail(pp, "unknown object id " + literal(to));
        const double v = number(p, pp);
        if (!(v >= 0.0 && v <= 1.0)) fail(pp, "probability must be in [0, 1], got " + num(v));
        out[to] = v;
        sum += v;
      }
      if (std::abs(sum - 1.0) > kRowSumTolerance + kRowSumRounding) {
        fail(rp, "probabilities must sum to 1 (+-1e-6), got " + num(sum));
      }
    }
    if (!a.transitions.contains(std::string(kStartNodeId))) {
      fail(child(tp, kStartNodeId), "missing required row of the start node");
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
};

}  // namespace

Scene parse_scene(std::string_view text, const std::string& label) {
  SceneReader reader(label);
  const Json root = scene_io::parse_json(text, reader);
  try {
    return reader.read(root);
  } catch (const Json::exception& e) {
    // Unreachable if every access above checks its type first; kept so that a
    // missed check still ends as one line and exit status 2, not an abort.
    reader.fail("", std::string("malformed scene: ") + e.what());
  }
}

std::string read_input_file(const std::string& path) {
  if (path.find('\0') != std::string::npos)
    throw InputError(one_line(path) + ": the path contains a NUL character");
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status))
    throw InputError(one_line(path + ": is a directory, expected a file"));
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(one_line(path + ": not a regular file (a device, FIFO or socket); give a file"));
  if (std::filesystem::is_regular_file(status)) {
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > limits::kInputBytes)
      throw InputError(one_line(path + ": " + std::to_string(size) + " bytes, more than the " +
                                std::to_string(limits::kInputBytes >> 20) +
                                " MiB an input file may have"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(one_line(path + ": cannot open file (missing or unreadable)"));
  return read_input_stream(in, path);
}

std::string read_input_stream(std::istream& in, const std::string& label) {
  std::string text;
  char chunk[1 << 16];
  while (in) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limits::kInputBytes)
      throw InputError(one_line(label + ": more than the " +
                                std::to_string(limits::kInputBytes >> 20) +
                                " MiB an input may have"));
  }
  if (in.bad()) throw InputError(one_line(label + ": cannot read"));
  return text;
}

Scene load_scene(const std::string& path) { return parse_scene(read_input_file(path), path); }

}  // namespace hrs::geometry
