// SPDX-License-Identifier: GPL-3.0-or-later
#include "planning/reuse_options.h"

#include <algorithm>

namespace hrs::planning {

const std::array<ReuseOptions::Technique, 11>& ReuseOptions::techniques() {
  static const std::array<Technique, 11> list{{{"samples", &ReuseOptions::samples},
                                               {"steering", &ReuseOptions::steering},
                                               {"paths", &ReuseOptions::paths},
                                               {"trees", &ReuseOptions::trees},
                                               {"failures", &ReuseOptions::failures},
                                               {"shortcuts", &ReuseOptions::shortcuts},
                                               {"budget", &ReuseOptions::budget},
                                               {"metrics", &ReuseOptions::metrics},
                                               {"backoff", &ReuseOptions::backoff},
                                               {"speculate", &ReuseOptions::speculate},
                                               {"proofs", &ReuseOptions::proofs}}};
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
