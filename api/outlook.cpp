// SPDX-License-Identifier: GPL-3.0-or-later
// What a design will face; see outlook.h.

#include "api/outlook.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "api/reuse_list.h"
#include "geometry/cspace.h"
#include "geometry/error.h"
#include "optimize/design.h"
#include "optimize/sequences.h"
#include "planning/goals.h"

namespace hrs::api {

DesignOutlook design_outlook(const geometry::Scene& scene, double seconds) {
  DesignOutlook out;
  const std::vector<optimize::Sequence> sequences = optimize::scene_sequences(scene);
  const geometry::CSpace cspace(scene);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const geometry::Object& o = scene.objects[i];
    bool stop = false;
    for (const auto& s : sequences)
      for (std::size_t k = 1; k < s.nodes.size(); ++k) stop = stop || s.nodes[k] == o.id;
    if (stop && planning::goal_poses(scene, o, o.pose, cspace).empty())
      out.stops_without_goal.push_back(o.id);
  }
  optimize::DesignOptions options;
  options.iterations = 0;
  options.planner = parse_planner("default,-escape,-prefer");
  std::atomic<bool> stop{false};
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::thread watchdog([&] {
    std::unique_lock<std::mutex> lock(m);
    if (!cv.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return done; }))
      stop.store(true);
  });
  try {
    const optimize::DesignResult r = optimize::design(scene, options, &stop);
    out.planned = !r.stopped && !stop.load();
    out.tours_found = r.initial.tours_found;
    out.tours_total = r.initial.tours_total;
    for (std::size_t k = 0; k < r.tours.size() && k < r.sequences.size(); ++k) {
      if (r.tours[k].found) continue;
      std::string text;
      for (const auto& n : r.sequences[k].nodes) text += (text.empty() ? "" : ",") + n;
      out.unfound.push_back(text);
    }
    out.preferences = r.preferences_initial;
  } catch (const Interrupted&) {
    out.planned = false;
  }
  {
    std::lock_guard<std::mutex> lock(m);
    done = true;
  }
  cv.notify_all();
  watchdog.join();
  if (!out.planned) {
    // Without tours the preferences are still known.
    const optimize::CostModel model(scene, sequences);
    std::vector<geometry::Pose2> poses;
    for (const auto& o : scene.objects) poses.push_back(o.pose);
    out.preferences = optimize::check_preferences(scene, model, poses);
  }
  return out;
}

}  // namespace hrs::api
