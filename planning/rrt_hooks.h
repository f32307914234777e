// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The two points where the RRT of planning/rrt.h can be changed without
// touching it (paper §III-B for the baseline, §V-A for the proposed
// planner): where random targets come from (SampleSource) and how the tree
// steers towards a target (Steering). Null hooks mean the baseline: uniform
// samples in the room's box and exact shortest Reeds–Shepp paths.

#include <random>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "rs/reeds_shepp.h"

namespace hrs::planning {

using geometry::Pose2;

//! Where non-goal targets come from. Baseline: uniform in a box.
class SampleSource {
 public:
  virtual ~SampleSource() = default;
  //! A target pose; must draw randomness only from `rng`.
  virtual Pose2 sample(std::mt19937_64& rng) = 0;
};

//! Uniform poses in an axis-aligned box times the heading circle (baseline).
class UniformSampler final : public SampleSource {
 public:
  UniformSampler(double xmin, double ymin, double xmax, double ymax)
      : xmin_(xmin), ymin_(ymin), xmax_(xmax), ymax_(ymax) {}
  //! The bounding box of the scene's room.
  static UniformSampler for_room(const geometry::Scene& scene);
  Pose2 sample(std::mt19937_64& rng) override;

 private:
  double xmin_, ymin_, xmax_, ymax_;
};

//! The RS steering function. Baseline: the exact shortest path (rs/).
class Steering {
 public:
  virtual ~Steering() = default;
  //! RS length used to rank the k nearest nodes.
  virtual double distance(const Pose2& from, const Pose2& to, double radius) = 0;
  //! The RS path actually driven.
  virtual rs::Path path(const Pose2& from, const Pose2& to, double radius) = 0;
};

//! Exact shortest RS paths (all 48 words).
class ExactSteering final : public Steering {
 public:
  double distance(const Pose2& from, const Pose2& to, double radius) override;
  rs::Path path(const Pose2& from, const Pose2& to, double radius) override;
};

//! Optional reuse hooks; null pointers mean the baseline behaviour.
struct PlannerHooks {
  SampleSource* sampler = nullptr;  //!< null: uniform in the room's box
  Steering* steering = nullptr;     //!< null: exact RS
};

}  // namespace hrs::planning
