// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace validate` and `hrspace collide`: the geometry layer on the command line.

#include <cstdio>
#include <iostream>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "geometry/cspace.h"
#include "geometry/error.h"
#include "geometry/scene.h"

namespace hrs::cli {

int cmd_validate(const Argv& argv) {
  const Args args(argv, {});
  const std::string usage = "hrspace validate SCENE";
  if (args.help()) {
    std::cout << "usage: " << usage
              << "\n\nChecks a scene file (hrspace-scene/1) against every rule of the format and\n"
                 "prints a summary. Exit 0 when valid, 2 with one line naming the file, the\n"
                 "field (JSON pointer) and the problem otherwise.\n";
    return 0;
  }
  args.expect_positional(1, usage);
  const geometry::Scene s = geometry::load_scene(args.positional()[0]);
  for (const std::string& w : geometry::degree_like_angles(s, args.positional()[0]))
    std::cerr << "hrspace validate: warning: " << w << "\n";
  std::size_t edges = 0, fixed = 0;
  for (const auto& [from, row] : s.activity.transitions) edges += row.size();
  for (const auto& o : s.objects) fixed += o.fixed;
  const geometry::CSpace cs(s);
  std::printf("scene      %s (valid)\n", s.name.c_str());
  std::printf("room       %zu vertices, area %.2f m^2\n", s.room.polygon.size(),
              geometry::signed_area(s.room.polygon));
  std::printf("door       centre (%.2f, %.2f), width %.2f m, clear depth %.2f m\n", s.door.center.x,
              s.door.center.y, s.door.width, s.door.clear_depth);
  std::printf("wheelchair %.2f x %.2f m, turning radius %.2f m\n", s.wheelchair.length,
              s.wheelchair.width, s.wheelchair.turning_radius);
  std::printf("objects    %zu (%zu fixed):", s.objects.size(), fixed);
  for (const auto& o : s.objects) std::printf(" %s", o.id.c_str());
  std::printf("\nrelations  %zu\n", s.relations.size());
  std::printf("AO graph   %zu nodes, %zu edges; M = %d sequences of %d visits\n",
              s.activity.transitions.size(), edges, s.activity.sequences, s.activity.visits);
  std::printf("c-space    %d slices, %zu convex pieces\n", cs.slices(), cs.piece_count());
  if (const int longest = geometry::longest_walk(s.activity, s.activity.visits);
      longest < s.activity.visits) {
    std::printf("note       no sequence of %d visits (longest %d): hrspace design refuses it\n",
                s.activity.visits, longest);
  }
  return 0;
}

int cmd_collide(const Argv& argv) {
  const Args args(argv, {"poses", "slices"});
  const std::string usage = "hrspace collide SCENE [--poses F|-] [--slices K]";
  if (args.help()) {
    std::cout << "usage: " << usage
              << "\n\nFor each pose x,y,theta (CSV; an optional first line x,y,theta is a header;\n"
                 "|x|, |y| <= 1000 m, |theta| <= 1000 rad; default stdin) prints\n"
                 "x,y,theta,free,clear_left,clear_right. free is 1 only when the chair is\n"
                 "certainly inside the room and clear of all furniture (exact conservative\n"
                 "check with K orientation slices, default 72); clear_left/right are the\n"
                 "distances to the nearest obstacle boundary on each side of the heading.\n";
    return 0;
  }
  args.expect_positional(1, usage);
  const geometry::Scene s = geometry::load_scene(args.positional()[0]);
  geometry::CSpaceOptions opt;
  opt.slices = static_cast<int>(args.integer("slices", 72, 4, 100000));
  const geometry::CSpace cs(s, opt);
  const std::string source = args.get_or("poses", "-");
  const double c = geometry::limits::kCoordinate, a = geometry::limits::kAngle;
  const auto rows = read_numeric_csv(read_input(source), {{"x", c}, {"y", c}, {"theta", a}},
                                     source == "-" ? "stdin" : source);
  std::printf("x,y,theta,free,clear_left,clear_right\n");
  for (const auto& r : rows) {
    const geometry::Pose2 p{r[0], r[1], r[2]};
    const geometry::Clearance c = cs.clearance(p);
    std::printf("%s,%s,%s,%d,%s,%s\n", format_number(r[0]).c_str(), format_number(r[1]).c_str(),
                format_number(r[2]).c_str(), cs.is_free(p) ? 1 : 0, format_number(c.left).c_str(),
                format_number(c.right).c_str());
  }
  return 0;
}

}  // namespace hrs::cli
