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
#include "experiments/stats.h"
#include "experiments/study.h"
#include "experiments/table.h"
#include "geometry/error.h"

namespace {

namespace fs = std::filesystem;
using namespace hrs::experiments;

fs::path temp_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("hrspace_harness_" + name + "_" +
                                                  std::to_string(::getpid()));
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

}  // namespace
