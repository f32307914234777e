#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to experiments/room_zoo*.cpp, not part of the API: the furniture
// items of a zoo room, the seeded draws the generator shares, and the
// placement of the items (the plant, room_zoo_plant.cpp) and of the input
// layout (the scramble).

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "geometry/random.h"
#include "geometry/scene.h"

namespace hrs::experiments::zoo::detail {

//! A kind of furniture.
struct Kind {
  const char* name;
  double depth, width;  //!< m, before a ±10 % jitter
  bool wall;            //!< back against a wall, with a wall preference
  unsigned sides;       //!< approach sides
  double fixed_share;   //!< probability of being fixed
  double weight;        //!< how often it is drawn
};


//! One piece of furniture of a room (drawn once per room).
struct Item {
  const Kind* kind;
  double depth, width;
  bool fixed;
  std::string id;
  bool toured = false;  //!< a node of the AO graph: gets a stopping zone
};



//! Fisher–Yates with uniform_index (std::shuffle's draws differ between
//! standard libraries).
template <class T>
void shuffle(std::vector<T>& v, std::mt19937_64& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[uniform_index(rng, i)]);
}

inline double draw(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform01(rng); }
inline double cm(double x) { return std::round(100.0 * x) / 100.0; }

//! Places every item into `scene` (room, door, chair and partition walls
//! set): toured objects first, wall objects with their backs to a wall, no
//! overlaps, the door's clear zone and a turning area inside the door free,
//! a stopping zone free beside one approach side of every toured object.
//! False when an item found no place.
bool plant(geometry::Scene& scene, const std::vector<Item>& items, std::mt19937_64& rng);

//! Moves every movable object to a random pose and heading inside the room,
//! without overlaps (fixed objects, the door's clear zone) when one is
//! found, else anywhere inside, else leaves it where it was planted.
void scramble(geometry::Scene& scene, std::mt19937_64& rng);

}  // namespace hrs::experiments::zoo::detail
