// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The --reuse list syntax: text naming the proposed planner's techniques
// (planning::ReuseOptions) as the command line, the Python module, the
// experiments and the benchmarks accept it. Parsing is input handling, so it
// lives here with the other user-facing checks; planning/ only knows the
// switches and how to name them (ReuseOptions::names, for reports).

#include <string_view>

#include "optimize/planner_config.h"
#include "planning/reuse_options.h"

namespace hrs::api {

//! Parses "none" or a comma list of the techniques of
//! planning::ReuseOptions::techniques() and "all" (every technique on by
//! default), applied left to right: a name turns its technique on, -name
//! turns it off ("all,-budget"), NAME=N turns it on with parameter N
//! (budget=500, backoff=10). hrs::InputError, one line naming the item, for
//! anything else. parse_reuse(o.names()) gives back o.
planning::ReuseOptions parse_reuse(std::string_view list);

//! Parses a planner configuration, "PRESET[,ITEM...]" (optimize/planner_config.h):
//! a preset (default, baseline, paper, literal; "proposed" is read as
//! default), then items applied left to right: a design-loop switch
//! (goalskip, refuse, escape, early) or, for the proposed planner's presets,
//! a technique as parse_reuse() reads it. -NAME turns a switch off.
//! hrs::InputError naming `option` and the item for anything else, and for
//! a technique with a preset that plans each leg by the RRT.
//! parse_planner(c.name()) gives back c.
optimize::PlannerConfig parse_planner(std::string_view text,
                                      std::string_view option = "--planner");

}  // namespace hrs::api
