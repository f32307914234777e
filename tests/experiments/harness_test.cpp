// SPDX-License-Identifier: GPL-3.0-or-later
// The experiments harness (experiments/): CSV tables, aggregation against
// hand-computed values, shard selection, and the runner's resume and
// shard/merge behaviour on a small synthetic study whose runs are pure
// functions of their parameters.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <random>
#include <set>
#include <string>

#include "experiments/runner.h"
#include "experiments/studies_shared.h"
#include "experiments/stats.h"
#include "experiments/study.h"
#include "experiments/table.h"
#include "geometry/error.h"
#include "optimize/planner_config.h"

namespace {

namespace fs = std::filesystem;
using namespace hrs::experiments;

fs::path temp_dir(const std::string& name) {
  const fs::path p =
      fs::temp_directory_path() / ("hrspace_harness_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

TEST(Table, CsvRoundTripKeepsEveryCellOfRandomTables) {
  std::mt19937_64 rng(7);
  const std::string alphabet = "ab,\"\n\r 1.-x";
  for (int t = 0; t < 2000; ++t) {
    Table rows;
    const int n_rows = static_cast<int>(rng() % 5) + 1, n_cols = static_cast<int>(rng() % 4) + 1;
    for (int r = 0; r < n_rows; ++r) {
      Row row;
      for (int c = 0; c < n_cols; ++c) {
        std::string cell;
        const int len = static_cast<int>(rng() % 6);
        for (int k = 0; k < len; ++k) cell += alphabet[rng() % alphabet.size()];
        row.set("c" + std::to_string(c), cell);
      }
      rows.push_back(row);
    }
    const Table back = parse_csv(to_csv(rows), "t");
    ASSERT_EQ(back.size(), rows.size()) << to_csv(rows);
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (const auto& [name, value] : rows[r].cells())
        ASSERT_EQ(back[r].get(name).value_or("<missing>"), value) << to_csv(rows);
  }
}

TEST(Table, MalformedCsvIsAnInputErrorNamingTheRecord) {
  EXPECT_THROW(parse_csv("a,b\n\"1,2\n", "f.csv"), hrs::InputError);
  try {
    parse_csv("a,b\n1,2\n3\n", "f.csv");
    FAIL() << "a short record was accepted";
  } catch (const hrs::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.csv: record 3"), std::string::npos) << e.what();
  }
}

TEST(Table, FormatDoubleReadsBackExactly) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 10000; ++i) {
    const double v = u(rng) * std::pow(10.0, static_cast<int>(rng() % 20) - 10);
    Row r;
    r.set("v", v);
    ASSERT_EQ(*r.number("v"), v);
  }
}

TEST(Stats, SummaryMatchesHandComputedValues) {
  const Summary s = summarize({1.0, 2.0, 3.0, 4.0});
  EXPECT_EQ(s.n, 4);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.sd, std::sqrt(5.0 / 3.0), 1e-15);  // Σ(x − 2.5)² = 5, n − 1 = 3
  const Summary one = summarize({7.0});
  EXPECT_EQ(one.n, 1);
  EXPECT_EQ(one.sd, 0.0);
  const Summary with_nan = summarize({1.0, std::nan(""), 3.0});
  EXPECT_EQ(with_nan.n, 2);
  EXPECT_DOUBLE_EQ(with_nan.mean, 2.0);
  EXPECT_NEAR(with_nan.sd, std::sqrt(2.0), 1e-15);
}

Table sample_runs() {
  Table rows;
  auto add = [&](const char* room, const char* planner, double t, double cost) {
    Row r;
    r.set("room", room);
    r.set("planner", planner);
    r.set("planning_s", t);
    r.set("cost", cost);
    rows.push_back(r);
  };
  add("a", "baseline", 10, 1);
  add("a", "baseline", 14, 3);
  add("a", "fast", 2, 2);
  add("a", "fast", 3, 2);
  add("b", "baseline", 6, 5);
  add("b", "fast", 4, 5);
  return rows;
}

TEST(Stats, GroupsAndRatiosMatchHandComputedValues) {
  Table s = summarize_table(sample_runs(), {"room", "planner"}, {"planning_s", "cost", "absent"});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(*s[0].get("room"), "a");
  EXPECT_EQ(*s[0].get("planner"), "baseline");
  EXPECT_EQ(*s[0].number("n"), 2);
  EXPECT_DOUBLE_EQ(*s[0].number("planning_s_mean"), 12.0);
  EXPECT_NEAR(*s[0].number("planning_s_sd"), std::sqrt(8.0), 1e-12);  // (4 + 4) / 1
  EXPECT_FALSE(s[0].get("absent_mean").has_value());
  add_ratio(s, "planner", "baseline", {"room"}, "planning_s");
  EXPECT_DOUBLE_EQ(*s[0].number("planning_s_ratio_vs_baseline"), 1.0);
  EXPECT_DOUBLE_EQ(*s[1].number("planning_s_ratio_vs_baseline"), 12.0 / 2.5);
  EXPECT_DOUBLE_EQ(*s[3].number("planning_s_ratio_vs_baseline"), 6.0 / 4.0);
}

TEST(Runner, ShardsPartitionTheRunListForAnySizeAndCount) {
  for (int size = 0; size < 40; ++size) {
    std::vector<RunSpec> runs(size);
    for (int i = 0; i < size; ++i) runs[i].key = "k" + std::to_string(i);
    for (int n = 1; n <= 12; ++n) {
      std::multiset<std::string> seen;
      for (int i = 1; i <= n; ++i)
        for (const auto& r : select_shard(runs, i, n)) seen.insert(r.key);
      ASSERT_EQ(seen.size(), runs.size());
      for (const auto& r : runs) ASSERT_EQ(seen.count(r.key), 1u) << r.key;
    }
  }
  EXPECT_THROW(select_shard({}, 0, 3), hrs::InputError);
  EXPECT_THROW(select_shard({}, 4, 3), hrs::InputError);
}

//! A study of 11 runs; each run's measures are a pure function of its
//! parameters, plus a timing column that differs from run to run.
Study synthetic_study(std::atomic<int>* executed) {
  Study s;
  s.name = "synthetic";
  s.runs = [](const StudyConfig& c) {
    std::vector<RunSpec> runs;
    for (int seed = 1; seed <= c.seeds; ++seed)
      for (const char* p : {"x", "y"}) {
        RunSpec r;
        r.key = std::string("synthetic-") + p + "-s" + std::to_string(seed);
        r.params.set("planner", std::string(p));
        r.params.set("seed", static_cast<long>(seed));
        runs.push_back(r);
      }
    return runs;
  };
  s.run = [executed](const RunSpec& spec, RunContext&) {
    ++*executed;
    RunOutput out;
    const double seed = *spec.params.number("seed");
    std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 31 + (*spec.params.get("planner"))[0]);
    out.measures.set("cost", std::uniform_real_distribution<double>(0, 1)(rng));
    static std::atomic<int> clock{0};
    out.measures.set("work_s", static_cast<double>(++clock));
    Table h;
    for (int i = 0; i < 3; ++i) {
      Row r;
      r.set("bin", static_cast<long>(i));
      r.set("count", static_cast<long>(seed * 10 + i));
      h.push_back(r);
    }
    out.tables.emplace_back("hist", h);
    return out;
  };
  s.summarize = [](const Table& runs) { return summarize_table(runs, {"planner"}, {"cost"}); };
  return s;
}

//! runs.csv rows without timing and environment columns.
std::vector<std::string> comparable_rows(const fs::path& file) {
  std::vector<std::string> out;
  for (const Row& r : parse_csv(read_text(file), file.string())) {
    std::string line;
    for (const auto& [name, value] : r.cells()) {
      if (is_timing_column(name) || is_environment_column(name)) continue;
      line += name + "=" + value + ";";
    }
    out.push_back(line);
  }
  return out;
}

TEST(Runner, MergedShardsEqualTheWholeRun) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 5;  // 10 runs: shards of 4, 3, 3
  config.out = temp_dir("whole");
  RunnerOptions whole;
  whole.jobs = 2;
  EXPECT_EQ(run_study(study, config, whole).done, 10);
  std::vector<fs::path> shards;
  for (int i = 1; i <= 3; ++i) {
    StudyConfig c = config;
    c.out = temp_dir("shard" + std::to_string(i));
    RunnerOptions o;
    o.shard_index = i;
    o.shard_count = 3;
    const RunnerReport r = run_study(study, c, o);
    EXPECT_EQ(r.in_shard, i == 1 ? 4 : 3);
    EXPECT_EQ(r.missing, 10 - r.in_shard);
    shards.push_back(c.out);
  }
  StudyConfig merged = config;
  merged.out = temp_dir("merged");
  EXPECT_EQ(merge_shards(study, merged, shards), 0);
  const auto a = comparable_rows(config.out / "synthetic" / "runs.csv");
  const auto b = comparable_rows(merged.out / "synthetic" / "runs.csv");
  ASSERT_EQ(a.size(), 10u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(comparable_rows(config.out / "synthetic" / "hist.csv"),
            comparable_rows(merged.out / "synthetic" / "hist.csv"));
  EXPECT_EQ(read_text(config.out / "synthetic" / "summary.csv"),
            read_text(merged.out / "synthetic" / "summary.csv"));
  for (const auto& p : shards) fs::remove_all(p);
  fs::remove_all(config.out);
  fs::remove_all(merged.out);
}

TEST(Runner, ARerunSkipsStoredRunsAndRedoesOnlyMissingOnes) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 3;
  config.out = temp_dir("resume");
  EXPECT_EQ(run_study(study, config, {}).done, 6);
  const auto first = comparable_rows(config.out / "synthetic" / "runs.csv");
  executed = 0;
  const RunnerReport again = run_study(study, config, {});
  EXPECT_EQ(again.skipped, 6);
  EXPECT_EQ(executed.load(), 0);
  fs::remove(config.out / "synthetic" / "runs" / "synthetic-y-s2.csv");
  const RunnerReport third = run_study(study, config, {});
  EXPECT_EQ(third.done, 1);
  EXPECT_EQ(executed.load(), 1);
  EXPECT_EQ(comparable_rows(config.out / "synthetic" / "runs.csv"), first);
  fs::remove_all(config.out);
}

TEST(Runner, AStoppedRunIsNotStored) {
  std::atomic<int> executed{0};
  Study study = synthetic_study(&executed);
  study.run = [](const RunSpec&, RunContext&) {
    RunOutput out;
    out.stopped = true;
    return out;
  };
  StudyConfig config;
  config.seeds = 2;
  config.out = temp_dir("stopped");
  const RunnerReport r = run_study(study, config, {});
  EXPECT_TRUE(r.stopped);
  EXPECT_EQ(r.done, 0);
  EXPECT_EQ(r.missing, 4);
  EXPECT_TRUE(fs::is_empty(config.out / "synthetic" / "runs"));
  fs::remove_all(config.out);
}

TEST(Runner, AFailingRunIsReportedAndTheOthersAreStored) {
  std::atomic<int> executed{0};
  Study study = synthetic_study(&executed);
  const auto inner = study.run;
  study.run = [inner](const RunSpec& spec, RunContext& c) {
    if (spec.key == "synthetic-x-s2") throw std::runtime_error("boom");
    return inner(spec, c);
  };
  StudyConfig config;
  config.seeds = 2;
  config.out = temp_dir("failing");
  const RunnerReport r = run_study(study, config, {});
  EXPECT_EQ(r.failed, 1);
  EXPECT_EQ(r.done, 3);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0], "synthetic-x-s2: boom");
  fs::remove_all(config.out);
}

// --- results that cannot be mixed (issue 33) ----------------------------------

//! The synthetic study with a room parameter and a Study::identity that
//! digests the room's file, like the real studies' scene_digest.
Study study_with_scenes(std::atomic<int>* executed, const fs::path& scene) {
  Study s = synthetic_study(executed);
  const auto inner = s.runs;
  s.runs = [inner, scene](const StudyConfig& c) {
    std::vector<RunSpec> runs = inner(c);
    for (RunSpec& r : runs) r.params.set("room", scene.string());
    return runs;
  };
  s.identity = [](const RunSpec& spec, const StudyConfig&) {
    Row id;
    id.set("scene_digest", file_digest(*spec.params.get("room")));
    return id;
  };
  return s;
}

//! The message of the hrs::InputError `f` throws; a failure when it throws none.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const hrs::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no hrs::InputError";
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Identity, RunRowsCarryEveryColumnThatDeterminesTheRun) {
  std::atomic<int> executed{0};
  const fs::path dir = temp_dir("columns");
  write_text_atomic(dir / "room.json", "{}");
  const Study study = study_with_scenes(&executed, dir / "room.json");
  StudyConfig config;
  config.seeds = 1;
  config.iterations = 123;
  config.threads = 3;
  config.out = dir / "out";
  ASSERT_EQ(run_study(study, config, {}).done, 2);
  const Table rows = parse_csv(read_text(config.out / "synthetic" / "runs.csv"), "runs.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const Row& r : rows) {
    EXPECT_EQ(r.get("iterations"), "123");
    EXPECT_EQ(r.get("threads"), "3");
    EXPECT_EQ(r.get("quick"), "0");
    EXPECT_EQ(r.get("version"), code_version());
    EXPECT_EQ(r.get("commit"), code_commit());
    EXPECT_EQ(r.get("scene_digest"), file_digest(dir / "room.json"));
  }
  fs::remove_all(dir);
}

TEST(Identity, FileDigestIsFnv1a64OfTheBytes) {
  const fs::path dir = temp_dir("digest");
  write_text_atomic(dir / "empty", "");
  write_text_atomic(dir / "a", "a");
  write_text_atomic(dir / "foobar", "foobar");
  EXPECT_EQ(file_digest(dir / "empty"), "cbf29ce484222325");  // the offset basis
  EXPECT_EQ(file_digest(dir / "a"), "af63dc4c8601ec8c");
  EXPECT_EQ(file_digest(dir / "foobar"), "85944171f73967e8");
  EXPECT_TRUE(contains(input_error([&] { file_digest(dir / "missing"); }), "missing"));
  EXPECT_TRUE(contains(input_error([&] { file_digest(dir); }), "is a directory"));
  fs::remove_all(dir);
}

TEST(Identity, ARerunWithOtherIterationsIsRefusedNamingTheColumn) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 2;
  config.iterations = 100;
  config.out = temp_dir("iterations");
  ASSERT_EQ(run_study(study, config, {}).done, 4);
  const std::string stored = read_text(config.out / "synthetic" / "runs.csv");
  executed = 0;
  StudyConfig other = config;
  other.iterations = 50;
  const std::string what = input_error([&] { run_study(study, other, {}); });
  EXPECT_TRUE(contains(what, "iterations '100'")) << what;
  EXPECT_TRUE(contains(what, "iterations '50'")) << what;
  EXPECT_TRUE(contains(what, "synthetic-x-s1.csv")) << what;
  EXPECT_EQ(executed.load(), 0);
  EXPECT_EQ(read_text(config.out / "synthetic" / "runs.csv"), stored);
  // So is another thread count, or a quick sweep; the same options resume.
  other = config;
  other.threads = 2;
  EXPECT_TRUE(contains(input_error([&] { run_study(study, other, {}); }), "threads"));
  other = config;
  other.quick = true;
  EXPECT_TRUE(contains(input_error([&] { run_study(study, other, {}); }), "quick"));
  EXPECT_EQ(run_study(study, config, {}).skipped, 4);
  EXPECT_EQ(executed.load(), 0);
  fs::remove_all(config.out);
}

TEST(Identity, ARunOfAnotherShardIsCheckedToo) {
  // Shard 2 of 2 into a root where shard 1 ran with other iterations: the
  // tables would mix both, so it is refused before anything runs.
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 2;
  config.iterations = 100;
  config.out = temp_dir("othershard");
  RunnerOptions first;
  first.shard_index = 1;
  first.shard_count = 2;
  ASSERT_EQ(run_study(study, config, first).done, 2);
  StudyConfig other = config;
  other.iterations = 7;
  RunnerOptions second = first;
  second.shard_index = 2;
  executed = 0;
  EXPECT_TRUE(contains(input_error([&] { run_study(study, other, second); }), "iterations"));
  EXPECT_EQ(executed.load(), 0);
  fs::remove_all(config.out);
}

TEST(Identity, AnEditedSceneOfTheSameFileNameIsRefused) {
  std::atomic<int> executed{0};
  const fs::path dir = temp_dir("edited");
  write_text_atomic(dir / "bedroom.json", "{\"v\": 1}\n");
  const Study study = study_with_scenes(&executed, dir / "bedroom.json");
  StudyConfig config;
  config.seeds = 1;
  config.out = dir / "out";
  ASSERT_EQ(run_study(study, config, {}).done, 2);
  EXPECT_EQ(run_study(study, config, {}).skipped, 2);
  write_text_atomic(dir / "bedroom.json", "{\"v\": 2}\n");
  executed = 0;
  const std::string what = input_error([&] { run_study(study, config, {}); });
  EXPECT_TRUE(contains(what, "scene_digest")) << what;
  EXPECT_EQ(executed.load(), 0);
  fs::remove_all(dir);
}

TEST(Identity, RunFilesOfAnOlderHrspaceAreRefused) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 1;
  config.out = temp_dir("older");
  ASSERT_EQ(run_study(study, config, {}).done, 2);
  // The row as hrspace wrote it before runs carried their identity.
  const fs::path file = config.out / "synthetic" / "runs" / "synthetic-y-s1.csv";
  Row old;
  const Table stored = parse_csv(read_text(file), file.string());
  ASSERT_EQ(stored.size(), 1u);
  for (const auto& [name, value] : stored[0].cells())
    if (name != "iterations" && name != "version" && name != "quick") old.set(name, value);
  write_text_atomic(file, to_csv({old}));
  const std::string what = input_error([&] { run_study(study, config, {}); });
  EXPECT_TRUE(contains(what, "older hrspace")) << what;
  EXPECT_TRUE(contains(what, "synthetic-y-s1.csv")) << what;
  fs::remove_all(config.out);
}

TEST(Identity, ARunFileWhoseKeyIsNotItsFileNameIsRefused) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 1;
  config.out = temp_dir("renamed");
  ASSERT_EQ(run_study(study, config, {}).done, 2);
  const fs::path runs = config.out / "synthetic" / "runs";
  fs::copy_file(runs / "synthetic-x-s1.csv", runs / "synthetic-y-s1.csv",
                fs::copy_options::overwrite_existing);
  std::string what = input_error([&] { run_study(study, config, {}); });
  EXPECT_TRUE(contains(what, "synthetic-y-s1.csv: key cell 'synthetic-x-s1'")) << what;
  what = input_error([&] { write_tables(study, config); });
  EXPECT_TRUE(contains(what, "key cell")) << what;
  StudyConfig merged = config;
  merged.out = temp_dir("renamed_merged");
  what = input_error([&] { merge_shards(study, merged, {config.out}); });
  EXPECT_TRUE(contains(what, "key cell")) << what;
  fs::remove_all(config.out);
  fs::remove_all(merged.out);
}

TEST(Identity, ADirectoryWhereARunFileBelongsIsNamed) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 1;
  config.out = temp_dir("dirfile");
  const fs::path where = config.out / "synthetic" / "runs" / "synthetic-x-s1.csv";
  fs::create_directories(where);
  const std::string what = input_error([&] { run_study(study, config, {}); });
  EXPECT_TRUE(contains(what, where.string() + ": is a directory")) << what;
  EXPECT_FALSE(contains(what, "underflow")) << what;
  EXPECT_EQ(executed.load(), 0);
  EXPECT_TRUE(contains(input_error([&] { read_text(where); }), "is a directory"));
  fs::remove_all(config.out);
}

TEST(Identity, OutputFailuresAreOutputErrorsWithTheSystemsReason) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  const fs::path dir = temp_dir("unwritable");
  write_text_atomic(dir / "afile", "x");
  StudyConfig config;
  config.seeds = 1;
  config.out = dir / "afile" / "sub";
  try {
    run_study(study, config, {});
    FAIL() << "an output root under a file was accepted";
  } catch (const hrs::OutputError& e) {
    EXPECT_TRUE(contains(e.what(), (dir / "afile" / "sub").string())) << e.what();
    EXPECT_TRUE(contains(e.what(), "Not a directory")) << e.what();
  }
  try {
    write_text_atomic(dir / "missing" / "f.csv", "x");
    FAIL() << "a write into a missing directory passed";
  } catch (const hrs::OutputError& e) {
    EXPECT_TRUE(contains(e.what(), "No such file or directory")) << e.what();
  }
  fs::remove_all(dir);
}

//! Runs shard i of n of `study` with `config` into a fresh root.
fs::path run_shard(const Study& study, StudyConfig config, int i, int n, const std::string& name) {
  config.out = temp_dir(name);
  RunnerOptions o;
  o.shard_index = i;
  o.shard_count = n;
  run_study(study, config, o);
  return config.out;
}

TEST(Identity, MergeRefusesShardsOfOtherIterationsNamingTheColumn) {
  std::atomic<int> executed{0};
  const Study study = synthetic_study(&executed);
  StudyConfig config;
  config.seeds = 2;
  config.iterations = 100;
  StudyConfig other = config;
  other.iterations = 50;
  const fs::path a = run_shard(study, config, 1, 2, "merge_a");
  const fs::path b = run_shard(study, other, 2, 2, "merge_b");
  StudyConfig merged = config;
  merged.out = temp_dir("merge_ab");
  const std::string what = input_error([&] { merge_shards(study, merged, {a, b}); });
  EXPECT_TRUE(contains(what, "iterations '100'")) << what;
  EXPECT_TRUE(contains(what, "iterations '50'")) << what;
  EXPECT_FALSE(fs::exists(merged.out / "synthetic"));  // nothing written
  // A shard of the same sweep merges; the odd one is refused against what
  // is merged already.
  const fs::path c = run_shard(study, config, 2, 2, "merge_c");
  EXPECT_EQ(merge_shards(study, merged, {a, c}), 0);
  EXPECT_TRUE(contains(input_error([&] { merge_shards(study, merged, {b}); }), "iterations"));
  for (const auto& p : {a, b, c, merged.out}) fs::remove_all(p);
}

TEST(Identity, MergeRefusesTwoDigestsOfOneRoom) {
  std::atomic<int> executed{0};
  const fs::path dir = temp_dir("merge_scene");
  write_text_atomic(dir / "bedroom.json", "{\"v\": 1}\n");
  const Study study = study_with_scenes(&executed, dir / "bedroom.json");
  StudyConfig config;
  config.seeds = 2;
  const fs::path a = run_shard(study, config, 1, 2, "merge_scene_a");
  write_text_atomic(dir / "bedroom.json", "{\"v\": 2}\n");
  const fs::path b = run_shard(study, config, 2, 2, "merge_scene_b");
  StudyConfig merged = config;
  merged.out = temp_dir("merge_scene_ab");
  const std::string what = input_error([&] { merge_shards(study, merged, {a, b}); });
  EXPECT_TRUE(contains(what, "scene_digest")) << what;
  for (const auto& p : {a, b, merged.out, dir}) fs::remove_all(p);
}

TEST(Identity, EveryRunOfTheShippedStudiesDigestsTheScenesItReads) {
  StudyConfig config;
  config.seeds = 1;
  config.quick = true;
  config.scenes_dir = HRSPACE_SCENES_DIR;
  for (const Study& s : studies()) {
    for (const RunSpec& r : s.runs(config)) {
      const Row id = run_identity(s, r, config);
      for (const std::string& c : sweep_columns()) EXPECT_TRUE(id.get(c)) << r.key << " " << c;
      EXPECT_TRUE(id.get("scene_digest")) << r.key;
      if (r.params.get("planner")) {
        EXPECT_TRUE(id.get("planner_config")) << r.key;
      }
    }
  }
  // Scene names are looked up in --scenes: a directory without them is an
  // InputError naming the missing file.
  config.scenes_dir = "/nonexistent-scenes";
  const Study& timing = *find_study("timing");
  const std::string what =
      input_error([&] { run_identity(timing, timing.runs(config).front(), config); });
  EXPECT_TRUE(contains(what, "/nonexistent-scenes/bedroom.json")) << what;
}

TEST(Studies, EveryStudyHasDistinctRunKeysAndAQuickSweep) {
  StudyConfig config;
  config.seeds = 2;
  config.quick = true;
  for (const Study& s : studies()) {
    const auto runs = s.runs(config);
    EXPECT_FALSE(runs.empty()) << s.name;
    std::set<std::string> keys;
    for (const auto& r : runs) {
      EXPECT_TRUE(keys.insert(r.key).second) << s.name << ": duplicate key " << r.key;
      EXPECT_EQ(r.key.find('/'), std::string::npos) << r.key;
    }
    EXPECT_EQ(find_study(s.name), &s);
  }
  EXPECT_EQ(find_study("nope"), nullptr);
}

// The studies ask for designs through the front ends' one contract
// (api::DesignRequest): their planner names are --planner/--reuse spellings.
TEST(StudyPlanners, AreDesignRequestsOfThePresetsAndTwoAblations) {
  StudyConfig config;
  config.iterations = 123;
  config.threads = 2;
  using hrs::optimize::PlannerConfig;
  for (const auto& p : PlannerConfig::presets()) {
    const auto o = shared::design_options(config, p.name, 7);
    EXPECT_EQ(o.planner.name(), PlannerConfig::from_preset(p.name).name()) << p.name;
    EXPECT_EQ(o.seed, 7u);
    EXPECT_EQ(o.iterations, 123);
    EXPECT_EQ(o.threads, 2);
  }
  const PlannerConfig all = shared::design_options(config, "all", 1).planner;
  EXPECT_EQ(all.name(), PlannerConfig::from_preset("default").name());
  PlannerConfig two = PlannerConfig::from_preset("default");
  two.reuse = hrs::planning::ReuseOptions::none();
  two.reuse.samples = two.reuse.steering = true;
  const PlannerConfig ss = shared::design_options(config, "samples_steering", 1).planner;
  EXPECT_EQ(ss.name(), two.name());
  EXPECT_EQ(ss.reuse.names(), "samples,steering");
  const PlannerConfig none = shared::design_options(config, "none", 1).planner;
  EXPECT_TRUE(none.proposed);
  EXPECT_EQ(none.reuse.names(), "none");
  EXPECT_NE(none.name(), all.name());
  EXPECT_THROW(shared::design_options(config, "fastest", 1), hrs::InputError);
  config.iterations = -1;
  EXPECT_THROW(shared::design_options(config, "all", 1), hrs::InputError);
}

}  // namespace
