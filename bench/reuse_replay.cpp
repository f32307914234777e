// SPDX-License-Identifier: GPL-3.0-or-later
// Baseline vs proposed planner on the same planning problems (paper §V-VI).
// A design run's planners visit different layouts (a reused path has another
// length than a fresh one, so costs and Metropolis decisions differ), which
// makes design-level timings (bench/reuse_timing.cpp) mostly seed-to-seed
// noise. Here a baseline design run of each room records every layout it
// planned (DesignOptions::layouts_out); each planner configuration then
// replays exactly that layout sequence (optimize::replay_planning), so every
// configuration answers the same tours in the same layouts. Reported per
// (room, configuration): planning time (manual time, the benchmark's time),
// tours found and their mean length over all layouts.
//
//   cmake --build build --target reuse_replay
//   build/bench/reuse_replay --benchmark_counters_tabular=true
//
// Environment: HRSPACE_REPLAY_ITERATIONS (default 700) annealing iterations
// of the recording run, HRSPACE_REPLAY_SEEDS (default 2) recorded runs per
// room (seeds 1..N, replayed one after the other), HRSPACE_REPLAY_ROOMS
// (default bedroom,office,living_room), HRSPACE_REPLAY_THREADS (default 2).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "api/reuse_list.h"
#include "bench/bench_util.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "planning/reuse.h"

namespace {

using namespace hrs;
using Layouts = std::vector<std::vector<geometry::Pose2>>;

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

struct Recording {
  geometry::Scene scene;
  std::vector<Layouts> runs;  //!< one layout sequence per recorded seed
};

void replay(benchmark::State& state, const Recording* rec, const std::string& config, int threads) {
  for (auto _ : state) {
    double planning = 0.0, length = 0.0;
    long found = 0, layouts = 0, tours = 0;
    planning::ReuseCounters legs;
    for (std::size_t s = 0; s < rec->runs.size(); ++s) {
      optimize::DesignOptions o;
      o.seed = s + 1;
      o.threads = threads;
      o.planner = api::parse_planner(config == "baseline" ? "baseline" : "default");
      if (o.planner.proposed) o.planner.reuse = api::parse_reuse(config);
      const optimize::ReplayResult r = optimize::replay_planning(rec->scene, rec->runs[s], o);
      planning += r.planning_s;
      found += r.tours_found;
      length += r.tour_length;
      layouts += r.layouts;
      tours += r.tours_total;
      legs += r.counters;
    }
    state.SetIterationTime(planning);
    state.counters["layouts"] = static_cast<double>(layouts);
    state.counters["ms_per_layout"] = 1e3 * planning / static_cast<double>(layouts);
    state.counters["tours_found_%"] =
        100.0 * static_cast<double>(found) / static_cast<double>(tours);
    state.counters["mean_tour_m"] = found > 0 ? length / static_cast<double>(found) : 0.0;
    if (config != "baseline") {
      state.counters["legs_db"] = static_cast<double>(legs.legs_database);
      state.counters["legs_repaired"] = static_cast<double>(legs.legs_repaired);
      state.counters["legs_planned"] = static_cast<double>(legs.legs_planned);
      state.counters["legs_failed"] = static_cast<double>(legs.legs_failed);
      state.counters["legs_proven"] = static_cast<double>(legs.legs_proven);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const int iterations = env_int("HRSPACE_REPLAY_ITERATIONS", 700);
  const int seeds = env_int("HRSPACE_REPLAY_SEEDS", 2);
  const int threads = env_int("HRSPACE_REPLAY_THREADS", 2);
  const char* rooms_env = std::getenv("HRSPACE_REPLAY_ROOMS");
  const std::vector<std::string> rooms =
      bench::split_list(rooms_env ? rooms_env : "bedroom,office,living_room");
  // "all" (the defaults), all but one of the heuristics, then each
  // technique alone.
  // HRSPACE_REPLAY_CONFIGS replaces the list ('all;all,backoff=60': semicolons
  // when a config has commas).
  const char* configs_env = std::getenv("HRSPACE_REPLAY_CONFIGS");
  const std::vector<std::string> configs =
      configs_env ? bench::split_list(configs_env)
                  : std::vector<std::string>{
                        "baseline", "all",      "all,-budget", "all,-backoff", "paths",
                        "trees",    "samples",  "steering",    "failures",     "shortcuts",
                        "budget",   "metrics",  "backoff"};
  static std::map<std::string, Recording> recordings;
  for (const std::string& room : rooms) {
    Recording& rec = recordings[room];
    rec.scene = geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + room + ".json");
    for (int seed = 1; seed <= seeds; ++seed) {
      optimize::DesignOptions o;
      o.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
      o.seed = static_cast<std::uint64_t>(seed);
      o.iterations = iterations;
      o.threads = threads;
      Layouts layouts;
      o.layouts_out = &layouts;
      optimize::design(rec.scene, o);  // the baseline's own run
      rec.runs.push_back(std::move(layouts));
    }
    for (const std::string& config : configs) {
      const Recording* r = &rec;
      benchmark::RegisterBenchmark(
          ("Replay/" + room + "/" + config).c_str(),
          [r, config, threads](benchmark::State& state) { replay(state, r, config, threads); })
          ->UseManualTime()
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
