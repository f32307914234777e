#pragma once
// The files of one design (docs/design-notes.md "Output shapes"): layout.json (a valid
// scene with the optimized poses), tours.json (the M tours of the best
// layout), design.svg (room, door and its clear zone, objects with names and
// a front mark, the most likely tour bold and the others faint, a scale bar)
// and report.json (costs with every term, acceptance rate, time split, the
// per-iteration trace). layout.json and tours.json hold no timings, so the
// same seed gives byte-identical files whatever the number of threads.
// The paper shows the most likely tour of each design (§VI, Fig. 6).

#include <filesystem>
#include <string>
#include <vector>

#include "optimize/design.h"

namespace hrs::optimize {

//! What report.json says about how the design was asked for.
struct RunInfo {
  std::uint64_t seed = 1;
  std::string planner = "baseline";
  int iterations = 700;
};

//! tours.json text: {"tours": [...]} with sequence, likelihood, found, legs
//! (from, to, segments, waypoints, …), metrics; no timings.
std::string tours_document(const DesignResult& result);
//! report.json text.
std::string report_document(const DesignResult& result, const RunInfo& info);
//! design.svg text; `title` is printed above the room.
std::string design_svg(const DesignResult& result, const std::string& title);
//! One SVG showing several design.svg texts side by side (columns per row).
std::string contact_sheet_svg(const std::vector<std::string>& svgs, int columns = 4);
//! Writes layout.json, tours.json, design.svg and report.json into `dir`
//! (created if missing). Throws InputError when the directory is not writable.
void write_design(const DesignResult& result, const RunInfo& info,
                  const std::filesystem::path& dir);

}  // namespace hrs::optimize
