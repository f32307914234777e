// SPDX-License-Identifier: GPL-3.0-or-later
// The exact validity of a layout (declared in optimize/design.h): inside the
// room, clear of the door's clear zone, no overlap beyond contact.

#include <string>

#include "geometry/polygon_ops.h"
#include "optimize/design.h"

namespace hrs::optimize {

std::string object_violation(const geometry::Scene& scene, int index) {
  // Contact is allowed within geometry::kContactTolerance, as in the reader.
  const auto& o = scene.objects[index];
  const auto fp = geometry::world_footprint(o);
  if (const auto out = geometry::protrusion(fp, scene.room.polygon))
    return o.id + " " + geometry::sticks_out_text(*out, scene.room.polygon);
  if (const auto depth = geometry::overlap_depth(fp, geometry::door_clear_zone(scene)))
    return o.id + " enters the door's clear zone by " + geometry::metres_text(*depth) + " m";
  for (std::size_t j = 0; j < scene.objects.size(); ++j) {
    if (static_cast<int>(j) == index) continue;
    if (const auto depth =
            geometry::overlap_depth(fp, geometry::world_footprint(scene.objects[j])))
      return o.id + " overlaps " + scene.objects[j].id + " by " + geometry::metres_text(*depth) +
             " m";
  }
  return "";
}

std::string layout_violation(const geometry::Scene& scene) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    auto v = object_violation(scene, static_cast<int>(i));
    if (!v.empty()) return v;
  }
  return "";
}

}  // namespace hrs::optimize
