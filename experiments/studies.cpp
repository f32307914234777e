// The studies of the paper's §VI (and its method figures), in the order
// `scripts/reproduce.sh` runs them. Each is defined, as a run list, a run and
// a summary, in the file of its kind: studies_planners.cpp (planner speed),
// studies_designs.cpp (the designs), studies_method.cpp (method figures); what
// they share is in studies_shared.cpp. See study.h for the outputs and
// docs/experiments.md for what each study measures and how it maps to the paper.

#include "experiments/study.h"

#include "experiments/studies_shared.h"

namespace hrs::experiments {

const std::vector<Study>& studies() {
  static const std::vector<Study> all = {
      shared::timing_study(),     shared::rs_decomposition_study(), shared::rrt_iterations_study(),
      shared::small_room_study(), shared::ao_graph_study(),         shared::designs_study(),
      shared::hard_rooms_study(), shared::design_loop_study(),      shared::method_study(),
      shared::generalization_study(),
  };
  return all;
}

const Study* find_study(const std::string& name) {
  for (const Study& s : studies())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace hrs::experiments
