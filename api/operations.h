// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The operations behind `hrspace plan`, `hrspace tour` and `hrspace design`
// as plain functions: the command line (cli/) and the Python module
// (python/) both call these, so equal inputs give equal outputs and equal
// error messages (hrs::InputError, one line) whichever front end is used.

#include <cstdint>
#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/cspace.h"
#include "geometry/pose.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/design_io.h"
#include "planning/reuse_options.h"

namespace hrs::api {

//! The reuse techniques one operation accepts, and the ones it uses when the
//! caller names none (the --reuse syntax of api::parse_reuse).
struct ReuseRule {
  const char* allowed;
  const char* fallback;
};
inline constexpr ReuseRule kPlanReuse{"samples,steering", "samples,steering"};
inline constexpr ReuseRule kTourReuse{"samples,steering,paths,shortcuts,budget",
                                      "samples,steering,paths"};

//! For `hrspace plan` and `hrspace tour`: `planner` is "baseline" or
//! "default" ("proposed" is read the same); `reuse` (not baseline) a --reuse
//! list. nullopt for the baseline, else the proposed planner's techniques.
//! InputError, with the command line's wording (--planner, --reuse), for an
//! unknown planner, reuse without the proposed planner, or a technique
//! outside `rule.allowed`.
std::optional<planning::ReuseOptions> choose_planner(const std::string& planner,
                                                     const std::optional<std::string>& reuse,
                                                     const ReuseRule& rule);

//! "baseline" or "proposed".
std::string planner_name(const std::optional<planning::ReuseOptions>& reuse);

//! InputError naming `what` (e.g. "--from") when the chair at `pose` cannot
//! start or end a leg: outside the room, overlapping an object, or too close
//! to an obstacle for the conservative C-space to certify it free.
void require_free(const geometry::Scene& scene, const geometry::CSpace& cspace,
                  const geometry::Pose2& pose, const std::string& what);

//! "door,bed,tv" as ids; InputError for an empty id or an empty list.
std::vector<std::string> split_sequence(const std::string& text);
//! InputError for an id that is neither "door" nor an object of `scene`.
void check_sequence(const geometry::Scene& scene, const std::vector<std::string>& sequence);

//! Settings of one leg (`hrspace plan`).
struct LegSettings {
  std::uint64_t seed = 1;
  int iterations = 3000;  //!< RRT cap (planning::PlannerOptions::max_iterations)
  double step = 0.25;     //!< metres between tree nodes
  std::optional<planning::ReuseOptions> reuse;  //!< nullopt: the baseline
};

//! One leg in the scene's initial layout: the JSON object `hrspace plan`
//! prints (one line, no newline). InputError for a start or goal that is not
//! certified free (messages name "--from" and "--to") or a step <= 0.
std::string plan_leg_json(const geometry::Scene& scene, const geometry::Pose2& from,
                          const geometry::Pose2& to, const LegSettings& settings);

//! One tour of `sequence` ("door" first) in the scene's initial layout: the
//! JSON object `hrspace tour` prints (one line, no newline). InputError for
//! an unknown object id.
std::string plan_tour_json(const geometry::Scene& scene, const std::vector<std::string>& sequence,
                           std::uint64_t seed, const std::optional<planning::ReuseOptions>& reuse);

//! The planner of a design from the front ends' options: `planner` a
//! parse_planner() text (--planner, default "default"), `reuse` a
//! parse_reuse() list that replaces the techniques (proposed presets only),
//! `disable` "none" or a comma list of design-loop switches to turn off.
//! hrs::InputError naming the option for anything else. The command line and
//! the Python module both call this, so their messages are the same.
optimize::PlannerConfig design_planner(const std::string& planner,
                                       const std::optional<std::string>& reuse,
                                       const std::optional<std::string>& disable);

//! The options of one design run with the command's defaults (the fields
//! cli/cmd_optimize.cpp sets from --seed, --iterations, --threads and the
//! planner); python_design_test checks that both give the same files.
optimize::DesignOptions design_options(std::uint64_t seed, int iterations, int threads,
                                       const optimize::PlannerConfig& planner);

//! One annealing chain of a design with restarts (design_restarts()).
struct RestartChain {
  std::uint64_t seed = 0;
  double cost = 0.0;     //!< the chain's final total cost
  int tours_found = 0;   //!< of the chain's best layout
  bool valid = false;    //!< its best layout passed every exact check
};

//! The seed of chain `r` (from 0) of a design with seed `seed`: the seed
//! itself for r = 0, else a splitmix64 hash of both below 2^53 (a seed that
//! `--seed` accepts: `--seed S --restarts 1` repeats chain r alone).
std::uint64_t restart_seed(std::uint64_t seed, int r);

//! Restarts (beyond the paper; docs/optimize.md "Restarts"): `restarts`
//! independent designs of `options` at the seeds restart_seed(options.seed,
//! r), and the one with the lowest final total cost kept (a valid layout
//! before an invalid one; a tie to the lower r). The chains run side by
//! side on the threads that options.threads allows (0: all cores), each
//! with an equal share of them; a design does not depend on its thread
//! count, so neither does the one kept. `progress` hears chain 0 only;
//! `others` (may be empty) is called after each iteration of the other
//! chains, one call at a time (the Python module polls Ctrl-C there). A
//! stop (through `stop`) stops every chain: each keeps its best so far.
//! hrs::Interrupted escapes only when every chain stopped before its first
//! iteration. With restarts = 1 it is optimize::design() (`chains` empty).
struct RestartResult {
  optimize::DesignResult result;  //!< the design kept
  std::uint64_t seed = 0;         //!< the seed of its chain
  std::vector<RestartChain> chains;
};
RestartResult design_restarts(const geometry::Scene& scene, optimize::DesignOptions options,
                              int restarts, const std::atomic<bool>* stop,
                              const std::function<void(const optimize::DesignStep&)>& progress,
                              const std::function<void()>& others = {});

//! One design tried by design_for_access().
struct AccessTry {
  std::uint64_t seed = 0;
  bool pass = false;
  int failures = 0;   //!< access::Report::failures()
  double cost = 0.0;  //!< the design's final total cost
};

//! The accessibility goal (beyond the paper): a constraint on the layout a
//! design returns. Runs the design at seeds options.seed, options.seed +
//! stride, … (at most `tries`, each a whole design of options.iterations
//! with `restarts` chains, design_restarts()) and keeps the first whose layout passes `rules`; when none passes, the
//! one with the fewest failed checks, then the lower cost. With tries = 1 it
//! is one plain design (`tries` stays empty). A stop (through `stop`) ends
//! the tries: the best so far is kept. `on_try(k)` (may be empty) is called before try k (from 0);
//! `others` is design_restarts()'s.
//! hrs::Interrupted escapes only when the first try stopped before its first
//! iteration.
struct AccessGoalResult {
  optimize::DesignResult result;  //!< the design kept
  std::uint64_t seed = 0;         //!< its seed (of the try; its chains have their own)
  std::vector<AccessTry> tries;
  std::vector<RestartChain> chains;  //!< the kept design's chains (empty: one chain)
  std::uint64_t chain_seed = 0;      //!< the seed of its chain kept (`seed` with one chain)
};
AccessGoalResult design_for_access(const geometry::Scene& scene, optimize::DesignOptions options,
                                   const std::string& rules, int tries, std::uint64_t stride,
                                   int restarts,
                                   const std::atomic<bool>* stop,
                                   const std::function<void(const optimize::DesignStep&)>& progress,
                                   const std::function<void(int)>& on_try = {},
                                   const std::function<void()>& others = {});
//! report.json's "access_goal" section of a design_for_access() run.
std::string access_goal_json(const AccessGoalResult& goal);
//! Adds report.json's sections of a design_for_access() run to `info`:
//! "access_goal" when it tried several designs, "restarts" (the chains,
//! their seeds and costs, and the seed kept) when the design had several
//! chains. The command and the Python module both call it.
void add_goal_sections(const AccessGoalResult& goal, optimize::RunInfo& info);

//! The files the front end writes beside the design's own: accessibility.json
//! and design.html (view/viewer.h).
struct DesignExtras {
  std::string accessibility;  //!< accessibility.json's text
  std::string viewer;         //!< design.html's text
};

//! The accessibility report (access/accessibility.h) of a finished design
//! under rule set `rules` ("ada" or "iso"; InputError otherwise) and the
//! interactive page: adds their summaries to `info` (report.json sections
//! "accessibility" and "viewer", each naming its file with its FNV-1a
//! digest; design.svg's overlay) and returns both texts; `line` (may be
//! null) gets the accessibility's one-line summary for stdout. The CLI and
//! Python call this, so their files stay byte-identical.
DesignExtras attach_extras(const optimize::DesignResult& result, const std::string& rules,
                           optimize::RunInfo& info, std::string* line = nullptr);
//! The title of design.svg and design.html: "bedroom — seed 1", and
//! " (NOT VALID)" when the best layout failed an exact check.
std::string design_title(const optimize::DesignResult& result, std::uint64_t seed);
//! FNV-1a (64 bit) of `text` as 16 hex digits, as manifest.json uses.
std::string fnv1a64_hex(const std::string& text);
//! The names write_design_files writes beside optimize::design_file_names().
const std::vector<std::string>& extra_file_names();
//! accessibility.json and design.html (atomically), then the design's own
//! files and manifest (optimize::write_design); report.json pins the two by
//! their digests.
void write_design_files(const optimize::DesignResult& result, const optimize::RunInfo& info,
                        const DesignExtras& extras, const std::filesystem::path& dir);

}  // namespace hrs::api
