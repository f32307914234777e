// SPDX-License-Identifier: GPL-3.0-or-later
#include "experiments/runner.h"

#include "api/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <thread>

#include "geometry/error.h"
#include "geometry/version.h"

namespace hrs::experiments {

namespace fs = std::filesystem;
using json = nlohmann::json;

// --- recordings -------------------------------------------------------------

fs::path Recordings::path(const std::string& room, std::uint64_t seed, int iterations) const {
  return dir_ / (room + "-s" + std::to_string(seed) + "-i" + std::to_string(iterations) + ".json");
}

namespace {

json layouts_json(const Recordings::Layouts& layouts) {
  json out = json::array();
  for (const auto& poses : layouts) {
    json l = json::array();
    for (const auto& p : poses) l.push_back({p.x, p.y, p.theta});
    out.push_back(std::move(l));
  }
  return out;
}

Recordings::Layouts layouts_from(const json& j) {
  Recordings::Layouts out;
  for (const auto& l : j) {
    std::vector<geometry::Pose2> poses;
    for (const auto& p : l)
      poses.push_back({p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>()});
    out.push_back(std::move(poses));
  }
  return out;
}

}  // namespace

std::shared_ptr<std::mutex> Recordings::file_lock(const fs::path& file) {
  std::lock_guard lock(mutex_);
  auto& slot = busy_[file.string()];
  if (!slot) slot = std::make_shared<std::mutex>();
  return slot;
}

void Recordings::store(const fs::path& file, const Layouts& layouts) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw OutputError(dir_.string() + ": cannot create directory: " + ec.message());
  write_text_atomic(file, layouts_json(layouts).dump() + "\n");
}

Recordings::Layouts Recordings::get(const std::string& room, std::uint64_t seed, int iterations,
                                    const std::function<Layouts()>& record) {
  const fs::path file = path(room, seed, iterations);
  const std::shared_ptr<std::mutex> busy = file_lock(file);
  std::lock_guard lock(*busy);  // one job records, the others wait for its file
  if (fs::exists(file)) {
    try {
      return layouts_from(json::parse(read_text(file)));
    } catch (const json::exception&) {
      // A damaged recording is recorded again below.
    }
  }
  Layouts layouts = record();
  store(file, layouts);
  return layouts;
}

void Recordings::put(const std::string& room, std::uint64_t seed, int iterations,
                     const Layouts& layouts) {
  const fs::path file = path(room, seed, iterations);
  const std::shared_ptr<std::mutex> busy = file_lock(file);
  std::lock_guard lock(*busy);
  if (!fs::exists(file)) store(file, layouts);
}

// --- environment ------------------------------------------------------------

namespace {

std::string first_line_of_command(const std::string& command) {
  std::string out;
  if (std::FILE* p = ::popen(command.c_str(), "r")) {
    char buf[256];
    if (std::fgets(buf, sizeof buf, p)) out = buf;
    ::pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        std::string m = line.substr(colon + 1);
        while (!m.empty() && m.front() == ' ') m.erase(m.begin());
        return m;
      }
    }
  }
  return "unknown";
}

}  // namespace

const std::string& code_commit() {
  static const std::string commit = [] {
    if (const char* c = std::getenv("HRSPACE_COMMIT"); c && *c) return std::string(c);
#ifdef HRSPACE_SOURCE_DIR
    const std::string c = first_line_of_command("git -C '" HRSPACE_SOURCE_DIR
                                                "' rev-parse --short=12 HEAD 2>/dev/null");
    if (!c.empty()) {
      const std::string dirty = first_line_of_command(
          "git -C '" HRSPACE_SOURCE_DIR "' status --porcelain --untracked-files=no 2>/dev/null");
      return dirty.empty() ? c : c + "-dirty";
    }
#endif
    return std::string("unknown");
  }();
  return commit;
}

const std::string& code_version() {
  static const std::string version = hrs::version();
  return version;
}

Row environment_cells() {
  static const std::string cpu = cpu_model();
  Row r;
  r.set("cpu", cpu);
  r.set("cores", static_cast<long>(std::thread::hardware_concurrency()));
  return r;
}

std::string file_digest(const fs::path& path) {
  const std::string bytes = read_text(path);
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a 64: offset basis, prime
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

const std::vector<std::string>& sweep_columns() {
  static const std::vector<std::string> columns = {"version", "commit", "iterations", "threads",
                                                   "quick"};
  return columns;
}

Row run_identity(const Study& study, const RunSpec& spec, const StudyConfig& config) {
  Row id;
  id.set("version", code_version());
  id.set("commit", code_commit());
  id.set("iterations", config.iterations);
  id.set("threads", config.threads);
  id.set("quick", config.quick ? 1L : 0L);
  if (study.identity) id.merge(study.identity(spec, config));
  return id;
}

bool is_timing_column(const std::string& name) {
  return name.ends_with("_s") || name.ends_with("_ms") || name.ends_with("_share");
}

bool is_environment_column(const std::string& name) {
  return name == "version" || name == "commit" || name == "cpu" || name == "cores";
}

// --- running ----------------------------------------------------------------

std::vector<RunSpec> select_shard(const std::vector<RunSpec>& runs, int index, int count) {
  if (count < 1 || index < 1 || index > count)
    throw InputError("--shard " + std::to_string(index) + "/" + std::to_string(count) +
                     ": needs 1 <= i <= n");
  std::vector<RunSpec> out;
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (static_cast<int>(k % count) == index - 1) out.push_back(runs[k]);
  return out;
}

namespace {

fs::path run_file(const fs::path& study_dir, const std::string& key) {
  return study_dir / "runs" / (key + ".csv");
}

fs::path table_file(const fs::path& study_dir, const std::string& key, const std::string& table) {
  return study_dir / "runs" / (key + "." + table + ".csv");
}

//! Stores one finished run: its extra tables first, the run row last, so the
//! row's presence means the run is complete.
void store_run(const fs::path& study_dir, const RunSpec& spec, const Row& identity,
               const RunOutput& out, const std::string& study) {
  for (const auto& [name, table] : out.tables) {
    Table rows;
    for (const Row& t : table) {
      Row r;
      r.set("key", spec.key);
      r.merge(spec.params);
      r.merge(t);
      rows.push_back(std::move(r));
    }
    write_text_atomic(table_file(study_dir, spec.key, name), to_csv(rows));
  }
  Row row;
  row.set("study", study);
  row.set("key", spec.key);
  row.merge(spec.params);
  row.merge(identity);
  row.merge(out.measures);
  row.merge(environment_cells());
  std::string tables;
  for (const auto& [name, table] : out.tables) tables += (tables.empty() ? "" : ";") + name;
  row.set("tables", tables);
  write_text_atomic(run_file(study_dir, spec.key), to_csv({row}));
}

}  // namespace

namespace {

//! Creates the study's directories and fails now, not after hours of work,
//! when they are not writable.
void prepare_study_dir(const fs::path& study_dir) {
  std::error_code ec;
  fs::create_directories(study_dir / "runs", ec);
  if (ec) throw OutputError(study_dir.string() + ": cannot create directory: " + ec.message());
  write_text_atomic(study_dir / ".writable", "");
  fs::remove(study_dir / ".writable", ec);
}

//! A run to do and the identity its row gets.
struct Pending {
  const RunSpec* spec;
  Row identity;
};

//! The one row of the run file `file` of the run `key`: hrs::InputError when
//! the file is unreadable, not one CSV row, or its key cell is not `key`.
Row read_run_row(const fs::path& file, const std::string& key) {
  Table one = parse_csv(read_text(file), file.string());
  if (one.size() != 1)
    throw InputError(file.string() + ": expected one run row, found " + std::to_string(one.size()));
  const std::optional<std::string> stored = one[0].get("key");
  if (stored != key)
    throw InputError(file.string() + ": key cell '" + stored.value_or("") +
                     "' is not the run of this file name ('" + key +
                     "'): a run file renamed or copied by hand");
  return std::move(one[0]);
}

std::string cell_text(const std::optional<std::string>& v) {
  return v ? "'" + *v + "'" : std::string("no such column (stored by an older hrspace)");
}

//! The runs of `runs` with no stored result yet, with their identities; a
//! stored run with the same parameters and identity counts as skipped, one
//! that differs is an InputError naming the file and the column (checked for
//! every run of the study before any starts, so results of two different
//! sweeps are never mixed in one runs.csv).
std::vector<Pending> runs_not_stored(const Study& study, const StudyConfig& config,
                                     const fs::path& study_dir, const std::vector<RunSpec>& all,
                                     const std::vector<RunSpec>& mine, int& skipped) {
  std::map<std::string, Row> identities;
  for (const RunSpec& r : all) {
    Row expected = r.params;
    const Row identity = run_identity(study, r, config);
    expected.merge(identity);
    const fs::path file = run_file(study_dir, r.key);
    std::error_code ec;
    if (fs::exists(file, ec) || fs::is_symlink(file, ec)) {
      if (fs::is_directory(file, ec))
        throw InputError(file.string() + ": is a directory, expected a run file (remove it)");
      const Row stored = read_run_row(file, r.key);
      for (const auto& [column, value] : expected.cells()) {
        const auto have = stored.get(column);
        if (have == value) continue;
        throw InputError(file.string() + ": stored with " + column + " " + cell_text(have) +
                         ", this command asks for " + column + " '" + value +
                         "'; results of different runs are not mixed: use another --out, or "
                         "remove " +
                         study_dir.string() + " to start over");
      }
    }
    identities.emplace(r.key, identity);
  }
  std::vector<Pending> todo;
  for (const RunSpec& r : mine) {
    if (fs::exists(run_file(study_dir, r.key)))
      ++skipped;
    else
      todo.push_back({&r, identities.at(r.key)});
  }
  return todo;
}

//! The runs to do, shared by the runner's workers. Each worker takes the next
//! run not started; a stop request ends the workers after their current run,
//! whose result is dropped when stopped. What became of each run goes to the
//! report.
class RunQueue {
 public:
  RunQueue(const Study& study, const StudyConfig& config, const fs::path& study_dir,
           const RunnerOptions& options, const std::vector<Pending>& todo, Recordings& recordings,
           const api::ProgressBar& progress, RunnerReport& report)
      : study_(study),
        config_(config),
        study_dir_(study_dir),
        options_(options),
        todo_(todo),
        recordings_(recordings),
        progress_(progress),
        report_(report) {}

  //! One worker's loop: until no run is left, a stop is requested or a run stopped.
  void work() {
    for (;;) {
      if (options_.stop && options_.stop->load()) return;
      const std::size_t k = next_.fetch_add(1);
      if (k >= todo_.size()) return;
      if (!run_one(*todo_[k].spec, todo_[k].identity)) return;
    }
  }

 private:
  //! Runs and stores one run; false when it was stopped (the worker ends).
  bool run_one(const RunSpec& spec, const Row& identity) {
    RunContext context{config_, study_dir_, options_.stop, &recordings_};
    try {
      const RunOutput out = study_.run(spec, context);
      if (out.stopped) {
        std::lock_guard lock(report_mutex_);
        report_.stopped = true;
        return false;
      }
      store_run(study_dir_, spec, identity, out, study_.name);
      std::lock_guard lock(report_mutex_);
      ++report_.done;
      progress_.show(report_.done + report_.failed, spec.key);
    } catch (const Interrupted&) {  // stopped before the design's first iteration
      std::lock_guard lock(report_mutex_);
      report_.stopped = true;
      return false;
    } catch (const std::exception& e) {
      std::lock_guard lock(report_mutex_);
      ++report_.failed;
      report_.errors.push_back(spec.key + ": " + e.what());
      progress_.show(report_.done + report_.failed, spec.key + " FAILED");
    }
    return true;
  }

  const Study& study_;
  const StudyConfig& config_;
  const fs::path& study_dir_;
  const RunnerOptions& options_;
  const std::vector<Pending>& todo_;
  Recordings& recordings_;
  const api::ProgressBar& progress_;
  RunnerReport& report_;
  std::atomic<std::size_t> next_{0};
  std::mutex report_mutex_;  //!< guards report_ and progress_
};

//! Runs `work` on `jobs` threads, this one among them, and waits for all.
void run_on_threads(int jobs, const std::function<void()>& work) {
  std::vector<std::thread> pool;
  for (int j = 1; j < jobs; ++j) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

}  // namespace

RunnerReport run_study(const Study& study, const StudyConfig& config,
                       const RunnerOptions& options) {
  const fs::path study_dir = config.out / study.name;
  const std::vector<RunSpec> all = study.runs(config);
  const std::vector<RunSpec> mine = select_shard(all, options.shard_index, options.shard_count);
  RunnerReport report;
  report.total = static_cast<int>(all.size());
  report.in_shard = static_cast<int>(mine.size());
  // The stored runs are checked before anything is written: a refused
  // command leaves DIR as it was.
  const std::vector<Pending> todo =
      runs_not_stored(study, config, study_dir, all, mine, report.skipped);
  prepare_study_dir(study_dir);

  Recordings recordings(config.out / "recordings");
  const api::ProgressBar progress(options.progress, study.name, static_cast<long>(todo.size()));
  progress.show(0, "");
  RunQueue queue(study, config, study_dir, options, todo, recordings, progress, report);
  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(todo.size())));
  run_on_threads(jobs, [&queue] { queue.work(); });
  progress.clear();
  if (options.stop && options.stop->load()) report.stopped = true;
  report.missing = write_tables(study, config);
  return report;
}

int write_tables(const Study& study, const StudyConfig& config) {
  const fs::path study_dir = config.out / study.name;
  const std::vector<RunSpec> all = study.runs(config);
  Table rows;
  std::map<std::string, Table> tables;
  std::vector<std::string> table_order;
  int missing = 0;
  for (const RunSpec& spec : all) {
    const fs::path file = run_file(study_dir, spec.key);
    if (!fs::exists(file)) {
      ++missing;
      continue;
    }
    if (fs::is_directory(file))
      throw InputError(file.string() + ": is a directory, expected a run file (remove it)");
    Row run = read_run_row(file, spec.key);
    const std::string names = run.get("tables").value_or("");
    for (std::size_t start = 0; start < names.size();) {
      const std::size_t end = std::min(names.find(';', start), names.size());
      const std::string name = names.substr(start, end - start);
      start = end + 1;
      if (name.empty()) continue;
      const fs::path tf = table_file(study_dir, spec.key, name);
      Table t = parse_csv(read_text(tf), tf.string());
      if (!tables.count(name)) table_order.push_back(name);
      auto& dst = tables[name];
      for (Row& r : t) dst.push_back(std::move(r));
    }
    rows.push_back(std::move(run));
  }
  write_text_atomic(study_dir / "runs.csv", to_csv(rows));
  // Provenance: each summary row carries the commit of the runs behind it
  // ("mixed" when they differ, which identity checks keep out of one DIR).
  std::string commit;
  for (const Row& r : rows) {
    const std::string c = r.get("commit").value_or("unknown");
    commit = commit.empty() || commit == c ? c : "mixed";
  }
  Table summary = study.summarize(rows);
  for (Row& r : summary) r.set("commit", commit);
  write_text_atomic(study_dir / "summary.csv", to_csv(summary));
  for (const auto& name : table_order)
    write_text_atomic(study_dir / (name + ".csv"), to_csv(tables[name]));
  return missing;
}

namespace {

//! A run file found in a results root, with its row.
struct StoredRun {
  fs::path file;
  Row row;
};

//! Whether `name` is a run or table file of the runner (not a temporary).
bool is_result_file(const fs::path& path) {
  return path.extension() == ".csv" && path.filename().string().find(".tmp.") == std::string::npos;
}

//! The run files under `runs` (a study's runs/ directory): the CSV files
//! whose row has a "study" cell (table files have none), each checked to
//! carry its file name as its key.
std::vector<StoredRun> stored_runs(const fs::path& runs) {
  std::vector<StoredRun> out;
  std::error_code ec;
  if (!fs::is_directory(runs, ec)) return out;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(runs))
    if (is_result_file(entry.path())) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    if (fs::is_directory(file, ec))
      throw InputError(file.string() + ": is a directory, expected a run file (remove it)");
    Table rows = parse_csv(read_text(file), file.string());
    if (rows.size() != 1 || !rows[0].get("study")) continue;  // an extra table
    const std::string stem = file.stem().string();
    if (rows[0].get("key") != stem)
      throw InputError(file.string() + ": key cell '" + rows[0].get("key").value_or("") +
                       "' is not the run of this file name ('" + stem +
                       "'): a run file renamed or copied by hand");
    out.push_back({file, std::move(rows[0])});
  }
  return out;
}

//! Identity columns that are the same for every run of one value of a
//! parameter: the scene digest of a room, the switches of a planner.
struct ScopedColumn {
  const char* column;
  const char* scope;
};
constexpr ScopedColumn kScopedColumns[] = {
    {"scene_digest", "room"}, {"planner_config", "planner"}};

//! Refuses run files that cannot come from one sweep: sweep columns that
//! differ, scoped identity columns that differ for the same scope value.
void check_one_sweep(const std::vector<StoredRun>& runs) {
  if (runs.empty()) return;
  const StoredRun& first = runs.front();
  auto refuse = [](const StoredRun& a, const StoredRun& b, const std::string& column) {
    throw InputError("merge: " + a.file.string() + " has " + column + " " +
                     cell_text(a.row.get(column)) + ", " + b.file.string() + " has " + column +
                     " " + cell_text(b.row.get(column)) +
                     ": shards of one sweep differ in nothing but --shard (run the odd shard "
                     "again with the others' options, or merge into another --out)");
  };
  for (const StoredRun& r : runs)
    for (const std::string& column : sweep_columns())
      if (r.row.get(column) != first.row.get(column)) refuse(first, r, column);
  for (const auto& [column, scope] : kScopedColumns) {
    std::map<std::string, const StoredRun*> seen;
    for (const StoredRun& r : runs) {
      const auto value = r.row.get(scope);
      if (!value || !r.row.get(column)) continue;
      const auto [it, fresh] = seen.emplace(*value, &r);
      if (!fresh && it->second->row.get(column) != r.row.get(column))
        refuse(*it->second, r, column);
    }
  }
}

}  // namespace

int merge_shards(const Study& study, const StudyConfig& config,
                 const std::vector<fs::path>& shard_roots) {
  const fs::path study_dir = config.out / study.name;
  std::error_code ec;
  // Check everything before writing anything: the runs already merged here
  // and every shard's.
  std::vector<StoredRun> all = stored_runs(study_dir / "runs");
  std::vector<fs::path> shard_runs;
  for (const fs::path& root : shard_roots) {
    const fs::path runs = root / study.name / "runs";
    if (!fs::is_directory(runs))
      throw InputError(root.string() + ": no results of study '" + study.name + "' (" +
                       runs.string() + " missing)");
    if (fs::equivalent(runs, study_dir / "runs", ec)) continue;
    shard_runs.push_back(runs);
    for (StoredRun& r : stored_runs(runs)) all.push_back(std::move(r));
  }
  check_one_sweep(all);
  fs::create_directories(study_dir / "runs", ec);
  if (ec) throw OutputError(study_dir.string() + ": cannot create directory: " + ec.message());
  // The same run in two places must be the same run.
  std::map<std::string, const StoredRun*> by_key;
  for (const StoredRun& r : all) {
    const auto [it, fresh] = by_key.emplace(r.file.filename().string(), &r);
    if (fresh) continue;
    for (const auto& [col, value] : r.row.cells()) {
      if (is_timing_column(col) || is_environment_column(col)) continue;
      if (it->second->row.get(col) != value)
        throw InputError("merge: " + r.file.string() + " differs from " +
                         it->second->file.string() + " in column '" + col + "'");
    }
  }
  for (const fs::path& runs : shard_runs) {
    for (const auto& entry : fs::directory_iterator(runs)) {
      if (!is_result_file(entry.path())) continue;
      const fs::path dst = study_dir / "runs" / entry.path().filename();
      if (fs::exists(dst)) continue;  // checked above when it is a run file
      write_text_atomic(dst, read_text(entry.path()));
    }
    // Designs the shard kept for figures.
    const fs::path from = runs.parent_path() / "designs";
    if (fs::is_directory(from)) {
      fs::copy(from, study_dir / "designs",
               fs::copy_options::recursive | fs::copy_options::skip_existing, ec);
      if (ec)
        throw OutputError((study_dir / "designs").string() + ": cannot copy designs from " +
                          from.string() + ": " + ec.message());
    }
  }
  return write_tables(study, config);
}

}  // namespace hrs::experiments
