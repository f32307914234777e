// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Scenes for geometry tests: an L-shaped room with a non-convex (U-shaped)
// object, corridors for clearance, and the scene files in scenes/.

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/random.h"
#include "geometry/scene.h"
#include "tests/support/poses.h"

namespace hrs::test_support {

inline geometry::Scene l_shaped_scene() {
  using geometry::Object;
  geometry::Scene s;
  s.name = "l_room";
  s.room.polygon = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};
  s.door = {{1.5, 0}, 0.9, 1.2, std::nullopt};
  s.wheelchair = {1.1, 0.65, 0.7};
  Object u;
  u.id = "u_desk";  // a U-shaped desk: non-convex
  u.footprint = {{-0.6, -0.8}, {0.6, -0.8}, {0.6, 0.8},  {-0.6, 0.8},
                 {-0.6, 0.4},  {0.2, 0.4},  {0.2, -0.4}, {-0.6, -0.4}};
  u.pose = {4.3, 1.6, 0.7};
  Object t;
  t.id = "table";
  t.size = std::array<double, 2>{0.8, 1.2};
  t.footprint = {{-0.4, -0.6}, {0.4, -0.6}, {0.4, 0.6}, {-0.4, 0.6}};
  t.pose = {1.2, 4.2, -0.3};
  Object l;
  l.id = "lamp";
  l.size = std::array<double, 2>{0.4, 0.4};
  l.footprint = {{-0.2, -0.2}, {0.2, -0.2}, {0.2, 0.2}, {-0.2, 0.2}};
  l.pose = {0.4, 1.0, 0.0};
  s.objects = {u, t, l};
  return s;
}

//! A rectangular room with no furniture.
inline geometry::Scene empty_room(double width, double depth) {
  geometry::Scene s;
  s.name = "empty";
  s.room.polygon = {{0, 0}, {width, 0}, {width, depth}, {0, depth}};
  s.door = {{width / 2, 0}, 0.9, 1.2, std::nullopt};
  s.wheelchair = {1.1, 0.65, 0.7};
  return s;
}

//! A 6 × 3 m room split at x = 3 by a fixed 0.2 m partition that leaves a
//! gap of `gap` metres at the top (the chair is 0.65 m wide).
inline geometry::Scene split_room(double gap) {
  geometry::Scene s = empty_room(6.0, 3.0);
  s.name = "split";
  s.door.center = {1.0, 0.0};
  geometry::Object wall;
  wall.id = "partition";
  const double len = 3.0 - gap;
  wall.footprint = {{-0.1, -0.5 * len}, {0.1, -0.5 * len}, {0.1, 0.5 * len}, {-0.1, 0.5 * len}};
  wall.pose = {3.0, 0.5 * len, 0.0};
  wall.fixed = true;
  s.objects = {wall};
  return s;
}

//! Paths of the scene files shipped in scenes/ (sorted).
inline std::vector<std::string> scene_files() {
  std::vector<std::string> out;
  const std::filesystem::path dir = std::filesystem::path(HRSPACE_SOURCE_DIR) / "scenes";
  if (std::filesystem::exists(dir))
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hrs::test_support
