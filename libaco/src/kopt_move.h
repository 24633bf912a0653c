#pragma once
// A sequential k-opt move (k <= 5) as LKH makes its basis move (Helsgaun
// 2000 and 2009, "General k-opt submoves for the Lin-Kernighan TSP
// heuristic"): whether the exchange gives one cycle, and the reversals that
// make it. The search that finds the moves is LocalSearcher::try_five_opt
// (five_opt.cpp); this part knows nothing of costs.
//
// A move is t[0..2k-1]: it removes the route's edges (t[2i], t[2i+1]) and
// adds (t[2i+1], t[2i+2]), closing with (t[2k-1], t[0]). Cut at its k removed
// edges the route falls into k segments; the move joins them again in another
// order, some turned. With segment 0 kept in place, that is a signed
// permutation of the other k-1, and any one is made by at most a handful of
// reversals of consecutive segments, each one flip of the route: the table of
// the fewest for every permutation is found once, breadth first (384 of them
// for k = 5).
#include <array>
#include <cstdint>

#include "aco/problem.h"

namespace aco::detail {

constexpr int kMaxMoveK = 5;

struct KOptMove {
  int k = 0;
  HoleIndex t[2 * kMaxMoveK] = {};
};

// A flip as LocalSearcher::flip takes it: removes {a, b} and {c, d}, b after
// a and d after c the same way round, and adds {a, c} and {b, d}.
using FlipNodes = std::array<HoleIndex, 4>;

// The reversals of one k-opt move, in the order to make them.
struct KOptFlips {
  int count = 0;
  std::array<FlipNodes, 8> flip{};
};

// Whether `move` gives one cycle on `tour` (next(x, 0): x's successor;
// position(x): its place going forward, 0..size()-1); if so and `flips` is
// given, the flips that make it, in order. Every removed edge must be an edge
// of the route, no two the same. The route is read from t[1] on, the way
// t[1] follows t[0], so the flips are the same whichever way round the
// route is stored (the array and deepen's overlay store it differently).
template <class Tour>
bool kopt_feasible(const Tour& tour, const KOptMove& move, KOptFlips* flips);

// The same for any exchange of k edges, sequential or not (LKH's Gain23
// moves, bridge_moves.cpp): it removes (t[2i], t[2i+1]) and adds (t[i],
// t[mate[i]]) for every i, each end given one mate.
template <class Tour>
bool exchange_feasible(const Tour& tour, int k, const HoleIndex* t, const int* mate, KOptFlips* flips);

namespace kopt {

// For segments 1..m-1 (m = k - 1 of them after segment 0), the fewest
// reversals of consecutive places that turn the identity into `target`:
// target[p] = segment (1-based) at place p, negative when turned. Returns the
// count and fills `blocks` with (first place, last place) of each reversal.
int reversal_plan(int m, const int* target, std::array<std::pair<int, int>, 8>& blocks);

}  // namespace kopt

template <class Tour>
bool kopt_feasible(const Tour& tour, const KOptMove& move, KOptFlips* flips) {
  return exchange_feasible(tour, move.k, move.t, nullptr, flips);
}

template <class Tour>
bool exchange_feasible(const Tour& tour, int k, const HoleIndex* t, const int* mate, KOptFlips* flips) {
  const int dir = tour.next(t[0], 0) == t[1] ? 0 : 1;
  const std::size_t m = tour.size();
  // Places read that way, from t[0]'s.
  const std::size_t p0 = tour.position(t[0]);
  auto place = [&](HoleIndex x) {
    const std::size_t p = tour.position(x);
    return dir == 0 ? (p + m - p0) % m : (p0 + m - p) % m;
  };
  // Each cut c: lo[c] the index of its end the other follows.
  int lo[kMaxMoveK], hi[kMaxMoveK], order[kMaxMoveK];
  std::size_t key[kMaxMoveK];
  for (int c = 0; c < k; ++c) {
    const int a = 2 * c, b = 2 * c + 1;
    if (tour.next(t[a], dir) == t[b]) {
      lo[c] = a;
      hi[c] = b;
    } else {
      lo[c] = b;
      hi[c] = a;
    }
    key[c] = place(t[lo[c]]);
    order[c] = c;
  }
  for (int i = 1; i < k; ++i) {  // insertion sort of the cuts by place
    const int c = order[i];
    int j = i;
    while (j > 0 && key[order[j - 1]] > key[c]) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = c;
  }
  // Segment s runs from the hi end of sorted cut s to the lo end of sorted
  // cut s + 1. For every index of t: its segment, and whether it is that
  // segment's first end (1) or last (0).
  int seg[2 * kMaxMoveK], first_end[2 * kMaxMoveK];
  int seg_first[kMaxMoveK], seg_last[kMaxMoveK];  // indices of t
  for (int s = 0; s < k; ++s) {
    const int start = hi[order[s]], end = lo[order[(s + 1) % k]];
    seg[start] = s;
    first_end[start] = 1;
    seg[end] = s;
    first_end[end] = 0;
    seg_first[s] = start;
    seg_last[s] = end;
  }
  // Walk: out of segment 0's last end, along the added edges.
  auto partner = [k, mate](int i) {
    if (mate != nullptr) return mate[i];
    return i == 0 ? 2 * k - 1 : i == 2 * k - 1 ? 0 : (i % 2 == 1 ? i + 1 : i - 1);
  };
  int target[kMaxMoveK - 1];
  int visited = 1;
  int at = seg_last[0];
  for (;;) {
    const int e = partner(at);
    const int s = seg[e];
    if (s == 0) break;
    if (visited == k) return false;
    const bool turned = first_end[e] == 0;
    target[visited - 1] = turned ? -s : s;
    ++visited;
    at = turned ? seg_first[s] : seg_last[s];
  }
  if (visited != k) return false;
  if (flips == nullptr) return true;
  // The reversals, made on the arrangement as it stands: cur[p] the signed
  // segment at place p after segment 0.
  const int segments = k - 1;
  std::array<std::pair<int, int>, 8> blocks;
  flips->count = kopt::reversal_plan(segments, target, blocks);
  int cur[kMaxMoveK - 1];
  for (int p = 0; p < segments; ++p) cur[p] = p + 1;
  auto entry = [&](int x) { return x > 0 ? t[seg_first[x]] : t[seg_last[-x]]; };
  auto exit = [&](int x) { return x > 0 ? t[seg_last[x]] : t[seg_first[-x]]; };
  for (int r = 0; r < flips->count; ++r) {
    const auto [i, j] = blocks[static_cast<std::size_t>(r)];
    const HoleIndex a = i == 0 ? t[seg_last[0]] : exit(cur[i - 1]);
    const HoleIndex d = j == segments - 1 ? t[seg_first[0]] : entry(cur[j + 1]);
    flips->flip[static_cast<std::size_t>(r)] = {a, entry(cur[i]), exit(cur[j]), d};
    for (int l = i, h = j; l <= h; ++l, --h) {
      const int x = cur[l], y = cur[h];
      cur[l] = -y;
      cur[h] = -x;
    }
  }
  return true;
}

}  // namespace aco::detail
