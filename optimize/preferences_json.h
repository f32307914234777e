#pragma once
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to optimize/: the "preferences" section of report.json
// (docs/scene-format.md "report.json").

#include <nlohmann/json.hpp>

#include "optimize/preferences.h"

namespace hrs::optimize {

//! {met, total, worst_angle_deg, tolerances, items: [{kind, object, other,
//! wall, target, achieved, residual, tolerance, met}]}; angles in radians.
nlohmann::json preferences_json(const PreferenceReport& report,
                                const PreferenceTolerances& tolerances = {});

}  // namespace hrs::optimize
