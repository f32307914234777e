// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Paper §V-A in the leg planner: the RS-decomposition (rs/decomposition.h)
// as the RRT's source of random targets (DecompositionSampler: targets drawn
// from the decomposition's own configurations) and as its steering
// (DecompositionSteering: the predicted word's path, the exact shortest path
// when that word cannot connect the poses).

#include <random>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "planning/rrt.h"
#include "rs/decomposition.h"

namespace hrs::planning {

using geometry::Pose2;

//! §V-A: RRT targets drawn uniformly from the decomposition's samples, mapped
//! from its doubled room (centred on the start) onto the room's bounding box.
class DecompositionSampler final : public SampleSource {
 public:
  DecompositionSampler(const rs::Decomposition& decomposition, const geometry::Scene& scene);
  Pose2 sample(std::mt19937_64& rng) override;

 private:
  const rs::Decomposition* decomposition_;
  double cx_, cy_, sx_, sy_;  //!< room centre and scale from the doubled room
};

//! §V-A: RS paths by the decomposition's predicted word; the exact shortest
//! path when the predicted word cannot connect the poses. Thread-safe.
class DecompositionSteering final : public Steering {
 public:
  explicit DecompositionSteering(const rs::Decomposition& decomposition)
      : decomposition_(&decomposition) {}
  double distance(const Pose2& from, const Pose2& to, double radius) override;
  rs::Path path(const Pose2& from, const Pose2& to, double radius) override;

 private:
  const rs::Decomposition* decomposition_;
};

}  // namespace hrs::planning
