// SPDX-License-Identifier: GPL-3.0-or-later
// Seeded mutation fuzzing of the readers at hrspace's boundary (issue 20,
// docs/hardening.md): the scene reader (parse_scene) and the numeric CSV
// reader of `collide` and `rs` (read_numeric_csv). The corpus is the shipped
// scenes/*.json and small CSV files; mutations are byte-level (flips,
// insertions of hostile tokens, deletions, duplications) and JSON-level
// (extreme numbers at random leaves, deep nesting, removed keys). The oracle:
// a reader returns a value or throws InputError with one line naming the
// input, nothing else; an accepted scene writes back to itself and its
// derived geometry (start pose, goal poses) is finite and bounded in time.
// HRSPACE_FUZZ_SECONDS sets the time budget (default 60 s); HRSPACE_FUZZ_SEED
// the seed (default 20). The figures are printed at the end.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli/args.h"
#include "geometry/error.h"
#include "geometry/scene.h"
#include "planning/goals.h"

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double budget_seconds() {
  const char* s = std::getenv("HRSPACE_FUZZ_SECONDS");
  return s ? std::atof(s) : 60.0;
}

std::uint64_t seed() {
  const char* s = std::getenv("HRSPACE_FUZZ_SEED");
  return s ? std::strtoull(s, nullptr, 10) : 20;
}

std::vector<std::string> scene_corpus() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(HRSPACE_SOURCE_DIR) + "/scenes")) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path());
    std::stringstream ss;
    ss << in.rdbuf();
    out.push_back(ss.str());
  }
  return out;
}

const std::vector<std::string> kTokens = {
    "1e16", "-1e16", "1e308", "-1e308", "1e-16", "1e-320", "1e400", "0", "-0", "nan", "inf",
    "[", "]", "{", "}", "\"", "\\u0000", ",", ":", "null", "true", "\"comment\"", "\"door\"",
    "4294967296", "1001", "-1", "1e3", "0.0001", "[[[[[[[[", "]]]]]]]]", ";", "\n", "\r", " "};

const std::vector<double> kExtremes = {1e16, -1e16, 1e308, -1e308, 1e-16, 1e-320, 0.0, -0.0,
                                       1e3, 1000.0000001, 2000.0, 1e-3, 9.99e-4, 1e6, -1.0, 3.0};

std::string mutate_bytes(std::string text, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) { return n ? std::uniform_int_distribution<std::size_t>(0, n - 1)(rng) : 0; };
  const int rounds = 1 + static_cast<int>(pick(4));
  for (int r = 0; r < rounds; ++r) {
    const std::size_t at = pick(text.size() + 1);
    switch (pick(5)) {
      case 0:
        if (!text.empty()) text[pick(text.size())] ^= static_cast<char>(1 << pick(8));
        break;
      case 1:
        text.insert(at, kTokens[pick(kTokens.size())]);
        break;
      case 2:
        text.erase(at, pick(32));
        break;
      case 3:
        if (at < text.size()) text.insert(pick(text.size() + 1), text.substr(at, pick(64)));
        break;
      default:
        text.insert(at, 1, static_cast<char>(pick(256)));
    }
  }
  return text;
}

//! Every leaf of `j` (pointers), to pick one at random.
void leaves(const json& j, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
  if (j.is_structured()) {
    if (j.is_object()) {
      for (const auto& [k, v] : j.items()) leaves(v, at / k, out);
    } else {
      for (std::size_t i = 0; i < j.size(); ++i) leaves(j[i], at / i, out);
    }
    out.push_back(at);
  } else {
    out.push_back(at);
  }
}

std::string mutate_json(const std::string& text, std::mt19937_64& rng) {
  json j = json::parse(text);
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const int rounds = 1 + static_cast<int>(pick(3));
  for (int r = 0; r < rounds; ++r) {
    std::vector<json::json_pointer> all;
    leaves(j, json::json_pointer(), all);
    const json::json_pointer p = all[pick(all.size())];
    if (p.empty()) continue;
    switch (pick(5)) {
      case 0:
      case 1:
        j[p] = kExtremes[pick(kExtremes.size())];
        break;
      case 2: {
        json& v = j[p];
        if (v.is_number()) v = v.get<double>() * std::ldexp(1.0, static_cast<int>(pick(120)) - 60);
        else v = kExtremes[pick(kExtremes.size())];
        break;
      }
      case 3:
        j[p.parent_pointer()].is_object() ? void(j[p.parent_pointer()].erase(p.back()))
                                          : void(j[p] = json::array());
        break;
      default: {
        json deep = 1;
        for (std::size_t d = pick(80); d-- > 0;) deep = json::array({deep});
        j[p] = deep;
      }
    }
  }
  return j.dump();
}

struct Figures {
  long executions = 0, accepted = 0, refused = 0;
  std::map<std::string, long> refusals;  //!< by pointer (the "coverage" of the rules)
};

void check_scene_text(const std::string& text, Figures& f, std::mt19937_64& rng) {
  ++f.executions;
  hrs::geometry::Scene scene;
  try {
    scene = hrs::geometry::parse_scene(text, "fuzz.json");
  } catch (const hrs::InputError& e) {
    const std::string what = e.what();
    ++f.refused;
    ASSERT_EQ(what.rfind("fuzz.json: ", 0), 0u) << what;
    ASSERT_EQ(what.find('\n'), std::string::npos) << what;
    const std::string rest = what.substr(11);
    const auto colon = rest.find(": ");
    std::string ptr = rest[0] == '/' && colon != std::string::npos ? rest.substr(0, colon) : "(document)";
    for (char& c : ptr)
      if (c >= '0' && c <= '9') c = '#';
    ++f.refusals[ptr];
    return;
  }
  ++f.accepted;
  // Accepted: written back it reads to the same scene; the derived geometry is sound.
  ASSERT_EQ(hrs::geometry::parse_scene(hrs::geometry::write_scene(scene), "back.json"), scene);
  const hrs::geometry::Pose2 start = hrs::geometry::door_start_pose(scene);
  ASSERT_TRUE(std::isfinite(start.x) && std::isfinite(start.y) && std::isfinite(start.theta));
  if (!scene.objects.empty() && rng() % 8 == 0) {
    const auto goals =
        hrs::planning::local_goal_poses(scene, scene.objects[rng() % scene.objects.size()]);
    ASSERT_LE(goals.size(), 256u);  // the slot bound: the work is bounded by construction
    for (const auto& g : goals) ASSERT_TRUE(std::isfinite(g.pose.x) && std::isfinite(g.pose.y));
  }
}

TEST(Fuzz, SceneReaderNeverCrashesOrAcceptsNonsense) {
  const auto corpus = scene_corpus();
  ASSERT_FALSE(corpus.empty());
  std::mt19937_64 rng(seed());
  Figures f;
  const auto t0 = Clock::now();
  const double budget = 0.75 * budget_seconds();
  for (const auto& text : corpus) check_scene_text(text, f, rng);
  ASSERT_EQ(f.accepted, static_cast<long>(corpus.size()));  // the shipped scenes are valid
  while (std::chrono::duration<double>(Clock::now() - t0).count() < budget) {
    const std::string& base = corpus[rng() % corpus.size()];
    const std::string text = rng() % 2 ? mutate_bytes(base, rng) : mutate_json(base, rng);
    check_scene_text(text, f, rng);
    if (HasFatalFailure()) {
      ADD_FAILURE() << "input: " << text;
      return;
    }
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("scene fuzz: %ld executions in %.1f s (%.0f/s), %ld accepted, %ld refused, %zu "
              "distinct refusal pointers\n",
              f.executions, s, f.executions / s, f.accepted, f.refused, f.refusals.size());
  EXPECT_GT(f.refusals.size(), 20u);  // the mutations reach many rules
}

TEST(Fuzz, CsvReaderNeverDropsRowsOrAcceptsNonsense) {
  const std::vector<std::string> corpus = {"x,y,theta\n2.2,1.2,0\n-1,0,0\n0.2,0.2,0\n",
                                           "2.2,1.2,0\n1,1,1\r\n\n3,3,3",
                                           "x0,y0,t0,x1,y1,t1\n0,0,0,2,0,0\n0,0,0,-1,0,0\n"};
  const std::vector<hrs::cli::CsvColumn> poses = {{"x", 1000}, {"y", 1000}, {"theta", 1000}};
  const std::vector<hrs::cli::CsvColumn> pairs = {{"x0", 1000}, {"y0", 1000}, {"t0", 1000},
                                                  {"x1", 1000}, {"y1", 1000}, {"t1", 1000}};
  // The corpus itself reads as written: a header is skipped, CRLF and blank
  // lines are accepted, and every other line is a row.
  EXPECT_EQ(hrs::cli::read_numeric_csv(corpus[0], poses, "c0").size(), 3u);
  EXPECT_EQ(hrs::cli::read_numeric_csv(corpus[1], poses, "c1").size(), 3u);
  EXPECT_EQ(hrs::cli::read_numeric_csv(corpus[2], pairs, "c2").size(), 2u);
  // Whether `line` is a header: its comma-separated fields, spaces and tabs
  // around them ignored, are the column names in order (a final CR dropped).
  auto is_header = [](std::string line, const std::vector<hrs::cli::CsvColumn>& columns) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<std::string> fields;
    for (std::size_t start = 0;;) {
      const std::size_t comma = line.find(',', start);
      std::string f = line.substr(start, comma == std::string::npos ? comma : comma - start);
      const std::size_t b = f.find_first_not_of(" \t"), e = f.find_last_not_of(" \t");
      fields.push_back(b == std::string::npos ? "" : f.substr(b, e - b + 1));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (fields.size() != columns.size()) return false;
    for (std::size_t i = 0; i < columns.size(); ++i)
      if (fields[i] != columns[i].name) return false;
    return true;
  };
  std::mt19937_64 rng(seed() + 1);
  long executions = 0, accepted = 0;
  const auto t0 = Clock::now();
  const double budget = 0.25 * budget_seconds();
  while (std::chrono::duration<double>(Clock::now() - t0).count() < budget) {
    const std::string text = mutate_bytes(corpus[rng() % corpus.size()], rng);
    const auto& columns = rng() % 2 ? poses : pairs;
    ++executions;
    // Lines that hold something: every one is a row, except the first when
    // it is a header.
    std::size_t lines = 0;
    bool header = false;
    std::stringstream ss(text);
    for (std::string line; std::getline(ss, line);) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      if (lines++ == 0) header = is_header(line, columns);
    }
    try {
      const auto rows = hrs::cli::read_numeric_csv(text, columns, "fuzz.csv");
      ++accepted;
      ASSERT_EQ(rows.size(), lines - (header ? 1 : 0)) << text;
      for (const auto& r : rows) {
        ASSERT_EQ(r.size(), columns.size());
        for (double v : r) ASSERT_TRUE(std::isfinite(v) && std::abs(v) <= 1000) << text;
      }
    } catch (const hrs::InputError& e) {
      const std::string what = e.what();
      ASSERT_EQ(what.rfind("fuzz.csv: line ", 0), 0u) << what;
      ASSERT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("csv fuzz: %ld executions in %.1f s (%.0f/s), %ld accepted\n", executions, s,
              executions / s, accepted);
  EXPECT_GT(executions, 0);
}

}  // namespace
