// SPDX-License-Identifier: GPL-3.0-or-later
#include "experiments/stats.h"

#include <cmath>
#include <map>

namespace hrs::experiments {

Summary summarize(const std::vector<double>& values) {
  Summary s;
  double sum = 0.0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    sum += v;
    ++s.n;
  }
  if (s.n == 0) return s;
  s.mean = sum / s.n;
  if (s.n < 2) return s;
  double sq = 0.0;
  for (double v : values)
    if (!std::isnan(v)) sq += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(sq / (s.n - 1));
  return s;
}

Table summarize_table(const Table& rows, const std::vector<std::string>& group_by,
                      const std::vector<std::string>& measures) {
  std::vector<std::vector<std::string>> order;
  std::map<std::vector<std::string>, std::vector<const Row*>> groups;
  for (const Row& r : rows) {
    std::vector<std::string> key;
    for (const auto& g : group_by) key.push_back(r.get(g).value_or(""));
    auto [it, inserted] = groups.try_emplace(key);
    if (inserted) order.push_back(key);
    it->second.push_back(&r);
  }
  Table out;
  for (const auto& key : order) {
    const auto& members = groups[key];
    Row s;
    for (std::size_t i = 0; i < group_by.size(); ++i) s.set(group_by[i], key[i]);
    s.set("n", static_cast<long>(members.size()));
    for (const auto& m : measures) {
      std::vector<double> values;
      for (const Row* r : members)
        if (auto v = r->number(m)) values.push_back(*v);
      if (values.empty()) continue;
      const Summary sum = summarize(values);
      if (sum.n == 0) continue;
      s.set(m + "_mean", sum.mean);
      s.set(m + "_sd", sum.sd);
    }
    out.push_back(std::move(s));
  }
  return out;
}

void add_ratio(Table& summary, const std::string& column, const std::string& reference,
               const std::vector<std::string>& match, const std::string& measure) {
  const std::string mean = measure + "_mean";
  for (Row& r : summary) {
    const auto own = r.number(mean);
    if (!own || *own == 0.0) continue;
    for (const Row& ref : summary) {
      if (ref.get(column) != reference) continue;
      bool same = true;
      for (const auto& m : match) same = same && ref.get(m) == r.get(m);
      if (!same) continue;
      if (const auto base = ref.number(mean))
        r.set(measure + "_ratio_vs_" + reference, *base / *own);
      break;
    }
  }
}

}  // namespace hrs::experiments
