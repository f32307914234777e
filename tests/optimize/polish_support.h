#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of the polish's and the rearrangement's tests: the layout of a
// scene, its violation, a layout hash for stand-in checks and planners, the
// gross misses counted independently of optimize/rearrange.cpp, and polish
// hooks on the exact layout checks.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/scene.h"
#include "optimize/costs.h"
#include "optimize/design.h"
#include "optimize/polish.h"
#include "optimize/preferences.h"
#include "optimize/rearrange.h"
#include "optimize/sequences.h"

namespace hrs::optimize::testing {

//! Which objects may move (not fixed), in scene order.
inline std::vector<bool> movable_of(const geometry::Scene& scene) {
  std::vector<bool> out;
  for (const auto& o : scene.objects) out.push_back(!o.fixed);
  return out;
}

//! Every object's pose, in scene order.
inline std::vector<geometry::Pose2> poses_of(const geometry::Scene& scene) {
  std::vector<geometry::Pose2> out;
  for (const auto& o : scene.objects) out.push_back(o.pose);
  return out;
}

//! The layout violation of `scene` with its objects at `poses` ("" when
//! valid).
inline std::string violation_at(geometry::Scene scene, const std::vector<geometry::Pose2>& poses) {
  for (std::size_t i = 0; i < poses.size(); ++i) scene.objects[i].pose = poses[i];
  return layout_violation(scene);
}

//! A 64-bit hash of a layout (its poses to 0.1 mm and 1e-4 rad).
inline std::uint64_t layout_hash(const std::vector<geometry::Pose2>& p, std::uint64_t salt) {
  std::uint64_t h = salt;
  for (const geometry::Pose2& q : p)
    h = h * 1000003u ^
        static_cast<std::uint64_t>(std::llround(1e4 * (q.x + 3 * q.y + 7 * q.theta)));
  return h;
}

//! Angle preferences more than 20° off, counted from the report's
//! residuals, and the polish's score (preferences met, less one per such
//! miss).
inline int gross_count(const PreferenceReport& r) {
  int n = 0;
  for (const PreferenceCheck& c : r.checks)
    n += c.angular() && c.residual > 20.0 * std::numbers::pi / 180.0;
  return n;
}
inline int score_of(const PreferenceReport& r) { return r.met - gross_count(r); }

//! The cost model of `scene` and its sequences with bounded preference
//! terms (the default preset's objective).
inline CostModel bounded_model(const geometry::Scene& scene) {
  CostModel model(scene, scene_sequences(scene));
  model.set_bounded_preferences(true);
  return model;
}

//! Terms with both of two tours found (a plan() that never loses a tour).
inline CostTerms two_tours_found() {
  CostTerms t;
  t.tours_total = t.tours_found = 2;
  return t;
}

//! Polish hooks whose validity is the exact layout checks on `scratch`;
//! place() and kept() do nothing (plan() is the caller's).
inline PolishHooks exact_hooks(geometry::Scene& scratch) {
  PolishHooks hooks;
  hooks.valid = [&scratch](const std::vector<geometry::Pose2>& p, int moved) {
    for (std::size_t i = 0; i < p.size(); ++i) scratch.objects[i].pose = p[i];
    return object_violation(scratch, moved).empty();
  };
  hooks.place = [](int, const geometry::Pose2&) {};
  hooks.kept = [] {};
  return hooks;
}

//! Rearrangement hooks whose `fits` and `valid` are both the exact layout
//! checks on `scratch`, with every place clear of the tours' corridor.
inline RearrangeHooks exact_rearrange_hooks(geometry::Scene& scratch) {
  RearrangeHooks hooks;
  hooks.fits = hooks.valid = exact_hooks(scratch).valid;
  hooks.clear = [](int, const geometry::Pose2&) { return true; };
  return hooks;
}

//! Polishes `poses` (at most 50 plannings) with the exact checks on
//! `scratch` and a planner that finds both tours of every layout.
inline PolishResult polish_all_found(const geometry::Scene& scene, const CostModel& model,
                                     const std::vector<bool>& movable,
                                     std::vector<geometry::Pose2>& poses,
                                     geometry::Scene& scratch) {
  PolishHooks hooks = exact_hooks(scratch);
  hooks.plan = [](const std::vector<geometry::Pose2>&) { return two_tours_found(); };
  CostTerms terms = two_tours_found();
  return polish(scene, model, movable, poses, terms, hooks, 50);
}

}  // namespace hrs::optimize::testing
