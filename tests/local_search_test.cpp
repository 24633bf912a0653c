// White-box tests of the local search's moves and of the alpha-nearness
// candidates (they reach into libaco/src): routes stay routes, no move
// lengthens one, the result is checked for local optimality by a search of
// our own, and alpha-nearness against a minimum spanning tree built here by
// Prim's O(n²) algorithm.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <set>

#include "aco/baselines.h"
#include "aco/solve.h"
#include "candidates.h"
#include "colony.h"
#include "flip_overlay.h"
#include "local_search.h"
#include "recombine.h"
#include "space.h"

namespace {

using aco::HoleIndex;
using aco::detail::Moves;

aco::Problem random_problem(std::size_t n, unsigned seed, aco::Shape shape, bool clustered) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1000.0);
  std::normal_distribution<double> spread(0.0, 15.0);
  std::vector<aco::Point2> centres;
  for (int c = 0; c < 12; ++c) centres.push_back({u(rng), u(rng)});
  aco::Problem p;
  p.shape = shape;
  p.start = {-50.0, -50.0};
  for (std::size_t i = 0; i < n; ++i) {
    if (clustered) {
      const aco::Point2 c = centres[i % centres.size()];
      p.points.push_back({c.x + spread(rng), c.y + spread(rng)});
    } else {
      p.points.push_back({u(rng), u(rng)});
    }
  }
  return p;
}

std::vector<HoleIndex> start_route(const aco::detail::Space& space, const aco::Problem& p, unsigned seed) {
  aco::Order order = aco::nearest_neighbor(p);
  if (seed % 2 == 1) {
    std::mt19937 rng(seed);
    std::shuffle(order.begin(), order.end(), rng);
  }
  std::vector<HoleIndex> route;
  if (space.open()) route.push_back(space.virtual_node());
  route.insert(route.end(), order.begin(), order.end());
  return route;
}

void expect_route(const aco::detail::Space& space, const std::vector<HoleIndex>& route) {
  ASSERT_EQ(route.size(), space.route_size());
  std::set<HoleIndex> seen(route.begin(), route.end());
  EXPECT_EQ(seen.size(), route.size());
  EXPECT_EQ(*seen.rbegin(), space.route_size() - 1);
  if (space.open()) {
    EXPECT_EQ(route[0], space.virtual_node());
  }
}

// The best 2-opt move of the neighbour-list neighbourhood (Bentley 1992): it
// adds edge (a, c) for c in a's list and removes an edge at a longer than
// (a, c). Found here by trying every such pair, independent of the searcher's
// queue, don't-look bits and positions.
double best_two_opt_gain(const aco::detail::Space& space, const aco::detail::Candidates& cand,
                         const std::vector<HoleIndex>& route) {
  const std::size_t m = route.size();
  std::vector<std::size_t> pos(m);
  for (std::size_t i = 0; i < m; ++i) pos[route[i]] = i;
  auto e = [&](std::size_t i) { return space.e(route[i], route[(i + 1) % m]); };
  auto before = [&](std::size_t i) { return i == 0 ? m - 1 : i - 1; };
  double best = 0.0;
  for (HoleIndex a = 0; a < space.holes(); ++a) {
    for (int r = 0; r < cand.k; ++r) {
      const HoleIndex c = cand.of(a)[r];
      // Edges (a, after a) and (c, after c), or (before a, a) and (before c, c).
      for (bool forward : {true, false}) {
        const std::size_t x = forward ? pos[a] : before(pos[a]), y = forward ? pos[c] : before(pos[c]);
        if (e(x) - space.d(a, c) <= 0.0) continue;
        const std::size_t lo = std::min(x, y), hi = std::max(x, y);
        if (hi <= lo + 1) continue;
        const double gain = e(lo) + e(hi) - space.e(route[lo], route[hi]) - space.e(route[lo + 1], route[(hi + 1) % m]);
        best = std::max(best, gain);
      }
    }
  }
  return best;
}

TEST(local_search_test, every_move_set_keeps_a_route_never_lengthens_it_and_ends_with_no_two_opt_move) {
  for (aco::Shape shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
    for (bool clustered : {false, true}) {
      for (unsigned seed = 1; seed <= 4; ++seed) {
        const aco::Problem p = random_problem(300 + 250 * seed, seed, shape, clustered);
        const aco::detail::Space space(p);
        const aco::detail::Candidates cand = aco::detail::build_candidates(space, 8);
        const std::vector<HoleIndex> start = start_route(space, p, seed);
        // Far Or-opt moves by reversals (see kFarShift) on these routes too.
        for (auto [moves, far_shift] : {std::pair{Moves::TwoOpt, aco::detail::LocalSearcher::kFarShift},
                                        std::pair{Moves::OrOpt, aco::detail::LocalSearcher::kFarShift},
                                        std::pair{Moves::OrOpt, std::size_t{0}},
                                        std::pair{Moves::ThreeOpt, aco::detail::LocalSearcher::kFarShift},
                                        std::pair{Moves::ThreeOpt, std::size_t{0}},
                                        std::pair{Moves::FiveOpt, aco::detail::LocalSearcher::kFarShift}}) {
          SCOPED_TRACE(::testing::Message() << "shape " << int(shape) << " clustered " << clustered << " seed " << seed
                                            << " moves " << int(moves) << " far shift " << far_shift);
          std::vector<HoleIndex> route = start;
          aco::detail::LocalSearcher ls(space, cand);
          ls.audit(true);
          ls.far_shift(far_shift);
          // Don't-look bits are a heuristic: a hole is looked at again only
          // when its own edges change, so a pass can leave a move a later
          // pass finds. Passes are repeated until one changes nothing.
          double length = std::numeric_limits<double>::infinity();
          for (int pass = 0; pass < 50 && space.route_cost(route) < length - 1e-9; ++pass) {
            length = space.route_cost(route);
            ls.improve(route, moves);
            expect_route(space, route);
            // The colony takes an ant's length from its walk minus these gains.
            EXPECT_NEAR(ls.gain(), length - space.route_cost(route), 1e-9 * length);
          }
          EXPECT_EQ(ls.failed_audits(), 0u) << "moves that did not shorten the route";
          EXPECT_GT(ls.audited_searches(), 0u);
          EXPECT_LE(best_two_opt_gain(space, cand, route), 1e-6);
        }
      }
    }
  }
}

// A double bridge within 60 positions anywhere after position 0 (A B C D ->
// A C B D); appends the ends of its new edges to seeds (none if its three
// cuts did not fall apart).
void local_double_bridge(std::vector<HoleIndex>& route, std::mt19937& rng, std::vector<HoleIndex>& seeds) {
  const std::size_t a = 1 + rng() % (route.size() - 70);
  std::size_t cut[3] = {a + rng() % 60, a + rng() % 60, a + rng() % 60};
  std::sort(cut, cut + 3);
  if (!(cut[0] < cut[1] && cut[1] < cut[2])) return;
  std::rotate(route.begin() + static_cast<long>(cut[0] + 1), route.begin() + static_cast<long>(cut[1] + 1),
              route.begin() + static_cast<long>(cut[2] + 1));
  const std::size_t mid = cut[0] + (cut[2] - cut[1]);
  for (std::size_t q : {cut[0], cut[0] + 1, mid, mid + 1, cut[2], cut[2] + 1}) seeds.push_back(route[q]);
}

// An ant's exchange against the reference, read only at the holes its search
// was given or changed edges at (what the colony does above 10 000 holes),
// against the same exchange read from a pass over the whole route.
TEST(local_search_test, an_ants_exchange_read_where_its_search_looked_is_the_whole_routes) {
  for (auto shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
    for (bool clustered : {false, true}) {
      const aco::Problem p = random_problem(3000, clustered ? 5u : 6u, shape, clustered);
      const aco::detail::Space space(p);
      const aco::detail::Candidates cand = aco::detail::build_candidates(space, 8);
      aco::detail::LocalSearcher ls(space, cand);
      // A 2-opt optimum, so the ants' 3-opt searches find more to change.
      std::vector<HoleIndex> ref = start_route(space, p, 2);
      ls.improve(ref, Moves::TwoOpt);
      EXPECT_FALSE(ls.searched_all());  // searched() tells of improve_from alone
      std::vector<std::uint32_t> ref_pos(ref.size());
      for (std::size_t i = 0; i < ref.size(); ++i) ref_pos[ref[i]] = static_cast<std::uint32_t>(i);
      std::mt19937 rng(7);
      int exchanges = 0;
      for (int trial = 0; trial < 40; ++trial) {
        // One to three double bridges, each within 60 positions (A B C D ->
        // A C B D), anywhere along the route.
        std::vector<HoleIndex> route = ref;
        std::vector<HoleIndex> seeds;
        for (int kick = 0; kick < 1 + trial % 3; ++kick) local_double_bridge(route, rng, seeds);
        ls.improve_from(route, Moves::ThreeOpt, seeds);
        expect_route(space, route);
        aco::detail::RouteDiff whole, near;
        aco::detail::route_diff(ref, ref_pos, route, whole);
        if (!whole.added.empty()) ++exchanges;
        if (seeds.empty()) continue;
        ASSERT_TRUE(ls.searched_all());
        aco::detail::route_diff(ref, ref_pos, route, ls.positions(), ls.searched(), near);
        EXPECT_EQ(near.added, whole.added) << "trial " << trial;
        EXPECT_EQ(near.removed, whole.removed) << "trial " << trial;
      }
      // Most searches end on another route, not back on the reference.
      EXPECT_GT(exchanges, 20);
    }
  }
}

TEST(local_search_test, three_opt_improves_routes_that_two_opt_and_or_opt_left_alone) {
  // Fails if 3-opt finds nothing (or only what Or-opt finds): from an
  // Or-opt local optimum, the 3-opt moves shorten every one of these routes.
  for (aco::Shape shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const aco::Problem p = random_problem(2000, seed, shape, seed % 2 == 0);
      const aco::detail::Space space(p);
      const aco::detail::Candidates cand = aco::detail::build_candidates(space, 10);
      std::vector<HoleIndex> route = start_route(space, p, 2);
      aco::detail::LocalSearcher ls(space, cand);
      ls.audit(true);
      ls.far_shift(0);
      ls.improve(route, Moves::OrOpt);
      const double or_opt = space.route_cost(route);
      ls.improve(route, Moves::ThreeOpt);
      expect_route(space, route);
      EXPECT_LT(space.route_cost(route), or_opt * 0.995) << "seed " << seed;
      EXPECT_EQ(ls.failed_audits(), 0u) << "moves that did not shorten the route";
    }
  }
}

// The overlay against the same flips made on an array: after every flip,
// each hole's position and both neighbours, a flip's length and betweenness
// read the same as on the array (position 0 never moves in either).
TEST(local_search_test, flip_overlay_reads_as_the_same_flips_made_on_an_array) {
  std::mt19937 rng(11);
  for (std::size_t m : {std::size_t{5}, std::size_t{9}, std::size_t{64}, std::size_t{1000}}) {
    for (bool shortest_side : {false, true}) {
      for (int trial = 0; trial < 30; ++trial) {
        std::vector<HoleIndex> route(m);
        std::iota(route.begin(), route.end(), 0);
        std::shuffle(route.begin(), route.end(), rng);
        std::vector<std::uint32_t> pos(m);
        for (std::size_t i = 0; i < m; ++i) pos[route[i]] = static_cast<std::uint32_t>(i);
        aco::detail::FlipOverlay overlay;
        overlay.reset(route.data(), pos.data(), m, shortest_side);
        std::vector<HoleIndex> flipped = route;  // the array the flips are made on
        std::vector<std::size_t> at(m);          // its positions
        auto index = [&] {
          for (std::size_t i = 0; i < m; ++i) at[flipped[i]] = i;
        };
        index();
        int made = 0;
        for (int f = 0; f < aco::detail::FlipOverlay::kMaxFlips; ++f) {
          // Two different edges, each (x, next x), given either way round.
          const std::size_t i = rng() % m, j = rng() % m;
          if (i == j) continue;
          HoleIndex a = flipped[i], b = flipped[(i + 1) % m], c = flipped[j], d = flipped[(j + 1) % m];
          if (rng() % 2) {
            std::swap(a, b);
            std::swap(c, d);
          }
          const std::size_t lo = std::min(i, j), hi = std::max(i, j);
          const std::size_t inner = hi - lo;
          EXPECT_EQ(overlay.flip_length(a, b, c, d), shortest_side ? std::min(inner, m - inner) : inner);
          overlay.flip(a, b, c, d);
          std::reverse(flipped.begin() + static_cast<long>(lo + 1), flipped.begin() + static_cast<long>(hi + 1));
          index();
          ++made;
          ASSERT_EQ(overlay.flips(), made);
          EXPECT_EQ(overlay.flip_at(made - 1), (std::array<HoleIndex, 4>{a, b, c, d}));
          for (HoleIndex x = 0; x < m; ++x) {
            ASSERT_EQ(overlay.position(x), at[x]) << "m " << m << " flip " << f << " hole " << x;
            ASSERT_EQ(overlay.next(x, 0), flipped[(at[x] + 1) % m]);
            ASSERT_EQ(overlay.next(x, 1), flipped[(at[x] + m - 1) % m]);
          }
          // Betweenness found by walking the array from x to z each way.
          auto met_on_the_walk = [&](HoleIndex x, HoleIndex y, HoleIndex z, std::size_t step) {
            for (std::size_t q = at[x];; q = (q + step) % m) {
              if (flipped[q] == y) return true;
              if (flipped[q] == z) return false;
            }
          };
          for (int q = 0; q < 20; ++q) {
            const HoleIndex x = flipped[rng() % m], y = flipped[rng() % m], z = flipped[rng() % m];
            EXPECT_EQ(overlay.between(x, y, z, 0), met_on_the_walk(x, y, z, 1));
            EXPECT_EQ(overlay.between(x, y, z, 1), met_on_the_walk(x, y, z, m - 1));
          }
        }
        // The array the overlay reads was never written.
        for (std::size_t i = 0; i < m; ++i) ASSERT_EQ(pos[route[i]], i);
      }
    }
  }
}

// deepen()'s trial flips, made on the array and undone or kept in the
// overlay from their first long one on: the same routes and gains whichever
// way, closed and open, from whole searches and from an ant's seeds.
TEST(local_search_test, deepen_finds_the_same_moves_with_its_trial_flips_in_the_overlay) {
  for (aco::Shape shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
   for (Moves moves : {Moves::ThreeOpt, Moves::FiveOpt}) {  // 3-opt's deeper steps and 5-opt's chain
    for (bool clustered : {false, true}) {
      const aco::Problem p = random_problem(4000, clustered ? 3u : 4u, shape, clustered);
      const aco::detail::Space space(p);
      const aco::detail::Candidates cand = aco::detail::build_candidates(space, 6);
      std::vector<std::vector<HoleIndex>> routes;
      std::vector<double> gains;
      for (std::size_t array_flip : {std::numeric_limits<std::size_t>::max(), std::size_t{0}, std::size_t{40}}) {
        SCOPED_TRACE(::testing::Message() << "shape " << int(shape) << " moves " << int(moves) << " clustered " << clustered
                                          << " array flip " << array_flip);
        aco::detail::LocalSearcher ls(space, cand);
        ls.array_flip(array_flip);
        std::vector<HoleIndex> route = start_route(space, p, 1);  // shuffled: long flips from the start
        ls.improve(route, moves);
        double gain = ls.gain();
        std::mt19937 rng(5);
        for (int kick = 0; kick < 30; ++kick) {
          // A double bridge within 60 positions, then a search from its ends.
          std::vector<HoleIndex> seeds;
          local_double_bridge(route, rng, seeds);
          if (seeds.empty()) continue;
          ls.improve_from(route, moves, seeds);
          gain += ls.gain();
        }
        expect_route(space, route);
        routes.push_back(route);
        gains.push_back(gain);
      }
      EXPECT_EQ(routes[1], routes[0]);
      EXPECT_EQ(routes[2], routes[0]);
      EXPECT_EQ(gains[1], gains[0]);
      EXPECT_EQ(gains[2], gains[0]);
    }
   }
  }
}

TEST(local_search_test, five_opt_on_penalised_costs_shortens_three_opt_optima) {
  // LKH's 5-opt step with alpha-nearness candidates, its gains paid in the
  // ascent's penalised costs (the colony's set-up above 800 holes): every
  // move it makes must shorten the route in lengths (audited), its gains
  // must add up to what the route lost, and from a 3-opt local optimum it
  // must find more. Fails if the penalties were added on one side of a move
  // only, or if the chain's trial moves were kept without a gain.
  for (aco::Shape shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const aco::Problem p = random_problem(2500, seed, shape, seed % 2 == 0);
      const aco::detail::Space space(p);
      // As the colony builds them: the clusters joined, so the ascent runs.
      const aco::detail::Candidates nearest = aco::detail::joined_nearest(space, 16);
      const aco::detail::Candidates cand = aco::detail::alpha_candidates(space, nearest, 5, 30);
      ASSERT_TRUE(cand.has_pi());
      ASSERT_TRUE(std::any_of(cand.pi.begin(), cand.pi.end(), [](double x) { return x != 0.0; }));
      // The penalised rows: the same holes, sorted by d + pi + pi, which stands beside each.
      for (HoleIndex i = 0; i < space.holes(); ++i) {
        const std::size_t row = static_cast<std::size_t>(i) * static_cast<std::size_t>(cand.k);
        std::vector<HoleIndex> a(cand.of(i), cand.of(i) + cand.k), b(cand.pi_list.begin() + static_cast<long>(row),
                                                                      cand.pi_list.begin() + static_cast<long>(row) + cand.k);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        ASSERT_EQ(a, b) << "hole " << i;
        for (int r = 0; r < cand.k; ++r) {
          const HoleIndex j = cand.pi_list[row + static_cast<std::size_t>(r)];
          ASSERT_DOUBLE_EQ(cand.pi_length[row + static_cast<std::size_t>(r)], space.d(i, j) + cand.pi[i] + cand.pi[j]);
          if (r > 0) {
            ASSERT_LE(cand.pi_length[row + static_cast<std::size_t>(r) - 1], cand.pi_length[row + static_cast<std::size_t>(r)]);
          }
        }
      }
      if (seed == 1) {
        // Not asked for (a colony whose search is not 5-opt): the same lists, without the penalised rows.
        const aco::detail::Candidates bare = aco::detail::alpha_candidates(space, nearest, 5, 30, 1, false);
        EXPECT_EQ(bare.list, cand.list);
        EXPECT_EQ(bare.length, cand.length);
        EXPECT_FALSE(bare.has_pi());
        EXPECT_TRUE(bare.pi_list.empty() && bare.pi_length.empty());
      }
      std::vector<HoleIndex> route = start_route(space, p, 2);
      aco::detail::LocalSearcher ls(space, cand);
      ls.audit(true);
      ls.improve(route, Moves::ThreeOpt);
      const double three_opt = space.route_cost(route);
      ls.improve(route, Moves::FiveOpt);
      expect_route(space, route);
      EXPECT_NEAR(ls.gain(), three_opt - space.route_cost(route), 1e-9 * three_opt);
      EXPECT_LT(space.route_cost(route), three_opt * 0.998) << "seed " << seed;
      EXPECT_EQ(ls.failed_audits(), 0u) << "moves that did not shorten the route";
    }
  }
}

TEST(local_search_test, non_sequential_moves_shorten_five_opt_optima) {
  // LKH's Gain23 moves at the 5-opt step's dead ends (bridge_moves.cpp):
  // from a route no sequential 5-opt move improves, they must find more,
  // every move they make must shorten the route (audited), their gains must
  // add up to what it lost, and it must stay a route, closed or open. Fails
  // if the search made exchanges that split the route, paid the penalties on
  // one side only, or found nothing.
  for (aco::Shape shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE(::testing::Message() << "shape " << int(shape) << " seed " << seed);
      const aco::Problem p = random_problem(2000, seed, shape, seed % 2 == 0);
      const aco::detail::Space space(p);
      const aco::detail::Candidates nearest = aco::detail::joined_nearest(space, 16);
      const aco::detail::Candidates cand = aco::detail::alpha_candidates(space, nearest, 5, 30);
      std::vector<HoleIndex> route = start_route(space, p, seed);
      aco::detail::LocalSearcher ls(space, cand);
      ls.audit(true);
      ls.non_sequential(false);
      double length = std::numeric_limits<double>::infinity();
      for (int pass = 0; pass < 20 && space.route_cost(route) < length - 1e-9; ++pass) {
        length = space.route_cost(route);
        ls.improve(route, Moves::FiveOpt);
      }
      const double five_opt = space.route_cost(route);
      ls.non_sequential(true);
      ls.improve(route, Moves::FiveOpt);
      expect_route(space, route);
      EXPECT_NEAR(ls.gain(), five_opt - space.route_cost(route), 1e-9 * five_opt);
      EXPECT_LT(space.route_cost(route), five_opt - 1e-6);
      EXPECT_EQ(ls.failed_audits(), 0u) << "moves that did not shorten the route";
    }
  }
}

// The 5-opt step pays its gains in the ascent's penalised costs up to
// kPenalisedTo holes and in plain lengths above (where the ascent is cut
// short), and no other search reads the penalties.
TEST(local_search_test, penalised_costs_are_kept_for_the_5opt_step_up_to_20000_holes_only) {
  using aco::LocalSearch;
  using aco::detail::uses_penalised_costs;
  EXPECT_TRUE(uses_penalised_costs(3000, LocalSearch::FiveOpt));
  EXPECT_TRUE(uses_penalised_costs(20000, LocalSearch::FiveOpt));
  EXPECT_FALSE(uses_penalised_costs(20001, LocalSearch::FiveOpt));
  EXPECT_FALSE(uses_penalised_costs(100000, LocalSearch::FiveOpt));
  EXPECT_FALSE(uses_penalised_costs(5000, LocalSearch::ThreeOpt));
  EXPECT_FALSE(uses_penalised_costs(5000, LocalSearch::Auto));
  // What auto resolves to, above the bound: the 5-opt step, on plain lengths.
  const aco::Params resolved = aco::resolve(aco::Params{}, 36985);
  EXPECT_EQ(resolved.local_search, LocalSearch::FiveOpt);
  EXPECT_FALSE(uses_penalised_costs(36985, resolved.local_search));
}

TEST(local_search_test, lkh_stall_answers_are_used_up_to_800_holes_and_from_3000_to_10000) {
  EXPECT_TRUE(aco::detail::uses_lkh_stall_answers(10));
  EXPECT_TRUE(aco::detail::uses_lkh_stall_answers(800));
  EXPECT_FALSE(aco::detail::uses_lkh_stall_answers(801));
  EXPECT_FALSE(aco::detail::uses_lkh_stall_answers(2999));
  EXPECT_TRUE(aco::detail::uses_lkh_stall_answers(3000));
  EXPECT_TRUE(aco::detail::uses_lkh_stall_answers(10000));
  EXPECT_FALSE(aco::detail::uses_lkh_stall_answers(10001));
  EXPECT_FALSE(aco::detail::uses_lkh_stall_answers(100000));
}

TEST(local_search_test, alpha_candidates_are_nearest_holes_and_hold_the_spanning_tree_edges) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const aco::Problem p = random_problem(400, seed, aco::Shape::ClosedTour, seed == 2);
    const aco::detail::Space space(p);
    const HoleIndex n = space.holes();
    const aco::detail::Candidates nearest = aco::detail::build_candidates(space, 16);
    // Without the ascent alpha is measured on the plain minimum spanning
    // tree, whose own edges have alpha 0: Prim's tree, built here over all
    // pairs, must then be in the lists of holes with at most k tree edges.
    const int k = 5;
    const aco::detail::Candidates alpha = aco::detail::alpha_candidates(space, nearest, k, 0);
    ASSERT_EQ(alpha.k, k);
    std::vector<double> best(n, std::numeric_limits<double>::infinity());
    std::vector<HoleIndex> parent(n, 0);
    std::vector<char> done(n, 0);
    std::vector<std::vector<HoleIndex>> tree(n);
    best[0] = 0.0;
    for (HoleIndex step = 0; step < n; ++step) {
      HoleIndex u = n;
      for (HoleIndex v = 0; v < n; ++v) {
        if (!done[v] && (u == n || best[v] < best[u])) u = v;
      }
      done[u] = 1;
      if (step > 0) {
        tree[u].push_back(parent[u]);
        tree[parent[u]].push_back(u);
      }
      for (HoleIndex v = 0; v < n; ++v) {
        if (!done[v] && space.d(u, v) < best[v]) {
          best[v] = space.d(u, v);
          parent[v] = u;
        }
      }
    }
    int checked = 0;
    for (HoleIndex i = 0; i < n; ++i) {
      const HoleIndex* row = alpha.of(i);
      const HoleIndex* near = nearest.of(i);
      std::set<HoleIndex> in_row(row, row + k);
      EXPECT_EQ(in_row.size(), static_cast<std::size_t>(k));
      EXPECT_EQ(in_row.count(i), 0u);
      for (int r = 0; r < k; ++r) {
        EXPECT_NE(std::find(near, near + nearest.k, row[r]), near + nearest.k) << "not one of the 16 nearest";
        if (r > 0) {
          EXPECT_LE(space.d(i, row[r - 1]), space.d(i, row[r])) << "rows are sorted by distance";
        }
      }
      if (tree[i].size() > static_cast<std::size_t>(k)) continue;
      for (HoleIndex j : tree[i]) {
        if (std::find(near, near + nearest.k, j) == near + nearest.k) continue;
        EXPECT_EQ(in_row.count(j), 1u) << "tree edge " << i << "-" << j << " missing from " << i << "'s row";
        ++checked;
      }
    }
    EXPECT_GT(checked, static_cast<int>(n));  // most tree edges were checked
  }
}

TEST(local_search_test, the_ascent_keeps_rows_valid_and_changes_them) {
  const aco::Problem p = random_problem(1500, 7, aco::Shape::ClosedTour, false);
  const aco::detail::Space space(p);
  const aco::detail::Candidates nearest = aco::detail::build_candidates(space, 16);
  const aco::detail::Candidates plain = aco::detail::alpha_candidates(space, nearest, 5, 0);
  const aco::detail::Candidates raised = aco::detail::alpha_candidates(space, nearest, 5, 60);
  ASSERT_EQ(raised.list.size(), plain.list.size());
  std::size_t differ = 0;
  for (HoleIndex i = 0; i < space.holes(); ++i) {
    std::set<HoleIndex> row(raised.of(i), raised.of(i) + 5);
    EXPECT_EQ(row.size(), 5u);
    EXPECT_EQ(row.count(i), 0u);
    if (!std::equal(plain.of(i), plain.of(i) + 5, raised.of(i))) ++differ;
  }
  // pi moves the trees, so some rows must change (else the ascent did nothing).
  EXPECT_GT(differ, space.holes() / 50);
}

// Holes on a lattice, which makes many lengths equal, and a pile of holes on
// one spot, whose nearest are all each other: a neighbour graph of several
// pieces, with ties everywhere.
aco::Problem lattice_with_pile() {
  aco::Problem p;
  p.shape = aco::Shape::ClosedTour;
  for (int x = 0; x < 50; ++x) {
    for (int y = 0; y < 30; ++y) p.points.push_back({10.0 * x, 10.0 * y});
  }
  for (int i = 0; i < 40; ++i) p.points.push_back({1000.0, 1000.0});
  return p;
}

TEST(local_search_test, candidate_rows_are_the_same_on_any_thread_count) {
  // On several threads each step's tree is grown in parts and joined (one
  // strip of holes a thread, each joined to the next by the chains of its
  // forest): the same tree, so the same rows.
  for (const int layout : {0, 1, 2}) {
    const aco::Problem p = layout == 2 ? lattice_with_pile() : random_problem(3000, 11, aco::Shape::ClosedTour, layout == 1);
    const aco::detail::Space space(p);
    // The 16 nearest of clustered holes alone are a forest, without the ascent.
    for (const bool joined : {true, false}) {
      auto neighbours = [&](int threads) {
        return joined ? aco::detail::joined_nearest(space, 16, threads) : aco::detail::build_candidates(space, 16, threads);
      };
      const aco::detail::Candidates nearest = neighbours(1);
      const aco::detail::Candidates alpha = aco::detail::alpha_candidates(space, nearest, 5, 30, 1);
      for (const int threads : {2, 3, 5}) {
        SCOPED_TRACE(::testing::Message() << threads << " threads, layout " << layout << ", joined " << joined);
        const aco::detail::Candidates nearest_t = neighbours(threads);
        EXPECT_EQ(nearest_t.list, nearest.list);
        EXPECT_EQ(aco::detail::alpha_candidates(space, nearest_t, 5, 30, threads).list, alpha.list);
      }
    }
  }
}

// The local search reads a row's distances from the lists (Candidates::length):
// each must be Space::d of its entry, the same bits, from every builder.
TEST(local_search_test, candidate_lengths_are_the_distances_of_their_rows) {
  for (const int layout : {0, 1, 2}) {
    const aco::Problem p = layout == 2 ? lattice_with_pile() : random_problem(1500, 5, aco::Shape::ClosedTour, layout == 1);
    const aco::detail::Space space(p);
    auto expect_lengths = [&](const aco::detail::Candidates& c, const char* builder) {
      SCOPED_TRACE(::testing::Message() << builder << ", layout " << layout);
      ASSERT_EQ(c.length.size(), c.list.size());
      std::size_t wrong = 0;
      for (HoleIndex i = 0; i < space.holes(); ++i) {
        for (int r = 0; r < c.k; ++r) wrong += c.lengths_of(i)[r] != space.d(i, c.of(i)[r]);
      }
      EXPECT_EQ(wrong, 0u);
    };
    const aco::detail::Candidates nearest = aco::detail::build_candidates(space, 16, 2);
    expect_lengths(nearest, "build_candidates");
    expect_lengths(aco::detail::build_candidates(space, static_cast<int>(space.holes()) - 1), "build_candidates, every hole");
    expect_lengths(aco::detail::with_quadrant_neighbours(space, nearest), "with_quadrant_neighbours");
    expect_lengths(aco::detail::joined_nearest(space, 16, 2), "joined_nearest");
    expect_lengths(aco::detail::alpha_candidates(space, nearest, 5, 20, 2), "alpha_candidates");
  }
}

TEST(local_search_test, candidate_edges_are_each_row_edge_once_in_order) {
  for (const int layout : {0, 1, 2}) {
    const aco::Problem p = layout == 2 ? lattice_with_pile() : random_problem(700, 3, aco::Shape::ClosedTour, layout == 1);
    const aco::detail::Space space(p);
    const HoleIndex n = space.holes();
    const aco::detail::Candidates c = aco::detail::build_candidates(space, 9);
    std::vector<std::pair<HoleIndex, HoleIndex>> expected;
    for (HoleIndex i = 0; i < n; ++i) {
      for (int r = 0; r < c.k; ++r) expected.emplace_back(std::min(i, c.of(i)[r]), std::max(i, c.of(i)[r]));
    }
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    EXPECT_EQ(aco::detail::candidate_edges(c, n), expected) << "layout " << layout;
  }
}

// Which quadrant around `from` a point is in, as bucket_grid.h counts them.
int quadrant_of(aco::Point2 from, aco::Point2 p) {
  const double dx = p.x - from.x, dy = p.y - from.y;
  if (dx > 0 && dy >= 0) return 0;
  if (dx <= 0 && dy > 0) return 1;
  if (dx < 0 && dy <= 0) return 2;
  if (dx >= 0 && dy < 0) return 3;
  return -1;
}

TEST(local_search_test, quadrant_neighbours_are_the_nearest_in_each_quadrant_and_join_clusters) {
  // Twelve tight clusters: the 16 nearest of every hole are in its own cluster.
  const aco::Problem p = random_problem(600, 4, aco::Shape::ClosedTour, true);
  const aco::detail::Space space(p);
  const HoleIndex n = space.holes();
  const aco::detail::Candidates nearest = aco::detail::build_candidates(space, 16);
  const aco::detail::Candidates joined = aco::detail::with_quadrant_neighbours(space, nearest);
  ASSERT_EQ(joined.k, 16);
  for (HoleIndex i = 0; i < n; ++i) {
    const HoleIndex* row = joined.of(i);
    EXPECT_EQ(std::set<HoleIndex>(row, row + 16).size(), 16u);
    for (int r = 1; r < 16; ++r) EXPECT_LE(space.d(i, row[r - 1]), space.d(i, row[r]));
    // Brute force: the nearest hole in each quadrant is in the row.
    for (int q = 0; q < 4; ++q) {
      HoleIndex best = n;
      for (HoleIndex j = 0; j < n; ++j) {
        if (j == i || quadrant_of(space.point(i), space.point(j)) != q) continue;
        if (best == n || space.d(i, j) < space.d(i, best)) best = j;
      }
      if (best == n) continue;
      bool found = false;
      for (int r = 0; r < 16; ++r) found = found || space.d(i, row[r]) == space.d(i, best);
      EXPECT_TRUE(found) << "hole " << i << " quadrant " << q;
    }
  }
  // The rows as a graph: the nearest alone fall apart, with the quadrants one piece.
  auto pieces = [&](const aco::detail::Candidates& c) {
    std::vector<HoleIndex> root(n);
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](HoleIndex x) {
      while (root[x] != x) x = root[x] = root[root[x]];
      return x;
    };
    for (auto [a, b] : aco::detail::candidate_edges(c, n)) root[find(a)] = find(b);
    std::set<HoleIndex> roots;
    for (HoleIndex i = 0; i < n; ++i) roots.insert(find(i));
    return roots.size();
  };
  EXPECT_GT(pieces(nearest), 1u);
  EXPECT_EQ(pieces(joined), 1u);
  // joined_nearest joins only what falls apart: these clusters, not uniform holes.
  EXPECT_EQ(aco::detail::joined_nearest(space, 16).list, joined.list);
  const aco::Problem uniform = random_problem(600, 4, aco::Shape::ClosedTour, false);
  const aco::detail::Space uniform_space(uniform);
  EXPECT_EQ(aco::detail::joined_nearest(uniform_space, 16).list, aco::detail::build_candidates(uniform_space, 16).list);
}

// The colony's kick: a true double bridge, so four edges of the route are new
// (three cuts, a segment exchange, would be a 3-opt move the search undoes),
// the seeds are their ends, and an open path keeps V at position 0.
TEST(local_search_test, walk_double_bridge_makes_four_new_edges_and_seeds_their_ends) {
  for (aco::Shape shape : {aco::Shape::ClosedTour, aco::Shape::OpenPath}) {
    for (bool clustered : {false, true}) {
      const aco::Problem p = random_problem(600, clustered ? 3u : 4u, shape, clustered);
      const aco::detail::Space space(p);
      const aco::detail::Candidates cand = aco::detail::build_candidates(space, 8);
      const std::vector<HoleIndex> start = start_route(space, p, 2);
      const auto edges_of = [](const std::vector<HoleIndex>& r) {
        std::set<std::pair<HoleIndex, HoleIndex>> e;
        for (std::size_t i = 0; i < r.size(); ++i) {
          const HoleIndex a = r[i], b = r[(i + 1) % r.size()];
          e.insert({std::min(a, b), std::max(a, b)});
        }
        return e;
      };
      const auto before = edges_of(start);
      int kicked = 0, four_new = 0;
      for (std::uint64_t k = 1; k <= 20; ++k) {
        SCOPED_TRACE(::testing::Message() << "shape " << int(shape) << " clustered " << clustered << " kick " << k);
        std::vector<HoleIndex> route = start;
        std::vector<HoleIndex> seeds;
        aco::detail::Rng rng(7, k, 0);
        aco::detail::walk_double_bridge(space, cand, route, rng, seeds);
        expect_route(space, route);
        if (seeds.empty()) {
          EXPECT_EQ(route, start);
          continue;
        }
        ++kicked;
        std::set<std::pair<HoleIndex, HoleIndex>> fresh;
        for (const auto& e : edges_of(route)) {
          if (before.count(e) == 0) fresh.insert(e);
        }
        // Four, but for two single-hole stretches side by side, whose join
        // comes back the other way round.
        ASSERT_GE(fresh.size(), 3u);
        ASSERT_LE(fresh.size(), 4u);
        if (fresh.size() == 4) ++four_new;
        EXPECT_EQ(seeds.size(), 8u);
        const std::set<HoleIndex> seeded(seeds.begin(), seeds.end());
        for (const auto& [a, b] : fresh) EXPECT_TRUE(seeded.count(a) == 1 && seeded.count(b) == 1);
      }
      EXPECT_GE(kicked, 18);
      EXPECT_GE(four_new, 15);
    }
  }
}

// LKH's restricted search: a focused ant's 3-opt or 5-opt step starts only by
// taking out an edge the reference lacks. Searched against itself a route
// gets no such step; unrestricted, the same 2-opt and Or-opt optimum gets shorter.
TEST(local_search_test, a_search_restricted_to_a_route_starts_no_step_from_its_edges) {
  for (Moves moves : {Moves::ThreeOpt, Moves::FiveOpt}) {
    const aco::Problem p = random_problem(2000, 9, aco::Shape::ClosedTour, false);
    const aco::detail::Space space(p);
    const aco::detail::Candidates cand = aco::detail::build_candidates(space, 8);
    std::vector<HoleIndex> reference = start_route(space, p, 2);
    aco::detail::LocalSearcher ls(space, cand);
    // Passes until one changes nothing (don't-look bits can leave a move).
    for (int pass = 0; pass < 50; ++pass) {
      ls.improve(reference, Moves::OrOpt);
      if (ls.gain() == 0.0) break;
    }
    std::vector<std::uint32_t> pos(reference.size());
    for (std::size_t i = 0; i < reference.size(); ++i) pos[reference[i]] = static_cast<std::uint32_t>(i);
    std::vector<HoleIndex> all(reference.begin(), reference.end());

    std::vector<HoleIndex> restricted = reference;
    ls.restrict_to(&reference, &pos);
    ls.non_sequential(false);  // as LKH's Gain23, not restricted
    ls.improve_from(restricted, moves, all);
    EXPECT_EQ(restricted, reference) << "moves " << int(moves);
    EXPECT_EQ(ls.gain(), 0.0);

    std::vector<HoleIndex> free = reference;
    ls.restrict_to(nullptr, nullptr);
    ls.improve_from(free, moves, all);
    EXPECT_GT(ls.gain(), 0.0) << "moves " << int(moves);
  }
}

// The fresh restarts' route (restarts.cpp): nearest neighbour from a given
// hole. Holes on a line with widening gaps, so no distance ties.
TEST(local_search_test, nearest_neighbour_starts_at_the_given_hole_of_a_closed_tour_and_at_the_start_point_of_an_open_path) {
  aco::Problem p;
  for (const double x : {0.0, 1.0, 3.0, 6.0, 10.0, 15.0}) p.points.push_back({x, 0.0});
  {
    const aco::detail::Space space(p);
    EXPECT_EQ(aco::detail::nearest_neighbor_order(space, {}, 2), (aco::Order{2, 1, 0, 3, 4, 5}));
    EXPECT_EQ(aco::detail::nearest_neighbor_order(space, {}, 4), (aco::Order{4, 3, 2, 1, 0, 5}));
    EXPECT_EQ(aco::detail::nearest_neighbor_order(space, {}), (aco::Order{0, 1, 2, 3, 4, 5}));
  }
  p.shape = aco::Shape::OpenPath;
  p.start = {16.0, 0.0};
  const aco::detail::Space space(p);
  EXPECT_EQ(aco::detail::nearest_neighbor_order(space, {}, 2), (aco::Order{5, 4, 3, 2, 1, 0}));
}

}  // namespace
