// SPDX-License-Identifier: GPL-3.0-or-later
// The studies of the paper's §VI (and its method figures), in the order
// `scripts/reproduce.sh` runs them. Each is defined, as a run list, a run and
// a summary, in the file of its kind: studies_planners.cpp (planner speed),
// studies_designs.cpp (the designs), studies_method.cpp (method figures); what
// they share is in studies_shared.cpp. See study.h for the outputs and
// docs/experiments.md for what each study measures and how it maps to the paper.

#include "experiments/study.h"

#include "experiments/studies_shared.h"

namespace hrs::experiments {

std::filesystem::path scene_path(const StudyConfig& config, const std::string& room) {
  if (room.ends_with(".json")) return room;
  return config.scenes_dir / (room + ".json");
}

const std::vector<Study>& studies() {
  static const std::vector<Study> all = [] {
    std::vector<Study> s = {
        shared::timing_study(),         shared::rs_decomposition_study(),
        shared::rrt_iterations_study(), shared::sensitivity_study(),
        shared::small_room_study(),
        shared::ao_graph_study(),       shared::designs_study(),
        shared::hard_rooms_study(),     shared::design_loop_study(),
        shared::method_study(),         shared::generalization_study(),
        shared::tradeoff_study(),
    };
    // A run's identity (runner.h run_identity): its room's scene digest and
    // its planner's switches, unless the study reads more than that.
    for (Study& study : s)
      if (!study.identity) study.identity = shared::run_identity;
    return s;
  }();
  return all;
}

const Study* find_study(const std::string& name) {
  for (const Study& s : studies())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace hrs::experiments
