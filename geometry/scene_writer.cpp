// SPDX-License-Identifier: GPL-3.0-or-later
// Writer of `hrspace-scene/1` (docs/scene-format.md): a Scene as JSON text
// that reads back to the same Scene, section by section, pretty-printed so
// that scene files stay readable and diffable.

#include "geometry/scene.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/scene_json.h"

namespace hrs::geometry {
namespace {

using OrderedJson = nlohmann::ordered_json;
using scene_io::kFormat;
using scene_io::kSideNames;

// ---- values and the layout of the text ------------------------------------

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

//! Ends an object or array: a new line, `indent` spaces, the bracket. (Not
//! "\n" + std::string: GCC 12 warns falsely (-Wrestrict) on it.)
void close_block(int indent, char bracket, std::string& out) {
  out += '\n';
  out.append(static_cast<std::size_t>(indent), ' ');
  out += bracket;
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
    close_block(indent, '}', out);
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
    close_block(indent, ']', out);
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

// ---- sections -------------------------------------------------------------

OrderedJson room_json(const Room& room) {
  OrderedJson out = OrderedJson::object();
  if (room.size) {
    out["size"] = OrderedJson::array({(*room.size)[0], (*room.size)[1]});
  } else {
    out["polygon"] = to_json(room.polygon);
  }
  return out;
}

OrderedJson door_json(const Door& door) {
  OrderedJson out;
  out["center"] = to_json(door.center);
  out["width"] = door.width;
  out["clear_depth"] = door.clear_depth;
  if (door.start) out["start"] = to_json(*door.start);
  return out;
}

OrderedJson wheelchair_json(const Wheelchair& chair) {
  return {
      {"length", chair.length}, {"width", chair.width}, {"turning_radius", chair.turning_radius}};
}

//! One object: its size or polygon, pose, and only the optional fields it has.
OrderedJson object_json(const Object& o) {
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
  return j;
}

OrderedJson objects_json(const std::vector<Object>& objects) {
  OrderedJson out = OrderedJson::array();
  for (const Object& o : objects) out.push_back(object_json(o));
  return out;
}

//! The relations, each with only the fields it has (weight when not 1).
OrderedJson relations_json(const std::vector<Relation>& relations) {
  OrderedJson out = OrderedJson::array();
  for (const Relation& r : relations) {
    OrderedJson j;
    j["a"] = r.a;
    j["b"] = r.b;
    if (r.distance) j["distance"] = *r.distance;
    if (r.angle) j["angle"] = *r.angle;
    if (r.faces) j["faces"] = true;
    if (r.weight != 1.0) j["weight"] = r.weight;
    out.push_back(j);
  }
  return out;
}

//! Adds the AO graph's row of node `from` (if it has one) to `transitions`:
//! the objects' columns in scene order, then any other destinations.
void add_transition_row(const Scene& scene, const std::string& from, OrderedJson& transitions) {
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
}

//! The start row first, then the objects' rows in scene order, then any others.
OrderedJson transitions_json(const Scene& scene) {
  OrderedJson transitions = OrderedJson::object();
  add_transition_row(scene, std::string(kStartNodeId), transitions);
  for (const Object& o : scene.objects) add_transition_row(scene, o.id, transitions);
  for (const auto& [from, row] : scene.activity.transitions) {
    if (!transitions.contains(from)) add_transition_row(scene, from, transitions);
  }
  return transitions;
}

OrderedJson activity_json(const Scene& scene) {
  return {{"transitions", transitions_json(scene)},
          {"sequences", scene.activity.sequences},
          {"visits", scene.activity.visits}};
}

//! Path and interior weights; clearance_width only when not the default.
OrderedJson weights_json(const Weights& weights) {
  OrderedJson out = {
      {"path", OrderedJson::array({weights.path[0], weights.path[1], weights.path[2]})},
      {"interior", OrderedJson::array({weights.interior[0], weights.interior[1]})}};
  if (weights.clearance_width != Weights{}.clearance_width)
    out["clearance_width"] = weights.clearance_width;
  return out;
}

}  // namespace

std::string write_scene(const Scene& scene) {
  OrderedJson root;
  root["format"] = kFormat;
  root["name"] = scene.name;
  root["room"] = room_json(scene.room);
  root["door"] = door_json(scene.door);
  root["wheelchair"] = wheelchair_json(scene.wheelchair);
  root["objects"] = objects_json(scene.objects);
  if (!scene.relations.empty()) root["relations"] = relations_json(scene.relations);
  root["activity"] = activity_json(scene);
  if (scene.weights != Weights{}) root["weights"] = weights_json(scene.weights);
  std::string out;
  pretty(root, 0, out);
  out += "\n";
  return out;
}

}  // namespace hrs::geometry
