// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/reuse_options.h"

#include <algorithm>

namespace hrs::planning {

const std::array<ReuseOptions::Technique, 10>& ReuseOptions::techniques() {
  static const std::array<Technique, 10> list{{{"samples", &ReuseOptions::samples,
                                                "RRT samples from the RS-decomposition (§V-A)"},
                                               {"steering", &ReuseOptions::steering,
                                                "RS look-ups through the decomposition, exact fallback (§V-A)"},
                                               {"paths", &ReuseOptions::paths,
                                                "path database, within and across iterations, repaired when ends move (§V-B)"},
                                               {"trees", &ReuseOptions::trees,
                                                "RRT trees kept while their root barely moves (§V-C)"},
                                               {"failures", &ReuseOptions::failures,
                                                "a failed leg is not re-planned while no object moved within reach of its RRT (ours, exact)"},
                                               {"shortcuts", &ReuseOptions::shortcuts,
                                                "every stored path is shortened first (ours)"},
                                               {"budget", &ReuseOptions::budget,
                                                "opt-in: fresh plans stop after 300 RRT iterations (budget=N: after N; ours, costs tours)"},
                                               {"metrics", &ReuseOptions::metrics,
                                                "a found leg's clearance metrics and re-certification are kept and updated (ours, exact)"},
                                               {"backoff", &ReuseOptions::backoff,
                                                "opt-in: a leg that keeps failing gets half the budget each time, down to 120 (backoff=N; ours)"},
                                               {"speculate", &ReuseOptions::speculate,
                                                "a tour waiting for a leg plans its own next candidate meanwhile (ours, same results)"}}};
  return list;
}

const std::array<ReuseOptions::Parameter, 2>& ReuseOptions::parameters() {
  static const std::array<Parameter, 2> list{
      {{"budget", &ReuseOptions::budget, &ReuseOptions::budget_iterations, "RRT iterations"},
       {"backoff", &ReuseOptions::backoff, &ReuseOptions::backoff_floor, "RRT iterations"}}};
  return list;
}

bool ReuseOptions::any() const {
  return std::ranges::any_of(techniques(), [this](const Technique& t) { return this->*t.on; });
}

ReuseOptions ReuseOptions::none() {
  ReuseOptions o;
  for (const Technique& t : techniques()) o.*t.on = false;
  return o;
}

std::string ReuseOptions::names() const {
  std::string out;
  for (const Technique& t : techniques()) {
    if (!(this->*t.on)) continue;
    if (!out.empty()) out += ',';
    out += t.name;
    for (const Parameter& x : parameters()) {
      if (t.on == x.on && this->*x.value != ReuseOptions{}.*x.value)
        out.append("=").append(std::to_string(this->*x.value));
    }
  }
  return out.empty() ? "none" : out;
}

}  // namespace hrs::planning
