#include "optimize/sequences.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <queue>
#include <set>

namespace hrs::optimize {

AoGraph::AoGraph(const geometry::Activity& activity) {
  std::set<std::string> ids;
  for (const auto& [from, row] : activity.transitions) {
    ids.insert(from);
    for (const auto& [to, p] : row) ids.insert(to);
  }
  nodes_.assign(ids.begin(), ids.end());
  const int n = static_cast<int>(nodes_.size());
  p_.assign(n, std::vector<double>(n, 0.0));
  for (const auto& [from, row] : activity.transitions) {
    const int a = index_of(from);
    double leave = 0.0;
    for (const auto& [to, p] : row)
      if (to != from) leave += p;
    if (leave <= 0.0) continue;  // absorbing: no way out
    for (const auto& [to, p] : row)
      if (to != from) p_[a][index_of(to)] = p / leave;
  }
}

int AoGraph::index_of(const std::string& id) const {
  auto it = std::lower_bound(nodes_.begin(), nodes_.end(), id);
  if (it == nodes_.end() || *it != id) return -1;
  return static_cast<int>(it - nodes_.begin());
}

namespace {

struct Partial {
  double cost;             // −log L of the prefix
  std::vector<int> nodes;  // node indices
  // Min-heap order: lower cost first, then lexicographically smaller nodes.
  bool operator<(const Partial& o) const {
    if (cost != o.cost) return cost > o.cost;
    return nodes > o.nodes;
  }
};

}  // namespace

std::vector<Sequence> top_sequences(const AoGraph& graph, const std::string& start, int visits,
                                    int count) {
  std::vector<Sequence> out;
  const int s = graph.index_of(start);
  if (s < 0 || count <= 0 || visits < 0) return out;
  const int n = static_cast<int>(graph.nodes().size());
  std::priority_queue<Partial> queue;
  queue.push({0.0, {s}});
  while (!queue.empty() && static_cast<int>(out.size()) < count) {
    Partial top = queue.top();
    queue.pop();
    if (static_cast<int>(top.nodes.size()) == visits + 1) {
      Sequence seq;
      seq.likelihood = 1.0;
      for (std::size_t i = 0; i < top.nodes.size(); ++i) {
        seq.nodes.push_back(graph.nodes()[top.nodes[i]]);
        if (i > 0) seq.likelihood *= graph.probability(top.nodes[i - 1], top.nodes[i]);
      }
      out.push_back(std::move(seq));
      continue;
    }
    const int last = top.nodes.back();
    for (int next = 0; next < n; ++next) {
      const double p = graph.probability(last, next);
      if (p <= 0.0) continue;
      Partial child{top.cost - std::log(p), top.nodes};
      child.nodes.push_back(next);
      queue.push(std::move(child));
    }
  }
  return out;
}

std::vector<Sequence> scene_sequences(const geometry::Scene& scene) {
  const AoGraph graph(scene.activity);
  return top_sequences(graph, "door", scene.activity.visits, scene.activity.sequences);
}

std::map<std::string, double> object_scales(const std::vector<Sequence>& sequences) {
  std::map<std::string, double> alpha;
  for (const auto& seq : sequences) {
    const std::size_t k = seq.nodes.size();
    if (k < 2) continue;
    std::map<std::string, int> counts;
    for (std::size_t i = 0; i < k; ++i) counts[seq.nodes[i]] += (i == 0 || i + 1 == k) ? 1 : 2;
    const double total = 2.0 * static_cast<double>(k - 1);  // two ends per leg
    for (const auto& [id, c] : counts) alpha[id] += seq.likelihood * c / total;
  }
  return alpha;
}

}  // namespace hrs::optimize
