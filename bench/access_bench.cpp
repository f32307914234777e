// SPDX-License-Identifier: GPL-3.0-or-later
// The accessibility report (access/accessibility.h) of a finished design,
// per shipped room: one default design of 700 iterations (seed 1, one
// thread) is made once, then access::evaluate is timed on it. The design's
// own wall time is reported as a counter, so the report's share of a
// design is read off one run (docs/BENCHMARKS.md). BM_ReportAndViewer times
// all the front end adds: the report and design.html.

#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "access/accessibility.h"
#include "api/operations.h"
#include "api/reuse_list.h"
#include "optimize/design.h"

namespace {

const char* const kRooms[] = {"bedroom", "office", "living_room", "small_bedroom", "l_studio",
                              "narrow_passage", "crowded_living", "office_round_table"};

const hrs::optimize::DesignResult& designed(int room) {
  static std::map<int, hrs::optimize::DesignResult> cache;
  auto it = cache.find(room);
  if (it != cache.end()) return it->second;
  const auto scene = hrs::geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" +
                                               kRooms[room] + ".json");
  const auto options =
      hrs::api::design_options(1, 700, 1, hrs::api::parse_planner("default"));
  return cache.emplace(room, hrs::optimize::design(scene, options)).first->second;
}

void BM_AccessibilityReport(benchmark::State& state) {
  const int room = static_cast<int>(state.range(0));
  const auto& d = designed(room);
  const auto rules = hrs::access::Rules::named("ada");
  bool pass = false;
  for (auto _ : state) {
    const auto report = hrs::access::evaluate(d.layout, d.tours, rules);
    pass = report.pass();
    benchmark::DoNotOptimize(pass);
  }
  state.SetLabel(std::string(kRooms[room]) + (pass ? " pass" : " fail"));
  state.counters["design_s"] = d.time_total_s;
}
BENCHMARK(BM_AccessibilityReport)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

//! Everything the front end adds to a design: the accessibility report and
//! design.html (api::attach_extras: the report, its JSON, the overlay and
//! the page with its goal poses and route widths).
void BM_ReportAndViewer(benchmark::State& state) {
  const int room = static_cast<int>(state.range(0));
  const auto& d = designed(room);
  std::size_t bytes = 0;
  for (auto _ : state) {
    hrs::optimize::RunInfo info{1, "default", 700};
    const auto extras = hrs::api::attach_extras(d, "ada", info);
    bytes = extras.viewer.size();
    benchmark::DoNotOptimize(bytes);
  }
  state.SetLabel(kRooms[room]);
  state.counters["design_s"] = d.time_total_s;
  state.counters["html_kB"] = static_cast<double>(bytes) / 1000.0;
}
BENCHMARK(BM_ReportAndViewer)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
