// SPDX-License-Identifier: GPL-3.0-or-later
#include "optimize/sequences.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <set>

#include "geometry/error.h"

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

//! One prefix of a layer: its last node and where it came from.
struct Prefix {
  int parent;  //!< index in the previous layer (-1 for the start)
  int node;
};

//! Ranking data of the current layer's prefixes.
struct Key {
  double cost;  //!< −log L of the prefix, summed from the start in order
  int rank;     //!< position of the prefix's node sequence in lexicographic order
};

//! Best first: lower cost, then lexicographically smaller node indices.
bool better(const Key& a, const Key& b) { return a.cost != b.cost ? a.cost < b.cost : a.rank < b.rank; }

//! The layer of prefixes one node longer than `last`: for each node j, the
//! `m` best extensions to j; `keys` become theirs (ranks renumbered).
std::vector<Prefix> extend_layer(const AoGraph& graph, const std::vector<Prefix>& last,
                                 std::vector<Key>& keys, std::size_t m,
                                 const std::atomic<bool>* stop) {
  const int n = static_cast<int>(graph.nodes().size());
  std::vector<Prefix> layer;
  std::vector<Key> next_keys;
  std::vector<std::pair<Key, int>> candidates;  // key (rank of the parent), parent index
  for (int j = 0; j < n; ++j) {
    throw_if_stopped(stop, "sequence enumeration");
    candidates.clear();
    for (std::size_t e = 0; e < last.size(); ++e) {
      const double p = graph.probability(last[e].node, j);
      if (p <= 0.0) continue;
      candidates.push_back({{keys[e].cost - std::log(p), keys[e].rank}, static_cast<int>(e)});
    }
    auto order = [&](const auto& a, const auto& b) { return better(a.first, b.first); };
    if (candidates.size() > m) {
      std::nth_element(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(m),
                       candidates.end(), order);
      candidates.resize(m);
    }
    for (const auto& [key, parent] : candidates) {
      layer.push_back({parent, j});
      next_keys.push_back(key);  // rank of the parent for now
    }
  }
  // Lexicographic rank of the new prefixes: by the parent's rank, then the node.
  std::vector<int> index(layer.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<int>(i);
  std::sort(index.begin(), index.end(), [&](int a, int b) {
    const int ra = next_keys[a].rank, rb = next_keys[b].rank;
    return ra != rb ? ra < rb : layer[a].node < layer[b].node;
  });
  for (std::size_t r = 0; r < index.size(); ++r) next_keys[index[r]].rank = static_cast<int>(r);
  keys = std::move(next_keys);
  return layer;
}

//! The sequence ending at prefix `at` of the last layer, with its likelihood.
Sequence sequence_of(const AoGraph& graph, const std::vector<std::vector<Prefix>>& layers, int at) {
  std::vector<int> nodes(layers.size());
  for (std::size_t k = layers.size(); k-- > 0;) {
    nodes[k] = layers[k][static_cast<std::size_t>(at)].node;
    at = layers[k][static_cast<std::size_t>(at)].parent;
  }
  Sequence seq;
  seq.likelihood = 1.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    seq.nodes.push_back(graph.nodes()[nodes[i]]);
    if (i > 0) seq.likelihood *= graph.probability(nodes[i - 1], nodes[i]);
  }
  return seq;
}

}  // namespace

// Layered selection rather than best-first search, so that memory is bounded
// by count × nodes × visits whatever the graph: the `count` best sequences of
// k + 1 nodes ending at j extend sequences among the `count` best of k nodes
// ending at their second-to-last node (any other prefix is beaten by `count`
// prefixes with the same extension). The order is the best-first order: lower
// cost, then lexicographically smaller node indices.
std::vector<Sequence> top_sequences(const AoGraph& graph, const std::string& start, int visits,
                                    int count, const std::atomic<bool>* stop) {
  std::vector<Sequence> out;
  const int s = graph.index_of(start);
  if (s < 0 || count <= 0 || visits < 0) return out;
  const auto m = static_cast<std::size_t>(count);
  std::vector<std::vector<Prefix>> layers{{{-1, s}}};
  std::vector<Key> keys{{0.0, 0}};
  for (int step = 0; step < visits; ++step) {
    std::vector<Prefix> layer = extend_layer(graph, layers.back(), keys, m, stop);
    if (layer.empty()) return out;
    layers.push_back(std::move(layer));
  }
  std::vector<int> best(keys.size());
  for (std::size_t i = 0; i < best.size(); ++i) best[i] = static_cast<int>(i);
  std::sort(best.begin(), best.end(), [&](int a, int b) { return better(keys[a], keys[b]); });
  if (best.size() > m) best.resize(m);
  for (const int b : best) out.push_back(sequence_of(graph, layers, b));
  return out;
}

std::vector<Sequence> scene_sequences(const geometry::Scene& scene,
                                      const std::atomic<bool>* stop) {
  const AoGraph graph(scene.activity);
  return top_sequences(graph, std::string(geometry::kStartNodeId), scene.activity.visits,
                       scene.activity.sequences, stop);
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
