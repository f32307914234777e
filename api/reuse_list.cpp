// SPDX-License-Identifier: GPL-3.0-or-later
#include "api/reuse_list.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "geometry/error.h"
#include "optimize/planner_config.h"

namespace hrs::api {
namespace {

using planning::ReuseOptions;

[[noreturn]] void unknown_item(std::string_view item, std::string_view option) {
  std::string known;
  for (const ReuseOptions::Technique& x : ReuseOptions::techniques())
    known.append(", ").append(x.name);
  for (const ReuseOptions::Parameter& x : ReuseOptions::parameters())
    known.append(", ").append(x.technique).append("=N");
  if (option == "--reuse")
    throw InputError("--reuse: unknown technique '" + std::string(item) +
                     "' (all, none, or a comma list of all" + known +
                     "; -NAME turns one off, e.g. all,-trees)");
  std::string switches;
  for (const optimize::PlannerConfig::Switch& x : optimize::PlannerConfig::switches())
    switches.append(", ").append(x.name);
  throw InputError(std::string(option) + ": unknown item '" + std::string(item) +
                   "' (a preset, then a comma list of" + switches.substr(1) + known +
                   "; -NAME turns one off, e.g. default,-trees)");
}

//! NAME=N: turns the technique on with parameter N; false when `name` is no
//! known NAME=N.
bool apply_parameter(std::string_view name, ReuseOptions& o, std::string_view option) {
  const std::size_t eq = name.find('=');
  if (eq == std::string_view::npos) return false;
  const auto& list = ReuseOptions::parameters();
  const auto p = std::ranges::find_if(
      list, [&](const ReuseOptions::Parameter& x) { return name.substr(0, eq) == x.technique; });
  if (p == list.end()) return false;
  const std::string digits(name.substr(eq + 1));
  char* stop = nullptr;
  const long n = std::strtol(digits.c_str(), &stop, 10);
  if (digits.empty() || *stop != '\0' || n < 1 || n > 1'000'000)
    throw InputError(std::string(option) + ": '" + std::string(name) + "': " + p->technique +
                     "=N needs a whole number of " + p->unit + " in 1..1000000");
  o.*p->on = true;
  o.*p->value = static_cast<int>(n);
  return true;
}

//! One item of the list: all, NAME, -NAME or NAME=N.
void apply_item(std::string_view item, ReuseOptions& o, std::string_view option = "--reuse") {
  const bool off = item.starts_with('-');
  const std::string_view name = off ? item.substr(1) : item;
  if (!off && apply_parameter(name, o, option)) return;
  if (!off && name == "all") {
    const ReuseOptions d;  // every technique that is on by default
    for (const ReuseOptions::Technique& x : ReuseOptions::techniques())
      o.*x.on = o.*x.on || d.*x.on;
    return;
  }
  const auto& list = ReuseOptions::techniques();
  const auto t =
      std::ranges::find_if(list, [name](const ReuseOptions::Technique& x) { return name == x.name; });
  if (t == list.end()) unknown_item(item, option);
  o.*t->on = !off;
}

}  // namespace

ReuseOptions parse_reuse(std::string_view list) {
  ReuseOptions o = ReuseOptions::none();
  if (list == "none") return o;
  for (std::size_t start = 0; start <= list.size();) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    apply_item(list.substr(start, end - start), o);
    start = end + 1;
  }
  return o;
}

optimize::PlannerConfig parse_planner(std::string_view text, std::string_view option) {
  const std::size_t comma = std::min(text.find(','), text.size());
  std::string_view preset = text.substr(0, comma);
  if (preset == "proposed") preset = "default";  // the name before presets existed
  optimize::PlannerConfig c = optimize::PlannerConfig::from_preset(preset, option);
  for (std::size_t start = comma + 1; start <= text.size() && comma < text.size();) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string_view item = text.substr(start, end - start);
    start = end + 1;
    const bool off = item.starts_with('-');
    const std::string_view name = off ? item.substr(1) : item;
    const auto& list = optimize::PlannerConfig::switches();
    const auto s = std::ranges::find_if(
        list, [name](const optimize::PlannerConfig::Switch& x) { return name == x.name; });
    if (s != list.end()) {
      c.*s->on = !off;
      continue;
    }
    if (!c.proposed)
      throw InputError(std::string(option) + ": '" + std::string(item) + "': the " + c.preset +
                       " preset plans each leg with the RRT, which has no reuse techniques "
                       "(they need the default or paper preset)");
    apply_item(item, c.reuse, option);
  }
  return c;
}

}  // namespace hrs::api
