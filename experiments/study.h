// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A study of the experiments harness: one experiment of the paper's §VI (or
// one of its figures), defined as a list of runs, each a pure function of
// its parameters, and a summary of the runs. The runner (runner.h) executes
// the runs, stores each under its key, and writes the study's tables.
//
// Output of study S under the root DIR:
//   DIR/S/runs/KEY.csv          one run: its parameters, identity and measures (one row)
//   DIR/S/runs/KEY.TABLE.csv    the run's extra tables (histograms, samples)
//   DIR/S/runs.csv              every stored run, in the study's run order
//   DIR/S/summary.csv           mean, sd and n per group, with ratios
//   DIR/S/TABLE.csv             each extra table over every stored run
//   DIR/S/designs/KEY/          designs the study keeps for its figures
//   DIR/recordings/             baseline layout sequences for replays

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "experiments/table.h"

namespace hrs::experiments {

//! What a study is asked for (`hrspace experiment` options).
struct StudyConfig {
  int seeds = 10;                    //!< seeds 1..seeds
  int iterations = 700;              //!< annealing iterations per design (paper: 700)
  int threads = 1;                   //!< tour-planning threads per design
  bool quick = false;                //!< the smallest sweep that exercises every output
  std::vector<std::string> rooms;    //!< overrides the study's rooms (names or .json paths)
  std::filesystem::path scenes_dir;  //!< where room names are looked up
  std::filesystem::path out;         //!< root output directory
  std::uint64_t zoo_seed = 1;        //!< generalization: seed of the room zoo
  int zoo_rooms = 20;                //!< generalization: rooms per object-count bucket
};

//! The scene file of a room: a .json path as given, else
//! config.scenes_dir/ROOM.json.
std::filesystem::path scene_path(const StudyConfig& config, const std::string& room);

//! One run: a key (unique in its study, safe as a file name) and its parameters.
struct RunSpec {
  std::string key;
  Row params;
};

class Recordings;

//! What a run may use besides its parameters.
struct RunContext {
  const StudyConfig& config;
  std::filesystem::path study_dir;
  const std::atomic<bool>* stop = nullptr;  //!< set on SIGINT/SIGTERM/SIGHUP
  Recordings* recordings = nullptr;
};

struct RunOutput {
  Row measures;
  std::vector<std::pair<std::string, Table>> tables;  //!< extra tables, by name
  bool stopped = false;                               //!< interrupted: not stored
};

struct Study {
  std::string name;
  std::string paper;        //!< the paper item it regenerates
  std::string description;  //!< one line for --help
  std::function<std::vector<RunSpec>(const StudyConfig&)> runs;
  std::function<RunOutput(const RunSpec&, RunContext&)> run;
  //! summary.csv from the stored runs (in run order).
  std::function<Table(const Table& runs)> summarize;
  //! What determines a run besides its parameters and the sweep's options
  //! (runner.h run_identity): digests of the scenes it reads, the switches
  //! of its planner. Optional; studies() sets it for every study.
  std::function<Row(const RunSpec&, const StudyConfig&)> identity = {};
};

//! Every study, in the order `scripts/reproduce.sh` runs them.
const std::vector<Study>& studies();
//! The study called `name`, or nullptr.
const Study* find_study(const std::string& name);

}  // namespace hrs::experiments
