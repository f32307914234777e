// SPDX-License-Identifier: GPL-3.0-or-later
// The planner presets and switches; see planner_config.h.

#include "optimize/planner_config.h"

#include <algorithm>

#include "geometry/error.h"

namespace hrs::optimize {
namespace {

using planning::ReuseOptions;

PlannerConfig literal_config() {
  PlannerConfig c;
  c.preset = "literal";
  c.proposed = false;
  c.reuse = ReuseOptions::none();
  c.goalskip = c.refuse = c.escape = c.early = c.prefer = c.shorten = c.rescue = false;
  return c;
}

PlannerConfig paper_config() {
  PlannerConfig c = literal_config();
  c.preset = "paper";
  c.proposed = true;
  c.reuse.samples = c.reuse.steering = c.reuse.paths = c.reuse.trees = true;
  return c;
}

PlannerConfig baseline_config() {
  PlannerConfig c;
  c.preset = "baseline";
  c.proposed = false;
  c.reuse = ReuseOptions::none();
  return c;
}

PlannerConfig default_config() { return PlannerConfig{}; }

//! The techniques' switches and parameters that differ from `base`, as items.
std::string reuse_diff(const ReuseOptions& r, const ReuseOptions& base) {
  std::string out;
  for (const ReuseOptions::Technique& t : ReuseOptions::techniques()) {
    std::string item;
    for (const ReuseOptions::Parameter& p : ReuseOptions::parameters())
      if (p.on == t.on && r.*t.on && r.*p.value != base.*p.value)
        item = std::string(t.name) + "=" + std::to_string(r.*p.value);
    if (item.empty() && r.*t.on != base.*t.on) item = (r.*t.on ? "" : "-") + std::string(t.name);
    if (!item.empty()) out += "," + item;
  }
  return out;
}

}  // namespace

const std::array<PlannerConfig::Preset, 4>& PlannerConfig::presets() {
  static const std::array<Preset, 4> list{{
      {"default",
       "the proposed planner with every technique that pays, and the design loop's "
       "additions (goalskip, refuse, escape, early, prefer, shorten, rescue)"},
      {"baseline", "RRT per leg (§III-B) with the design loop's additions"},
      {"paper",
       "the paper's proposed planner (§V): samples, steering, paths, trees; none of our "
       "additions"},
      {"literal",
       "the paper's baseline read literally: RRT per leg, tried goal nodes tried again, "
       "none of our additions"},
  }};
  return list;
}

PlannerConfig PlannerConfig::from_preset(std::string_view name, std::string_view option) {
  if (name == "default") return default_config();
  if (name == "baseline") return baseline_config();
  if (name == "paper") return paper_config();
  if (name == "literal") return literal_config();
  std::string known;
  for (const Preset& p : presets()) known += std::string(known.empty() ? "" : ", ") + p.name;
  throw InputError(std::string(option) + ": unknown planner preset '" + std::string(name) + "' (" +
                   known + ")");
}

const std::array<PlannerConfig::Switch, 7>& PlannerConfig::switches() {
  static const std::array<Switch, 7> list{{
      {"goalskip", &PlannerConfig::goalskip,
       "an RRT does not steer to the goal again from a node it already tried"},
      {"refuse", &PlannerConfig::refuse,
       "a leg unfound after 300 RRT iterations whose ends the certified free grid "
       "separates stops there"},
      {"escape", &PlannerConfig::escape,
       "unfound tours are graded by how walled off their stops are; walling objects move "
       "first; no move leaves a stop without a free goal pose"},
      {"early", &PlannerConfig::early,
       "a proposal stops being planned once a lower bound of its cost is rejected"},
      {"prefer", &PlannerConfig::prefer,
       "preference terms bounded and scaled to their tolerances, preference moves, an "
       "opening arrangement of the input, an arrangement clear of the found tours, and a "
       "final polish that keeps every found tour"},
      {"shorten", &PlannerConfig::shorten,
       "with prefer, last in the polish when every tour is found: layouts at a score no "
       "lower whose tour proxy is more than 1 % lower, kept at a lower total cost"},
      {"rescue", &PlannerConfig::rescue,
       "after the design, the first 5 unfound tours are planned again with the lattice "
       "planner answering up to 4 legs of each that the RRT misses"},
  }};
  return list;
}

std::string PlannerConfig::name() const {
  const PlannerConfig base = from_preset(preset);
  std::string out = preset;
  for (const Switch& s : switches())
    if (this->*s.on != base.*s.on) out += std::string(",") + (this->*s.on ? "" : "-") + s.name;
  if (proposed) out += reuse_diff(reuse, base.reuse);
  return out;
}

std::string PlannerConfig::describe() const {
  std::string out = name() + " (" + (proposed ? "proposed planner: " + reuse.names() : "RRT per leg");
  for (const Switch& s : switches())
    if (this->*s.on) out += std::string(", ") + s.name;
  return out + ")";
}

std::string PlannerConfig::help() {
  const auto row = [](std::string name, const char* what) {
    name.resize(std::max<std::size_t>(name.size(), 10), ' ');
    return "    " + name + what + "\n";
  };
  std::string out = "  presets:\n";
  for (const Preset& p : presets()) out += row(p.name, p.what);
  out += "  switches (NAME on, -NAME off), the design loop's:\n";
  for (const Switch& s : switches()) out += row(s.name, s.what);
  out += "  and the proposed planner's techniques (NAME, -NAME, NAME=N):\n";
  for (const ReuseOptions::Technique& t : ReuseOptions::techniques()) out += row(t.name, t.what);
  return out;
}

}  // namespace hrs::optimize
