// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One front-end contract for a design: what `hrspace design`, the Python
// module's design() and anything else that designs ask for, checked in one
// place with one set of messages (each names its option as the command line
// spells it, e.g. "--seed: -1 is outside [0, 9007199254740992]"). The front
// ends only translate their syntax into a DesignRequest.
#include <cstdint>
#include <optional>
#include <string>

#include "geometry/scene.h"
#include "optimize/design.h"

namespace hrs::api {

//! Chains per design unless --restarts says otherwise (docs/optimize.md
//! "Restarts": the spread across seeds is larger than what a longer chain gains).
inline constexpr long long kDefaultRestarts = 2;

struct DesignRequest {
  std::string planner = "default";     //!< --planner: a preset, then comma items
  std::optional<std::string> reuse;    //!< --reuse: replaces the techniques
  std::optional<std::string> disable;  //!< --disable: design-loop switches off
  //! --weights: "L,R,C" (path length, rotation, clearance) or "L,R,C,D,A"
  //! (and interior distance, angle); each finite, >= 0 and <= 1e6.
  std::optional<std::string> weights;
  long long seed = 1;         //!< first seed, [0, 2^53]
  long long iterations = 700;  //!< annealing iterations, [0, 1e8]
  long long designs = 1;       //!< designs, seeds seed … seed + designs − 1, [1, 1000]
  long long threads = 0;       //!< tour-planning threads (0: all cores), [0, 1024]
  std::string rules = "ada";   //!< accessibility rule set: ada or iso
  long long access_goal = 1;   //!< designs tried per design until one passes, [1, 100]
  //! Annealing chains per design, the lowest final cost kept
  //! (api::design_restarts()), [1, 100].
  long long restarts = kDefaultRestarts;

  //! Checks every field, in the order above; the first bad one throws
  //! hrs::InputError.
  void validate() const;
  //! The planner configuration (validated).
  optimize::PlannerConfig planner_config() const;
  //! The options of design `d` (from 0): seed + d, the iterations, threads
  //! and planner (validated).
  optimize::DesignOptions options(long long d = 0) const;
  //! Replaces the scene's weights with --weights (nothing when unset).
  void apply_weights(geometry::Scene& scene) const;
};

}  // namespace hrs::api
