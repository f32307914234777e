// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small scenes of the planning suites: boxes, an enclosed goal and a pocket
// behind a neck narrower than the chair (queries no planner can solve).

#include <array>
#include <numbers>
#include <optional>
#include <string>

#include "geometry/scene.h"

namespace hrs::test_support {

using geometry::Pose2;

inline geometry::Object box(const std::string& id, double depth, double width, Pose2 pose) {
  geometry::Object o;
  o.id = id;
  o.size = std::array<double, 2>{depth, width};
  o.footprint = {{-depth / 2, -width / 2},
                 {depth / 2, -width / 2},
                 {depth / 2, width / 2},
                 {-depth / 2, width / 2}};
  o.pose = pose;
  return o;
}

inline geometry::Scene base_scene(geometry::Polygon room) {
  geometry::Scene s;
  s.name = "test";
  s.room.polygon = std::move(room);
  s.door = {{2.0, 0.0}, 0.9, 1.2, std::nullopt};
  s.wheelchair = {1.1, 0.65, 0.7};
  return s;
}

//! A 7 x 7 room whose middle (4.2 x 4.2) is fenced in by four pieces of furniture.
inline geometry::Scene enclosed_goal_scene() {
  geometry::Scene s = base_scene({{0, 0}, {7, 0}, {7, 7}, {0, 7}});
  s.objects = {box("south", 0.2, 4.6, {3.5, 1.3, std::numbers::pi / 2}),
               box("north", 0.2, 4.6, {3.5, 5.7, -std::numbers::pi / 2}),
               box("west", 0.2, 4.4, {1.3, 3.5, 0.0}), box("east", 0.2, 4.4, {5.7, 3.5, 0.0})};
  return s;
}

//! A 4 x 4 room with a 2 x 2 pocket behind a 0.4 m neck (the chair is 0.65 m wide).
inline geometry::Scene pocket_scene() {
  return base_scene({{0, 0},
                     {4, 0},
                     {4, 1.8},
                     {4.5, 1.8},
                     {4.5, 1.0},
                     {6.5, 1.0},
                     {6.5, 3.0},
                     {4.5, 3.0},
                     {4.5, 2.2},
                     {4, 2.2},
                     {4, 4},
                     {0, 4}});
}

}  // namespace hrs::test_support
