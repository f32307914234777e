// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the scene reader (geometry::parse_scene) on arbitrary
// bytes (docs/hardening.md, "Fuzzing the readers"). The oracle is the seeded
// GoogleTest fuzzer's (tests/cli/fuzz_readers_test.cpp): the reader returns
// a scene or throws one InputError line naming the input; an accepted scene
// written back reads to the same scene and has a finite start pose. Any other
// exception, an abort, a sanitizer report or a hang is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "geometry/error.h"
#include "geometry/scene.h"

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_scene: %s: %s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  hrs::geometry::Scene scene;
  try {
    scene = hrs::geometry::parse_scene(text, "fuzz.json");
  } catch (const hrs::InputError& e) {
    const std::string what = e.what();
    if (what.rfind("fuzz.json: ", 0) != 0) finding("message does not name the input", what);
    if (what.find('\n') != std::string::npos) finding("message of several lines", what);
    return 0;
  }
  const std::string written = hrs::geometry::write_scene(scene);
  hrs::geometry::Scene back;
  try {
    back = hrs::geometry::parse_scene(written, "back.json");
  } catch (const hrs::InputError& e) {
    finding("an accepted scene written back is refused", e.what());
  }
  if (!(back == scene)) finding("an accepted scene does not read back equal", written);
  const hrs::geometry::Pose2 start = hrs::geometry::door_start_pose(scene);
  if (!std::isfinite(start.x) || !std::isfinite(start.y) || !std::isfinite(start.theta))
    finding("start pose not finite", written);
  return 0;
}
