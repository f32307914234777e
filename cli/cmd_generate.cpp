// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace generate`: the room zoo (experiments/room_zoo.h) on the command
// line: random rooms that are tourable by construction, each written with
// its witness (the planted layout).

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "cli/args.h"
#include "cli/commands.h"
#include "experiments/room_zoo.h"
#include "experiments/table.h"
#include "geometry/error.h"
#include "geometry/scene.h"

namespace hrs::cli {

namespace {

//! --objects MIN-MAX (or a single count N).
std::pair<int, int> object_range(const Args& args) {
  const auto v = args.get("objects");
  if (!v) return {4, 40};
  const std::string bad = "--objects '" + *v + "': expected MIN-MAX with 4 <= MIN <= MAX <= " +
                          std::to_string(geometry::limits::kObjects);
  const auto dash = v->find('-');
  const std::string lo = v->substr(0, dash), hi = dash == std::string::npos ? lo : v->substr(dash + 1);
  auto whole = [&](const std::string& t) {
    if (t.empty() || t.size() > 4 || t.find_first_not_of("0123456789") != std::string::npos)
      throw InputError(bad);
    return std::stoi(t);
  };
  const int a = whole(lo), b = whole(hi);
  if (a < 4 || b < a || b > static_cast<int>(geometry::limits::kObjects)) throw InputError(bad);
  return {a, b};
}

}  // namespace

int cmd_generate(const Argv& argv) {
  const Args args(argv, {"out", "seed", "count", "first", "objects", "shape", "threads"}, {"no-check"});
  const std::string usage =
      "hrspace generate --out DIR [--seed S] [--count N] [--first I] [--objects MIN-MAX] "
      "[--shape rect|l|u|flat|any] [--threads T] [--no-check]";
  if (args.help()) {
    const experiments::zoo::ZooOptions defaults;
    std::cout
        << "usage: " << usage
        << "\n\nWrites N random rooms (the room zoo) into DIR: zoo_S_I.json, the scene with its\n"
           "movable objects scrambled, and zoo_S_I.witness.json, the same scene in the planted\n"
           "layout that meets every preference and in which all M tours of the AO graph are\n"
           "found by the baseline planner (checked; a failing plant is redrawn, and a room\n"
           "whose " << defaults.max_plants << " plants all fail is drawn again, up to "
        << defaults.max_draws << " draws). Prints one line per\n"
           "room: name, shape, objects, floor area, room draws, plants drawn, witness tours,\n"
           "time.\n"
           "The same seed gives the same files, whatever the number of threads.\n\n"
           "  --out DIR        output directory (created; required)\n"
           "  --seed S         zoo seed (default 1); rooms are zoo_S_I .. zoo_S_(I+N-1)\n"
           "  --count N        rooms to write (default 10)\n"
           "  --first I        index of the first room (default 1). A room depends only on\n"
           "                   the seed, its index and --objects/--shape, so the generalization\n"
           "                   study's room zoo_S_I of the bucket A-B is --first I --count 1\n"
           "                   --objects A-B\n"
           "  --objects A-B    objects per room, partition walls included (default 4-40)\n"
           "  --shape K        rect, l, u, flat (2 or 3 rooms joined by openings) or any\n"
           "                   (default: drawn per room)\n"
           "  --threads T      tour-planning threads of the check (default 0: all cores)\n"
           "  --no-check       skip the tour check (geometry and preferences only)\n\n"
           "Exit 0 when every witness is tourable, 1 when a room's plants all failed (its\n"
           "files are written and its line says so), 2 on bad input.\n";
    return 0;
  }
  args.expect_positional(0, usage);
  const auto out = args.get("out");
  if (!out || out->empty()) throw InputError("--out DIR is required (see --help)");
  experiments::zoo::ZooOptions o;
  o.seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 1000000000000L));
  const int count = static_cast<int>(args.integer("count", 10, 1, 100000));
  const int first = static_cast<int>(args.integer("first", 1, 1, 1000000));
  std::tie(o.min_objects, o.max_objects) = object_range(args);
  if (const auto s = args.get("shape"); s && *s != "any") {
    o.shape = experiments::zoo::parse_shape(*s);
    if (!o.shape) throw InputError("--shape '" + *s + "': expected rect, l, u, flat or any");
  }
  o.threads = static_cast<int>(args.integer("threads", 0, 0, 1024));
  o.check_tours = !args.flag("no-check");
  const std::filesystem::path dir = *out;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw OutputError("--out '" + dir.string() + "': cannot create the directory");
  int failed = 0;
  for (int i = first; i < first + count; ++i) {
    const experiments::zoo::ZooRoom r = experiments::zoo::generate_room(o, i);
    if (r.scene.objects.empty()) {
      std::printf("%-14s %-4s no plant fitted in %d attempts (%d draws of the room): nothing written\n",
                  r.name.c_str(), experiments::zoo::shape_name(r.shape).c_str(), r.plant_attempts,
                  r.room_draws);
      ++failed;
      continue;
    }
    try {
      experiments::write_text_atomic(dir / (r.name + ".json"), geometry::write_scene(r.scene));
      experiments::write_text_atomic(dir / (r.name + ".witness.json"),
                                     geometry::write_scene(r.witness));
    } catch (const InputError& e) {
      throw OutputError(e.what());
    }
    std::string tours = o.check_tours
                            ? std::to_string(r.tours_found) + "/" + std::to_string(r.tours_total)
                            : "unchecked";
    if (!r.feasible) {
      tours += " WITNESS NOT TOURABLE";
      ++failed;
    }
    std::printf(
        "%-14s %-4s objects %3zu  area %6.2f m^2  draws %d  plants %2d (unplaced %d, "
        "untourable %d)  tours %s  %.2f s\n",
        r.name.c_str(), experiments::zoo::shape_name(r.shape).c_str(), r.scene.objects.size(),
        r.area, r.room_draws, r.plant_attempts, r.unplaced, r.untourable, tours.c_str(), r.seconds);
    std::fflush(stdout);
  }
  return failed ? 1 : 0;
}

}  // namespace hrs::cli
