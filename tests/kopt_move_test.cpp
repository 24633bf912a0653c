// The k-opt move of LKH's basis step (libaco/src/kopt_move.h) against a
// brute-force oracle: the edges that remain after the exchange, counted and
// walked here, say whether it gives one cycle; the flips it returns, made on
// a plain array, must give exactly those edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "kopt_move.h"

namespace {

using aco::HoleIndex;
using aco::detail::KOptFlips;
using aco::detail::KOptMove;

// A cycle in an array, read and flipped as the local search's array route is.
struct ArrayCycle {
  std::vector<HoleIndex> route;
  std::vector<std::size_t> pos;

  explicit ArrayCycle(std::vector<HoleIndex> r) : route(std::move(r)), pos(route.size()) {
    for (std::size_t i = 0; i < route.size(); ++i) pos[route[i]] = i;
  }
  std::size_t m() const { return route.size(); }
  std::size_t size() const { return route.size(); }
  HoleIndex next(HoleIndex x, int dir) const { return route[dir == 0 ? (pos[x] + 1) % m() : (pos[x] + m() - 1) % m()]; }
  std::size_t position(HoleIndex x) const { return pos[x]; }
  // Removes {a, b} and {c, d} (b after a, d after c, the same way round), adds {a, c} and {b, d}.
  void flip(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) {
    ASSERT_TRUE(next(a, 0) == b || next(a, 1) == b) << "not an edge";
    if (next(a, 0) != b) {
      std::swap(a, b);
      std::swap(c, d);
    }
    ASSERT_EQ(next(c, 0), d) << "the two edges are not read the same way round";
    std::size_t i = pos[a], j = pos[c];
    if (i > j) std::swap(i, j);
    std::reverse(route.begin() + static_cast<long>(i + 1), route.begin() + static_cast<long>(j + 1));
    for (std::size_t p = i + 1; p <= j; ++p) pos[route[p]] = p;
  }
  // The flips in order; stops at the first that is not one.
  void make(const KOptFlips& flips) {
    for (int f = 0; f < flips.count && !::testing::Test::HasFatalFailure(); ++f) {
      const auto& x = flips.flip[static_cast<std::size_t>(f)];
      flip(x[0], x[1], x[2], x[3]);
    }
  }
  std::multiset<std::pair<HoleIndex, HoleIndex>> edges() const {
    std::multiset<std::pair<HoleIndex, HoleIndex>> e;
    for (std::size_t i = 0; i < m(); ++i) e.insert(std::minmax(route[i], route[(i + 1) % m()]));
    return e;
  }
};

// The oracle: the cycle's edges less the removed, plus the added; whether
// every hole then has two and one walk goes round them all.
bool one_cycle(std::size_t m, const std::multiset<std::pair<HoleIndex, HoleIndex>>& edges) {
  std::vector<std::vector<HoleIndex>> adj(m);
  for (const auto& [a, b] : edges) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  for (const auto& a : adj) {
    if (a.size() != 2) return false;
  }
  std::size_t seen = 1;
  HoleIndex prev = 0, at = adj[0][0];
  while (at != 0) {
    ++seen;
    const HoleIndex nxt = adj[at][0] == prev ? adj[at][1] : adj[at][0];
    if (adj[at][0] == adj[at][1]) return false;  // a double edge
    prev = at;
    at = nxt;
    if (seen > m) return false;
  }
  return seen == m;
}

// A random sequential k-opt move whose removed edges are distinct edges of the
// cycle and whose added edges are not: t2 after or before t1, each next t an
// arbitrary hole, and its partner one of its two neighbours.
bool random_move(const ArrayCycle& c, int k, std::mt19937& rng, KOptMove& move) {
  move.k = k;
  std::set<std::pair<HoleIndex, HoleIndex>> removed;
  auto edge_of_cycle = [&](HoleIndex a, HoleIndex b) { return c.next(a, 0) == b || c.next(a, 1) == b; };
  move.t[0] = static_cast<HoleIndex>(rng() % c.m());
  move.t[1] = c.next(move.t[0], static_cast<int>(rng() % 2));
  removed.insert(std::minmax(move.t[0], move.t[1]));
  for (int i = 1; i < k; ++i) {
    const HoleIndex a = static_cast<HoleIndex>(rng() % c.m());
    const HoleIndex b = c.next(a, static_cast<int>(rng() % 2));
    if (a == move.t[2 * i - 1] || edge_of_cycle(move.t[2 * i - 1], a)) return false;
    if (!removed.insert(std::minmax(a, b)).second) return false;
    move.t[2 * i] = a;
    move.t[2 * i + 1] = b;
  }
  return move.t[2 * k - 1] != move.t[0] && !edge_of_cycle(move.t[2 * k - 1], move.t[0]);
}

TEST(kopt_move_test, feasibility_and_flips_agree_with_the_edges_the_exchange_leaves) {
  std::mt19937 rng(11);
  int feasible_seen[aco::detail::kMaxMoveK + 1] = {}, moves_seen[aco::detail::kMaxMoveK + 1] = {};
  for (int trial = 0; trial < 200000; ++trial) {
    const std::size_t m = 10 + rng() % 21;  // small cycles: holes repeat in a move often
    std::vector<HoleIndex> r(m);
    for (std::size_t i = 0; i < m; ++i) r[i] = static_cast<HoleIndex>(i);
    std::shuffle(r.begin(), r.end(), rng);
    ArrayCycle cycle(r);
    const int k = 2 + static_cast<int>(rng() % (aco::detail::kMaxMoveK - 1));
    KOptMove move;
    if (!random_move(cycle, k, rng, move)) continue;
    auto edges = cycle.edges();
    for (int i = 0; i < k; ++i) edges.erase(edges.find(std::minmax(move.t[2 * i], move.t[2 * i + 1])));
    for (int i = 0; i < k; ++i) edges.insert(std::minmax(move.t[2 * i + 1], move.t[(2 * i + 2) % (2 * k)]));
    const bool expected = one_cycle(m, edges);
    KOptFlips flips;
    const bool feasible = aco::detail::kopt_feasible(cycle, move, &flips);
    ++moves_seen[k];
    ASSERT_EQ(feasible, expected) << "trial " << trial << " k " << k;
    if (!feasible) continue;
    ++feasible_seen[k];
    EXPECT_LE(flips.count, k) << "more reversals than a k-opt move needs";
    cycle.make(flips);
    if (::testing::Test::HasFatalFailure()) return;
    ASSERT_EQ(cycle.edges(), edges) << "trial " << trial << " k " << k;
  }
  for (int k = 2; k <= aco::detail::kMaxMoveK; ++k) {
    EXPECT_GT(feasible_seen[k], 100) << "k " << k;                // both outcomes are exercised
    EXPECT_GT(moves_seen[k] - feasible_seen[k], 100) << "k " << k;
  }
}

// Any exchange of k distinct edges of the cycle, its ends paired at random
// (LKH's non-sequential moves, bridge_moves.cpp): the same oracle. Pairings
// that re-add a removed edge, join a hole to itself or add an edge twice are
// not exchanges and are skipped.
TEST(kopt_move_test, any_exchange_is_judged_and_flipped_as_its_edges_say) {
  std::mt19937 rng(23);
  int feasible_seen[aco::detail::kMaxMoveK + 1] = {}, moves_seen[aco::detail::kMaxMoveK + 1] = {};
  for (int trial = 0; trial < 200000; ++trial) {
    const std::size_t m = 10 + rng() % 21;
    std::vector<HoleIndex> r(m);
    for (std::size_t i = 0; i < m; ++i) r[i] = static_cast<HoleIndex>(i);
    std::shuffle(r.begin(), r.end(), rng);
    ArrayCycle cycle(r);
    const int k = 2 + static_cast<int>(rng() % (aco::detail::kMaxMoveK - 1));
    HoleIndex t[2 * aco::detail::kMaxMoveK];
    std::set<std::pair<HoleIndex, HoleIndex>> removed;
    bool ok = true;
    for (int i = 0; i < k && ok; ++i) {
      t[2 * i] = static_cast<HoleIndex>(rng() % m);
      t[2 * i + 1] = cycle.next(t[2 * i], static_cast<int>(rng() % 2));
      ok = removed.insert(std::minmax(t[2 * i], t[2 * i + 1])).second;
    }
    if (!ok) continue;
    std::vector<int> ends(static_cast<std::size_t>(2 * k));
    for (int i = 0; i < 2 * k; ++i) ends[static_cast<std::size_t>(i)] = i;
    std::shuffle(ends.begin(), ends.end(), rng);
    int mate[2 * aco::detail::kMaxMoveK];
    for (int i = 0; i < 2 * k; i += 2) {
      mate[ends[static_cast<std::size_t>(i)]] = ends[static_cast<std::size_t>(i) + 1];
      mate[ends[static_cast<std::size_t>(i) + 1]] = ends[static_cast<std::size_t>(i)];
    }
    auto edges = cycle.edges();
    for (int i = 0; i < k; ++i) edges.erase(edges.find(std::minmax(t[2 * i], t[2 * i + 1])));
    std::set<std::pair<HoleIndex, HoleIndex>> added;
    for (int i = 0; i < 2 * k && ok; ++i) {
      if (i > mate[i]) continue;
      const auto e = std::minmax(t[i], t[mate[i]]);
      ok = t[i] != t[mate[i]] && removed.count(e) == 0 && added.insert(e).second;
      edges.insert(e);
    }
    if (!ok) continue;
    const bool expected = one_cycle(m, edges);
    KOptFlips flips;
    const bool feasible = aco::detail::exchange_feasible(cycle, k, t, mate, &flips);
    ++moves_seen[k];
    ASSERT_EQ(feasible, expected) << "trial " << trial << " k " << k;
    if (!feasible) continue;
    ++feasible_seen[k];
    cycle.make(flips);
    if (::testing::Test::HasFatalFailure()) return;
    ASSERT_EQ(cycle.edges(), edges) << "trial " << trial << " k " << k;
  }
  for (int k = 2; k <= aco::detail::kMaxMoveK; ++k) {
    EXPECT_GT(feasible_seen[k], 100) << "k " << k;
    EXPECT_GT(moves_seen[k] - feasible_seen[k], 100) << "k " << k;
  }
}

TEST(kopt_move_test, every_reversal_plan_is_shortest_and_reaches_its_permutation) {
  // Segments 1..m after segment 0: every signed permutation is reached, and
  // the count of reversals never exceeds what a k-opt move is known to need
  // (k = m + 1; a 3-opt move takes at most three).
  for (int m = 1; m < aco::detail::kMaxMoveK; ++m) {
    std::vector<int> perm(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) perm[static_cast<std::size_t>(i)] = i + 1;
    int longest = 0, count = 0;
    do {
      for (int signs = 0; signs < (1 << m); ++signs) {
        std::vector<int> target(perm);
        for (int i = 0; i < m; ++i) {
          if (signs & (1 << i)) target[static_cast<std::size_t>(i)] = -target[static_cast<std::size_t>(i)];
        }
        std::array<std::pair<int, int>, 8> blocks;
        const int n = aco::detail::kopt::reversal_plan(m, target.data(), blocks);
        std::vector<int> cur(static_cast<std::size_t>(m));
        for (int i = 0; i < m; ++i) cur[static_cast<std::size_t>(i)] = i + 1;
        for (int r = 0; r < n; ++r) {
          auto [i, j] = blocks[static_cast<std::size_t>(r)];
          std::reverse(cur.begin() + i, cur.begin() + j + 1);
          for (int q = i; q <= j; ++q) cur[static_cast<std::size_t>(q)] = -cur[static_cast<std::size_t>(q)];
        }
        EXPECT_EQ(cur, target);
        longest = std::max(longest, n);
        ++count;
      }
    } while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_LE(longest, m + 1) << "m " << m;
    if (m == 2) {
      EXPECT_EQ(longest, 3);
    }
    EXPECT_GT(count, 0);
  }
}

}  // namespace
