// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The --reuse list syntax: text naming the proposed planner's techniques
// (planning::ReuseOptions) as the command line, the Python module, the
// experiments and the benchmarks accept it. Parsing is input handling, so it
// lives here with the other user-facing checks; planning/ only knows the
// switches and how to name them (ReuseOptions::names, for reports).

#include <string_view>

#include "planning/reuse_options.h"

namespace hrs::api {

//! Parses "none" or a comma list of the techniques of
//! planning::ReuseOptions::techniques() and "all" (every technique on by
//! default), applied left to right: a name turns its technique on, -name
//! turns it off ("all,-budget"), NAME=N turns it on with parameter N
//! (budget=500, backoff=10). hrs::InputError, one line naming the item, for
//! anything else. parse_reuse(o.names()) gives back o.
planning::ReuseOptions parse_reuse(std::string_view list);

}  // namespace hrs::api
