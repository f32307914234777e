// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// design.html: an interactive, self-contained view of one design (beyond the
// paper). One file with inline SVG, script and style, no network access (a
// Content-Security-Policy forbids it) and no server: it opens from file://.
// It shows the layout, each tour selectable, the chair's footprint driven
// along the selected tour (play, pause, scrub, speed) with its cusps marked,
// the annealing trace (cost and tours found against the iteration, accepted
// and rejected proposals) and overlays that toggle: the candidate goal poses,
// the accessibility findings (access/accessibility.h) and the route width
// along the path. docs/viewer.md describes the page.
//
// The page's data is computed here, in C++, from the design itself: world
// footprints, the door's clear zone, the cusps (gear changes of each
// Reeds–Shepp leg, §IV), the goal poses (planning/goals.h) and the route
// width at every waypoint (access::route_width_at). The script only draws.
// It holds no timing, so the same seed gives the same bytes.
#include <string>

#include "optimize/design.h"

namespace hrs::view {

//! The page's data as JSON text: room, door, objects (world footprints,
//! front marks, unmet preferences), tours (waypoints, stops, cusps, route
//! width per waypoint), goal poses, the trace, and `accessibility_json`
//! (accessibility.json's text) embedded as it is.
std::string design_data(const optimize::DesignResult& result, const std::string& title,
                        const std::string& accessibility_json);

//! design.html's text: the page with design_data() embedded.
std::string design_html(const optimize::DesignResult& result, const std::string& title,
                        const std::string& accessibility_json);

}  // namespace hrs::view
