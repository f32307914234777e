#include "planning/reuse_options.h"

#include <algorithm>
#include <cstdlib>

#include "geometry/error.h"

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

ReuseOptions ReuseOptions::parse(std::string_view list) {
  ReuseOptions o = none();
  if (list == "none") return o;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string_view item = list.substr(start, end - start);
    const bool off = item.starts_with('-');
    const std::string_view name = off ? item.substr(1) : item;
    const auto t =
        std::ranges::find_if(techniques(), [name](const Technique& x) { return name == x.name; });
    const std::size_t eq = name.find('=');
    const auto p = std::ranges::find_if(parameters(), [&](const Parameter& x) {
      return eq != std::string_view::npos && name.substr(0, eq) == x.technique;
    });
    if (!off && p != parameters().end()) {
      const std::string digits(name.substr(eq + 1));
      char* stop = nullptr;
      const long n = std::strtol(digits.c_str(), &stop, 10);
      if (digits.empty() || *stop != '\0' || n < 1 || n > 1'000'000)
        throw InputError("--reuse: '" + std::string(name) + "': " + p->technique +
                         "=N needs a whole number of " + p->unit + " in 1..1000000");
      o.*p->on = true;
      o.*p->value = static_cast<int>(n);
    } else if (name == "all" && !off) {
      const ReuseOptions d;  // every technique that is on by default
      for (const Technique& x : techniques()) o.*x.on = o.*x.on || d.*x.on;
    } else if (t != techniques().end()) {
      o.*t->on = !off;
    } else {
      std::string known;
      for (const Technique& x : techniques()) known.append(", ").append(x.name);
      for (const Parameter& x : parameters()) known.append(", ").append(x.technique).append("=N");
      throw InputError("--reuse: unknown technique '" + std::string(item) +
                       "' (all, none, or a comma list of all" + known +
                       "; -NAME turns one off, e.g. all,-trees)");
    }
    start = end + 1;
  }
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
