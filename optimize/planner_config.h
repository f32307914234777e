#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Which planner a design uses, as one value (docs/planner.md "Presets").
//
// A PlannerConfig says which leg planner serves the tours (the baseline RRT
// per leg, paper §III-B, or the proposed planner that reuses work across
// layouts, §V), which of the proposed planner's techniques are on
// (planning::ReuseOptions), whether the RRT skips goal nodes it already
// tried, and which of the design loop's own additions are on (refusal gate,
// escape from walled-in layouts, early rejection, preferences, shorter tours,
// the lattice rescue of unfound tours; docs/optimize.md).
//
// Four presets name the planners that people compare:
//   literal   the paper's baseline read literally: RRT per leg, tried goal
//             nodes tried again, the paper's interior cost and moves, none
//             of our additions;
//   paper     the paper's proposed planner: its four techniques
//             (RS-decomposition samples and steering, path database, tree
//             reuse) and nothing of ours;
//   baseline  our RRT baseline (tried goal nodes skipped) with our design
//             loop additions;
//   default   the proposed planner with every technique that pays and our
//             additions: what `hrspace design` uses unless told otherwise.
// The text form is "PRESET[,ITEM...]" where an ITEM turns one switch on
// (NAME), off (-NAME) or sets a technique's parameter (NAME=N); name() gives
// the shortest such text and api::parse_planner(c.name()) gives back c.

#include <array>
#include <string>
#include <string_view>

#include "planning/reuse_options.h"

namespace hrs::optimize {

struct PlannerConfig {
  std::string preset = "default";  //!< the preset this configuration starts from
  bool proposed = true;            //!< the proposed planner (§V); false: RRT per leg
  planning::ReuseOptions reuse;    //!< its techniques (meaningless for the RRT per leg)
  //! Ours: an RRT does not steer to the goal again from a node it already
  //! tried it from (the paper's text tries every time).
  bool goalskip = true;
  //! Ours: a leg still unfound after kRefuseAfter RRT iterations whose ends
  //! the certified free grid separates stops there (planning/reach_gate.h).
  bool refuse = true;
  //! Ours: unfound tours are charged by how walled off their stops are, the
  //! walling objects are moved first, and no move may leave an object of a
  //! sequence without a free goal pose (docs/optimize.md "Blocked layouts").
  bool escape = true;
  //! Ours: a proposal stops being planned once a lower bound of its cost is
  //! rejected by the Metropolis draw (the same decisions).
  bool early = true;
  //! Ours: preferences as a designer reads them (optimize/preferences.h):
  //! each interior term is bounded and scaled to its tolerance, the annealer
  //! also proposes preference moves (against a wall, a wall slot, aligned
  //! with a relation partner), an opening arrangement re-packs the input
  //! before the annealing, an arrangement re-packs the best layout on
  //! the interior cost clear of the found tours' corridor
  //! (optimize/arrange.h), and a final polish moves each object to a pose
  //! that meets its preferences wherever every found tour stays found.
  //! Off: the paper's squared interior terms and moves.
  bool prefer = true;
  //! Ours, with `prefer`: last in the polish and only when every tour is
  //! found, layouts at a preference score no lower, with no more angles
  //! grossly off and a tour proxy (optimize/tour_proxy.h) more than 1 %
  //! lower, kept only at a lower total cost with every tour found.
  bool shorten = true;
  //! Ours: after the design, the first TourRound::kRescueTours (5) unfound
  //! tours are planned once more, up to TourRound::kRescueLegs (4) legs of
  //! each that the RRT misses (and the gate does not refuse) answered by
  //! the lattice planner (planning/lattice.h): such a leg that exists at
  //! the lattice's resolution is found (docs/planner.md "Lattice rescue").
  bool rescue = true;

  //! A named starting point.
  struct Preset {
    const char* name;
    const char* what;  //!< one line for --help and the docs
  };
  static const std::array<Preset, 4>& presets();
  //! The configuration of preset `name`; hrs::InputError naming `option`
  //! (e.g. "--planner") for an unknown name.
  static PlannerConfig from_preset(std::string_view name, std::string_view option = "--planner");

  //! A design-loop switch (not a reuse technique): NAME / -NAME in the text.
  struct Switch {
    const char* name;
    bool PlannerConfig::*on;
    const char* what;
  };
  static const std::array<Switch, 7>& switches();

  //! The shortest text that parses back to this configuration: the preset,
  //! then every switch and technique that differs from it.
  std::string name() const;
  //! One line: the preset and, for the proposed planner, its techniques.
  std::string describe() const;
  //! The preset list and switch list as indented help text (the one source of
  //! `hrspace design --help` and the Python docstring).
  static std::string help();
};

}  // namespace hrs::optimize
