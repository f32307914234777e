#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// The final polish of a design (docs/optimize.md "Preferences"): after the
// annealing, each movable object with an unmet preference is tried at the
// poses that would meet it (optimize/preferences.h, preferred_poses), one
// at a time; a pose is kept when it is valid, every tour found before is
// still found (the tours are planned again) and more preferences are met.
// The order is fixed (objects ascending, candidates in preferred_poses
// order), so the result is a function of the layout and the planner's
// seeds, whatever the thread count.

#include <atomic>
#include <functional>
#include <vector>

#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/costs.h"

namespace hrs::optimize {

struct PolishHooks {
  //! Exact validity of `poses` after moving object `moved`.
  std::function<bool(const std::vector<geometry::Pose2>& poses, int moved)> valid;
  //! Moves object `object` to `to` (C-space included), plans the tours and
  //! returns the layout's terms.
  std::function<CostTerms(const std::vector<geometry::Pose2>& poses, int object,
                          const geometry::Pose2& to)>
      try_pose;
  //! Puts object `object` back at `to` (its pose before try_pose): the
  //! tours of the layout before are restored by the caller's snapshot.
  std::function<void(int object, const geometry::Pose2& to)> undo;
  //! The pose tried last was kept: snapshot its tours.
  std::function<void()> kept;
};

struct PolishResult {
  int tried = 0;  //!< poses planned
  int kept = 0;   //!< poses kept
};

//! Polishes `poses` (the best layout, whose terms are `terms`) in place;
//! at most `max_tries` plannings; `stop` (may be null) ends it early.
PolishResult polish(const geometry::Scene& scene, const CostModel& model,
                    const std::vector<bool>& movable, std::vector<geometry::Pose2>& poses,
                    CostTerms& terms, const PolishHooks& hooks, int max_tries,
                    const std::atomic<bool>* stop = nullptr);

}  // namespace hrs::optimize
