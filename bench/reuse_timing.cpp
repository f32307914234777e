// SPDX-License-Identifier: GPL-3.0-or-later
// Baseline vs proposed planner (paper §VI, Fig. "time"): designs of several
// rooms from the same seeds, planning time, total time and final cost per
// design, plus an ablation of each reuse technique alone (§V). Not a Google
// Benchmark: each row is one whole design; writes one CSV line per design
// and prints a Markdown summary (mean ± sd over the seeds).
//
//   ./build/bench/reuse_timing --iterations 700 --seeds 10 --threads 2
//       --rooms bedroom,office,living_room
//       --configs baseline,all,paths,trees,samples,steering,failures --out timing.csv
//
// Configs: baseline or any --reuse list of `hrspace design`; a list with
// commas needs semicolons between configs: --configs 'baseline;all;all,-budget'.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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

struct Stat {
  std::vector<double> v;
  double mean() const {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0 : s / v.size();
  }
  double sd() const {
    if (v.size() < 2) return 0;
    const double m = mean();
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / (v.size() - 1));
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> opt{{"iterations", "700"},
                                         {"seeds", "10"},
                                         {"threads", "0"},
                                         {"rooms", "bedroom,office,living_room"},
                                         {"configs", "baseline,all"},
                                         {"out", "reuse_timing.csv"}};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::printf(
          "usage: reuse_timing [--iterations N] [--seeds K] [--threads T] [--rooms LIST]\n"
          "                    [--configs LIST] [--out FILE]\n"
          "Designs each room (scenes/ROOM.json) with seeds 1..K under each config and\n"
          "prints mean +- sd of planning time, total time and final cost per (room, config);\n"
          "one CSV line per design goes to FILE (default reuse_timing.csv).\n"
          "Configs: baseline or any --reuse list of hrspace design; with commas inside\n"
          "a config, separate configs by semicolons: 'baseline;all;all,-budget'.\n"
          "Defaults: 700 iterations, 10 seeds, all cores, bedroom,office,living_room,\n"
          "baseline,all.\n");
      return 0;
    }
  }
  if (argc % 2 == 0) {
    std::fprintf(stderr, "option %s needs a value (see --help)\n", argv[argc - 1]);
    return 2;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string k = argv[i];
    if (k.rfind("--", 0) != 0 || !opt.count(k.substr(2))) {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
    opt[k.substr(2)] = argv[i + 1];
  }
  const int iterations = std::atoi(opt["iterations"].c_str());
  const int seeds = std::atoi(opt["seeds"].c_str());
  const int threads = std::atoi(opt["threads"].c_str());
  std::ofstream csv(opt["out"]);
  csv << "room,config,seed,iterations,threads,total_s,planning_s,cost_initial,cost_final,"
         "tours_found,legs_database,legs_repaired,legs_planned,legs_failed,failures_reused,legs_"
         "proven\n";
  // (room, config) -> stats
  std::map<std::pair<std::string, std::string>, std::map<std::string, Stat>> stats;
  for (const std::string& room : bench::split_list(opt["rooms"])) {
    const geometry::Scene scene =
        geometry::load_scene(std::string(HRSPACE_SOURCE_DIR) + "/scenes/" + room + ".json");
    for (int seed = 1; seed <= seeds; ++seed) {
      for (const std::string& config : bench::split_list(opt["configs"])) {
        optimize::DesignOptions o;
        o.seed = static_cast<std::uint64_t>(seed);
        o.iterations = iterations;
        o.threads = threads;
        o.planner = api::parse_planner(config == "baseline" ? "baseline" : "default");
        if (o.planner.proposed) o.planner.reuse = api::parse_reuse(config);
        const optimize::DesignResult r = optimize::design(scene, o);
        const auto& c = r.counters;
        csv << room << ",\"" << config << "\"," << seed << ',' << iterations << ',' << r.threads
            << ',' << r.time_total_s << ',' << r.time_planning_s << ',' << r.initial.total() << ','
            << r.final.total() << ',' << r.final.tours_found << ',' << c.legs_database << ','
            << c.legs_repaired << ',' << c.legs_planned << ',' << c.legs_failed << ','
            << c.failures_reused << ',' << c.legs_proven << '\n'
            << std::flush;
        auto& s = stats[{room, config}];
        s["total"].v.push_back(r.time_total_s);
        s["planning"].v.push_back(r.time_planning_s);
        s["cost"].v.push_back(r.final.total());
        s["found"].v.push_back(r.final.tours_found);
        std::fprintf(stderr, "%s %s seed %d: planning %.2f s, total %.2f s, cost %.3f\n",
                     room.c_str(), config.c_str(), seed, r.time_planning_s, r.time_total_s,
                     r.final.total());
      }
    }
  }
  std::printf(
      "| room | planner | planning s | total s | planning ratio vs baseline | final cost | tours "
      "found |\n|---|---|---|---|---|---|---|\n");
  for (auto& [key, s] : stats) {
    const auto base = stats.find({key.first, "baseline"});
    const double ratio = base != stats.end() && s["planning"].mean() > 0
                             ? base->second["planning"].mean() / s["planning"].mean()
                             : 0.0;
    std::printf("| %s | %s | %.2f ± %.2f | %.2f ± %.2f | %.2f× | %.3f ± %.3f | %.1f |\n",
                key.first.c_str(), key.second.c_str(), s["planning"].mean(), s["planning"].sd(),
                s["total"].mean(), s["total"].sd(), ratio, s["cost"].mean(), s["cost"].sd(),
                s["found"].mean());
  }
  return 0;
}
