// SPDX-License-Identifier: GPL-3.0-or-later
#include "api/design_request.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "access/accessibility.h"
#include "api/operations.h"
#include "geometry/error.h"

namespace hrs::api {

namespace {

void in_range(const char* option, long long v, long long min, long long max) {
  if (v < min || v > max)
    throw InputError(std::string("--") + option + ": " + std::to_string(v) + " is outside [" +
                     std::to_string(min) + ", " + std::to_string(max) + "]");
}

//! --weights as numbers: 3 or 5 finite values in [0, 1e6].
std::vector<double> parse_weights(const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(',', start);
    const std::string field = text.substr(start, end == std::string::npos ? end : end - start);
    char* stop = nullptr;
    const double v = std::strtod(field.c_str(), &stop);
    if (field.empty() || stop != field.c_str() + field.size() || !std::isfinite(v))
      throw InputError("--weights: not a finite number: '" + field + "' in '" + text + "'");
    out.push_back(v);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (out.size() != 3 && out.size() != 5)
    throw InputError("--weights: expected 3 or 5 comma-separated numbers, got '" + text + "'");
  for (const double x : out)
    if (x < 0.0 || x > 1e6)
      throw InputError("--weights '" + text + "': each weight must be finite, >= 0 and <= 1e6");
  return out;
}

}  // namespace

void DesignRequest::validate() const {
  (void)planner_config();
  in_range("seed", seed, 0, 1LL << 53);
  in_range("iterations", iterations, 0, 100000000);
  in_range("designs", designs, 1, 1000);
  (void)access::Rules::named(rules);
  in_range("access-goal", access_goal, 1, 100);
  in_range("restarts", restarts, 1, 100);
  in_range("threads", threads, 0, 1024);
  if (weights) (void)parse_weights(*weights);
}

optimize::PlannerConfig DesignRequest::planner_config() const {
  return design_planner(planner, reuse, disable);
}

optimize::DesignOptions DesignRequest::options(long long d) const {
  validate();
  return design_options(static_cast<std::uint64_t>(seed + d), static_cast<int>(iterations),
                        static_cast<int>(threads), planner_config());
}

void DesignRequest::apply_weights(geometry::Scene& scene) const {
  if (!weights) return;
  const std::vector<double> v = parse_weights(*weights);
  scene.weights.path = {v[0], v[1], v[2]};
  if (v.size() == 5) scene.weights.interior = {v[3], v[4]};
}

}  // namespace hrs::api
