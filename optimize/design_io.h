// SPDX-License-Identifier: GPL-3.0-or-later
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
#include <utility>
#include <vector>

#include "optimize/design.h"

namespace hrs::optimize {

//! What report.json says about how the design was asked for.
struct RunInfo {
  std::uint64_t seed = 1;
  std::string planner = "baseline";
  int iterations = 700;
  //! Further top-level sections of report.json: (name, JSON text), written
  //! after the design's own (e.g. the accessibility summary of the front end).
  std::vector<std::pair<std::string, std::string>> report_sections = {};
  //! SVG elements in room coordinates (metres, y up), drawn in design.svg
  //! above the tours (e.g. the accessibility overlay).
  std::string svg_overlay = {};
};

//! tours.json text: {"tours": [...]} with sequence, likelihood, found, legs
//! (from, to, segments, waypoints, …), metrics; no timings.
std::string tours_document(const DesignResult& result);
//! report.json text.
std::string report_document(const DesignResult& result, const RunInfo& info);
//! design.svg text; `title` is printed above the room; `overlay` (SVG
//! elements in room coordinates, metres, y up) is drawn above the tours.
std::string design_svg(const DesignResult& result, const std::string& title,
                       const std::string& overlay = {});
//! An SVG picture and its canvas size in pixels.
struct Picture {
  std::string svg;
  double width = 0.0, height = 0.0;
};
//! design_svg() with the canvas size it drew on (from the room, not read
//! back from the text).
Picture design_picture(const DesignResult& result, const std::string& title,
                       const std::string& overlay = {});
//! One SVG showing several pictures side by side (columns per row), each
//! in a cell as large as the largest.
std::string contact_sheet_svg(const std::vector<Picture>& pictures, int columns = 4);
//! Writes layout.json, tours.json, design.svg and report.json into `dir`
//! (created if missing), all four through write_files_atomic, then
//! manifest.json: the four names with their sizes and FNV-1a digests. The
//! old manifest is removed first, so the files are one set exactly when
//! manifest.json exists and matches them (a kill between two renames
//! leaves no manifest). Throws
//! InputError when the directory cannot be created, OutputError when a write
//! fails.
void write_design(const DesignResult& result, const RunInfo& info,
                  const std::filesystem::path& dir);

//! The names write_design writes into a design directory (manifest.json last).
const std::vector<std::string>& design_file_names();

}  // namespace hrs::optimize
