// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/recheck.h"

#include "planning/motion_validator.h"

namespace hrs::planning {

bool recheck_tour(const geometry::CSpace& cspace, double radius, Tour& tour,
                  LegMeasures* measures) {
  if (!tour.found) return true;
  MotionValidator validator(cspace, radius);
  for (std::size_t i = 0; i < tour.legs.size(); ++i) {
    const auto& leg = tour.legs[i];
    const double length = leg.path.length();
    const double prefix = measures ? measures->certified_prefix(leg, kRecheckPiece)
                                   : validator.certified_prefix(leg.from, leg.path, kRecheckPiece);
    if (prefix < length - 1e-9) {
      tour.found = false;
      tour.legs.clear();
      tour.metrics = {};
      tour.stats.depth = static_cast<int>(i);
      return false;
    }
  }
  return true;
}

}  // namespace hrs::planning
