// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile inputs, one test per class of issue 20 (docs/hardening.md): every
// bad scene is refused with one line "FILE: /pointer: what" (InputError),
// never a crash, and the inner loops that used to blow up on small inputs
// (sequence enumeration, goal-pose generation) stay bounded.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "geometry/error.h"
#include "geometry/scene.h"
#include "optimize/design.h"
#include "optimize/sequences.h"
#include "planning/goals.h"

namespace {

using nlohmann::json;
using hrs::geometry::parse_scene;
using hrs::geometry::Scene;

json bedroom() {
  std::ifstream in(std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json");
  return json::parse(in);
}

//! The message of the InputError parse_scene throws for `j` ("" if none).
std::string refusal(const json& j) {
  try {
    parse_scene(j.dump(), "hostile.json");
  } catch (const hrs::InputError& e) {
    return e.what();
  }
  return "";
}

//! Expects `j` refused with one line naming the file and `pointer`.
void expect_refused(const json& j, const std::string& pointer) {
  const std::string what = refusal(j);
  EXPECT_EQ(what.rfind("hostile.json: " + pointer + ": ", 0), 0u)
      << "expected a refusal at " << pointer << ", got: '" << what << "'";
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}

TEST(Hardening, ExtremeMagnitudesAreRefused) {
  const std::pair<std::string, json> cases[] = {
      {"/objects/0/pose/0", 1e16},   {"/objects/0/pose/1", -1e200}, {"/objects/0/pose/2", 1e16},
      {"/objects/0/size/0", 1e-16},  {"/objects/0/size/1", 1e-4},   {"/door/width", 1e300},
      {"/door/clear_depth", 1e-300}, {"/wheelchair/length", 1e6},   {"/wheelchair/width", 1e-9},
      {"/wheelchair/turning_radius", 1e6}, {"/wheelchair/turning_radius", 1e-300},
  };
  for (const auto& [pointer, value] : cases) {
    json j = bedroom();
    j[json::json_pointer(pointer)] = value;
    SCOPED_TRACE(pointer);
    expect_refused(j, pointer);
  }
  json room = bedroom();
  room["room"] = {{"polygon", {{0, 0}, {2000, 0}, {2000, 2000}, {0, 2000}}}};
  expect_refused(room, "/room/polygon/1/0");
  json big = bedroom();
  big["room"] = {{"size", {1500, 4}}};
  expect_refused(big, "/room/size/0");
  json weights = bedroom();
  weights["weights"] = {{"path", {1e308, 1, 1}}};
  expect_refused(weights, "/weights/path/0");
  json relation = bedroom();
  relation["relations"] = {{{"a", "tv"}, {"b", "bed"}, {"distance", 1e308}}};
  expect_refused(relation, "/relations/0/distance");
  relation["relations"] = {{{"a", "tv"}, {"b", "bed"}, {"distance", 1}, {"weight", 1e308}}};
  expect_refused(relation, "/relations/0/weight");
  json gap = bedroom();
  gap["objects"][0]["approach"] = {{"gap", 1e6}};
  expect_refused(gap, "/objects/0/approach/gap");
  // A polygon footprint whose edge is below a millimetre.
  json tiny = bedroom();
  tiny["objects"][0].erase("size");
  tiny["objects"][0]["polygon"] = {{0, 0}, {1e-9, 0}, {0, 1}};
  expect_refused(tiny, "/objects/0/polygon/1");
}

TEST(Hardening, DeepNestingIsRefused) {
  for (const int depth : {100000, 5000, 65}) {
    const std::string text = std::string(depth, '[') + std::string(depth, ']');
    try {
      parse_scene(text, "deep.json");
      ADD_FAILURE() << depth << " levels accepted";
    } catch (const hrs::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("nested deeper"), std::string::npos) << e.what();
    }
  }
  // Brackets inside strings do not count; a deep comment within the limit is fine.
  json j = bedroom();
  j["name"] = std::string(500, '[');
  json deep = json::array();
  for (int i = 0; i < 50; ++i) deep = json::array({deep});
  j["comment"] = deep;
  EXPECT_EQ(refusal(j), "");
}

TEST(Hardening, NonsenseIsRefused) {
  json outside = bedroom();
  outside["door"]["start"] = {-5, -5, 0};
  expect_refused(outside, "/door/start");
  json in_fixed = bedroom();  // the closet is fixed, at (0.31, 2.6)
  in_fixed["door"]["start"] = {0.5, 2.6, 0};
  expect_refused(in_fixed, "/door/start");
  json huge_chair = bedroom();
  huge_chair["wheelchair"]["length"] = 10.0;
  expect_refused(huge_chair, "/wheelchair/length");
  json wide_turn = bedroom();  // 4.5 x 4 m room: at most 2.25 m
  wide_turn["wheelchair"]["turning_radius"] = 3.0;
  expect_refused(wide_turn, "/wheelchair/turning_radius");
  json blocked = bedroom();  // the door is at (1, 0), clear zone 0.9 x 1.2 m
  blocked["objects"][0]["fixed"] = true;
  blocked["objects"][0]["size"] = {0.5, 0.5};
  blocked["objects"][0]["pose"] = {1.0, 0.6, 0.0};
  expect_refused(blocked, "/objects/0/pose");
  json limits = bedroom();
  limits["activity"]["visits"] = 101;
  expect_refused(limits, "/activity/visits");
  limits["activity"]["visits"] = 3;
  limits["activity"]["sequences"] = 1001;
  expect_refused(limits, "/activity/sequences");
  // No sequence of the requested length: accepted by the reader, refused by design.
  json dead_end = bedroom();
  dead_end["activity"]["transitions"] = {{"door", {{"bed", 1.0}}}};
  const Scene s = parse_scene(dead_end.dump(), "hostile.json");
  try {
    hrs::geometry::require_sequences(s, "hostile.json");
    ADD_FAILURE() << "no sequence of 3 visits accepted";
  } catch (const hrs::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("hostile.json: /activity/visits: ", 0), 0u) << e.what();
  }
  // The shipped scenes satisfy every limit.
  EXPECT_EQ(refusal(bedroom()), "");
}

TEST(Hardening, ResourceBlowUpsAreBounded) {
  // Six equally likely nodes: best-first search over prefixes needed
  // gigabytes at 30 visits; the layered enumeration needs M x nodes x visits.
  hrs::geometry::Activity act;
  const char* ids[] = {"a", "b", "c", "d", "e", "f"};
  for (const char* from : {"door", "a", "b", "c", "d", "e", "f"}) {
    for (const char* to : ids) {
      if (std::string(from) != to) act.transitions[from][to] = 1.0;
    }
  }
  // Bounded by the suite's external timeout (ctest TIMEOUT), not by a clock
  // read here: the old search would not end (or end in bad_alloc) at all.
  const auto top = hrs::optimize::top_sequences(hrs::optimize::AoGraph(act), "door", 100, 1000);
  ASSERT_EQ(top.size(), 1000u);
  EXPECT_EQ(top.front().nodes.size(), 101u);
  // Lexicographic among equals: a, b, a, b, ... first.
  EXPECT_EQ(top.front().nodes[1], "a");
  EXPECT_EQ(top.front().nodes[2], "b");
  for (std::size_t i = 1; i < top.size(); ++i) EXPECT_LT(top[i - 1].nodes, top[i].nodes);

  // Goal poses with the largest gap and chair the format allows: bounded work.
  json j = bedroom();
  j["room"] = {{"size", {1000, 1000}}};
  j["door"] = {{"center", {1, 0}}, {"width", 0.9}};
  j["wheelchair"] = {{"length", 1.1}, {"width", 0.001}, {"turning_radius", 0.7}};
  j["objects"] = {{{"id", "t"}, {"size", {900, 900}}, {"pose", {500, 500, 0}},
                   {"approach", {{"gap", 2000}}}}};
  j["activity"] = {{"transitions", {{"door", {{"t", 1.0}}}}}, {"visits", 1}};
  j.erase("relations");
  const Scene s = parse_scene(j.dump(), "big.json");
  // The work is bounded by construction (at most 256 slots); the count shows it.
  const auto goals = hrs::planning::local_goal_poses(s, s.objects[0]);
  EXPECT_LE(goals.size(), 256u);
}

// The long inner loops check a stop request (Ctrl-C of `hrspace design`):
// set, they throw Interrupted and return nothing partial; unset, the results
// are those of a run without a flag.
TEST(Hardening, LongLoopsHonourAStopRequest) {
  const Scene scene = parse_scene(bedroom().dump(), "bedroom.json");
  const hrs::optimize::AoGraph graph(scene.activity);
  std::atomic<bool> stop{false};
  const auto plain = hrs::optimize::top_sequences(graph, "door", 3, 10);
  const auto flagged = hrs::optimize::top_sequences(graph, "door", 3, 10, &stop);
  ASSERT_EQ(plain.size(), flagged.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i].nodes, flagged[i].nodes);
    EXPECT_EQ(plain[i].likelihood, flagged[i].likelihood);
  }
  const auto goals = hrs::planning::local_goal_poses(scene, scene.objects[0]);
  const auto goals_flagged = hrs::planning::local_goal_poses(scene, scene.objects[0], {}, &stop);
  ASSERT_EQ(goals.size(), goals_flagged.size());
  for (std::size_t i = 0; i < goals.size(); ++i) {
    EXPECT_EQ(goals[i].pose, goals_flagged[i].pose);
    EXPECT_EQ(goals[i].slot, goals_flagged[i].slot);
  }

  stop.store(true);
  EXPECT_THROW(hrs::optimize::top_sequences(graph, "door", 3, 10, &stop), hrs::Interrupted);
  EXPECT_THROW(hrs::optimize::scene_sequences(scene, &stop), hrs::Interrupted);
  EXPECT_THROW(hrs::planning::local_goal_poses(scene, scene.objects[0], {}, &stop),
               hrs::Interrupted);
  hrs::optimize::DesignOptions options;
  options.planner = hrs::optimize::PlannerConfig::from_preset("baseline");
  options.iterations = 5;
  EXPECT_THROW(hrs::optimize::design(scene, options, &stop), hrs::Interrupted);

  // A stop request during an enumeration at the format's limits (100 nodes,
  // 100 visits, M = 1000: seconds of work) ends it within a fraction of a
  // second; the bound here is generous.
  hrs::geometry::Activity act;
  std::vector<std::string> ids;
  for (int i = 0; i < 100; ++i) ids.push_back("o" + std::to_string(i));
  for (const auto& to : ids) act.transitions["door"][to] = 1.0;
  for (const auto& from : ids)
    for (const auto& to : ids)
      if (from != to) act.transitions[from][to] = 1.0;
  const hrs::optimize::AoGraph big(act);
  std::atomic<bool> late{false};
  std::atomic<std::int64_t> set_at{0};
  std::thread setter([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    set_at.store(std::chrono::steady_clock::now().time_since_epoch().count());
    late.store(true);
  });
  bool interrupted = false;
  try {
    hrs::optimize::top_sequences(big, "door", 100, 1000, &late);
  } catch (const hrs::Interrupted& e) {
    interrupted = true;
    EXPECT_EQ(std::string(e.what()), "sequence enumeration: interrupted");
  }
  const auto ended = std::chrono::steady_clock::now();
  setter.join();
  EXPECT_TRUE(interrupted);
  const std::chrono::steady_clock::time_point asked{
      std::chrono::steady_clock::duration(set_at.load())};
  EXPECT_LT(std::chrono::duration<double>(ended - asked).count(), 10.0);
}

}  // namespace

// Issue 33 item 7: ids and the name go into SVG, CSV and the terminal, so the
// reader refuses control characters (C0, DEL, C1) and U+FFFE/U+FFFF there.
TEST(Hardening, ControlCharactersInIdsAndNamesAreRefused) {
  const std::string bad[] = {std::string("bed\x1b[31m"), std::string("a\x01"), "tab\there",
                             "del\x7f", "csi\xc2\x9b", "nc\xef\xbf\xbe", "nc\xef\xbf\xbf"};
  for (const std::string& s : bad) {
    json j = bedroom();
    j["objects"][0]["id"] = s;
    expect_refused(j, "/objects/0/id");
    j = bedroom();
    j["name"] = s;
    expect_refused(j, "/name");
  }
  // Printable text beyond ASCII stays accepted.
  json j = bedroom();
  j["name"] = "chambre à coucher \xe2\x80\x94 寝室";
  EXPECT_EQ(refusal(j), "");
}

// Issue 33 item 3: reads are bounded, special files and NUL paths refused.
TEST(Hardening, InputsAreReadWithABound) {
  const auto message = [](const std::string& path) {
    try {
      hrs::geometry::load_scene(path);
    } catch (const hrs::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("/dev/zero").find("/dev/zero: not a regular file"), std::string::npos);
  const std::string bedroom_path = std::string(HRSPACE_SOURCE_DIR) + "/scenes/bedroom.json";
  EXPECT_NE(message(bedroom_path + std::string(1, '\0') + "junk").find("NUL character"),
            std::string::npos);
  // A sparse file just over the limit is refused by its size, without reading it.
  const std::string big = ::testing::TempDir() + "/hrspace_big_scene.json";
  {
    std::ofstream out(big, std::ios::binary);
    out.seekp(static_cast<std::streamoff>(hrs::geometry::limits::kInputBytes));
    out.put('}');
  }
  EXPECT_NE(message(big).find("MiB an input file may have"), std::string::npos) << message(big);
  std::remove(big.c_str());
  // A stream longer than the limit stops one chunk past it.
  std::istringstream zeros(std::string(hrs::geometry::limits::kInputBytes + 1, '\0'));
  EXPECT_THROW(hrs::geometry::read_input_stream(zeros, "stdin"), hrs::InputError);
  std::istringstream small("{}");
  EXPECT_EQ(hrs::geometry::read_input_stream(small, "stdin"), "{}");
}
