// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene-format tests' fixture: a valid base scene touching every section,
// and the helpers that break one rule of it and check the error message.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "geometry/error.h"
#include "geometry/scene.h"

namespace hrs::geometry::scene_fixture {

using Json = nlohmann::json;
using Ptr = Json::json_pointer;

//! A valid scene touching every section; each test breaks one rule of it.
inline const char* const kBase = R"({
  "format": "hrspace-scene/1",
  "name": "base",
  "comment": "test fixture",
  "room": { "polygon": [[0, 0], [5, 0], [5, 4], [0, 4]] },
  "door": { "center": [1.0, 0.0], "width": 0.9, "clear_depth": 1.2 },
  "wheelchair": { "length": 1.1, "width": 0.65, "turning_radius": 0.7 },
  "objects": [
    { "id": "desk", "size": [0.8, 1.6], "pose": [2.5, 3.5, -1.5707963267948966],
      "wall": { "distance": 0.0, "angle": 0.0 },
      "approach": { "sides": ["front"], "gap": 0.1 } },
    { "id": "shelf", "size": [0.4, 1.0], "pose": [4.7, 2.0, 3.141592653589793], "fixed": true },
    { "id": "plant", "polygon": [[0, 0], [0.4, 0], [0.2, 0.3]], "pose": [0.3, 3.5, 0.0],
      "fixed": true },
    { "id": "table", "size": [0.8, 0.8], "pose": [3.0, 1.5, 0.0] }
  ],
  "relations": [ { "a": "table", "b": "desk", "distance": 2.0, "weight": 0.5 } ],
  "activity": {
    "transitions": {
      "door":  { "desk": 0.5, "table": 0.3, "shelf": 0.2 },
      "desk":  { "desk": 0.2, "table": 0.4, "shelf": 0.4 },
      "table": { "desk": 1.0 },
      "shelf": { "desk": 0.7, "plant": 0.3 }
    },
    "sequences": 4,
    "visits": 2
  },
  "weights": { "path": [1, 2, 0.5], "interior": [1, 1] }
})";

inline const std::string kLabel = "scenes/base.json";

inline Json base() { return Json::parse(kBase); }

inline Scene parse(const Json& j) { return parse_scene(j.dump(2), kLabel); }

//! Expects `text` to be rejected with one line naming the file, the pointer and `word`.
inline void expect_rejected(const std::string& text, const std::string& pointer,
                            const std::string& word) {
  try {
    parse_scene(text, kLabel);
    FAIL() << "accepted a broken scene; expected an error at " << pointer;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    const std::string head = pointer.empty() ? kLabel + ": " : kLabel + ": " + pointer + ": ";
    EXPECT_EQ(msg.rfind(head, 0), 0u) << msg;
    EXPECT_NE(msg.find(word), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

//! Mutates the base scene and expects the error at `pointer` mentioning `word`.
inline void expect_broken(const std::function<void(Json&)>& mutate, const std::string& pointer,
                          const std::string& word) {
  Json j = base();
  mutate(j);
  expect_rejected(j.dump(2), pointer, word);
}

inline void set(Json& j, const std::string& pointer, Json value) {
  j[Ptr(pointer)] = std::move(value);
}
inline void erase(Json& j, const std::string& parent, const std::string& key) {
  j[Ptr(parent)].erase(key);
}

//! The scene files shipped in scenes/, sorted.
inline std::vector<std::filesystem::path> scene_files() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(HRSPACE_SOURCE_DIR "/scenes")) {
    if (e.path().extension() == ".json") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace hrs::geometry::scene_fixture
