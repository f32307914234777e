// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Internal to experiments/studies*.cpp, not part of the API: what the studies
// share (the planners they compare, run keys and parameters, the design or
// replay run most of them make) and the definition of each study.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "api/design_request.h"
#include "experiments/study.h"
#include "geometry/scene.h"
#include "optimize/design.h"

namespace hrs::experiments::shared {

// ---- rooms and runs ---------------------------------------------------------

//! A room's name in keys and tables: the file stem of a .json path.
std::string room_label(const std::string& room);
//! The scene of a room name (looked up in --scenes) or .json path.
geometry::Scene load_room(const StudyConfig& config, const std::string& room);
//! The digest of a room's scene file (runner.h file_digest); InputError
//! naming the room and the path when there is no such file.
std::string scene_digest(const StudyConfig& config, const std::string& room);
//! The identity column of a planner (kPlanners): planner_config, the
//! planner configuration it stands for (optimize::PlannerConfig::name()).
Row planner_identity(const StudyConfig& config, const std::string& planner);
//! Study::identity of most studies: the digest of the run's room
//! (scene_digest) and its planner's switches, for the parameters it has.
Row run_identity(const RunSpec& spec, const StudyConfig& config);
//! The study's rooms: --rooms when given, else its own (the first only with --quick).
std::vector<std::string> rooms_of(const StudyConfig& config, std::vector<std::string> defaults);
//! The seeds 1..config.seeds, as parameter values.
std::vector<std::string> seed_list(const StudyConfig& c);
//! A run of `study` with parameters `p`, keyed by the study and the values.
RunSpec make_run(const std::string& study, std::vector<std::pair<std::string, std::string>> p);
//! A parameter of the run; InputError when it has none of that name.
std::string param(const RunSpec& spec, const std::string& name);
long int_param(const RunSpec& spec, const std::string& name);

// ---- designs ----------------------------------------------------------------

//! The design request of a study's run, as the command and the Python module
//! make theirs (api::DesignRequest): one of the compared planners (kPlanners)
//! spelled as --planner/--reuse ("all" is the default preset; the ablations
//! "samples_steering" and "none" are the default preset with only those §V
//! techniques), the study's iterations and threads, and `seed`.
api::DesignRequest design_request(const StudyConfig& config, const std::string& planner,
                                  std::uint64_t seed);
//! design_request(...).options(): checked by DesignRequest::validate().
optimize::DesignOptions design_options(const StudyConfig& config, const std::string& planner,
                                       std::uint64_t seed);
//! The design options of a run: its planner and seed.
optimize::DesignOptions run_options(const RunSpec& spec, const RunContext& context);
//! A finished design's measures; a stopped one is marked stopped (not stored).
RunOutput design_output(const optimize::DesignResult& r);
//! Keeps a design's four files under the study's designs/KEY/.
void keep_design(const RunContext& context, const std::string& key, const optimize::DesignResult& r,
                 const optimize::DesignOptions& o, const std::string& planner);
//! A design run (mode "design") or a replay of the baseline's layouts (mode
//! "replay"): the measures of one (room, planner, seed). With `trace`, a
//! design run also returns the table "trace": per annealing iteration its
//! planning time and whether the M tours were planned.
RunOutput design_or_replay(const RunSpec& spec, RunContext& context, bool keep = false,
                           bool trace = false);

//! The measures summarize_table() groups for design and replay runs.
inline const std::vector<std::string> kDesignMeasures = {
    "total_s",     "planning_s",  "planning_share", "cost_initial",      "cost_final",
    "tours_found", "tours_total", "mean_tour_m",    "tours_found_pct",   "acceptance",
    "layouts",     "valid",       "setup_s",        "tours_invalidated", "trees_reused"};

// ---- the studies, in their files --------------------------------------------

// studies_planners.cpp: how fast the planners are (§VI-A, §V-A, §V-C).
Study timing_study();
Study rs_decomposition_study();
Study rrt_iterations_study();
Study sensitivity_study();
// studies_designs.cpp: what the designs look like and how the loop fares.
Study small_room_study();
Study ao_graph_study();
Study designs_study();
Study hard_rooms_study();
Study design_loop_study();
// studies_method.cpp: the method figures.
Study method_study();
// studies_generalization.cpp: designs in rooms of the room zoo.
Study generalization_study();
Study tradeoff_study();  //!< studies_generalization.cpp

}  // namespace hrs::experiments::shared
