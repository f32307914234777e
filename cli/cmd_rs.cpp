// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace rs`: shortest Reeds–Shepp paths for pose pairs (paper §III-B),
// CSV in (x0,y0,t0,x1,y1,t1, header optional), CSV out (length,word,segments).

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "geometry/error.h"
#include "geometry/scene.h"
#include "rs/reeds_shepp.h"

namespace hrs::cli {

namespace {

constexpr const char* kUsage =
    "usage: hrspace rs --radius R [--pairs FILE|-]\n"
    "\n"
    "Shortest Reeds-Shepp path (all 48 words, exact) for each pose pair.\n"
    "\n"
    "  --radius R     turning radius in metres (0.001 to 2000), required\n"
    "  --pairs FILE   CSV with columns x0,y0,t0,x1,y1,t1 (metres, radians;\n"
    "                 |x|, |y| <= 1000, |t| <= 1000); an optional first line\n"
    "                 x0,y0,t0,x1,y1,t1 is a header; '-' (default) reads stdin\n"
    "\n"
    "Output (stdout): CSV with header length,word,segments, one row per pair in\n"
    "input order. word is the steering letters each followed by its gear sign\n"
    "(e.g. L+S+R-); segments are the signed lengths in metres (sign = gear),\n"
    "space-separated, in the same order. Identical poses give length 0 and an\n"
    "empty word.\n";

}  // namespace

int cmd_rs(const Argv& argv) {
  const Args args(argv, {"radius", "pairs"});
  if (args.help()) {
    std::cout << kUsage;
    return 0;
  }
  args.expect_positional(0, "hrspace rs --radius R [--pairs FILE|-]");
  if (!args.get("radius")) throw InputError("--radius is required (turning radius in metres)");
  const double radius = args.number("radius", 0.0);
  if (!(radius >= geometry::limits::kMinLength && radius <= geometry::limits::kLength))
    throw InputError("--radius: must be within [" + format_number(geometry::limits::kMinLength) +
                     ", " + format_number(geometry::limits::kLength) + "] m, got " +
                     *args.get("radius"));
  const std::string path = args.get_or("pairs", "-");
  const double c = geometry::limits::kCoordinate, a = geometry::limits::kAngle;
  const auto rows = read_numeric_csv(
      read_input(path), {{"x0", c}, {"y0", c}, {"t0", a}, {"x1", c}, {"y1", c}, {"t1", a}},
      path == "-" ? "stdin" : path);

  std::string out = "length,word,segments\n";
  for (const auto& r : rows) {
    const rs::Path p = rs::shortest_path({r[0], r[1], r[2]}, {r[3], r[4], r[5]}, radius);
    out += format_number(p.length());
    out += ',';
    out += p.word();
    out += ',';
    for (std::size_t i = 0; i < p.segments.size(); ++i) {
      if (i) out += ' ';
      out += format_number(p.segments[i].gear * p.segments[i].length);
    }
    out += '\n';
  }
  std::cout << out;
  return 0;
}

}  // namespace hrs::cli
