// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The last guard on every output: a found tour is certified again, leg by
// leg, with the continuous collision checks before a design may count it
// (paper §III-C's tours, our certification; docs/geometry.md). A defect in
// any planner or reuse technique that produced a colliding leg turns the
// tour into an unfound one instead of reaching tours.json.

#include "geometry/cspace.h"
#include "planning/leg_measures.h"
#include "planning/tour.h"

namespace hrs::planning {

//! Pieces (metres) in which recheck_tour() certifies each leg.
inline constexpr double kRecheckPiece = 0.05;

//! Re-validates a found tour in `cspace` with the continuous checks, every
//! leg cut into kRecheckPiece pieces, a piece that fails bisected before it
//! counts (MotionValidator::certified_prefix); a tour with a leg that is not
//! certified free becomes unfound (stats.depth = the failing leg). Returns
//! false when it did so. Guards the outputs against planner defects.
//! With `measures`, the certified prefixes come through it (the same values).
bool recheck_tour(const geometry::CSpace& cspace, double radius, Tour& tour,
                  LegMeasures* measures = nullptr);

}  // namespace hrs::planning
