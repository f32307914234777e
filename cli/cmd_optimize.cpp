// SPDX-License-Identifier: GPL-3.0-or-later
// `hrspace design`: the layout optimizer of paper §III (optimize/design.h)
// with its outputs (optimize/design_io.h), a progress bar on a terminal and
// Ctrl-C, SIGTERM or SIGHUP writing the best design so far (exit 128 + the
// signal's number; nothing is written when the signal comes before the first
// iteration, e.g. during a long sequence enumeration).

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <functional>
#include <iostream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "access/accessibility.h"
#include "api/design_request.h"
#include "api/operations.h"
#include "api/progress.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "geometry/error.h"
#include "geometry/scene.h"
#include "io/files.h"
#include "optimize/design.h"
#include "optimize/design_io.h"
#include "planning/reuse.h"

namespace hrs::cli {

namespace {

// Set by the signal handler; a signal handler can only reach a static.
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};  //!< the first stop signal received

//! The signals that ask for a clean stop.
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

// The first stop signal asks for a clean stop; a second one ends the process
// at once (that signal's default action), for when an iteration takes too long.
extern "C" void on_design_stop_signal(int sig) {
  int none = 0;
  g_signal.compare_exchange_strong(none, sig);
  if (g_interrupted.exchange(true)) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

//! Removes outputs of an earlier run in `out` that this run did not write:
//! with several designs (`multi`), numbered design directories beyond `keep`
//! and the files of a single design; with one, all numbered design
//! directories and the contact sheet. Only hrspace's own file names are
//! removed; a numbered directory holding anything else is refused
//! (InputError). `dry_run` only checks. Returns the number of stale outputs.
int remove_stale_outputs(const std::filesystem::path& out, bool multi, long keep, bool dry_run) {
  namespace fs = std::filesystem;
  // The design's own files and the front end's (accessibility.json, design.html).
  std::vector<std::string> names = optimize::design_file_names();
  for (const std::string& n : api::extra_file_names()) names.push_back(n);
  std::vector<fs::path> stale;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.size() > 9 || !std::all_of(name.begin(), name.end(), ::isdigit))
      continue;
    if (!entry.is_directory(ec)) continue;
    const long k = std::stol(name);
    if (multi && k >= 1 && k <= keep && name == std::to_string(k)) continue;
    for (const auto& inner : fs::directory_iterator(entry.path(), ec)) {
      const std::string f = inner.path().filename().string();
      if (std::find(names.begin(), names.end(), f) == names.end() && f.rfind(".", 0) != 0) {
        throw InputError(entry.path().string() + ": holds " + f +
                         ", not an output of hrspace design; remove it or choose another --out");
      }
    }
    stale.push_back(entry.path());
  }
  if (multi) {
    for (const auto& n : names)
      if (fs::exists(out / n, ec)) stale.push_back(out / n);
  } else if (fs::exists(out / "contact_sheet.svg", ec)) {
    stale.push_back(out / "contact_sheet.svg");
  }
  if (!dry_run) {
    for (const auto& p : stale) {
      fs::remove_all(p, ec);
      if (ec) throw OutputError(p.string() + ": cannot remove stale output: " + ec.message());
    }
  }
  return static_cast<int>(stale.size());
}

constexpr const char* kDesignUsageHead =
    "hrspace design SCENE --out DIR [--seed N] [--iterations N] [--designs K] [--threads T]\n"
    "                     [--planner PRESET[,ITEM...]] [--reuse LIST] [--weights W]\n"
    "                     [--disable LIST] [--rules ada|iso] [--access-goal N] [--restarts R]\n\n"
    "Optimizes the furniture layout of SCENE (paper §III): simulated annealing where every\n"
    "layout is toured by the wheelchair along the M most likely AO-graph sequences.\n"
    "Writes DIR/layout.json (a scene file), DIR/tours.json, DIR/design.svg, DIR/report.json.\n"
    "With --designs K > 1: seeds N..N+K-1 into DIR/1..DIR/K and DIR/contact_sheet.svg.\n\n"
    "  --seed N        first seed (default 1)\n"
    "  --iterations N  annealing iterations (default 700)\n"
    "  --restarts R    annealing chains per design (default 2, up to 100), run side by side\n"
    "                  on the threads; the lowest final cost is kept. Chain 0 has seed N,\n"
    "                  chain r a seed derived from N and r (report.json: restarts.kept_seed;\n"
    "                  --seed S --restarts 1 repeats the chain of seed S alone)\n"
    "  --designs K     number of designs (default 1)\n"
    "  --threads T     tour-planning threads (default: all cores); results do not depend on it\n"
    "  --weights W     override the scene's weights: L,R,C (path length, rotation, clearance)\n"
    "                  or L,R,C,D,A (and interior distance, angle); each finite and >= 0.\n"
    "                  --weights 0,0,0 designs without the wheelchair (paper Fig. 1)\n"
    "  --planner P     a preset (default: default), then optional comma items that turn a\n"
    "                  switch or technique on (NAME), off (-NAME) or set it (NAME=N),\n"
    "                  e.g. --planner baseline,-escape or --planner default,-trees\n";

constexpr const char* kDesignUsageTail =
    "  --reuse LIST    replaces the proposed planner's techniques: all, none or a comma list\n"
    "  --disable LIST  turns design-loop switches off: none or a comma list (ablations)\n"
    "  --rules R       accessibility rule set of accessibility.json: ada (default; 2010 ADA\n"
    "                  Standards) or iso (ISO 21542's 1500 mm turning circle, else ADA)\n"
    "  --access-goal N make the rules a goal: try up to N designs (seeds N0, N0+K, ...,\n"
    "                  K = --designs) and keep the first whose layout passes --rules, else\n"
    "                  the one with the fewest failed checks (report.json: access_goal)\n"
"DIR is created and checked writable before any work. Each file is written to a\n"
    "temporary file and renamed into place once all of a design's files are written.\n"
    "Outputs of an earlier run that this run does not rewrite (numbered design\n"
    "directories beyond K, a stale contact sheet) are removed at the end, with a note.\n"
    "Ctrl-C, SIGTERM or SIGHUP stops after the current iteration, writes the best\n"
    "design so far and exits 128 + the signal (130 for Ctrl-C); a second one quits at once.\n"
    "Before the first iteration (enumerating sequences, generating goal poses) it stops\n"
    "at once and writes nothing.\n";

//! The design's progress (api::ProgressBar) with the best cost so far.
std::function<void(const optimize::DesignStep&)> progress_bar(bool tty, long iterations,
                                                              const std::string& prefix) {
  if (!tty) return {};
  const auto bar = std::make_shared<api::ProgressBar>(
      true, prefix.empty() ? std::string("design") : prefix.substr(0, prefix.size() - 1), iterations);
  return [bar](const optimize::DesignStep& step) {
    char best[64];
    std::snprintf(best, sizeof best, "best %.3f", step.anneal.best_cost);
    bar->show(step.anneal.iteration + 1, best);
  };
}

//! One line per design on stdout.
void print_summary(const std::filesystem::path& dir, const optimize::DesignResult& result) {
  std::printf(
      "%s: cost %.4f -> %.4f, tours found %d/%d, preferences met %d/%d, acceptance %.2f, %.1f s "
      "(planning %.0f%%)%s%s\n",
      dir.string().c_str(), result.initial.total(), result.final.total(), result.final.tours_found,
      result.final.tours_total, result.preferences.met, result.preferences.total,
      result.proposals ? static_cast<double>(result.accepted) / result.proposals : 0.0,
      result.time_total_s,
      result.time_total_s > 0 ? 100.0 * result.time_planning_s / result.time_total_s : 0.0,
      result.valid ? "" : "  WARNING: no valid layout found",
      result.stopped ? "  (interrupted)" : "");
}

//! What one `hrspace design` command asks for: the shared request
//! (api/design_request.h), where its scene and outputs are, and the planner
//! it names.
struct DesignRequest : api::DesignRequest {
  std::string scene_path;  //!< a scene file, or "-" for stdin
  std::string out;
  optimize::PlannerConfig planner_choice;  //!< planner_config(), computed once
};

//! The command's arguments translated into an api::DesignRequest, which
//! checks them (the first bad one is reported, with the same message as
//! from Python).
DesignRequest design_request(const Args& args) {
  args.expect_positional(1, "hrspace design SCENE --out DIR [options] (see --help)");
  const auto out = args.get("out");
  if (!out) throw InputError("--out DIR is required (see --help)");
  DesignRequest r;
  r.out = *out;
  r.planner = args.get_or("planner", "default");
  r.reuse = args.get("reuse");
  r.disable = args.get("disable");
  r.weights = args.get("weights");
  constexpr long kAny = std::numeric_limits<long>::max();
  r.seed = args.integer("seed", 1, -kAny, kAny);
  r.iterations = args.integer("iterations", 700, -kAny, kAny);
  r.designs = args.integer("designs", 1, -kAny, kAny);
  r.rules = args.get_or("rules", "ada");
  r.access_goal = args.integer("access-goal", 1, -kAny, kAny);
  r.restarts = args.integer("restarts", api::kDefaultRestarts, -kAny, kAny);
  r.threads = args.integer("threads", 0, -kAny, kAny);
  r.validate();
  r.planner_choice = r.planner_config();
  r.scene_path = args.positional()[0];
  return r;
}

//! Reads the scene and checks it has sequences to tour, checks --out, then
//! applies --weights: everything that can fail on input, before any work.
geometry::Scene prepare_design(const DesignRequest& r) {
  const std::string& path = r.scene_path;
  geometry::Scene scene =
      path == "-" ? geometry::parse_scene(read_input("-"), "stdin") : geometry::load_scene(path);
  geometry::require_sequences(scene, path == "-" ? "stdin" : path);
  for (const std::string& w : geometry::degree_like_angles(scene, path == "-" ? "stdin" : path))
    std::cerr << "hrspace design: warning: " << w << "\n";
  // The output directory before any work: an unwritable --out loses nothing.
  io::require_writable_directory(r.out);
  remove_stale_outputs(r.out, r.designs > 1, r.designs,
                       true);  // refuses foreign files now, not at the end
  r.apply_weights(scene);
  return scene;
}

//! on_design_stop_signal for the stop signals while designs run; restore()
//! puts back the handlers it replaced.
class StopSignalHandlers {
 public:
  //! Clears any earlier stop and installs the handler.
  void install() {
    g_interrupted.store(false);
    g_signal.store(0);
    struct sigaction action {};
    action.sa_handler = on_design_stop_signal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i)
      sigaction(kStopSignals[i], &action, &previous_[i]);
  }
  void restore() const {
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i)
      sigaction(kStopSignals[i], &previous_[i], nullptr);
  }

 private:
  struct sigaction previous_[std::size(kStopSignals)]{};
};

//! Exit status after a stop signal: 128 + the signal (SIGINT when unknown).
int stop_exit_status() { return 128 + (g_signal.load() ? g_signal.load() : SIGINT); }

//! Where design `d` (from 0) goes: --out itself, or --out/d+1 with several.
std::filesystem::path design_dir(const DesignRequest& r, long d) {
  return r.designs > 1 ? std::filesystem::path(r.out) / std::to_string(d + 1)
                       : std::filesystem::path(r.out);
}

//! Runs design `d` (seed + d), writes its files, keeps its SVG for the
//! contact sheet and prints its summary. True when a stop was requested: the
//! design was written as it stood, or (stopped before its first iteration)
//! nothing was written for it.
bool run_design(const DesignRequest& r, const geometry::Scene& scene, long d, bool tty,
                std::vector<optimize::Picture>& pictures) {
  // The same options as the Python module's design() (api/operations.h).
  optimize::DesignOptions options = r.options(d);
  const auto progress = progress_bar(
      tty, r.iterations, r.designs > 1 ? "design " + std::to_string(d + 1) + " " : std::string());
  api::AccessGoalResult goal;
  try {
    // Try k of design d has seed N + d + k·K, so no two tries share a seed.
    goal = api::design_for_access(scene, options, r.rules, static_cast<int>(r.access_goal),
                                  static_cast<std::uint64_t>(r.designs),
                                  static_cast<int>(r.restarts), &g_interrupted, progress,
                                  [&](int k) {
                                    if (k > 0 && tty) std::cerr << "\r\033[K" << std::flush;
                                    if (k > 0)
                                      std::fprintf(stderr,
                                                   "hrspace design: accessibility goal: try %d "
                                                   "of %lld (seed %llu)\n",
                                                   k + 1, r.access_goal,
                                                   static_cast<unsigned long long>(
                                                       options.seed + k * r.designs));
                                  });
  } catch (const Interrupted&) {
    // Stopped while enumerating the sequences or generating goal poses:
    // there is no design to write (earlier designs of --designs are kept).
    if (tty) std::cerr << "\r\033[K" << std::flush;
    std::fprintf(stderr,
                 "hrspace design: interrupted before the first iteration%s; nothing written%s\n",
                 r.designs > 1 ? (" of design " + std::to_string(d + 1)).c_str() : "",
                 r.designs > 1 ? " for it" : "");
    return true;
  }
  const optimize::DesignResult& result = goal.result;
  options.seed = goal.seed;
  if (tty) std::cerr << "\r\033[K" << std::flush;
  const std::filesystem::path dir = design_dir(r, d);
  optimize::RunInfo info{options.seed, r.planner_choice.name(), static_cast<int>(r.iterations)};
  api::add_goal_sections(goal, info);
  std::string access_line;
  const api::DesignExtras extras = api::attach_extras(result, r.rules, info, &access_line);
  api::write_design_files(result, info, extras, dir);
  pictures.push_back(
      optimize::design_picture(result, api::design_title(result, options.seed)));
  print_summary(dir, result);
  std::printf("%s: %s\n", dir.string().c_str(), access_line.c_str());
  return result.stopped || g_interrupted.load();
}

//! After the designs: the contact sheet of several, then the removal (with a
//! note) of an earlier run's outputs beyond what this run wrote, which would
//! sit beside the new contact sheet unnoticed.
void finish_outputs(const DesignRequest& r, const std::vector<optimize::Picture>& pictures) {
  if (r.designs > 1) {
    io::write_files_atomic(
        {{std::filesystem::path(r.out) / "contact_sheet.svg", optimize::contact_sheet_svg(pictures)}});
  }
  const auto written = static_cast<long>(pictures.size());
  if (const int removed = remove_stale_outputs(r.out, r.designs > 1, written, false)) {
    std::fprintf(stderr, "hrspace design: removed %d stale output(s) of an earlier run in %s\n",
                 removed, r.out.c_str());
  }
}

}  // namespace

int cmd_design(const Argv& argv) {
  const Args args(argv, {"out", "seed", "iterations", "designs", "threads", "planner", "reuse",
                         "weights", "disable", "rules", "access-goal", "restarts"});
  if (args.help()) {
    std::cout << "usage: " << kDesignUsageHead << optimize::PlannerConfig::help()
              << kDesignUsageTail;
    return 0;
  }
  const DesignRequest request = design_request(args);
  const geometry::Scene scene = prepare_design(request);
  // One writer per --out: a second design into it is refused, not mixed in.
  const io::DirectoryLock lock(request.out);
  StopSignalHandlers handlers;
  handlers.install();
  const bool tty = isatty(STDERR_FILENO) != 0;
  std::vector<optimize::Picture> pictures;
  bool interrupted = false;
  for (long d = 0; d < request.designs && !interrupted; ++d)
    interrupted = run_design(request, scene, d, tty, pictures);
  if (pictures.empty()) {  // interrupted before the first design: --out is left as it was
    handlers.restore();
    return stop_exit_status();
  }
  finish_outputs(request, pictures);
  std::fflush(stdout);
  handlers.restore();
  return interrupted ? stop_exit_status() : 0;
}

}  // namespace hrs::cli
