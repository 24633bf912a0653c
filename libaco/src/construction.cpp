// An ant's route. The classic colonies (AS, MMAS, ACS) build a whole route
// by the random proportional rule (ACS's pseudo-random one with q0); a
// focused ant walks from a random hole of the reference route, leaving it
// with probability kDeviate until it has made its bound of new edges, then
// copies the rest of R.
#include <numeric>

#include "colony.h"

namespace aco::detail {

HoleIndex Colony::choose_focused(HoleIndex cur, const AntWork& w, Rng& rng, HoleIndex exclude) const {
  // ACS's pseudo-random proportional rule over the unvisited candidates, with
  // tau^alpha * eta^beta computed here: a focused ant looks at few rows, so
  // refreshing all n*k of them every iteration would cost more than it saves.
  const HoleIndex* c = cand_.of(cur);
  const std::size_t row = idx(cur, 0);
  const detail::Trail& tau = tau_;
  const double* eb = eta_beta_.data() + idx(cur, 0);
  double weight[64];
  const int k = std::min(k_, 64);
  double total = 0.0;
  int best_r = -1;
  for (int r = 0; r < k; ++r) {
    const bool free = w.mark[c[r]] != w.stamp && c[r] != exclude;
    const double t = free ? tau[row + r] : 0.0;
    const double v = free ? (p_.alpha == 1.0 ? t : std::pow(t, p_.alpha)) * eb[r] : 0.0;
    weight[r] = v;
    total += v;
    if (free && (best_r < 0 || v > weight[best_r])) best_r = r;
  }
  if (best_r < 0) return n_ + 1;  // every candidate visited
  if (rng.uniform() < p_.q0 || !(total > 0.0)) return c[best_r];
  double x = rng.uniform() * total;
  for (int r = 0; r < k; ++r) {
    x -= weight[r];
    if (x < 0.0 && weight[r] > 0.0) return c[r];
  }
  return c[best_r];
}

void Colony::construct_focused(AntWork& w, Rng& rng, int bound) const {
  // Walk from a random node of the reference route R. While the ant has made
  // fewer than `bound` new edges it chooses by the ACS rule; after that it
  // copies R, skipping what it has visited. Every edge that is not R's is new,
  // and its two ends seed the local search. The copy is made run by run of R
  // between the few visited positions, its length read from R's prefix sums,
  // so an ant costs a memcpy of the route plus what it changes, not a step
  // per hole (100 000 holes: 1.8 ms an ant before).
  const std::size_t m = ref_route_.size();  // nodes, V included for an open path
  if (w.mark.size() != m) {
    w.mark.assign(m, 0);
    w.stamp = 0;
  }
  if (++w.stamp == 0) {
    std::fill(w.mark.begin(), w.mark.end(), 0);
    w.stamp = 1;
  }
  const std::uint32_t last_pos = static_cast<std::uint32_t>(m - 1);
  auto after = [&](std::uint32_t p) { return p == last_pos ? 0u : p + 1; };
  w.route.clear();
  w.seeds.clear();
  w.visited_pos.clear();
  w.length = 0.0;
  auto visit = [&](HoleIndex h) {
    w.mark[h] = w.stamp;
    w.visited_pos.push_back(ref_pos_[h]);
    w.route.push_back(h);
  };
  HoleIndex cur = ref_route_[rng.below(static_cast<std::uint32_t>(m))];
  const HoleIndex first = cur;
  visit(cur);
  int changes = 0;
  while (w.route.size() < m && changes < bound) {
    const std::uint32_t pc = ref_pos_[cur];
    const HoleIndex follow = ref_route_[after(pc)];
    const bool follow_free = w.mark[follow] != w.stamp;
    HoleIndex next = n_ + 1;
    if (cur < n_) {
      // Deviate from R here with probability p_dev (the choice then excludes
      // R's own edge); where R's next hole is already visited a new edge must
      // be made anyway, and the same rule picks it.
      if (!follow_free || rng.uniform() < kDeviate) next = choose_focused(cur, w, rng, follow);
      else next = follow;
    }
    if (next > n_) {
      // The next unvisited position of R: few are visited, so a scan is short.
      std::uint32_t p = after(pc);
      while (w.mark[ref_route_[p]] == w.stamp) p = after(p);
      next = ref_route_[p];
    }
    if (next != follow) {  // a new edge: its ends, in pairs (V among them is skipped later)
      ++changes;
      w.seeds.push_back(cur);
      w.seeds.push_back(next);
    }
    w.length += space_.e(cur, next);
    visit(next);
    cur = next;
  }
  if (w.route.size() < m) {
    // The rest is R from after cur, cyclically, without the visited positions.
    std::vector<std::uint32_t>& gaps = w.visited_pos;
    std::sort(gaps.begin(), gaps.end());
    auto copy_run = [&](std::uint32_t a, std::uint32_t b) {  // positions a..b-1 of R, a < b
      const HoleIndex head = ref_route_[a];
      if (ref_route_[after(ref_pos_[cur])] != head) {
        w.seeds.push_back(cur);
        w.seeds.push_back(head);
      }
      w.length += space_.e(cur, head) + (ref_prefix_[b - 1] - ref_prefix_[a]);
      w.route.insert(w.route.end(), ref_route_.begin() + a, ref_route_.begin() + b);
      cur = ref_route_[b - 1];
    };
    auto copy_range = [&](std::uint32_t lo, std::uint32_t hi) {  // unvisited positions in [lo, hi)
      auto g = std::lower_bound(gaps.begin(), gaps.end(), lo);
      std::uint32_t p = lo;
      for (; g != gaps.end() && *g < hi; ++g) {
        if (*g > p) copy_run(p, *g);
        p = *g + 1;
      }
      if (p < hi) copy_run(p, hi);
    };
    const std::uint32_t start = after(ref_pos_[cur]);
    copy_range(start, static_cast<std::uint32_t>(m));
    if (start > 0) copy_range(0, start);
  }
  if (ref_route_[after(ref_pos_[cur])] != first) {
    w.seeds.push_back(cur);
    w.seeds.push_back(first);
  }
  w.length += space_.e(cur, first);
  // An open path keeps V at position 0.
  if (space_.open()) {
    const auto v = std::find(w.route.begin(), w.route.end(), n_);
    std::rotate(w.route.begin(), v, w.route.end());
  }
}

HoleIndex Colony::nearest_unvisited(HoleIndex cur, const AntWork& w) const {
  // Every candidate is visited: take the nearest unvisited hole, which is the
  // argmax of tau^alpha * eta^beta when all non-candidate edges share one tau.
  // The grid finds it without scanning every unvisited hole (that scan made
  // tour construction quadratic on large panels). Only candidate-list mode
  // gets here, and it always has a grid.
  return w.grid->nearest(space_.point(cur), [&](HoleIndex h) { return space_.d(cur, h); });
}

HoleIndex Colony::choose_next(HoleIndex cur, AntWork& w, Rng& rng, bool acs) {
  if (cur == n_) {
    // Leaving the open path's start: no pheromone is kept on V's edges, so
    // choose by eta^beta alone over all unvisited holes.
    double total = 0.0;
    w.weight.resize(w.unvisited.size());
    for (std::size_t u = 0; u < w.unvisited.size(); ++u) {
      w.weight[u] = start_weight_[w.unvisited[u]];
      total += w.weight[u];
    }
    double r = rng.uniform() * total;
    for (std::size_t u = 0; u < w.unvisited.size(); ++u) {
      r -= w.weight[u];
      if (r < 0.0) return w.unvisited[u];
    }
    return w.unvisited.back();
  }
  if (!dense_choice_.empty()) {
    const double* row = dense_choice_.data() + static_cast<std::size_t>(cur) * n_;
    const std::size_t m = w.unvisited.size();
    w.weight.resize(m);
    double total = 0.0;
    for (std::size_t u = 0; u < m; ++u) {
      const double v = row[w.unvisited[u]];
      w.weight[u] = v;
      total += v;
    }
    auto argmax = [&] {
      // Ties go to the lower hole index, so the choice does not depend on list order.
      std::size_t best = 0;
      for (std::size_t u = 1; u < m; ++u) {
        if (w.weight[u] > w.weight[best] || (w.weight[u] == w.weight[best] && w.unvisited[u] < w.unvisited[best])) best = u;
      }
      return w.unvisited[best];
    };
    if ((acs && rng.uniform() < p_.q0) || !(total > 0.0)) return argmax();
    double r = rng.uniform() * total;
    for (std::size_t u = 0; u < m; ++u) {
      r -= w.weight[u];
      if (r < 0.0 && w.weight[u] > 0.0) return w.unvisited[u];
    }
    return argmax();
  }
  const HoleIndex* c = cand_.of(cur);
  const double* ch = choice_.data() + idx(cur, 0);
  w.weight.resize(static_cast<std::size_t>(k_));
  double total = 0.0;
  int best_r = -1;
  for (int r = 0; r < k_; ++r) {
    const bool free = w.where[c[r]] != UINT32_MAX;
    const double v = free ? ch[r] : 0.0;
    w.weight[r] = v;
    total += v;
    if (free && (best_r < 0 || v > w.weight[best_r])) best_r = r;
  }
  if (best_r < 0) return nearest_unvisited(cur, w);
  if (acs && rng.uniform() < p_.q0) return c[best_r];
  if (!(total > 0.0)) return c[best_r];  // underflow of tiny weights: fall back to the best
  double r = rng.uniform() * total;
  for (int q = 0; q < k_; ++q) {
    r -= w.weight[q];
    if (r < 0.0 && w.weight[q] > 0.0) return c[q];
  }
  return c[best_r];
}

void Colony::construct(AntWork& w, Rng& rng, bool acs) {
  w.route.clear();
  w.unvisited.resize(n_);
  w.where.resize(n_);
  std::iota(w.unvisited.begin(), w.unvisited.end(), 0);
  std::iota(w.where.begin(), w.where.end(), 0);
  const bool use_grid = dense_choice_.empty();  // candidate-list mode
  if (use_grid) {
    if (!w.grid) w.grid = std::make_unique<detail::BucketGrid>(space_);
    else w.grid->reset();
  }
  auto visit = [&w, use_grid](HoleIndex h) {
    if (use_grid) w.grid->remove(h);
    const HoleIndex at = w.where[h];
    const HoleIndex last = w.unvisited.back();
    w.unvisited[at] = last;
    w.where[last] = at;
    w.unvisited.pop_back();
    w.where[h] = UINT32_MAX;
    w.route.push_back(h);
  };
  HoleIndex cur;
  if (space_.open()) {
    w.route.push_back(n_);
    cur = n_;
  } else {
    cur = static_cast<HoleIndex>(rng.below(n_));  // the thesis: ants start at random holes
    visit(cur);
  }
  while (!w.unvisited.empty()) {
    const HoleIndex next = choose_next(cur, w, rng, acs);
    visit(next);
    cur = next;
  }
}

}  // namespace aco::detail
