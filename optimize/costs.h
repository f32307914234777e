// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The cost of a layout (paper §III-D, docs/design-notes.md "Costs"):
//   C_total = Σ_s L̂(s) · Σ_legs α̂_end · (w_l·length + w_r·rotation + w_c·clearance)
//           + Σ_s unfound L̂(s) · (penalty: w_l·length + w_r·length/r + w_c·w_ref per leg)
//           + w_I,d · C_I^d + w_I,r · C_I^r.
// Every term is reported separately (CostTerms).
//
// Decisions where the paper is ambiguous (documented in docs/optimize.md):
// - Clearance is bounded and decreases as corridors widen: the per-leg mean
//   over waypoints of max(0, w_ref − (left + right)), w_ref the scene's
//   weights.clearance_width (default 1.525 m, the ADA turning diameter),
//   measured by planning::measure as clearance_deficit; the paper's mean
//   width would reward narrow corridors under minimization.
// - α_i (sequences.h) weights the legs that end at object i.
// - Normalization: the paper's raw L(s) (≈ 0.01–0.1) and α_i make the path
//   term vanish next to the interior term, so we use L̂(s) = L(s) / Σ_M L and
//   α̂_i = α_i / ᾱ, ᾱ the L̂-weighted mean of α over leg ends. Then, with every
//   leg of length ℓ, the length term is exactly w_l · legs · ℓ: the expected
//   tour cost over the M sequences, with frequently visited objects weighted up.
// - A tour that cannot be found costs as if its length were
//   kUnfoundPerimeterFactor × the room's perimeter P, spread evenly over its
//   legs and weighted by α̂ like a found tour, with the most rotation and
//   clearance deficit a found tour of that length can have: rotation
//   length / r, r the chair's turning radius (a Reeds–Shepp path turns at
//   most ds / r along ds), and a deficit of w_ref per leg (the per-leg mean
//   of max(0, w_ref − width) is at most w_ref). So an unfound tour none of
//   whose legs was joined costs at least as much as any found tour whose
//   legs are no longer than the penalty's, whatever the path weights.
//   (Charged its length alone, a missing tour cost about two found ones in
//   a room whose tours turn a lot, and the annealer traded tours for
//   interior cost; docs/optimize.md.) So that the annealer can tell
//   "nearly tourable" from "sealed off", each leg's share is graded: the
//   first Tour::stats.depth legs (those the planner could join before
//   failing) are charged 1/2 of it; a leg not joined is charged 1 + b/2,
//   where b (planning::ReachGate::blockage) is 0 when the free grid lets the
//   door reach one of the leg's goal poses and else grows from 1/2 to 1 with
//   the distance from the door's reachable region to the nearest goal pose.
//   A layout that walls less of the room off from the door costs less
//   (docs/optimize.md "Blocked layouts").
// - Interior: pairwise distance (Σ relations weight·(|c_a − c_b| − d)² plus,
//   per object with a wall distance preference, (footprint-to-nearest-wall
//   distance − d)²) and pairwise rotation (Σ relations weight·wrap(θ_a − θ_b −
//   θ_ab)² plus, per object with a wall angle preference, wrap(θ − normal −
//   angle)²). Angles are wrapped to (−π, π]. The "nearest wall" is, among the
//   room edges within kWallTieTolerance of the nearest one, the one whose
//   angle preference fits best (an object in a corner touches two walls).

#include <array>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/sequences.h"
#include "planning/tour.h"

namespace hrs::optimize {

using geometry::Pose2;

//! An unfound tour costs as if its length were this many room perimeters.
inline constexpr double kUnfoundPerimeterFactor = 3.0;
//! The most one preference term costs with bounded preferences (before the
//! interior weight and the relation's weight).
inline constexpr double kPreferencePenalty = 2.0;
//! The bounded terms' scale is at least this (metres, radians): a term is a
//! smooth well about its target, not a cliff at its tolerance, so that the
//! annealer can cross a layout a few decimetres or degrees away from the
//! preferences (the exact pose is the polish's job).
inline constexpr double kDistanceScaleFloor = 0.3;
inline constexpr double kAngleScaleFloor = 15.0 * 3.14159265358979323846 / 180.0;
//! Walls this close (metres) to the nearest one also count as "nearest".
inline constexpr double kWallTieTolerance = 0.01;

//! Every term of C_total, already weighted (their sum is the total).
struct CostTerms {
  double path_length = 0.0;        //!< w_l · Σ L̂ Σ α̂ · length of found tours
  double path_rotation = 0.0;      //!< w_r · Σ L̂ Σ α̂ · rotation
  double path_clearance = 0.0;     //!< w_c · Σ L̂ Σ α̂ · clearance deficit
  double unfound_penalty = 0.0;    //!< Σ L̂ · penalty of unfound tours (all three path weights)
  double interior_distance = 0.0;  //!< w_I,d · C_I^d
  double interior_rotation = 0.0;  //!< w_I,r · C_I^r
  int tours_found = 0;
  int tours_total = 0;
  double path() const { return path_length + path_rotation + path_clearance + unfound_penalty; }
  double interior() const { return interior_distance + interior_rotation; }
  double total() const { return path() + interior(); }
};

//! How far a's front (heading) is turned from pointing at b's position,
//! wrapped to (−π, π]; 0 when the two positions coincide.
double facing_error(const Pose2& a, const Pose2& b);

//! Unweighted interior costs.
struct InteriorCosts {
  double distance = 0.0;  //!< C_I^d, m²
  double rotation = 0.0;  //!< C_I^r, rad²
};

//! The cost model of one scene and its M sequences.
class CostModel {
 public:
  CostModel(const geometry::Scene& scene, std::vector<Sequence> sequences);

  const std::vector<Sequence>& sequences() const { return sequences_; }
  //! L̂(s) of sequence k (sums to 1 over the sequences).
  double sequence_weight(int k) const { return seq_weight_[k]; }
  //! α̂ of an object id (0 for ids not in any sequence).
  double object_weight(const std::string& id) const;
  //! Room perimeter, metres.
  double perimeter() const { return perimeter_; }
  //! Length an unfound tour is charged as (metres).
  double unfound_length() const { return kUnfoundPerimeterFactor * perimeter_; }

  //! With `on`, interior() charges each preference term (the terms
  //! optimize/preferences.h counts) kPreferencePenalty · (1 − exp(−z²/2)),
  //! z = residual / max(2 · its tolerance, the scale floor), times the
  //! relation's weight, instead
  //! of its squared residual: bounded, so that no preference outweighs an
  //! unfound tour, and in units of what a designer tolerates, so that 3° off
  //! a wall counts like 5 cm off it (docs/optimize.md "Preferences").
  void set_bounded_preferences(bool on) { bounded_ = on; }
  bool bounded_preferences() const { return bounded_; }
  //! With `on`, every object's α̂ is 1: legs count alike whatever their
  //! end object (the control of the α experiment, docs/experiments.md).
  void set_uniform_alpha(bool on);
  //! Unweighted interior costs of object poses (scene order).
  InteriorCosts interior(const std::vector<Pose2>& poses) const;
  //! α̂-weighted [length, rotation, clearance deficit] of one tour of
  //! sequence k (unweighted by L̂ and w); unfound: the penalty's length,
  //! rotation and clearance deficit (see the header), each leg's share
  //! graded by stats.depth and `blockage` (b of each leg, in sequence
  //! order; empty: b = 0).
  std::array<double, 3> tour_costs(int k, const planning::Tour& tour,
                                   std::span<const double> blockage = {}) const;
  //! Tour k's share of the total: its path terms weighted by w and L̂.
  double tour_total(int k, const planning::Tour& tour,
                    std::span<const double> blockage = {}) const;
  //! All terms for poses and the M tours (tours[k] tours sequences()[k]);
  //! `blockage` (may be null) holds each tour's leg grades. With
  //! `tours_counted` >= 0 only the first that many tours count (the terms of
  //! an early-rejected layout, tours_total = tours_counted).
  CostTerms evaluate(const std::vector<Pose2>& poses, const std::vector<planning::Tour>& tours,
                     const std::vector<std::vector<double>>* blockage = nullptr,
                     int tours_counted = -1) const;
  //! The same with the poses' interior costs already computed.
  CostTerms evaluate(const InteriorCosts& interior, const std::vector<planning::Tour>& tours,
                     const std::vector<std::vector<double>>* blockage = nullptr,
                     int tours_counted = -1) const;
  //! Terms with only the weighted interior costs set (no tour counted).
  CostTerms interior_terms(const InteriorCosts& interior) const;

  //! Distance from the footprint to the room edge `edge` (vertices edge, edge+1).
  double wall_distance(const geometry::Polygon& footprint, int edge) const;
  //! The wall an object at `pose` counts as nearest (see the header).
  int nearest_wall(int object, const Pose2& pose) const;
  //! Angle of the inward normal of room edge `edge`.
  double wall_normal_angle(int edge) const;

 private:
  geometry::Scene scene_;
  std::vector<Sequence> sequences_;
  std::vector<double> seq_weight_;
  std::map<std::string, double> alpha_hat_;
  double perimeter_ = 0.0;
  bool bounded_ = false;
  std::map<std::string, double> alpha_scene_;  //!< α̂ from the sequences
  struct RelationIndex {
    int a, b;
    int relation;  // index into scene_.relations
  };
  std::vector<RelationIndex> relations_;
};

}  // namespace hrs::optimize
