// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace experiment`: the experiments harness on the command line
// (experiments/study.h): one study, every study, or a merge of shard outputs.

#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "experiments/runner.h"
#include "experiments/study.h"
#include "geometry/error.h"
#include "geometry/scene.h"
#include "io/files.h"
#include "optimize/design_io.h"

namespace hrs::cli {

namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};

// The first signal asks for a clean stop (runs in flight are dropped, the
// tables of the finished ones are written); a second one ends the process.
extern "C" void on_stop_signal(int sig) {
  if (g_stop.exchange(true)) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
  g_signal.store(sig);
}

std::string usage_text() {
  std::string s =
      "hrspace experiment STUDY|all --out DIR [--seeds N] [--iterations N] [--threads T]\n"
      "                   [--jobs J] [--shard i/n] [--quick] [--rooms LIST] [--scenes DIR]\n"
      "                   [--zoo-seed S] [--zoo-rooms N]\n"
      "hrspace experiment merge STUDY|all --out DIR SHARD_DIR...\n"
      "hrspace experiment list\n\n"
      "Runs a study of the paper's experiments (§VI) and writes DIR/STUDY/runs.csv (one row\n"
      "per run: parameters, identity, measures, CPU), DIR/STUDY/summary.csv (mean, sd, n per\n"
      "group, ratios) and the study's extra tables and designs. A run's identity is all\n"
      "that determines it besides its parameters: version, commit, iterations, threads,\n"
      "quick, the digests of the scenes it reads, its planner's switches. Runs already\n"
      "stored under DIR with the same identity are skipped, so a killed sweep resumes where\n"
      "it stopped; a stored run of another identity is refused (exit 2, naming the column):\n"
      "use another --out. merge refuses shards that differ in anything but --shard.\n"
      "paper_figures/plot.py draws the figures and REPRODUCTION.md from DIR. Each option is\n"
      "given at most once. Every scene is checked before the first run; exit 2 for bad\n"
      "input, 1 for failed runs or failed writes (the message names the path and reason).\n\n"
      "  --out DIR       root of the outputs (required)\n"
      "  --seeds N       seeds 1..N (default 10; --quick: 2)\n"
      "  --iterations N  annealing iterations per design (default 700; --quick: 100)\n"
      "  --threads T     tour-planning threads per design (default 1, so timings compare)\n"
      "  --jobs J        designs run at once (default 1)\n"
      "  --shard i/n     run only the i-th of n deterministic parts (merge them afterwards)\n"
      "  --quick         the smallest sweep that writes every output (tests, smoke runs)\n"
      "  --rooms LIST    rooms instead of the study's own: scene names or .json paths, of\n"
      "                  distinct file names (runs are keyed by them)\n"
      "  --scenes DIR    where scene names are looked up (default: the source's scenes/)\n"
      "  --zoo-seed S    generalization: seed of the room zoo (default 1)\n"
      "  --zoo-rooms N   generalization: rooms per object-count bucket (default 20)\n\n"
      "studies:\n";
  for (const auto& st : experiments::studies()) {
    std::string n = st.name;
    n.resize(18, ' ');
    s += "  " + n + st.description + "\n  " + std::string(18, ' ') + "(" + st.paper + ")\n";
  }
  s += "\nCtrl-C, SIGTERM or SIGHUP stops after the runs in flight are dropped and writes the\n"
       "tables of the finished runs (exit 128 + signal); rerun the same command to resume.\n";
  return s;
}

std::vector<const experiments::Study*> select(const std::string& name) {
  std::vector<const experiments::Study*> out;
  if (name == "all") {
    for (const auto& s : experiments::studies()) out.push_back(&s);
    return out;
  }
  const experiments::Study* s = experiments::find_study(name);
  if (!s) {
    std::string known;
    for (const auto& st : experiments::studies()) known += (known.empty() ? "" : ", ") + st.name;
    throw InputError("unknown study '" + name + "' (one of: all, " + known + ")");
  }
  out.push_back(s);
  return out;
}

std::vector<std::string> split_list(const std::string& text, const std::string& what) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    if (item.empty()) throw InputError(what + ": empty item in '" + text + "'");
    out.push_back(item);
    start = end + 1;
  }
  return out;
}

//! The study configuration the options describe (--out required).
experiments::StudyConfig study_config(const Args& args) {
  const auto out = args.get("out");
  if (!out) throw InputError("--out DIR is required (see --help)");
  if (out->empty()) throw InputError("--out: empty directory name (give the root of the outputs)");
  experiments::StudyConfig config;
  config.quick = args.flag("quick");
  config.seeds = static_cast<int>(args.integer("seeds", config.quick ? 2 : 10, 1, 10000));
  config.iterations =
      static_cast<int>(args.integer("iterations", config.quick ? 100 : 700, 1, 10000000));
  config.threads = static_cast<int>(args.integer("threads", 1, 0, 1024));
  config.out = *out;
  config.zoo_seed = static_cast<std::uint64_t>(args.integer("zoo-seed", 1, 0, 1000000000000L));
  config.zoo_rooms = static_cast<int>(args.integer("zoo-rooms", 20, 1, 1000));
#ifdef HRSPACE_SOURCE_DIR
  config.scenes_dir = std::filesystem::path(HRSPACE_SOURCE_DIR) / "scenes";
#endif
  if (const auto s = args.get("scenes")) {
    std::error_code ec;
    if (s->empty()) throw InputError("--scenes: empty directory name");
    if (!std::filesystem::is_directory(*s, ec))
      throw InputError("--scenes " + *s + ": " +
                       (std::filesystem::exists(*s, ec) ? "not a directory" : "no such directory"));
    config.scenes_dir = *s;
  }
  if (const auto r = args.get("rooms")) {
    config.rooms = split_list(*r, "--rooms");
    // A room's name in run keys is its file stem: two entries of the same
    // name would store their runs under the same keys.
    std::map<std::string, std::filesystem::path> by_name;
    for (const auto& room : config.rooms) {
      const std::filesystem::path p = experiments::scene_path(config, room);
      std::error_code ec;
      if (!std::filesystem::is_regular_file(p, ec))
        throw InputError("--rooms: '" + room + "': no scene file " + p.string());
      const std::string name = p.stem().string();
      const auto [it, fresh] = by_name.emplace(name, p);
      if (!fresh)
        throw InputError("--rooms: " + it->second.string() + " and " + p.string() +
                         (std::filesystem::equivalent(it->second, p, ec)
                              ? " are the same scene, named twice"
                              : " are two scenes of the same name '" + name +
                                    "' (runs are keyed by the file name): rename one"));
    }
  }
  return config;
}

//! Checks every scene the chosen studies read before any run starts: each
//! exists (run_identity digests it) and each room of a run is a valid scene
//! with sequences. A bad scene is one message now, not one failed run per
//! seed later.
void check_scenes(const std::vector<const experiments::Study*>& chosen,
                  const experiments::StudyConfig& config) {
  std::set<std::string> checked;
  for (const experiments::Study* s : chosen)
    for (const experiments::RunSpec& spec : s->runs(config)) {
      experiments::run_identity(*s, spec, config);
      const auto room = spec.params.get("room");
      if (!room || !checked.insert(*room).second) continue;
      const std::string p = experiments::scene_path(config, *room).string();
      geometry::require_sequences(geometry::load_scene(p), p);
    }
}

//! --shard i/n as (i, n); (1, 1) without the option.
std::pair<int, int> shard_option(const Args& args) {
  const auto shard = args.get("shard");
  if (!shard) return {1, 1};
  const auto slash = shard->find('/');
  const std::vector<double> n =
      slash == std::string::npos
          ? std::vector<double>{}
          : parse_numbers(shard->substr(0, slash) + "," + shard->substr(slash + 1), 2, "--shard");
  if (n.size() != 2 || n[0] != std::floor(n[0]) || n[1] != std::floor(n[1]) || n[1] < 1 ||
      n[0] < 1 || n[0] > n[1] || n[1] > 100000)
    throw InputError("--shard '" + *shard + "': expected i/n with 1 <= i <= n");
  return {static_cast<int>(n[0]), static_cast<int>(n[1])};
}

//! Creates the output root (OutputError, exit 1, when it cannot be made).
void create_out(const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw OutputError(out.string() + ": cannot create directory: " + ec.message());
}

//! `experiment merge STUDY|all --out DIR SHARD_DIR...`.
int merge_command(const Args& args, const experiments::StudyConfig& config) {
  std::vector<std::filesystem::path> shards;
  for (std::size_t i = 2; i < args.positional().size(); ++i) {
    if (!std::filesystem::is_directory(args.positional()[i]))
      throw InputError(args.positional()[i] + ": not a directory");
    shards.emplace_back(args.positional()[i]);
  }
  create_out(config.out);
  const io::DirectoryLock lock(config.out);
  int missing = 0;
  for (const experiments::Study* s : select(args.positional()[1])) {
    const int m = experiments::merge_shards(*s, config, shards);
    std::cout << s->name << ": merged " << shards.size() << " shard(s) into "
              << (config.out / s->name).string()
              << (m ? ", " + std::to_string(m) + " runs missing" : "") << "\n";
    missing += m;
  }
  std::cout.flush();
  if (!std::cout) throw std::runtime_error("write error on standard output");
  if (missing) {
    std::cerr << "hrspace experiment merge: " << missing
              << " run(s) have no stored result in any shard\n";
    return 1;
  }
  return 0;
}

//! Runs the chosen studies; SIGINT, SIGTERM and SIGHUP stop them cleanly.
int run_command(const Args& args, const experiments::StudyConfig& config) {
  experiments::RunnerOptions options;
  options.jobs = static_cast<int>(args.integer("jobs", 1, 1, 256));
  std::tie(options.shard_index, options.shard_count) = shard_option(args);
  options.progress = isatty(STDERR_FILENO) != 0;
  options.stop = &g_stop;
  const std::vector<const experiments::Study*> chosen = select(args.positional()[0]);
  check_scenes(chosen, config);
  // One writer per output root: a second sweep into it is refused.
  create_out(config.out);
  const io::DirectoryLock lock(config.out);

  g_stop.store(false);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);

  int failed = 0;
  for (const experiments::Study* s : chosen) {
    if (g_stop.load()) break;
    const experiments::RunnerReport r = experiments::run_study(*s, config, options);
    for (const auto& e : r.errors)
      std::cerr << "hrspace experiment: " << s->name << ": " << e << "\n";
    std::cout << s->name << ": " << r.done << " run, " << r.skipped << " already stored, "
              << r.failed << " failed";
    if (options.shard_count > 1)
      std::cout << " (shard " << options.shard_index << "/" << options.shard_count << ": "
                << r.in_shard << " of " << r.total << " runs)";
    if (r.missing) std::cout << "; " << r.missing << " of " << r.total << " runs not stored yet";
    std::cout << " -> " << (config.out / s->name).string() << "\n" << std::flush;
    failed += r.failed;
  }
  std::cout.flush();
  if (!std::cout) throw std::runtime_error("write error on standard output");
  if (g_stop.load()) return 128 + (g_signal.load() ? g_signal.load() : SIGINT);
  return failed ? 1 : 0;
}

}  // namespace

int cmd_experiment(const Argv& argv) {
  const Args args(argv,
                  {"out", "seeds", "iterations", "threads", "jobs", "shard", "rooms", "scenes",
                   "zoo-seed", "zoo-rooms"},
                  {"quick"});
  if (args.help()) {
    std::cout << "usage: " << usage_text();
    return 0;
  }
  const auto& pos = args.positional();
  if (!pos.empty() && pos[0] == "list") {
    for (const auto& st : experiments::studies())
      std::cout << st.name << "\t" << st.description << "\n";
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("write error on standard output");
    return 0;
  }
  const bool merge = !pos.empty() && pos[0] == "merge";
  if (pos.size() < (merge ? 3u : 1u) || (!merge && pos.size() != 1))
    throw InputError(merge
                         ? "usage: hrspace experiment merge STUDY|all --out DIR SHARD_DIR..."
                         : "usage: hrspace experiment STUDY|all --out DIR [options] (see --help)");
  const experiments::StudyConfig config = study_config(args);
  return merge ? merge_command(args, config) : run_command(args, config);
}

}  // namespace hrs::cli
