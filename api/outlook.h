#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// What a design of a scene will face, from its input layout (`hrspace
// validate`): how many of the M tours exist there, which stops have no free
// goal pose, and which preferences are unmet. Information, not errors.

#include <string>
#include <vector>

#include "geometry/scene.h"
#include "optimize/preferences.h"

namespace hrs::api {

struct DesignOutlook {
  bool planned = false;  //!< the tours were planned within the time cap
  int tours_found = 0, tours_total = 0;
  std::vector<std::string> unfound;           //!< sequences without a tour, "door,bed,tv"
  std::vector<std::string> stops_without_goal;  //!< objects of a sequence with no free goal pose
  optimize::PreferenceReport preferences;      //!< of the input layout
};

//! Plans the M tours of the input layout with the default planner (no
//! annealing, no escape, no polish), stopping after `seconds`.
DesignOutlook design_outlook(const geometry::Scene& scene, double seconds);

}  // namespace hrs::api
