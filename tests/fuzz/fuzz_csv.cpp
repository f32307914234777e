// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the numeric CSV reader (cli::read_numeric_csv) on
// arbitrary bytes, read both as `hrspace collide --poses` reads it
// (x,y,theta) and as `hrspace rs --pairs` reads it (x0,y0,t0,x1,y1,t1), with
// the commands' limits. The oracle is the seeded GoogleTest fuzzer's: finite
// rows within the limits, one per line that holds something except an exact
// header, or one InputError line "fuzz.csv: line N...". Any other exception,
// an abort or a sanitizer report is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli/args.h"
#include "geometry/error.h"
#include "geometry/scene.h"

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_csv: %s: %s\n", what, detail.c_str());
  std::abort();
}

void check(const std::string& text, const std::vector<hrs::cli::CsvColumn>& columns,
           std::size_t lines) {
  std::vector<std::vector<double>> rows;
  try {
    rows = hrs::cli::read_numeric_csv(text, columns, "fuzz.csv");
  } catch (const hrs::InputError& e) {
    const std::string what = e.what();
    if (what.rfind("fuzz.csv: line ", 0) != 0) finding("message does not name the line", what);
    if (what.find('\n') != std::string::npos) finding("message of several lines", what);
    return;
  }
  if (rows.size() != lines && rows.size() + 1 != lines) finding("rows dropped", text);
  for (const auto& r : rows) {
    if (r.size() != columns.size()) finding("row of the wrong width", text);
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (!std::isfinite(r[i]) || std::abs(r[i]) > columns[i].max_abs)
        finding("value out of range", text);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Lines that hold something: every one is a row, except an exact header.
  std::size_t lines = 0;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) ++lines;
  const double c = hrs::geometry::limits::kCoordinate, a = hrs::geometry::limits::kAngle;
  check(text, {{"x", c}, {"y", c}, {"theta", a}}, lines);                                 // collide
  check(text, {{"x0", c}, {"y0", c}, {"t0", a}, {"x1", c}, {"y1", c}, {"t1", a}}, lines);  // rs
  return 0;
}
