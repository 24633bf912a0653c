// White-box tests of recombining ants (libaco/src/recombine.h): a route's
// exchange against the reference is what tells them apart, and merging
// exchanges gives one cycle holding exactly the exchanges it applied, never a
// route split in two.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "recombine.h"

namespace {

using aco::HoleIndex;
using aco::detail::Edge;
using aco::detail::RouteDiff;

using EdgeSet = std::set<Edge>;

Edge ordered(HoleIndex a, HoleIndex b) { return a < b ? Edge{a, b} : Edge{b, a}; }

EdgeSet edges_of(const std::vector<HoleIndex>& route) {
  EdgeSet e;
  for (std::size_t i = 0; i < route.size(); ++i) e.insert(ordered(route[i], route[(i + 1) % route.size()]));
  return e;
}

// A cycle's weight under an arbitrary symmetric whole-number edge weight.
long weight_of(const std::vector<HoleIndex>& route) {
  long w = 0;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Edge e = ordered(route[i], route[(i + 1) % route.size()]);
    w += static_cast<long>((e.first * 7919u + e.second * 104729u) % 1000u);
  }
  return w;
}

std::vector<std::uint32_t> positions(const std::vector<HoleIndex>& route) {
  std::vector<std::uint32_t> pos(route.size());
  for (std::size_t i = 0; i < route.size(); ++i) pos[route[i]] = static_cast<std::uint32_t>(i);
  return pos;
}

bool is_cycle_over_all(const std::vector<HoleIndex>& route, std::size_t m) {
  if (route.size() != m) return false;
  std::vector<HoleIndex> sorted = route;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < m; ++i) {
    if (sorted[i] != i) return false;
  }
  return true;
}

// Reverses route positions i+1..j: a 2-opt move.
std::vector<HoleIndex> two_opt(std::vector<HoleIndex> route, std::size_t i, std::size_t j) {
  std::reverse(route.begin() + static_cast<long>(i + 1), route.begin() + static_cast<long>(j + 1));
  return route;
}

TEST(RouteDiff, TheSameCycleFromAnotherStartOrTheOtherWayHasNoExchange) {
  std::vector<HoleIndex> ref(40);
  std::iota(ref.begin(), ref.end(), 0);
  std::shuffle(ref.begin(), ref.end(), std::mt19937(3));
  std::vector<HoleIndex> route = ref;
  std::rotate(route.begin(), route.begin() + 17, route.end());
  RouteDiff d;
  aco::detail::route_diff(ref, positions(ref), route, d);
  EXPECT_TRUE(d.removed.empty() && d.added.empty());
  std::reverse(route.begin(), route.end());
  aco::detail::route_diff(ref, positions(ref), route, d);
  EXPECT_TRUE(d.removed.empty() && d.added.empty());
}

TEST(RouteDiff, ATwoOptMoveRemovesTwoEdgesAndAddsTwo) {
  std::vector<HoleIndex> ref(30);
  std::iota(ref.begin(), ref.end(), 0);
  RouteDiff d;
  aco::detail::route_diff(ref, positions(ref), two_opt(ref, 4, 11), d);
  EXPECT_EQ(d.removed, (std::vector<Edge>{{4, 5}, {11, 12}}));
  std::vector<Edge> added = d.added;
  std::sort(added.begin(), added.end());
  EXPECT_EQ(added, (std::vector<Edge>{{4, 11}, {5, 12}}));
}

TEST(DiffMerger, InterleavedTwoOptMovesWouldSplitTheRouteSoOnlyTheFirstIsApplied) {
  // Positions i < k < j < l: each move alone is a route, both together two cycles.
  std::vector<HoleIndex> ref(40);
  std::iota(ref.begin(), ref.end(), 0);
  const auto pos = positions(ref);
  RouteDiff a, b;
  const std::vector<HoleIndex> route_a = two_opt(ref, 5, 20);
  aco::detail::route_diff(ref, pos, route_a, a);
  aco::detail::route_diff(ref, pos, two_opt(ref, 12, 30), b);
  aco::detail::DiffMerger merger;
  std::vector<HoleIndex> out;
  EXPECT_EQ(merger.merge(ref, pos, {&a, &b}, ref[1], out), 1u);
  EXPECT_EQ(edges_of(out), edges_of(route_a));
  EXPECT_EQ(out[0], ref[0]);
}

TEST(DiffMerger, ExchangesThatShareAHoleAreNotBothApplied) {
  std::vector<HoleIndex> ref(40);
  std::iota(ref.begin(), ref.end(), 0);
  const auto pos = positions(ref);
  RouteDiff a, b;
  aco::detail::route_diff(ref, pos, two_opt(ref, 5, 10), a);
  const std::vector<HoleIndex> route_b = two_opt(ref, 10, 15);  // hole 11 is in both
  aco::detail::route_diff(ref, pos, route_b, b);
  aco::detail::DiffMerger merger;
  std::vector<HoleIndex> out;
  EXPECT_EQ(merger.merge(ref, pos, {&b, &a}, ref[1], out), 1u);
  EXPECT_EQ(edges_of(out), edges_of(route_b));
}

// Random local moves (2-opt, or-opt, double bridge) in short stretches of a
// random route, merged in random order: the result is one cycle over every
// hole, each exchange is in it whole or not at all, it holds no other edge
// than R's and the applied ones', and disjoint nested moves all go in.
// applied() names those exchanges, and their gains add up to the merged
// route's (what the colony takes as its length before measuring it).
TEST(DiffMerger, MergedRouteIsOneCycleHoldingWholeExchangesOnly) {
  std::mt19937 rng(11);
  int merged_several = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t m = 60 + rng() % 400;
    std::vector<HoleIndex> ref(m);
    std::iota(ref.begin(), ref.end(), 0);
    std::shuffle(ref.begin(), ref.end(), rng);
    const auto pos = positions(ref);
    const int moves = 2 + static_cast<int>(rng() % 8);
    std::vector<RouteDiff> diffs(static_cast<std::size_t>(moves));
    std::vector<long> gain;  // of each exchange, in whole-number edge weights
    for (RouteDiff& d : diffs) {
      std::vector<HoleIndex> route = ref;
      const std::size_t span = 8 + rng() % 30;
      const std::size_t a = rng() % (m - span - 1);
      std::size_t cut[3];
      for (auto& c : cut) c = a + 1 + rng() % (span - 1);
      std::sort(cut, cut + 3);
      switch (rng() % 3) {
        case 0:
          route = two_opt(route, a, cut[2]);
          break;
        case 1:  // move positions cut[0]+1..cut[1] to after cut[2]
          std::rotate(route.begin() + static_cast<long>(cut[0] + 1), route.begin() + static_cast<long>(cut[1] + 1),
                      route.begin() + static_cast<long>(cut[2] + 1));
          break;
        default:  // double bridge: a..cut0 | cut0+1..cut1 | cut1+1..cut2 swapped
          std::rotate(route.begin() + static_cast<long>(cut[0] + 1), route.begin() + static_cast<long>(cut[1] + 1),
                      route.begin() + static_cast<long>(cut[2] + 1));
          std::reverse(route.begin() + static_cast<long>(a + 1), route.begin() + static_cast<long>(cut[2] + 1));
          break;
      }
      aco::detail::route_diff(ref, pos, route, d);
      // The exchange is exactly what differs.
      EdgeSet removed(d.removed.begin(), d.removed.end()), added(d.added.begin(), d.added.end());
      EdgeSet expected = edges_of(ref);
      for (const Edge& e : removed) expected.erase(e);
      for (const Edge& e : added) expected.insert(e);
      ASSERT_EQ(expected, edges_of(route)) << "trial " << trial;
      gain.push_back(weight_of(route) - weight_of(ref));
    }
    std::vector<const RouteDiff*> order;
    for (const RouteDiff& d : diffs) order.push_back(&d);
    aco::detail::DiffMerger merger;
    std::vector<HoleIndex> out;
    const std::size_t applied = merger.merge(ref, pos, order, ref[1], out);
    ASSERT_GE(applied, 1u) << "trial " << trial;  // the first one always fits
    ASSERT_TRUE(is_cycle_over_all(out, m)) << "trial " << trial;
    EXPECT_EQ(out[0], ref[0]);
    const EdgeSet got = edges_of(out);
    EdgeSet expected = edges_of(ref);
    std::vector<std::size_t> whole_ones;
    for (std::size_t i = 0; i < diffs.size(); ++i) {
      const RouteDiff& d = diffs[i];
      const std::size_t in = static_cast<std::size_t>(
          std::count_if(d.added.begin(), d.added.end(), [&](const Edge& e) { return got.count(e) > 0; }));
      const bool removed_all = std::none_of(d.removed.begin(), d.removed.end(), [&](const Edge& e) { return got.count(e) > 0; });
      if (in == d.added.size() && removed_all && !d.added.empty()) {
        whole_ones.push_back(i);
        for (const Edge& e : d.removed) expected.erase(e);
        for (const Edge& e : d.added) expected.insert(e);
      }
    }
    EXPECT_EQ(whole_ones.size(), applied) << "trial " << trial;
    EXPECT_EQ(merger.applied(), whole_ones) << "trial " << trial;
    EXPECT_EQ(got, expected) << "trial " << trial;
    long gains = 0;
    for (std::size_t i : merger.applied()) gains += gain[i];
    EXPECT_EQ(weight_of(out) - weight_of(ref), gains) << "trial " << trial;
    merged_several += applied >= 2;
  }
  EXPECT_GT(merged_several, 100);  // the test is about merging, not about skipping
}

}  // namespace
