#pragma once
// The candidate lists' second stage (alpha_nearness.cpp): the minimum
// spanning forest of the nearest lists' graph under the ascent's costs,
// grown in parts on several threads and joined.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "candidates.h"
#include "space.h"

namespace aco::detail {

// The minimum spanning forest of a fixed graph under costs
// length(a, b) + pi[a] + pi[b] that change at every step of the ascent, with
// ties broken by edge index: a strict order, so the forest is unique and
// Prim finds the one Kruskal would. Kruskal sorted all n k edges at every
// step, 80 % of the ascent (pcb1173: 83 ms of a 350 ms run); Prim looks at
// each edge from its two ends and keeps only the frontier in its heap, where a better
// offer moves a hole up instead of adding a second entry (a heap of every
// offer was as slow as the sort).
//
// On several threads the holes are split into parts (split()): each part's
// forest is grown by Prim over the edges inside it, at once, and Kruskal joins
// the parts' forests with the edges between parts. An edge inside a part that
// its part's forest leaves out is the longest of a cycle of that part's
// edges, so no spanning forest of the whole holds it either: the join finds
// the same forest as Prim over the whole graph.
//
// The join looks only at what an edge between parts can change. A part's
// tree edge can leave the forest only if it lies on a cycle through edges
// between parts, so on the tree path between two holes that such edges end
// at (terminals). Each part keeps of its forest only those paths, cut at the
// terminals and where they branch into chains, and each chain stands for its
// longest edge: a cycle holds a chain whole or not at all, so only that edge
// can leave. Kruskal over the chains and the edges between parts then says
// which chains' longest edges leave and which edges between parts come in.
// Sorting every tree edge and joining them all, as before, made a two-thread
// step no faster than one thread's Prim over the whole: pcb1173, 1000 steps
// timed in a copy, 265-275 ms on two threads against 235 on one; now 184-190.
class SpanningForest {
 public:
  struct Edge {
    HoleIndex a, b;  // a < b
    double length;
  };
  SpanningForest(std::vector<Edge> edges, HoleIndex holes)
      : edges_(std::move(edges)), n_(holes), first_arc_(static_cast<std::size_t>(holes) + 1, 0),
        in_tree_((edges_.size() + 63) / 64, 0), parts_(1) {
    for (const Edge& e : edges_) {
      ++first_arc_[e.a + 1];
      ++first_arc_[e.b + 1];
    }
    for (HoleIndex i = 0; i < n_; ++i) first_arc_[i + 1] += first_arc_[i];
    arcs_.resize(first_arc_[n_]);
    std::vector<std::uint32_t> fill(first_arc_.begin(), first_arc_.end() - 1);
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
      arcs_[fill[edges_[e].a]++] = {edges_[e].b, e, edges_[e].length};
      arcs_[fill[edges_[e].b]++] = {edges_[e].a, e, edges_[e].length};
    }
    arc_end_.assign(first_arc_.begin() + 1, first_arc_.end());
    parts_[0].holes.resize(n_);
    std::iota(parts_[0].holes.begin(), parts_[0].holes.end(), HoleIndex{0});
    parts_[0].size_arrays(n_, in_tree_.size(), false);
  }
  const std::vector<Edge>& edges() const { return edges_; }
  // The forest's edges, by edge index, and their costs under the last pi.
  const std::vector<std::uint32_t>& tree() const { return tree_; }
  const std::vector<double>& tree_costs() const { return tree_costs_; }

  // From now on the holes are grown in parts (part_of[h] < parts): see grow_part().
  void split(const std::vector<std::uint32_t>& part_of, std::uint32_t parts) {
    parts_.assign(parts, {});
    for (HoleIndex h = 0; h < n_; ++h) parts_[part_of[h]].holes.push_back(h);
    for (Part& part : parts_) part.size_arrays(n_, in_tree_.size(), true);
    // Each hole's arcs inside its part first, and its part's Prim reads only
    // those. (Which forest Prim grows, and in what order, does not depend on
    // the order it reads a hole's arcs in: an offer is the least of them.)
    for (HoleIndex h = 0; h < n_; ++h) {
      Arc* const first = arcs_.data() + first_arc_[h];
      Arc* const last = arcs_.data() + first_arc_[h + 1];
      const Arc* inner_end =
          std::partition(first, last, [&](const Arc& arc) { return part_of[arc.to] == part_of[h]; });
      arc_end_[h] = static_cast<std::uint32_t>(inner_end - arcs_.data());
    }
    terminal_.assign(n_, 0);
    for (HoleIndex h = 0; h < n_; ++h) terminal_[h] = arc_end_[h] != first_arc_[h + 1];
    // The edges between parts, priced and sorted by the parts in turn.
    std::uint32_t turn = 0;
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
      if (part_of[edges_[e].a] != part_of[edges_[e].b]) parts_[turn++ % parts].between.push_back({0.0, e});
    }
    root_.resize(n_);
  }

  std::uint32_t parts() const { return static_cast<std::uint32_t>(parts_.size()); }

  // Grows part p's forest under `pi` over the edges inside it (the whole
  // forest, unsplit). Parts may grow at once, on threads of their own; then
  // join() makes them one forest.
  void grow_part(std::uint32_t p, const std::vector<double>& pi) {
    Part& part = parts_[p];
    part.grow(*this, pi);
    if (parts_.size() == 1) return;
    // Sorted for Kruskal: the part's chains, and its share of the edges between parts.
    part.find_chains(*this);
    std::sort(part.chains.begin(), part.chains.end());
    for (Priced& edge : part.between) edge.first = cost(edge.second, pi);
    std::sort(part.between.begin(), part.between.end());
  }

  // Once every part has grown under `pi`: the forest, and its cost summed by
  // edge index (the same bits however it was grown).
  double join(const std::vector<double>& pi) {
    for (const Part& part : parts_) {
      for (std::size_t word = 0; word < in_tree_.size(); ++word) in_tree_[word] |= part.grown_bits[word];
    }
    if (parts_.size() > 1) join_parts();
    tree_.clear();
    tree_costs_.clear();
    double total = 0.0;
    for (std::size_t word = 0; word < in_tree_.size(); ++word) {
      for (std::uint64_t bits = in_tree_[word]; bits != 0; bits &= bits - 1) {
        const auto e = static_cast<std::uint32_t>(64 * word + static_cast<std::size_t>(__builtin_ctzll(bits)));
        tree_.push_back(e);
        tree_costs_.push_back(cost(e, pi));
        total += tree_costs_.back();
      }
      in_tree_[word] = 0;
    }
    return total;
  }

  // The forest under `pi` on this thread: its cost, as join() gives it.
  double grow(const std::vector<double>& pi) {
    for (std::uint32_t p = 0; p < parts(); ++p) grow_part(p, pi);
    return join(pi);
  }

 private:
  static constexpr std::uint32_t kOutside = UINT32_MAX;
  static constexpr std::uint8_t kJoint = 0xFF;
  // A spanned hole's offer: no edge's cost is below it.
  static constexpr double kSpanned = -std::numeric_limits<double>::infinity();
  struct Arc {
    HoleIndex to;
    std::uint32_t edge;
    double length;
  };
  // An edge priced: (cost, index), the order Kruskal and Prim take edges in.
  using Priced = std::pair<double, std::uint32_t>;
  void mark(std::uint32_t e) { in_tree_[e / 64] |= std::uint64_t{1} << (e % 64); }
  void unmark(std::uint32_t e) { in_tree_[e / 64] &= ~(std::uint64_t{1} << (e % 64)); }
  // Summed as (length + pi[a]) + pi[b], a < b, whichever end is reached first:
  // the same bits from either side.
  double cost(std::uint32_t e, const std::vector<double>& pi) const {
    return edges_[e].length + pi[edges_[e].a] + pi[edges_[e].b];
  }

  // A path of a part's forest between two terminals or branchings, with no
  // terminal or branching inside: (its longest edge, its two ends).
  struct Chain {
    Priced longest;
    HoleIndex from, to;
    bool operator<(const Chain& o) const { return longest < o.longest; }
  };
  // One thread's Prim over the holes of a part. Its own arrays, indexed by
  // hole (half of them unused with two parts), so two threads never write
  // the same cache line.
  struct Part {
    std::vector<HoleIndex> holes;
    // For each hole not yet spanned: its best offer (cost, edge), and its place in heap.
    std::vector<double> offer_cost;
    std::vector<std::uint32_t> offer_edge, heap_at;
    std::vector<HoleIndex> heap;  // the holes offered an edge, a binary heap by better()
    std::vector<Priced> grown;    // the forest's edges, as taken
    // The same, a bit by edge index: what join() reads, a sixth of the
    // lines of `grown` to take from the core that grew it.
    std::vector<std::uint64_t> grown_bits;
    std::vector<Priced> between;  // its share of the edges between parts
    // Only when split: the holes in the order spanned (each after the hole
    // it hangs from), and by hole: grown's edge to that hole (kOutside for a
    // tree's first), the terminals at or below it, its tree's first hole, and
    // its degree in the paths between terminals, or kJoint where a chain ends.
    std::vector<HoleIndex> order;
    // Only when split: by hole, the hole its offer comes from (offer_edge's
    // other end). A spanned hole is offered nothing more, so from then on it
    // is the hole it hangs from: the chains' passes walk up the trees by it,
    // one load a step where finding the edge's other end took three dependent ones.
    std::vector<HoleIndex> offer_from;
    std::vector<std::uint32_t> via, below;
    std::vector<HoleIndex> first;
    std::vector<std::uint8_t> degree;
    std::vector<Chain> chains;

    void size_arrays(HoleIndex n, std::size_t edge_words, bool split) {
      grown_bits.assign(edge_words, 0);
      offer_cost.assign(n, 0.0);
      offer_edge.assign(n, 0);
      heap_at.assign(n, kOutside);
      if (!split) return;
      via.assign(n, kOutside);
      offer_from.assign(n, 0);
      below.assign(n, 0);
      first.assign(n, 0);
      degree.assign(n, 0);
    }
    void grow(const SpanningForest& f, const std::vector<double>& pi) {
      for (HoleIndex h : holes) offer_cost[h] = std::numeric_limits<double>::infinity();
      grown.clear();
      std::fill(grown_bits.begin(), grown_bits.end(), 0);
      order.clear();
      const bool split = !via.empty();
      for (HoleIndex root : holes) {
        if (offer_cost[root] == kSpanned) continue;
        if (split) {
          via[root] = kOutside;
          order.push_back(root);
        }
        span(f, root, pi);
        while (!heap.empty()) {
          const HoleIndex h = pop();
          if (split) {
            via[h] = static_cast<std::uint32_t>(grown.size());
            order.push_back(h);
          }
          grown.push_back({offer_cost[h], offer_edge[h]});
          grown_bits[offer_edge[h] / 64] |= std::uint64_t{1} << (offer_edge[h] % 64);
          span(f, h, pi);
        }
      }
    }
    HoleIndex up(HoleIndex h) const { return offer_from[h]; }
    // Whether h's edge up lies on a path between two terminals of its tree:
    // it has some of them below it, but not all.
    bool on_path(HoleIndex h) const { return via[h] != kOutside && below[h] > 0 && below[h] < below[first[h]]; }
    // The chains of the grown forest (see the class comment), in O(part).
    void find_chains(const SpanningForest& f) {
      for (HoleIndex h : order) {
        below[h] = f.terminal_[h];
        degree[h] = 0;
      }
      for (auto h = order.rbegin(); h != order.rend(); ++h) {
        if (via[*h] != kOutside) below[up(*h)] += below[*h];
      }
      for (HoleIndex h : order) {
        first[h] = via[h] == kOutside ? h : first[up(h)];
        if (!on_path(h)) continue;
        degree[h] = static_cast<std::uint8_t>(std::min(3, degree[h] + 1));
        const HoleIndex u = up(h);
        degree[u] = static_cast<std::uint8_t>(std::min(3, degree[u] + 1));
      }
      // A chain ends at a terminal, where paths branch, and at the top of
      // the paths (a hole they pass through without its edge up).
      for (HoleIndex h : order) {
        if (f.terminal_[h] || degree[h] >= 3 || (degree[h] > 0 && !on_path(h))) degree[h] = kJoint;
      }
      chains.clear();
      for (HoleIndex h : order) {
        if (degree[h] != kJoint || !on_path(h)) continue;
        Priced longest = grown[via[h]];
        HoleIndex x = up(h);
        for (; degree[x] != kJoint; x = up(x)) longest = std::max(longest, grown[via[x]]);
        chains.push_back({longest, h, x});
      }
    }
    bool better(HoleIndex x, HoleIndex y) const {
      return offer_cost[x] < offer_cost[y] || (offer_cost[x] == offer_cost[y] && offer_edge[x] < offer_edge[y]);
    }
    void place(std::size_t i, HoleIndex h) {
      heap[i] = h;
      heap_at[h] = static_cast<std::uint32_t>(i);
    }
    // Over h's arcs up to arc_end_: all of them, or those inside its part.
    void span(const SpanningForest& f, HoleIndex h, const std::vector<double>& pi) {
      offer_cost[h] = kSpanned;
      const double* p = pi.data();
      const Arc* arc = f.arcs_.data() + f.first_arc_[h];
      const Arc* end = f.arcs_.data() + f.arc_end_[h];
      HoleIndex* const from = offer_from.empty() ? nullptr : offer_from.data();
      for (; arc != end; ++arc) {
        const HoleIndex to = arc->to;
        // cost(arc->edge, pi), read from the arc: the same sum, in the same order.
        const double c = arc->length + p[std::min(h, to)] + p[std::max(h, to)];
        if (!(c < offer_cost[to] || (c == offer_cost[to] && arc->edge < offer_edge[to]))) continue;
        offer_cost[to] = c;
        offer_edge[to] = arc->edge;
        if (from != nullptr) from[to] = h;
        if (heap_at[to] == kOutside) {
          heap.push_back(to);
          heap_at[to] = static_cast<std::uint32_t>(heap.size() - 1);
        }
        sift_up(heap_at[to]);
      }
    }
    void sift_up(std::size_t i) {
      const HoleIndex h = heap[i];
      for (; i > 0 && better(h, heap[(i - 1) / 2]); i = (i - 1) / 2) place(i, heap[(i - 1) / 2]);
      place(i, h);
    }
    HoleIndex pop() {
      const HoleIndex top = heap[0], h = heap.back();
      heap.pop_back();
      heap_at[top] = kOutside;
      if (heap.empty()) return top;
      std::size_t i = 0;
      for (;;) {
        std::size_t c = 2 * i + 1;
        if (c >= heap.size()) break;
        if (c + 1 < heap.size() && better(heap[c + 1], heap[c])) ++c;
        if (!better(heap[c], h)) break;
        place(i, heap[c]);
        i = c;
      }
      place(i, h);
      return top;
    }
  };

  void join_parts() {
    const auto parts = static_cast<std::uint32_t>(parts_.size());
    // Kruskal over the chains and the edges between parts, merged in order,
    // among the holes they end at. Every grown edge is marked already.
    for (const Part& part : parts_) {
      for (const Chain& c : part.chains) root_[c.from] = c.from, root_[c.to] = c.to;
      for (auto [c, e] : part.between) root_[edges_[e].a] = edges_[e].a, root_[edges_[e].b] = edges_[e].b;
    }
    auto find = [this](HoleIndex x) {
      while (root_[x] != x) x = root_[x] = root_[root_[x]];
      return x;
    };
    std::vector<const Chain*> chain(parts), chain_end(parts);
    std::vector<const Priced*> edge(parts), edge_end(parts);
    for (std::uint32_t p = 0; p < parts; ++p) {
      chain[p] = parts_[p].chains.data();
      chain_end[p] = chain[p] + parts_[p].chains.size();
      edge[p] = parts_[p].between.data();
      edge_end[p] = edge[p] + parts_[p].between.size();
    }
    for (;;) {
      // The least of the lists' heads: a chain (by its longest edge) or an edge between parts.
      const Priced* least = nullptr;
      std::uint32_t pick = 0;
      bool is_chain = false;
      for (std::uint32_t p = 0; p < parts; ++p) {
        if (chain[p] != chain_end[p] && (least == nullptr || chain[p]->longest < *least)) {
          least = &chain[p]->longest;
          pick = p;
          is_chain = true;
        }
        if (edge[p] != edge_end[p] && (least == nullptr || *edge[p] < *least)) {
          least = edge[p];
          pick = p;
          is_chain = false;
        }
      }
      if (least == nullptr) break;
      if (is_chain) {
        const Chain& c = *chain[pick]++;
        const HoleIndex ra = find(c.from), rb = find(c.to);
        if (ra == rb) {
          unmark(c.longest.second);  // the longest edge of a cycle
        } else {
          root_[ra] = rb;
        }
      } else {
        const std::uint32_t e = (edge[pick]++)->second;
        const HoleIndex ra = find(edges_[e].a), rb = find(edges_[e].b);
        if (ra == rb) continue;
        root_[ra] = rb;
        mark(e);
      }
    }
  }

  std::vector<Edge> edges_;
  HoleIndex n_;
  std::vector<std::uint32_t> first_arc_, arc_end_;
  std::vector<Arc> arcs_;
  std::vector<std::uint64_t> in_tree_;  // a bit by edge, between growing and summing
  // Written by join() alone, apart from edges_: the parts read edges_ at
  // every step, and a cost written there took the line from the core that
  // read it (and gave it back at its next read). That made a two-thread
  // step's join 7 times the one-thread join (pcb1173: 31 us a step against
  // 4.3, in a step of 190 us).
  std::vector<std::uint32_t> tree_;
  std::vector<double> tree_costs_;
  std::vector<Part> parts_;  // one unless split()
  std::vector<HoleIndex> root_;  // after split(): Kruskal's union-find
  std::vector<std::uint8_t> terminal_;  // after split(): whether a hole has an edge to another part
};

// Which of `parts` strips across the longer side of the holes' bounding box
// each hole is in, each strip of as many holes: few edges run between strips.
inline std::vector<std::uint32_t> strips(const Space& space, std::uint32_t parts) {
  const HoleIndex n = space.holes();
  const auto [lo, hi] = space.bounds();
  const bool across_x = hi.x - lo.x >= hi.y - lo.y;
  auto along = [&](HoleIndex h) { return across_x ? space.point(h).x : space.point(h).y; };
  std::vector<HoleIndex> by_position(n);
  std::iota(by_position.begin(), by_position.end(), HoleIndex{0});
  std::sort(by_position.begin(), by_position.end(), [&](HoleIndex a, HoleIndex b) {
    return along(a) < along(b) || (along(a) == along(b) && a < b);
  });
  std::vector<std::uint32_t> part_of(n);
  for (HoleIndex r = 0; r < n; ++r) {
    part_of[by_position[r]] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(r) * parts / n);
  }
  return part_of;
}

}  // namespace aco::detail
