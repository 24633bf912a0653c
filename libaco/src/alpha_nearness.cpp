// The candidate lists' last stage: Held and Karp's subgradient ascent over
// minimum spanning forests of the nearest lists (spanning_forest.h), then each
// hole's k alpha-nearest (Helsgaun 2000, LKH's candidates).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <utility>

#include "candidates.h"
#include "parallel.h"
#include "spanning_forest.h"

namespace aco::detail {

namespace {

// A spanning forest's parts each keep arrays over all holes, so there are at
// most this many (memory O(n k) whatever --threads says).
constexpr int kMaxParts = 8;

}  // namespace

struct AlphaLists::Impl {
  const Space& space;
  Candidates nearest;
  const int ascent_iterations;
  const bool penalised_rows;
  const HoleIndex n;
  enum class Stage { Ascent, Tree, Lifting, Rows, Done } stage = Stage::Ascent;
  Candidates out;
  std::optional<SpanningForest> forest;
  std::vector<double> pi, best_pi, degree, last_v;
  double best_w = -std::numeric_limits<double>::infinity();
  double step = 0.0, decay = 1.0;
  int it = 0;
  std::vector<std::vector<std::pair<HoleIndex, double>>> tree;
  int levels = 1;
  std::vector<HoleIndex> up;
  std::vector<double> longest;
  std::vector<int> depth;
  HoleIndex next_row = 0;
  std::vector<std::vector<std::pair<double, int>>> rows;

  Impl(const Space& sp, Candidates near, int k, int ascent, bool penalised)
    : space(sp), nearest(std::move(near)), ascent_iterations(ascent), penalised_rows(penalised), n(sp.holes()) {
    out.k = std::min(k, nearest.k);
    out.list.assign(static_cast<std::size_t>(n) * out.k, 0);
    out.length.assign(out.list.size(), 0.0);
    if (out.k == 0) {
      stage = Stage::Done;
      return;
    }
    if (penalised_rows) {
      out.pi_list.assign(out.list.size(), 0);
      out.pi_length.assign(out.list.size(), 0.0);
    }
  }

  void begin(Team& team) {
    // The neighbour graph, each edge once.
    std::vector<SpanningForest::Edge> graph;
    {
      // Freed before the forest is built: 13 MB at 100 000 holes.
      const std::vector<std::pair<HoleIndex, HoleIndex>> pairs = candidate_edges(nearest, n);
      graph.reserve(pairs.size());  // fresh pages cost on a VM: growing it step by step took 2 ms more on pcb1173
      for (auto [a, b] : pairs) graph.push_back({a, b, space.d(a, b)});
    }
    forest.emplace(std::move(graph), n);
    // Parts only for the ascent's steps, which run on the threads; without
    // steps the one tree is grown here, and parts would only cost a join.
    const int threads = team.threads();
    if (threads > 1 && ascent_iterations > 0) {
      const auto parts = static_cast<std::uint32_t>(std::min<HoleIndex>(std::min(threads, kMaxParts), n));
      forest->split(strips(space, parts), parts);
    }
    pi.assign(n, 0.0);
    best_pi.assign(n, 0.0);
    degree.resize(n);
    last_v.assign(n, 0.0);
    // The step shrinks to 5 % of its first size by the last iteration.
    decay = std::pow(0.05, 1.0 / std::max(1, ascent_iterations));
    if (ascent_iterations <= 0) stage = Stage::Tree;
  }

  // Subgradient ascent (Held & Karp 1970, as LKH runs it): raise pi on holes
  // the tree leaves as leaves, lower it where the tree branches, so the tree
  // looks more like a tour and alpha more like what a tour needs.
  // Only where the neighbour graph holds one tree. Over the 16 nearest alone
  // the clusters of fl1400 and brd14051 stayed apart, and the ascent on that
  // forest made the lists worse (fl1400 at 5 s: 0.68 % with it, 0.00 %
  // without); with_quadrant_neighbours joins them, and with the ascent the
  // 5 lists of brd14051 miss 23 edges of a 0.12 % route, against 102 without.
  // A forest now means degenerate input (many holes on one spot).
  // One step, given the tree under the current pi (the first: the plain tree);
  // says whether to take another.
  bool take_step(double tree_cost) {
    const auto& edges = forest->edges();
    const auto& in_tree = forest->tree();
    if (it == 0 && in_tree.size() + 1 < static_cast<std::size_t>(n)) return false;
    const double w = tree_cost - 2.0 * std::accumulate(pi.begin(), pi.end(), 0.0);
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
    if (norm == 0.0) return false;
    step *= decay;
    return ++it < ascent_iterations;
  }

  // A round a step: the parts' trees grown at once (a slot each), then joined
  // and the step taken by one thread. The team's rounds, not a parallel
  // region a step: on a busy machine a thread the kernel has put aside held
  // up every step's region (pcb1173 beside two busy processes: a 119-819 ms
  // start on two threads against 39-83 ms on one), where a round goes on
  // without a worker that has taken no slot.
  void ascent_step(Team& team) {
    std::vector<double> busy;
    bool more = true;
    team.rounds(
        static_cast<int>(forest->parts()), busy,
        [&](int part, int) { forest->grow_part(static_cast<std::uint32_t>(part), pi); },
        [&] {
          more = take_step(forest->join(pi));
          return false;  // a step a piece
        });
    if (!more) stage = Stage::Tree;
  }

  void grow_tree() {
    pi = best_pi;
    forest->grow(pi);
    const auto& edges = forest->edges();
    const auto& in_tree = forest->tree();
    tree.assign(n, {});
    for (std::size_t t = 0; t < in_tree.size(); ++t) {
      const SpanningForest::Edge& e = edges[in_tree[t]];
      tree[e.a].push_back({e.b, forest->tree_costs()[t]});
      tree[e.b].push_back({e.a, forest->tree_costs()[t]});
    }
    forest.reset();
  }

  // Root each tree; binary lifting gives the longest edge on any tree path in O(log n).
  void lift() {
    while ((HoleIndex{1} << levels) < n) ++levels;
    up.assign(static_cast<std::size_t>(levels) * n, 0);
    longest.assign(static_cast<std::size_t>(levels) * n, 0.0);
    depth.assign(n, -1);
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
    std::vector<std::vector<std::pair<HoleIndex, double>>>().swap(tree);
    for (int l = 1; l < levels; ++l) {
      const std::size_t cur = static_cast<std::size_t>(l) * n, prev = cur - n;
      for (HoleIndex v = 0; v < n; ++v) {
        const HoleIndex mid = up[prev + v];
        up[cur + v] = up[prev + mid];
        longest[cur + v] = std::max(longest[prev + v], longest[prev + mid]);
      }
    }
  }

  double path_longest(HoleIndex a, HoleIndex b) const {
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
  }

  void fill_rows(Team& team, HoleIndex from, HoleIndex to) {
    rows.resize(static_cast<std::size_t>(team.threads()));
    team.chunks(to - from, kRowChunk, [&](std::size_t begin, std::size_t end, int me) {
      std::vector<std::pair<double, int>>& row = rows[static_cast<std::size_t>(me)];
      for (auto i = static_cast<HoleIndex>(from + begin); i < from + end; ++i) {
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
        double* o_length = out.length.data() + static_cast<std::size_t>(i) * out.k;
        for (int r = 0; r < out.k; ++r) {
          o[r] = nr[row[r].second];
          o_length[r] = space.d(i, o[r]);
        }
        if (!penalised_rows) continue;
        row.clear();
        for (int r = 0; r < out.k; ++r) row.push_back({o_length[r] + pi[i] + pi[o[r]], r});
        std::stable_sort(row.begin(), row.end());
        for (int r = 0; r < out.k; ++r) {
          const std::size_t at = static_cast<std::size_t>(i) * out.k + static_cast<std::size_t>(r);
          out.pi_list[at] = o[row[r].second];
          out.pi_length[at] = row[r].first;
        }
      }
    });
  }
};

AlphaLists::AlphaLists(const Space& space, Candidates nearest, int k, int ascent_iterations, bool penalised_rows)
  : impl_(std::make_unique<Impl>(space, std::move(nearest), k, ascent_iterations, penalised_rows)) {}
AlphaLists::~AlphaLists() = default;

bool AlphaLists::step(Team& team, std::size_t rows) {
  Impl& m = *impl_;
  using Stage = Impl::Stage;
  switch (m.stage) {
    case Stage::Ascent:
      if (!m.forest) m.begin(team);
      else m.ascent_step(team);
      break;
    case Stage::Tree:
      if (!m.forest) m.begin(team);  // no ascent: the graph and the tree in one piece
      m.grow_tree();
      m.stage = Stage::Lifting;
      break;
    case Stage::Lifting:
      m.lift();
      m.stage = Stage::Rows;
      break;
    case Stage::Rows: {
      const auto to = static_cast<HoleIndex>(std::min<std::size_t>(m.n, m.next_row + rows));
      m.fill_rows(team, m.next_row, to);
      m.next_row = to;
      if (to == m.n) {
        if (m.penalised_rows) m.out.pi = std::move(m.pi);
        m.stage = Stage::Done;
      }
      break;
    }
    case Stage::Done: break;
  }
  return m.stage == Stage::Done;
}

Candidates AlphaLists::take() { return std::move(impl_->out); }

Candidates alpha_candidates(const Space& space, const Candidates& nearest, int k, int ascent_iterations, Team& team,
                            bool penalised_rows) {
  AlphaLists lists(space, nearest, k, ascent_iterations, penalised_rows);
  while (!lists.step(team, space.holes())) {
  }
  return lists.take();
}

Candidates alpha_candidates(const Space& space, const Candidates& nearest, int k, int ascent_iterations, int threads,
                            bool penalised_rows) {
  Candidates c;
  Team::run(threads, [&](Team& team) { c = alpha_candidates(space, nearest, k, ascent_iterations, team, penalised_rows); });
  return c;
}

}  // namespace aco::detail
