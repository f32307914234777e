// SPDX-License-Identifier: GPL-3.0-or-later
// The final polish of a design; see polish.h.

#include "optimize/polish.h"

#include <algorithm>

#include "optimize/preferences.h"

namespace hrs::optimize {

PolishResult polish(const geometry::Scene& scene, const CostModel& model,
                    const std::vector<bool>& movable, std::vector<geometry::Pose2>& poses,
                    CostTerms& terms, const PolishHooks& hooks, int max_tries,
                    const std::atomic<bool>* stop) {
  PolishResult out;
  PreferenceReport report = check_preferences(scene, model, poses);
  // Two passes: a pose kept in the first can make a partner's pose meet its
  // relation in the second.
  for (int pass = 0; pass < 2 && report.met < report.total; ++pass) {
    for (std::size_t i = 0; i < poses.size(); ++i) {
      if (!movable[i] || out.tried >= max_tries || (stop && stop->load())) continue;
      const std::string& id = scene.objects[i].id;
      const bool unmet = std::any_of(report.checks.begin(), report.checks.end(),
                                     [&](const PreferenceCheck& c) {
                                       return !c.met && (c.object == id || c.other == id);
                                     });
      if (!unmet) continue;
      const int object = static_cast<int>(i);
      for (const geometry::Pose2& to : preferred_poses(scene, model, poses, object)) {
        if (out.tried >= max_tries || (stop && stop->load())) break;
        std::vector<geometry::Pose2> p = poses;
        p[i] = to;
        if (!hooks.valid(p, object)) continue;
        const PreferenceReport next = check_preferences(scene, model, p);
        if (next.met <= report.met) continue;
        ++out.tried;
        const geometry::Pose2 from = poses[i];
        const CostTerms t = hooks.try_pose(p, object, to);
        if (t.tours_found >= terms.tours_found) {
          poses = std::move(p);
          terms = t;
          report = next;
          ++out.kept;
          hooks.kept();
          break;
        }
        hooks.undo(object, from);
      }
    }
  }
  return out;
}

}  // namespace hrs::optimize
