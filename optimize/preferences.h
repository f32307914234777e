#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// The interior-design preferences of a scene (paper §III-D's interior terms)
// as a designer reads them: each stated term met or not, at a tolerance
// (docs/optimize.md "Preferences"), and the poses that would meet them.
//
// Terms counted (each once):
//   - a movable object's wall distance and wall angle, separately, measured
//     against the wall the cost counts as nearest (CostModel::nearest_wall);
//   - a relation's distance and angle, separately, when at least one of its
//     two objects is movable.
// Tolerances (defaults): wall distance 5 cm, wall angle 3°, relation
// distance max(10 cm, 10 % of the target), relation angle 5°.
//
// preferred_poses() proposes poses of one object that meet its own wall
// preference (snapped to a wall at the wanted distance and heading) or a
// relation's angle and distance to its partner: the design loop's
// preference moves and its final polish (optimize/design.h) draw from them.

#include <random>
#include <string>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/costs.h"

namespace hrs::optimize {

struct PreferenceTolerances {
  double wall_distance = 0.05;                  //!< metres
  double wall_angle = 3.0 * 3.14159265358979323846 / 180.0;      //!< radians
  double relation_distance = 0.10;              //!< metres, at least
  double relation_distance_share = 0.10;        //!< of the target, when larger
  double relation_angle = 5.0 * 3.14159265358979323846 / 180.0;  //!< radians
};

//! One stated preference term on one layout.
struct PreferenceCheck {
  //! wall_distance, wall_angle, relation_distance, relation_angle,
  //! relation_faces (a's front turned from pointing at b's position)
  std::string kind;
  std::string object;   //!< the object (relation: a)
  std::string other;    //!< relation: b; wall terms: "" (the wall is `wall`)
  int wall = -1;        //!< wall terms: the room edge counted as nearest
  double target = 0.0;  //!< metres or radians
  double achieved = 0.0;
  double residual = 0.0;  //!< |achieved − target|, angles wrapped to [0, π]
  double tolerance = 0.0;
  bool met = false;
  //! An angle term (wall_angle, relation_angle, relation_faces): radians.
  bool angular() const { return kind.ends_with("angle") || kind == "relation_faces"; }
};

struct PreferenceReport {
  int met = 0;
  int total = 0;
  std::vector<PreferenceCheck> checks;
  //! The largest residual of an angle term, radians (0 when none).
  double worst_angle = 0.0;
};

//! Checks every counted preference of `scene` with the objects at `poses`.
PreferenceReport check_preferences(const geometry::Scene& scene, const CostModel& model,
                                   const std::vector<geometry::Pose2>& poses,
                                   const PreferenceTolerances& tolerances = {});

//! Poses of object `object` (movable) that meet one of its preferences,
//! the others at `poses`: for each wall, the pose at the wanted distance and
//! angle nearest the current position (when the object has a wall
//! preference); for each relation with an angle, the current position turned
//! to it; with a distance, moved along the line to the partner to it. Not
//! checked for validity (the caller's exact predicates decide).
std::vector<geometry::Pose2> preferred_poses(const geometry::Scene& scene, const CostModel& model,
                                             const std::vector<geometry::Pose2>& poses,
                                             int object);

//! Spacing of the wall places the polish and the rearrangement try
//! (wall_slides()' `step`), metres.
inline constexpr double kWallSlideStep = 0.2;

//! Poses of `object` against every wall at its wanted distance and angle,
//! spaced `step` metres along each wall's extent (ends included), nearest
//! the current position first: the places a wall preference can be met when
//! the spot straight across from the object is taken. Empty when the object
//! has no wall distance preference.
std::vector<geometry::Pose2> wall_slides(const geometry::Scene& scene, const CostModel& model,
                                         const std::vector<geometry::Pose2>& poses, int object,
                                         double step);

//! Poses of `object` on the circle of each of its relations' distances
//! around the partner, `step` metres apart along the arc, turned as the
//! relation asks (the partner's heading plus its angle, or facing the
//! partner when it is the facing side; else the object's own heading),
//! nearest the current position first; centres outside the room's bounding
//! box are left out. Empty when the object has a wall distance preference
//! (its places meeting a relation's distance are its wall places at that
//! distance, among preferred_poses()) or no relation with a distance. The
//! places a free object (a lamp, a stool) can meet a relation when the spot
//! on the line to its partner is taken or leaves no room in front of it.
std::vector<geometry::Pose2> relation_slides(const geometry::Scene& scene,
                                             const std::vector<geometry::Pose2>& poses,
                                             int object, double step);

//! The groups of objects linked by relation angles (connected through
//! relations with an `angle`), each ascending, groups by their first
//! object; only groups with at least two objects.
std::vector<std::vector<int>> heading_groups(const geometry::Scene& scene);

//! One move of several objects: (object, pose) pairs.
using GroupMove = std::vector<std::pair<int, geometry::Pose2>>;

//! The places of objects `a` and `b` exchanged, as two moves:
//! back to back (each takes the other's heading, and its footprint's back
//! edge, centred, goes where the other's was, so a wall object keeps the
//! wall it takes over at the same distance), then position for position
//! (each takes the other's pose position and keeps its own heading). A desk wanted beside the sofa whose corner
//! another desk holds needs both to move at once; no single move meets it.
//! Not checked for validity (the caller's exact predicates decide).
std::vector<GroupMove> swaps(const geometry::Scene& scene, const std::vector<geometry::Pose2>& poses,
                             int a, int b);

//! Turns of heading group `group` (heading_groups()) as one body, so that
//! its relation angles hold along a spanning tree (BFS from its first
//! object): relation angles fix the group's headings up to one common
//! rotation, drawn from each member's anchor — a fixed object's heading, a
//! wall-angle object's heading against its nearest wall, or a free object's
//! own heading. Movable members turn in place, except those with a wall
//! distance and angle: they go against the wall whose normal gives them the
//! wanted heading, nearest their position (none such: that rotation is
//! skipped). One move per distinct rotation that changes some pose, in
//! member order; not checked for validity.
std::vector<GroupMove> group_turns(const geometry::Scene& scene, const CostModel& model,
                                   const std::vector<geometry::Pose2>& poses,
                                   const std::vector<bool>& movable, const std::vector<int>& group);

//! One pose of `object` against a wall drawn at random (when it has a wall
//! preference; its heading and distance as wanted, its place along the wall
//! uniform): a "wall slot" move. nullopt when the object has none.
std::optional<geometry::Pose2> wall_slot(const geometry::Scene& scene, int object,
                                         std::mt19937_64& rng);

}  // namespace hrs::optimize
