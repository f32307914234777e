#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Beyond the paper: the design loop's escape from layouts that wall stops
// off from the door (docs/optimize.md "Blocked layouts"), switched by the
// planner configuration's `escape`:
//   - unblock(): before the annealing (and again after it, when tours are
//     unfound), a greedy search on the free grid alone moves the objects
//     that wall stops in until none is walled off (jumps, steps and turns;
//     wall slots for a wall object no jump of which lands);
//   - covers_a_stop(): a move (of one object, or of a pair) that leaves a
//     stop which has a free goal pose without any is invalid;
//   - walling_objects(): the annealer's focus, the objects that most likely
//     stand between the door and the stops unfound tours miss (and a
//     walled stop itself when fixed objects alone seal its pocket).
// The unfound-tour grades themselves are the round's (TourRound::blockage).

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "geometry/polygon_ops.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/sequences.h"
#include "optimize/tour_round.h"
#include "planning/reach_gate.h"

namespace hrs::optimize {

class EscapePolicy {
 public:
  using ValidFn = std::function<bool(const std::vector<Pose2>& poses, int moved)>;
  using PlaceFn = std::function<void(int object, const Pose2& to)>;

  //! `options`: the switch (planner.escape) and the C-space and gate
  //! options of the fixed-only gate; `plan_every`: tours are planned every
  //! iteration (not with all path weights 0).
  EscapePolicy(const geometry::Scene& scene, TourRound& round,
               const std::vector<Sequence>& sequences, const std::vector<bool>& movable,
               const DesignOptions& options, bool plan_every);

  //! True when the layout `poses` (object `moved` moved, and any other
  //! object whose pose differs from the C-space's: the partner of a pair
  //! move) leaves a stop that has a free goal pose now without any (counted
  //! in covering_moves()).
  bool covers_a_stop(const std::vector<Pose2>& poses, int moved);
  //! Recomputes the stops with a free goal pose in the current layout.
  void refresh_open_stops();
  //! The greedy unblocking of `poses` (the current layout, updated);
  //! `valid` the exact checks of a move, `place` moves an object in the
  //! working scene and C-space. True when the layout changed; the open
  //! stops (refresh_open_stops) are then the changed layout's.
  bool unblock(std::vector<Pose2>& poses, std::uint64_t seed, const std::atomic<bool>* stop,
               const ValidFn& valid, const PlaceFn& place, DesignResult::Unblock& stats);
  //! An input layout that is not valid (objects overlapping each other, the
  //! door's clear zone or the walls) is separated first: each movable object
  //! in violation, in index order, jumps to a uniform position in the room's
  //! box with its heading or a quarter turn of it, redrawn until `valid`
  //! (at most kSeparateDraws draws) or, when no draw is valid (a crowded
  //! room), to nearest_free_pose or, when no spot is free, to
  //! displacing_pose (the smaller objects it lands on are separated in
  //! turn), for up to kSeparatePasses passes; a pass that places nothing
  //! ends it (the layout is unchanged, so the scans would answer the same).
  //! `valid` decides what is free (the design loop passes the exact layout
  //! checks alone). Returns the objects moved (0 when the layout was valid
  //! or escape is off); `passes` gets the passes made.
  int separate(std::vector<Pose2>& poses, std::uint64_t seed, const ValidFn& valid,
               const PlaceFn& place, int& passes);
  //! The valid pose of object `o` nearest its place in `poses`: positions
  //! on a 10 cm grid over `box`, nearest first, each at the object's
  //! heading and its three quarter turns. nullopt when none is valid.
  std::optional<Pose2> nearest_free_pose(int o, const std::vector<Pose2>& poses,
                                         const geometry::Box& box, const ValidFn& valid);
  //! The pose of object `o` nearest its place in `poses` (a 20 cm grid over
  //! `box`, the same headings) that is valid among the fixed objects and
  //! the movable ones at least as large as it: smaller ones may overlap it
  //! there. nullopt when there is none.
  std::optional<Pose2> displacing_pose(int o, const std::vector<Pose2>& poses,
                                       const geometry::Box& box);
  //! The annealer's focus for the current layout (empty without escape).
  std::vector<int> walling_objects();
  int covering_moves() const { return covering_moves_; }

 private:
  //! How far from a stop (or the door's clear zone) an object joins the
  //! focus, metres.
  static constexpr double kFocusReach = 2.0;
  std::vector<int> stop_objects() const;
  std::vector<int> walled_off(const std::vector<int>& stops, double& total);
  std::optional<Pose2> unblock_move(int o, const std::vector<Pose2>& poses,
                                    const geometry::Box& box, std::mt19937_64& rng,
                                    std::mt19937_64& slots, const ValidFn& valid);
  std::vector<int> focus_for(const std::vector<int>& stops, bool in_grid);
  std::vector<int> near_targets(const std::vector<geometry::Polygon>& targets,
                                const std::vector<int>& members, bool in_grid);
  std::vector<int> sealed_by_fixed(const std::vector<int>& walled);
  //! walled_focus(): focus_for(walled, true) and the stops of `walled`
  //! that sealed_by_fixed() finds, ascending.
  std::vector<int> walled_focus(const std::vector<int>& walled);

  //! The room with its fixed objects alone, and a reach gate over it
  //! (built at the first sealed_by_fixed() query; fixed objects never move).
  struct FixedOnly {
    FixedOnly(const geometry::Scene& scene, const geometry::CSpaceOptions& cspace_options,
              const planning::ReachGateOptions& gate_options);
    geometry::Scene scene;
    geometry::CSpace cspace;
    planning::ReachGate gate;
  };
  std::unique_ptr<FixedOnly> fixed_only_;

  const geometry::Scene& scene_;
  TourRound& round_;
  const std::vector<Sequence>& sequences_;
  const std::vector<bool>& movable_;
  geometry::CSpaceOptions cspace_options_;
  planning::ReachGateOptions gate_options_;
  bool escape_;
  bool plan_every_;
  std::vector<int> open_stops_;  //!< stops with a free goal pose in the current layout
  int covering_moves_ = 0;
};

}  // namespace hrs::optimize
