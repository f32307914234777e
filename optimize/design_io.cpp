// SPDX-License-Identifier: GPL-3.0-or-later
// The output files of `hrspace design` (optimize/design_io.h): their texts,
// and writing them so that no failure leaves a truncated file behind.

#include "optimize/design_io.h"
#include "optimize/preferences_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/error.h"
#include "geometry/version.h"
#include "io/files.h"
#include "planning/tour_json.h"

namespace hrs::optimize {

namespace {

using geometry::Vec2;
using nlohmann::json;

json terms_json(const CostTerms& t) {
  return {{"path_length", t.path_length},
          {"path_rotation", t.path_rotation},
          {"path_clearance", t.path_clearance},
          {"unfound_penalty", t.unfound_penalty},
          {"interior_distance", t.interior_distance},
          {"interior_rotation", t.interior_rotation},
          {"path", t.path()},
          {"interior", t.interior()},
          {"total", t.total()},
          {"tours_found", t.tours_found},
          {"tours_total", t.tours_total}};
}

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

}  // namespace


const std::vector<std::string>& design_file_names() {
  static const std::vector<std::string> names{"layout.json", "tours.json", "design.svg",
                                              "report.json", "manifest.json"};
  return names;
}

std::string tours_document(const DesignResult& result) {
  std::vector<double> likelihoods;
  for (const Sequence& s : result.sequences) likelihoods.push_back(s.likelihood);
  return planning::tours_json(result.tours, likelihoods, /*timings=*/false, /*indent=*/1) + "\n";
}

namespace {

// ---- report.json sections -------------------------------------------------

//! "cost"/"terms": every cost term of the input and of the best layout.
json terms_comparison_json(const DesignResult& result) {
  json terms = json::object();
  const json initial = terms_json(result.initial), final = terms_json(result.final);
  for (const auto& [name, value] : initial.items())
    terms[name] = {{"initial", value}, {"final", final[name]}};
  return terms;
}

//! One entry of "trace": the annealer's step, then its planning when planned.
json trace_step_json(const DesignStep& s, const geometry::Scene& layout) {
  const auto& e = s.anneal;
  json step = {{"iteration", e.iteration + 1},
               {"temperature", e.temperature},
               {"object", e.object >= 0 ? json(layout.objects[e.object].id) : json(nullptr)},
               {"move", e.preference ? "prefer" : e.rotation ? "rotate" : (e.jump ? "jump" : "translate")},
               {"valid", e.valid},
               {"accepted", e.accepted},
               {"proposed", finite_or_null(e.proposed_cost)},
               {"current", e.current_cost},
               {"best", finite_or_null(e.best_cost)}};
  if (s.planned) {
    step["tours_found"] = s.proposed.tours_found;
    if (s.rejected_early) {
      step["rejected_early"] = true;
      step["tours_planned"] = s.proposed.tours_total;
    }
    step["planning_ms"] = s.planning_ms;
    if (s.legs) {
      const auto& c = *s.legs;
      step["legs"] = {{"database", c.legs_database}, {"repaired", c.legs_repaired},
                      {"planned", c.legs_planned},   {"failed", c.legs_failed},
                      {"failed_ms", c.failed_ms},    {"planned_ms", c.planned_ms}};
    }
  }
  return step;
}

//! "trace": one entry per iteration.
json trace_json(const DesignResult& result) {
  json trace = json::array();
  for (const auto& s : result.trace) trace.push_back(trace_step_json(s, result.layout));
  return trace;
}

//! "sequences": the M sequences with their likelihoods, most likely first.
json sequences_json(const DesignResult& result) {
  json seqs = json::array();
  for (const auto& s : result.sequences)
    seqs.push_back({{"sequence", s.nodes}, {"likelihood", s.likelihood}});
  return seqs;
}

//! The report's sections about how the run went: what was asked, how the
//! proposals fared, what was planned or skipped, costs, time and trace.
json run_report_json(const DesignResult& result, const RunInfo& info) {
  return {{"scene", result.layout.name},
          {"version", hrs::version()},
          {"commit", hrs::commit()},
          {"seed", info.seed},
          {"planner", info.planner},
          {"iterations", info.iterations},
          {"iterations_run", result.proposals},
          {"stopped", result.stopped},
          {"valid", result.valid},
          {"threads", result.threads},
          {"planned_every_iteration", result.planned_every_iteration},
          {"tours_invalidated", result.tours_invalidated},
          {"tours_planned", result.tours_planned},
          {"early_rejection",
           {{"proposals", result.early.proposals},
            {"tours_skipped", result.early.tours_skipped},
            {"legs_skipped", result.early.legs_skipped},
            {"planning_saved_estimate_s", result.early.saved_s_estimate}}},
          {"unblock",
           {{"walled_before", result.unblock.walled_before},
            {"walled_after", result.unblock.walled_after},
            {"proposals", result.unblock.proposals},
            {"accepted", result.unblock.accepted},
            {"separated", result.unblock.separated},
            {"separation_passes", result.unblock.separation_passes},
            {"left_invalid", result.unblock.left_invalid}}},
          {"covering_moves", result.covering_moves},
          {"opening",
           {{"ran", result.opening.ran},
            {"kept", result.opening.kept},
            {"proposals", result.opening.proposals},
            {"time_ms", result.opening.ms},
            {"tours_found_before", result.opening.tours_found_before},
            {"tours_found_after", result.opening.tours_found_after},
            {"cost_before", result.opening.cost_before},
            {"cost_after", result.opening.cost_after}}},
          {"arrange",
           {{"kept", result.arrange.kept},
            {"rounds", result.arrange.rounds},
            {"rounds_kept", result.arrange.rounds_kept},
            {"proposals", result.arrange.proposals},
            {"time_ms", result.arrange.ms},
            {"preferences_met_before", result.arrange.met_before},
            {"preferences_met_after", result.arrange.met_after},
            {"tours_found_before", result.arrange.tours_found_before},
            {"tours_found_after", result.arrange.tours_found_after}}},
          {"polish",
           {{"tried", result.polish.tried},
            {"kept", result.polish.kept},
            {"slid", result.polish.slid},
            {"swapped", result.polish.swapped},
            {"evicted", result.polish.evicted},
            {"rearranged", result.polish.rearranged},
            {"turned", result.polish.turned},
            {"squared", result.polish.squared},
            {"shortened", result.polish.shortened},
            {"tours_found_before", result.polish.tours_found_before},
            {"preferences_met_before", result.polish.met_before}}},
          {"refused_legs",
           {{"legs", result.legs_refused},
            {"reachability_fills", result.gate_fills},
            {"reachability_ms", result.gate_ms}}},
          {"preferences", preferences_json(result.preferences)},
          {"preferences_initial",
           {{"met", result.preferences_initial.met}, {"total", result.preferences_initial.total}}},
          {"cost",
           {{"initial", result.initial.total()},
            {"final", result.final.total()},
            {"terms", terms_comparison_json(result)}}},
          {"time_s",
           {{"total", result.time_total_s},
            {"planning", result.time_planning_s},
            {"setup", result.time_setup_s},
            {"annealing", result.time_anneal_s},
            {"finish", result.time_finish_s},
            {"grid", result.gate_ms / 1e3},
            {"planning_share",
             result.time_total_s > 0 ? result.time_planning_s / result.time_total_s : 0.0}}},
          {"acceptance_rate",
           result.proposals > 0 ? static_cast<double>(result.accepted) / result.proposals : 0.0},
          {"accepted", result.accepted},
          {"valid_proposals", result.valid_proposals},
          {"temperature", {{"start", result.t_start}, {"end", result.t_end}}},
          {"sequences", sequences_json(result)},
          {"trace", trace_json(result)}};
}

//! "reuse" of the proposed planner (paper §V): where the legs came from (each
//! key counted once per iteration) and the RRT iterations of the fresh plans
//! (Fig. "rrt-it").
json reuse_json(const DesignResult& result) {
  const auto& c = result.counters;
  json histogram = json::array();
  for (const auto& [iterations, count] : c.rrt_iterations)
    histogram.push_back({{"iterations", iterations}, {"legs", count}});
  return {{"techniques", result.reuse},
          {"legs_database", c.legs_database},
          {"legs_repaired", c.legs_repaired},
          {"legs_planned", c.legs_planned},
          {"legs_failed", c.legs_failed},
          {"legs_rejected", c.legs_rejected},
          {"checks_skipped", c.checks_skipped},
          {"trees_reused", c.trees_reused},
          {"failures_reused", c.failures_reused},
          {"legs_proven", c.legs_proven},
          {"leg_requests", c.leg_requests},
          {"rrt_iterations_histogram", histogram},
          {"time_ms",
           {{"database", c.database_ms},
            {"repaired", c.repaired_ms},
            {"planned", c.planned_ms},
            {"failed", c.failed_ms}}}};
}

}  // namespace

std::string report_document(const DesignResult& result, const RunInfo& info) {
  json r = run_report_json(result, info);
  if (result.proposed) r["reuse"] = reuse_json(result);
  if (result.rescue.ran || result.rescue.unblocked > 0)
    r["rescue"] = {{"tours_unfound", result.rescue.tours_unfound},
                   {"unblocked", result.rescue.unblocked},
                   {"tours_found", result.rescue.tours_found},
                   {"time_ms", result.rescue.ms}};
  for (const auto& [name, text] : info.report_sections) r[name] = json::parse(text);
  return r.dump(1) + "\n";
}


void write_design(const DesignResult& result, const RunInfo& info,
                  const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create directory: " + ec.message());
  const std::string title = result.layout.name + " — seed " + std::to_string(info.seed) +
                            (result.valid ? "" : " (NOT VALID)");
  const std::vector<std::pair<std::filesystem::path, std::string>> files = {
      {dir / "layout.json", geometry::write_scene(result.layout)},
      {dir / "tours.json", tours_document(result)},
      {dir / "design.svg", design_svg(result, title, info.svg_overlay)},
      {dir / "report.json", report_document(result, info)}};
  // The set is marked complete by the manifest, written last: a reader that
  // finds no manifest, or one that does not match, knows a write was cut.
  std::filesystem::remove(dir / "manifest.json", ec);
  if (ec) throw OutputError((dir / "manifest.json").string() + ": cannot remove: " + ec.message());
  io::write_files_atomic(files);
  json manifest = {{"format", "hrspace-design-manifest/1"}, {"files", json::array()}};
  for (const auto& [path, text] : files) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bit
    for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    manifest["files"].push_back(
        {{"name", path.filename().string()}, {"bytes", text.size()}, {"fnv1a64", hex}});
  }
  io::write_files_atomic({{dir / "manifest.json", manifest.dump(1) + "\n"}});
}

}  // namespace hrs::optimize
