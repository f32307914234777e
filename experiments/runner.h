// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The experiments runner: executes a study's runs (resumable, parallel,
// sharded), stores each run as it finishes and writes the study's tables.
//
// - Identified: a run's row holds its key, its parameters and its identity
//   (run_identity: the code's version and commit, the sweep's options
//   iterations, threads and quick, the digests of the scenes it reads and its
//   planner's switches), so two rows with the same identity come from the
//   same computation and rows that differ can be told apart.
// - Resumable: a run whose file DIR/S/runs/KEY.csv holds the same key,
//   parameters and identity is skipped. Before any run starts, every stored
//   run of the study is checked; one that differs (another --iterations, an
//   edited scene, another commit) is refused (hrs::InputError naming the
//   file, the column and both values) rather than mixed into the tables or
//   silently replaced. A run is written (atomically) only when it completed,
//   so a killed sweep loses at most the runs in flight.
// - Parallel: `jobs` runs at once on threads of this process.
// - Sharded: shard i of n takes the runs whose index in the study's run list
//   is ≡ i − 1 (mod n): deterministic, disjoint, and their union is the
//   whole list. merge_shards() copies the shards' run files into one root
//   and writes the tables from them; shards whose identities differ are
//   refused.
// - Deterministic: a run is a pure function of its parameters and identity
//   (designs are seeded and independent of thread counts), so a re-run
//   writes the same rows apart from timing columns (is_timing_column) and
//   the environment columns (commit, cpu, cores).
// - Errors: unusable stored results (a directory or a malformed file where a
//   run file is expected, a run file whose key cell is not its file name, a
//   different identity) are hrs::InputError (exit 2); failed writes (a full
//   disk, an unwritable directory) are hrs::OutputError naming the path and
//   the system's reason (exit 1).

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "experiments/study.h"
#include "geometry/pose.h"
#include "geometry/scene.h"

namespace hrs::experiments {

//! Baseline layout sequences of design runs, keyed by (room, seed,
//! iterations), kept on disk under DIR/recordings/ and computed once per
//! process when missing (jobs that need the same one wait for it).
class Recordings {
 public:
  explicit Recordings(std::filesystem::path dir) : dir_(std::move(dir)) {}
  using Layouts = std::vector<std::vector<geometry::Pose2>>;
  //! The layouts the baseline design of `scene` planned with this seed and
  //! iteration count; `record` computes them when they are not stored yet.
  Layouts get(const std::string& room, std::uint64_t seed, int iterations,
              const std::function<Layouts()>& record);
  //! Stores layouts a caller recorded anyway (a baseline design run).
  void put(const std::string& room, std::uint64_t seed, int iterations, const Layouts& layouts);

 private:
  std::filesystem::path path(const std::string& room, std::uint64_t seed, int iterations) const;
  //! The lock of one recording file (made on first use).
  std::shared_ptr<std::mutex> file_lock(const std::filesystem::path& file);
  //! Writes a recording (atomically); the caller holds its file_lock().
  void store(const std::filesystem::path& file, const Layouts& layouts);
  std::filesystem::path dir_;
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<std::mutex>> busy_;
};

struct RunnerOptions {
  int jobs = 1;
  int shard_index = 1;  //!< 1-based
  int shard_count = 1;
  bool progress = false;  //!< progress bar and ETA on stderr
  const std::atomic<bool>* stop = nullptr;
};

struct RunnerReport {
  int total = 0;     //!< runs of the study
  int in_shard = 0;  //!< of them in this shard
  int skipped = 0;   //!< already stored
  int done = 0;      //!< run and stored now
  int failed = 0;
  int missing = 0;  //!< runs of the whole study with no stored result
  bool stopped = false;
  std::vector<std::string> errors;  //!< "KEY: message" per failed run
};

//! The runs of shard `index` (1-based) of `count`.
std::vector<RunSpec> select_shard(const std::vector<RunSpec>& runs, int index, int count);

//! Runs the study's runs of this shard that are not stored yet, then writes
//! its tables (write_tables).
RunnerReport run_study(const Study& study, const StudyConfig& config, const RunnerOptions& options);

//! Writes runs.csv, summary.csv and the extra tables from the stored runs.
//! Returns how many runs of the study have no stored result.
int write_tables(const Study& study, const StudyConfig& config);

//! Copies the run files of `study` from each shard root into config.out and
//! writes the tables. Every run file of the shards and of config.out must
//! carry its key as its file name and the same sweep columns, each scene
//! digest must be the same for the same room and planner switches the same
//! for the same planner, and a run stored by two shards must be the same run;
//! else hrs::InputError naming both files and the column, before anything is
//! copied.
int merge_shards(const Study& study, const StudyConfig& config,
                 const std::vector<std::filesystem::path>& shard_roots);

//! Columns that describe the machine (added to every run row): cpu, cores.
Row environment_cells();

//! FNV-1a 64 of a file's bytes, 16 hex digits; hrs::InputError naming the
//! path when it is missing, a directory or unreadable.
std::string file_digest(const std::filesystem::path& path);

//! The code that computes runs: the project version and the git commit
//! (HRSPACE_COMMIT when set, else the source tree's HEAD, "-dirty" when it
//! has uncommitted changes, "unknown" outside a checkout).
const std::string& code_version();
const std::string& code_commit();

//! Identity columns that every run of one sweep shares: version, commit,
//! iterations, threads, quick. Shards of one sweep differ in nothing else.
const std::vector<std::string>& sweep_columns();

//! Everything besides its parameters that determines a run: the sweep
//! columns, then the study's own (Study::identity: scene digests, planner
//! switches). Throws hrs::InputError when a scene the run reads is missing.
Row run_identity(const Study& study, const RunSpec& spec, const StudyConfig& config);

//! Columns measured by the clock, which differ between re-runs: names ending
//! in `_s` or `_ms` (times) or `_share` (ratios of times).
bool is_timing_column(const std::string& name);
//! Columns that describe where a run ran (commit, cpu, cores): left out when
//! re-runs are compared cell by cell (the commit is still checked as part of
//! the identity).
bool is_environment_column(const std::string& name);

}  // namespace hrs::experiments
