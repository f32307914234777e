// SPDX-License-Identifier: GPL-3.0-or-later
#include "experiments/runner.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
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
  fs::create_directories(dir_);
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

Row environment_cells(int threads) {
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
  static const std::string cpu = cpu_model();
  Row r;
  r.set("version", std::string(hrs::version()));
  r.set("commit", commit);
  r.set("cpu", cpu);
  r.set("threads", threads);
  r.set("cores", static_cast<long>(std::thread::hardware_concurrency()));
  return r;
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

std::string format_clock(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

//! Stores one finished run: its extra tables first, the run row last, so the
//! row's presence means the run is complete.
void store_run(const fs::path& study_dir, const RunSpec& spec, const RunOutput& out,
               const StudyConfig& config, const std::string& study) {
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
  row.merge(out.measures);
  row.merge(environment_cells(config.threads));
  std::string tables;
  for (const auto& [name, table] : out.tables) tables += (tables.empty() ? "" : ";") + name;
  row.set("tables", tables);
  write_text_atomic(run_file(study_dir, spec.key), to_csv({row}));
}

}  // namespace

namespace {

//! A progress bar with elapsed time and ETA on stderr (a terminal only).
class ProgressBar {
 public:
  ProgressBar(bool on, std::string name, int total)
      : on_(on), name_(std::move(name)), total_(total), t0_(std::chrono::steady_clock::now()) {}
  void show(int finished, const std::string& last) const {
    if (!on_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const double eta = finished > 0 ? elapsed / finished * (total_ - finished) : 0.0;
    constexpr int kWidth = 30;
    const int filled = total_ > 0 ? kWidth * finished / total_ : kWidth;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    char line[256];
    std::snprintf(line, sizeof line, "\r\033[K%s [%s] %d/%d  %s  ETA %s  %s", name_.c_str(),
                  bar.c_str(), finished, total_, format_clock(elapsed).c_str(),
                  finished > 0 ? format_clock(eta).c_str() : "?", last.c_str());
    std::cerr << line << std::flush;
  }
  void clear() const {
    if (on_) std::cerr << "\r\033[K" << std::flush;
  }

 private:
  bool on_;
  std::string name_;
  int total_;
  std::chrono::steady_clock::time_point t0_;
};

//! Creates the study's directories and fails now, not after hours of work,
//! when they are not writable.
void prepare_study_dir(const fs::path& study_dir) {
  std::error_code ec;
  fs::create_directories(study_dir / "runs", ec);
  if (ec) throw InputError(study_dir.string() + ": cannot create directory: " + ec.message());
  write_text_atomic(study_dir / ".writable", "");
  fs::remove(study_dir / ".writable", ec);
}

//! The runs of `runs` with no stored result yet; the others count as skipped.
std::vector<const RunSpec*> runs_not_stored(const fs::path& study_dir,
                                            const std::vector<RunSpec>& runs, int& skipped) {
  std::vector<const RunSpec*> todo;
  for (const RunSpec& r : runs) {
    if (fs::exists(run_file(study_dir, r.key)))
      ++skipped;
    else
      todo.push_back(&r);
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
           const RunnerOptions& options, const std::vector<const RunSpec*>& todo,
           Recordings& recordings, const ProgressBar& progress, RunnerReport& report)
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
      if (!run_one(*todo_[k])) return;
    }
  }

 private:
  //! Runs and stores one run; false when it was stopped (the worker ends).
  bool run_one(const RunSpec& spec) {
    RunContext context{config_, study_dir_, options_.stop, &recordings_};
    try {
      const RunOutput out = study_.run(spec, context);
      if (out.stopped) {
        std::lock_guard lock(report_mutex_);
        report_.stopped = true;
        return false;
      }
      store_run(study_dir_, spec, out, config_, study_.name);
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
  const std::vector<const RunSpec*>& todo_;
  Recordings& recordings_;
  const ProgressBar& progress_;
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
  prepare_study_dir(study_dir);
  const std::vector<RunSpec> all = study.runs(config);
  const std::vector<RunSpec> mine = select_shard(all, options.shard_index, options.shard_count);
  RunnerReport report;
  report.total = static_cast<int>(all.size());
  report.in_shard = static_cast<int>(mine.size());
  const std::vector<const RunSpec*> todo = runs_not_stored(study_dir, mine, report.skipped);

  Recordings recordings(config.out / "recordings");
  const ProgressBar progress(options.progress, study.name, static_cast<int>(todo.size()));
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
    Table one = parse_csv(read_text(file), file.string());
    if (one.size() != 1) throw InputError(file.string() + ": expected one run row");
    const std::string names = one[0].get("tables").value_or("");
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
    rows.push_back(std::move(one[0]));
  }
  write_text_atomic(study_dir / "runs.csv", to_csv(rows));
  write_text_atomic(study_dir / "summary.csv", to_csv(study.summarize(rows)));
  for (const auto& name : table_order)
    write_text_atomic(study_dir / (name + ".csv"), to_csv(tables[name]));
  return missing;
}

int merge_shards(const Study& study, const StudyConfig& config,
                 const std::vector<fs::path>& shard_roots) {
  const fs::path study_dir = config.out / study.name;
  std::error_code ec;
  fs::create_directories(study_dir / "runs", ec);
  if (ec) throw InputError(study_dir.string() + ": cannot create directory: " + ec.message());
  for (const fs::path& root : shard_roots) {
    const fs::path runs = root / study.name / "runs";
    if (!fs::is_directory(runs))
      throw InputError(root.string() + ": no results of study '" + study.name + "' (" +
                       runs.string() + " missing)");
    if (fs::equivalent(runs, study_dir / "runs", ec)) continue;
    for (const auto& entry : fs::directory_iterator(runs)) {
      const fs::path name = entry.path().filename();
      if (entry.path().extension() != ".csv" || name.string().find(".tmp.") != std::string::npos)
        continue;
      const fs::path dst = study_dir / "runs" / name;
      const std::string text = read_text(entry.path());
      if (fs::exists(dst)) {
        // The same run in two shards: keep one, after checking it is the same run.
        const Table a = parse_csv(text, entry.path().string());
        const Table b = parse_csv(read_text(dst), dst.string());
        if (!a.empty() && !b.empty() && a[0].get("key") && a[0].get("key") == b[0].get("key")) {
          for (const auto& [col, value] : a[0].cells()) {
            if (is_timing_column(col) || is_environment_column(col)) continue;
            if (b[0].get(col) != value)
              throw InputError(entry.path().string() + ": differs from " + dst.string() +
                               " in column '" + col + "'");
          }
        }
        continue;
      }
      write_text_atomic(dst, text);
    }
    // Designs and recordings the shard kept for figures.
    for (const char* sub : {"designs"}) {
      const fs::path from = root / study.name / sub;
      if (fs::is_directory(from))
        fs::copy(from, study_dir / sub,
                 fs::copy_options::recursive | fs::copy_options::skip_existing, ec);
    }
  }
  return write_tables(study, config);
}

}  // namespace hrs::experiments
