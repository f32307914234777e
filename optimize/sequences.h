// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The action-object (AO) graph and the M most likely object sequences that the
// wheelchair must tour (paper §III-A), plus the per-object path-cost scale α_i
// of §III-D.
//
// Self-transitions. A row's self-transition p(a→a) means "stay at a"; a tour
// never drives from an object to itself, so the sequences are paths of the
// embedded jump chain: every row is conditioned on leaving its node,
//   p'(a→b) = p(a→b) / (1 − p(a→a))  for b ≠ a,
// which is exactly the probability that the next *different* node visited
// after a is b (staying any number of times, then moving). A row whose
// self-transition is 1 (or that has no row) has no way out, so a sequence can
// end there but not pass through it. L(s) = Π p' over the legs of s, so the
// likelihoods of all sequences of a given length sum to 1 when every node has
// a way out. Sequences may revisit a node, never twice in a row.
//
// Enumeration is exact: the sequences in order of −log L (summed along the
// sequence), ties broken by the node indices, so the result is deterministic.
// It proceeds layer by layer, keeping the `count` best prefixes ending at each
// node, so its memory is bounded by count × nodes × visits (a best-first
// search over prefixes grows exponentially with `visits` on graphs with many
// equally likely moves).

#include <atomic>
#include <map>
#include <string>
#include <vector>

#include "geometry/scene.h"

namespace hrs::optimize {

//! The AO graph with self-transitions removed and rows renormalized.
class AoGraph {
 public:
  //! Builds the graph from the scene's transitions table (nodes sorted by id,
  //! "door" included as any other node).
  explicit AoGraph(const geometry::Activity& activity);

  //! Node ids, sorted.
  const std::vector<std::string>& nodes() const { return nodes_; }
  //! Index of a node id, or -1.
  int index_of(const std::string& id) const;
  //! p'(from→to): the jump-chain probability (0 for from == to).
  double probability(int from, int to) const { return p_[from][to]; }

 private:
  std::vector<std::string> nodes_;
  std::vector<std::vector<double>> p_;
};

//! One object sequence: "door" then `visits` objects, and its likelihood.
struct Sequence {
  std::vector<std::string> nodes;  //!< starts with the start node ("door")
  double likelihood = 0.0;         //!< L(s) = Π p' over consecutive nodes
};

//! The `count` most likely sequences of `visits` moves from `start`, most
//! likely first (fewer if fewer exist). Exact; memory O(count · nodes · visits).
//! `stop` (may be null) is checked for every node of every step (up to about
//! a millisecond apart at the format's limits): once set, hrs::Interrupted is
//! thrown (geometry/error.h); no partial result is returned.
std::vector<Sequence> top_sequences(const AoGraph& graph, const std::string& start, int visits,
                                    int count, const std::atomic<bool>* stop = nullptr);

//! The scene's M sequences (activity.sequences, activity.visits, from "door");
//! `stop` as for top_sequences().
std::vector<Sequence> scene_sequences(const geometry::Scene& scene,
                                      const std::atomic<bool>* stop = nullptr);

//! α_i of §III-D for every node of the sequences: in sequence s a node is
//! counted once at the start or end and twice in the middle (the number of
//! legs touching it; counts add up for a revisit), freq_s = count / total
//! count of s, and α_i = Σ_{s ∋ i} L(s)·freq_s(i). The start node ("door")
//! is counted like any other node.
std::map<std::string, double> object_scales(const std::vector<Sequence>& sequences);

}  // namespace hrs::optimize
