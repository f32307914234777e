// SPDX-License-Identifier: GPL-3.0-or-later
// The "preferences" section of report.json; see preferences_json.h.

#include "optimize/preferences_json.h"

#include <numbers>

namespace hrs::optimize {

nlohmann::json preferences_json(const PreferenceReport& report,
                                const PreferenceTolerances& tolerances) {
  nlohmann::json items = nlohmann::json::array();
  for (const PreferenceCheck& c : report.checks) {
    nlohmann::json item = {{"kind", c.kind},          {"object", c.object},
                           {"target", c.target},      {"achieved", c.achieved},
                           {"residual", c.residual},  {"tolerance", c.tolerance},
                           {"met", c.met}};
    if (!c.other.empty()) item["other"] = c.other;
    if (c.wall >= 0) item["wall"] = c.wall;
    items.push_back(std::move(item));
  }
  return {{"met", report.met},
          {"total", report.total},
          {"worst_angle_deg", report.worst_angle * 180.0 / std::numbers::pi},
          {"tolerances",
           {{"wall_distance", tolerances.wall_distance},
            {"wall_angle", tolerances.wall_angle},
            {"relation_distance", tolerances.relation_distance},
            {"relation_distance_share", tolerances.relation_distance_share},
            {"relation_angle", tolerances.relation_angle}}},
          {"items", std::move(items)}};
}

}  // namespace hrs::optimize
