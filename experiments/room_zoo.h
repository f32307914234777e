#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// The room zoo (`hrspace generate`, the `generalization` study): random
// scenes that are tourable by construction.
//
// A room is drawn from (seed, index) alone: its shape (a rectangle, an L, a
// U, or a flat of two or three rooms joined by openings of at least 1.1 m,
// the partition walls being fixed 0.1 m thin objects), its object count and
// furniture (realistic [depth, width] sizes), a floor area scaled to the
// furniture (from cramped to open), the door, the wall and relation
// preferences, and an AO graph over the furniture (M = 10 sequences of 3
// visits).
//
// Feasible by construction: a layout is *planted* first (wall objects with
// their backs exactly against a wall, the others in the open, no overlap, the
// door's clear zone free, a chair-sized stopping zone kept free in front of
// one approach side of every object), the relation targets are read off the
// planted poses (so the plant meets every preference exactly), and the M tours
// of the planted layout are planned by the product's own design loop
// (optimize::design with 0 iterations, the baseline planner). A plant whose
// tours are not all found is redrawn (at most `max_plants` times; the floor
// grows by 10 % after every fourth failure). When every plant fails, the room
// itself (shape, object count, furniture, AO graph) is drawn again, at most
// `max_draws` times, so that a room of the zoo is feasible by construction:
// a design that misses tours there is the design loop's failure, not the
// room's. The movable objects are then
// scrambled (random poses and headings inside the room, without overlap when
// one is found) into the input layout; the planted layout is kept as the
// *witness*, the same scene with the planted poses.
//
// Deterministic: the same (seed, index, options) give the same rooms byte for
// byte, whatever the number of planning threads.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/scene.h"

namespace hrs::experiments::zoo {

//! Version of the generator's output: bumped whenever the rooms that a
//! (seed, index, options) give change, so that stored results of the
//! `generalization` study name the rooms they were made in.
inline constexpr int kGeneratorVersion = 2;

enum class Shape { kRect, kL, kU, kFlat };

//! "rect", "l", "u", "flat".
std::string shape_name(Shape shape);
//! The shape of a name, or nullopt ("any" too: the caller draws one).
std::optional<Shape> parse_shape(const std::string& name);

struct ZooOptions {
  std::uint64_t seed = 1;
  int min_objects = 4;               //!< objects of the scene, partition walls included
  int max_objects = 40;
  std::optional<Shape> shape;        //!< nullopt: drawn per room
  bool check_tours = true;           //!< plan the witness's tours (false: geometry only)
  int max_plants = 40;               //!< plants tried per draw of the room
  int max_draws = 4;                 //!< draws of the room before giving up
  int threads = 0;                   //!< tour-planning threads of the check (0: all cores)
};

struct ZooRoom {
  std::string name;          //!< zoo_SEED_INDEX
  Shape shape = Shape::kRect;
  geometry::Scene scene;     //!< the input: movable objects scrambled
  geometry::Scene witness;   //!< the same scene with the planted poses
  double area = 0.0;         //!< floor area, m²
  int room_draws = 0;        //!< draws of the room, the accepted one included
  int plant_attempts = 0;    //!< plants drawn over all draws, the accepted one included
  int unplaced = 0;          //!< plants dropped because an object found no place
  int untourable = 0;        //!< plants dropped because a tour of the witness failed
  bool feasible = false;     //!< the witness's tours were all found (or not checked)
  int tours_found = 0, tours_total = 0;  //!< of the witness (0 when not checked)
  double witness_cost = 0.0;             //!< C_total of the witness (0 when not checked)
  double seconds = 0.0;                  //!< time taken to generate the room
};

//! Room `index` (1-based) of the zoo of `options.seed`. When no plant of any
//! of the max_draws draws passes, the last one is returned with feasible = false.
ZooRoom generate_room(const ZooOptions& options, int index);

//! The witness check: the M tours of `scene`'s layout planned by
//! optimize::design with 0 iterations (baseline planner, seed 1).
struct WitnessCheck {
  int tours_found = 0, tours_total = 0;
  double cost = 0.0;  //!< C_total of the layout
};
WitnessCheck check_layout(const geometry::Scene& scene, int threads);

//! Objects that are partition walls of a flat (ids "partition_…").
bool is_partition(const geometry::Object& object);

}  // namespace hrs::experiments::zoo
