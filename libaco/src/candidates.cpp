#include "candidates.h"

#include "bucket_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nanoflann.hpp>
#include <numeric>
#include <utility>

namespace aco::detail {

namespace {

struct PointCloud {
  const Space* space;
  std::size_t kdtree_get_point_count() const { return space->holes(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return dim == 0 ? space->point(static_cast<HoleIndex>(i)).x : space->point(static_cast<HoleIndex>(i)).y;
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2,
                                                 std::size_t>;

// The minimum spanning forest of a fixed graph under costs
// length(a, b) + pi[a] + pi[b] that change at every step of the ascent, with
// ties broken by edge index: a strict order, so the forest is unique and
// Prim finds the one Kruskal would. Kruskal sorted all n k edges at every
// step, 80 % of the ascent (pcb1173: 83 ms of a 350 ms run); Prim looks at
// each edge from its two ends and keeps only the frontier in its heap, where a better
// offer moves a hole up instead of adding a second entry (a heap of every
// offer was as slow as the sort).
class SpanningForest {
 public:
  struct Edge {
    HoleIndex a, b;  // a < b
    double length;
    double cost = 0.0;  // of a tree edge: length + pi[a] + pi[b] at the last grow()
  };
  SpanningForest(std::vector<Edge> edges, HoleIndex holes)
      : edges_(std::move(edges)), n_(holes), first_arc_(static_cast<std::size_t>(holes) + 1, 0),
        offer_cost_(holes), offer_edge_(holes), heap_at_(holes, kOutside) {
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
  }
  const std::vector<Edge>& edges() const { return edges_; }
  // The forest's edges, in the order Prim took them: sums over them differ
  // from Kruskal's sorted order only in rounding (the same routes on all 11
  // instances of bench/tsplib, 30 or 5 iterations, seed 1, as with Kruskal).
  const std::vector<std::uint32_t>& tree() const { return tree_; }

  // Grows the forest under `pi` and returns its cost, summed in tree() order;
  // the tree's edges' `cost` is then up to date.
  double grow(const std::vector<double>& pi) {
    std::fill(offer_cost_.begin(), offer_cost_.end(), std::numeric_limits<double>::infinity());
    tree_.clear();
    for (HoleIndex root = 0; root < n_; ++root) {
      if (offer_cost_[root] == kSpanned) continue;
      span(root, pi);
      while (!heap_.empty()) {
        const HoleIndex h = pop();
        tree_.push_back(offer_edge_[h]);
        span(h, pi);
      }
    }
    for (std::uint32_t e : tree_) edges_[e].cost = cost(e, pi);
    double total = 0.0;
    for (std::uint32_t e : tree_) total += edges_[e].cost;
    return total;
  }

 private:
  static constexpr std::uint32_t kOutside = UINT32_MAX;
  // A spanned hole's offer: no edge's cost is below it.
  static constexpr double kSpanned = -std::numeric_limits<double>::infinity();
  struct Arc {
    HoleIndex to;
    std::uint32_t edge;
    double length;
  };
  // Summed as (length + pi[a]) + pi[b], a < b, whichever end is reached first:
  // the same bits from either side.
  double cost(std::uint32_t e, const std::vector<double>& pi) const {
    return edges_[e].length + pi[edges_[e].a] + pi[edges_[e].b];
  }
  bool better(HoleIndex x, HoleIndex y) const {
    return offer_cost_[x] < offer_cost_[y] || (offer_cost_[x] == offer_cost_[y] && offer_edge_[x] < offer_edge_[y]);
  }
  void place(std::size_t i, HoleIndex h) {
    heap_[i] = h;
    heap_at_[h] = static_cast<std::uint32_t>(i);
  }
  void span(HoleIndex h, const std::vector<double>& pi) {
    offer_cost_[h] = kSpanned;
    const double* p = pi.data();
    const Arc* arc = arcs_.data() + first_arc_[h];
    const Arc* end = arcs_.data() + first_arc_[h + 1];
    for (; arc != end; ++arc) {
      const HoleIndex to = arc->to;
      // cost(arc->edge, pi), read from the arc: the same sum, in the same order.
      const double c = arc->length + p[std::min(h, to)] + p[std::max(h, to)];
      if (!(c < offer_cost_[to] || (c == offer_cost_[to] && arc->edge < offer_edge_[to]))) continue;
      offer_cost_[to] = c;
      offer_edge_[to] = arc->edge;
      if (heap_at_[to] == kOutside) {
        heap_.push_back(to);
        heap_at_[to] = static_cast<std::uint32_t>(heap_.size() - 1);
      }
      sift_up(heap_at_[to]);
    }
  }
  void sift_up(std::size_t i) {
    const HoleIndex h = heap_[i];
    for (; i > 0 && better(h, heap_[(i - 1) / 2]); i = (i - 1) / 2) place(i, heap_[(i - 1) / 2]);
    place(i, h);
  }
  HoleIndex pop() {
    const HoleIndex top = heap_[0], h = heap_.back();
    heap_.pop_back();
    heap_at_[top] = kOutside;
    if (heap_.empty()) return top;
    std::size_t i = 0;
    for (;;) {
      std::size_t c = 2 * i + 1;
      if (c >= heap_.size()) break;
      if (c + 1 < heap_.size() && better(heap_[c + 1], heap_[c])) ++c;
      if (!better(heap_[c], h)) break;
      place(i, heap_[c]);
      i = c;
    }
    place(i, h);
    return top;
  }

  std::vector<Edge> edges_;
  HoleIndex n_;
  std::vector<std::uint32_t> first_arc_;
  std::vector<Arc> arcs_;
  // For each hole not yet spanned: its best offer (cost, edge), and its place in heap_.
  std::vector<double> offer_cost_;
  std::vector<std::uint32_t> offer_edge_, heap_at_;
  std::vector<HoleIndex> heap_;  // the holes offered an edge, a binary heap by better()
  std::vector<std::uint32_t> tree_;
};

}  // namespace

Candidates build_candidates(const Space& space, int k, int threads) {
  const HoleIndex n = space.holes();
  Candidates c;
  c.k = std::max(0, std::min<int>(k, static_cast<int>(n) - 1));
  c.list.assign(static_cast<std::size_t>(n) * c.k, 0);
  if (c.k == 0) return c;
  PointCloud cloud{&space};
  Tree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  // Ask for a few more than k: coincident holes and metric ties are then
  // resolved by our own sort (distance in the problem's metric, then index),
  // which keeps the lists identical on every machine and thread count.
  const std::size_t want = std::min<std::size_t>(n, static_cast<std::size_t>(c.k) + 1 + 4);
  // Rows are independent: each worker fills its share with its own scratch.
#pragma omp parallel num_threads(std::max(1, threads))
  {
  std::vector<std::size_t> idx(want);
  std::vector<double> dist2(want);
  std::vector<std::pair<double, HoleIndex>> row;
#pragma omp for schedule(static)
  for (HoleIndex i = 0; i < n; ++i) {
    const double q[2] = {space.point(i).x, space.point(i).y};
    std::size_t found = tree.knnSearch(q, want, idx.data(), dist2.data());
    row.clear();
    for (std::size_t r = 0; r < found; ++r) {
      auto j = static_cast<HoleIndex>(idx[r]);
      if (j != i) row.emplace_back(space.d(i, j), j);
    }
    std::sort(row.begin(), row.end());
    if (row.size() < static_cast<std::size_t>(c.k)) {
      // Many coincident points crowd the k-d result; fall back to a full scan for this row.
      row.clear();
      for (HoleIndex j = 0; j < n; ++j) {
        if (j != i) row.emplace_back(space.d(i, j), j);
      }
      std::partial_sort(row.begin(), row.begin() + c.k, row.end());
    }
    HoleIndex* out = c.list.data() + static_cast<std::size_t>(i) * c.k;
    for (int r = 0; r < c.k; ++r) out[r] = row[r].second;
  }
  }
  return c;
}

Candidates with_quadrant_neighbours(const Space& space, Candidates nearest) {
  const HoleIndex n = space.holes();
  const int k = nearest.k;
  if (k < 4) return nearest;
  BucketGrid grid(space);
  std::vector<HoleIndex> quadrant, row;
  for (HoleIndex i = 0; i < n; ++i) {
    HoleIndex* out = nearest.list.data() + static_cast<std::size_t>(i) * k;
    quadrant.clear();
    for (HoleIndex q : grid.nearest_by_quadrant(i, [&](HoleIndex h) { return space.d(i, h); }, kQuadrantRings)) {
      if (q != UINT32_MAX && std::find(quadrant.begin(), quadrant.end(), q) == quadrant.end()) quadrant.push_back(q);
    }
    // The quadrant neighbours, and the nearest of the rest to fill the row,
    // sorted by distance (a quadrant neighbour outside the k nearest is no
    // nearer than any of them, so this is the row with its last places given up).
    row = quadrant;
    for (int r = 0; r < k && row.size() < static_cast<std::size_t>(k); ++r) {
      if (std::find(quadrant.begin(), quadrant.end(), out[r]) == quadrant.end()) row.push_back(out[r]);
    }
    std::sort(row.begin(), row.end(), [&](HoleIndex a, HoleIndex b) {
      const double da = space.d(i, a), db = space.d(i, b);
      return da < db || (da == db && a < b);
    });
    std::copy(row.begin(), row.end(), out);
  }
  return nearest;
}

Candidates joined_nearest(const Space& space, int k, int threads) {
  Candidates nearest = build_candidates(space, k, threads);
  const HoleIndex n = space.holes();
  std::vector<HoleIndex> root(n);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](HoleIndex x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  // Straight from the rows: a union of two joined holes does nothing, so the
  // sorted edge list that alpha_candidates builds anyway is not needed here.
  HoleIndex pieces = n;
  for (HoleIndex a = 0; a < n; ++a) {
    for (int r = 0; r < nearest.k; ++r) {
      const HoleIndex ra = find(a), rb = find(nearest.of(a)[r]);
      if (ra == rb) continue;
      root[ra] = rb;
      --pieces;
    }
  }
  return pieces > 1 ? with_quadrant_neighbours(space, std::move(nearest)) : nearest;
}

std::vector<std::pair<HoleIndex, HoleIndex>> candidate_edges(const Candidates& candidates, HoleIndex holes) {
  std::vector<std::pair<HoleIndex, HoleIndex>> edges;
  edges.reserve(static_cast<std::size_t>(holes) * candidates.k);
  for (HoleIndex i = 0; i < holes; ++i) {
    const HoleIndex* row = candidates.of(i);
    for (int r = 0; r < candidates.k; ++r) edges.emplace_back(std::min(i, row[r]), std::max(i, row[r]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

Candidates alpha_candidates(const Space& space, const Candidates& nearest, int k, int ascent_iterations, int threads) {
  const HoleIndex n = space.holes();
  Candidates out;
  out.k = std::min(k, nearest.k);
  out.list.assign(static_cast<std::size_t>(n) * out.k, 0);
  if (out.k == 0) return out;
  // The neighbour graph, each edge once.
  std::vector<SpanningForest::Edge> graph;
  for (auto [a, b] : candidate_edges(nearest, n)) graph.push_back({a, b, space.d(a, b)});
  SpanningForest forest(std::move(graph), n);
  const auto& edges = forest.edges();
  const auto& in_tree = forest.tree();
  // Subgradient ascent (Held & Karp 1970, as LKH runs it): raise pi on holes
  // the tree leaves as leaves, lower it where the tree branches, so the tree
  // looks more like a tour and alpha more like what a tour needs.
  std::vector<double> pi(n, 0.0), best_pi(n, 0.0), degree(n), last_v(n, 0.0);
  double best_w = -std::numeric_limits<double>::infinity();
  double step = 0.0;
  // The step shrinks to 5 % of its first size by the last iteration.
  const double decay = std::pow(0.05, 1.0 / std::max(1, ascent_iterations));
  // Only where the neighbour graph holds one tree. Over the 16 nearest alone
  // the clusters of fl1400 and brd14051 stayed apart, and the ascent on that
  // forest made the lists worse (fl1400 at 5 s: 0.68 % with it, 0.00 %
  // without); with_quadrant_neighbours joins them, and with the ascent the
  // 5 lists of brd14051 miss 23 edges of a 0.12 % route, against 102 without.
  // A forest now means degenerate input (many holes on one spot).
  const double plain_tree = forest.grow(pi);
  if (in_tree.size() + 1 < static_cast<std::size_t>(n)) ascent_iterations = 0;
  for (int it = 0; it < ascent_iterations; ++it) {
    // The first step's tree is the plain one, just built.
    const double w = (it == 0 ? plain_tree : forest.grow(pi)) - 2.0 * std::accumulate(pi.begin(), pi.end(), 0.0);
    if (it == 0) {
      double mean = 0.0;
      for (std::uint32_t e : in_tree) mean += edges[e].length;
      step = 0.1 * mean / std::max<std::size_t>(1, in_tree.size());
    }
    if (w > best_w) {
      best_w = w;
      best_pi = pi;
    }
    std::fill(degree.begin(), degree.end(), 0.0);
    for (std::uint32_t e : in_tree) {
      degree[edges[e].a] += 1;
      degree[edges[e].b] += 1;
    }
    double norm = 0.0;
    for (HoleIndex i = 0; i < n; ++i) {
      const double v = degree[i] - 2.0;
      norm += v * v;
      pi[i] += step * (0.7 * v + 0.3 * last_v[i]);
      last_v[i] = v;
    }
    if (norm == 0.0) break;
    step *= decay;
  }
  pi = best_pi;
  forest.grow(pi);
  std::vector<std::vector<std::pair<HoleIndex, double>>> tree(n);
  for (std::uint32_t e : in_tree) {
    tree[edges[e].a].push_back({edges[e].b, edges[e].cost});
    tree[edges[e].b].push_back({edges[e].a, edges[e].cost});
  }
  // Root each tree; binary lifting gives the longest edge on any tree path in O(log n).
  int levels = 1;
  while ((HoleIndex{1} << levels) < n) ++levels;
  std::vector<HoleIndex> up(static_cast<std::size_t>(levels) * n);
  std::vector<double> longest(static_cast<std::size_t>(levels) * n, 0.0);
  std::vector<int> depth(n, -1);
  std::vector<HoleIndex> stack;
  for (HoleIndex s = 0; s < n; ++s) {
    if (depth[s] >= 0) continue;
    depth[s] = 0;
    up[s] = s;
    stack.push_back(s);
    while (!stack.empty()) {
      const HoleIndex u = stack.back();
      stack.pop_back();
      for (auto [w, d] : tree[u]) {
        if (depth[w] >= 0) continue;
        depth[w] = depth[u] + 1;
        up[w] = u;
        longest[w] = d;
        stack.push_back(w);
      }
    }
  }
  for (int l = 1; l < levels; ++l) {
    const std::size_t cur = static_cast<std::size_t>(l) * n, prev = cur - n;
    for (HoleIndex v = 0; v < n; ++v) {
      const HoleIndex mid = up[prev + v];
      up[cur + v] = up[prev + mid];
      longest[cur + v] = std::max(longest[prev + v], longest[prev + mid]);
    }
  }
  auto path_longest = [&](HoleIndex a, HoleIndex b) {
    double m = 0.0;
    if (depth[a] < depth[b]) std::swap(a, b);
    for (int l = levels - 1; l >= 0; --l) {
      const std::size_t at = static_cast<std::size_t>(l) * n;
      if (depth[a] - (1 << l) >= depth[b]) {
        m = std::max(m, longest[at + a]);
        a = up[at + a];
      }
    }
    if (a == b) return m;
    for (int l = levels - 1; l >= 0; --l) {
      const std::size_t at = static_cast<std::size_t>(l) * n;
      if (up[at + a] != up[at + b]) {
        m = std::max({m, longest[at + a], longest[at + b]});
        a = up[at + a];
        b = up[at + b];
      }
    }
    if (up[a] != up[b]) return -1.0;  // different trees
    return std::max({m, longest[a], longest[b]});
  };
#pragma omp parallel num_threads(std::max(1, threads))
  {
  std::vector<std::pair<double, int>> row;
#pragma omp for schedule(static)
  for (HoleIndex i = 0; i < n; ++i) {
    const HoleIndex* nr = nearest.of(i);
    row.clear();
    for (int r = 0; r < nearest.k; ++r) {
      const double m = path_longest(i, nr[r]);
      const double c = space.d(i, nr[r]) + pi[i] + pi[nr[r]];
      row.push_back({m < 0 ? 0.0 : c - m, r});
    }
    std::stable_sort(row.begin(), row.end());
    std::sort(row.begin(), row.begin() + out.k, [](auto x, auto y) { return x.second < y.second; });
    HoleIndex* o = out.list.data() + static_cast<std::size_t>(i) * out.k;
    for (int r = 0; r < out.k; ++r) o[r] = nr[row[r].second];
  }
  }
  return out;
}

}  // namespace aco::detail
