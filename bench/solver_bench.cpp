// Solver microbenchmarks: candidate lists, one ant's tour, one local-search
// pass, one pheromone update — optimised beside reference.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "aco/baselines.h"
#include "aco/solve.h"
#include "candidates.h"
#include "local_search.h"
#include "space.h"

namespace {

aco::Problem make_problem(std::size_t n) {
  std::mt19937 rng(static_cast<unsigned>(n));
  std::uniform_real_distribution<double> u(0.0, 1000.0);
  aco::Problem p;
  for (std::size_t i = 0; i < n; ++i) p.points.push_back({u(rng), u(rng)});
  return p;
}

// --- Candidate lists: k-d tree (ours) vs an n² scan with partial sort ---------

void BM_candidates_kdtree(benchmark::State& state) {
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  aco::detail::Space space(p);
  for (auto _ : state) benchmark::DoNotOptimize(aco::detail::build_candidates(space, 12));
  state.SetComplexityN(state.range(0));
}

void BM_candidates_reference_n2(benchmark::State& state) {
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  const std::size_t n = p.points.size();
  for (auto _ : state) {
    std::vector<aco::HoleIndex> lists(n * 12);
    std::vector<std::pair<double, aco::HoleIndex>> row(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) row[j] = {i == j ? 1e300 : aco::euclidean(p.points[i], p.points[j]), j};
      std::partial_sort(row.begin(), row.begin() + 12, row.end());
      for (int r = 0; r < 12; ++r) lists[i * 12 + r] = row[r].second;
    }
    benchmark::DoNotOptimize(lists);
  }
  state.SetComplexityN(state.range(0));
}

// --- Alpha-nearness lists: 100 steps of the Held-Karp ascent, each a
// minimum spanning tree over the 16-nearest graph, then 5 alpha-nearest --

void BM_alpha_candidates_100_ascent_steps(benchmark::State& state) {
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  aco::detail::Space space(p);
  const aco::detail::Candidates nearest = aco::detail::joined_nearest(space, 16);
  for (auto _ : state) benchmark::DoNotOptimize(aco::detail::alpha_candidates(space, nearest, 5, 100));
  state.SetComplexityN(state.range(0));
}

// --- One iteration of one ant without local search: candidate lists with a
// cached choice (ours, through solve) vs the textbook scan of all unvisited
// holes with pow() at every step -------------------------------------------

void BM_one_ant_tour_ours(benchmark::State& state) {
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  aco::Params params;
  params.algorithm = aco::Algorithm::AntSystem;
  params.local_search = aco::LocalSearch::None;
  params.ants = 1;
  params.iterations = 1;
  params.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(aco::solve(p, params));
}

void BM_one_ant_tour_reference(benchmark::State& state) {
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  const std::size_t n = p.points.size();
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double tau = 1e-3, alpha = 1.0, beta = 4.0;
  for (auto _ : state) {
    std::vector<char> visited(n, 0);
    std::vector<double> w(n);
    std::size_t cur = 0;
    visited[0] = 1;
    for (std::size_t step = 1; step < n; ++step) {
      double total = 0;
      for (std::size_t j = 0; j < n; ++j) {
        w[j] = visited[j] ? 0.0 : std::pow(tau, alpha) * std::pow(1.0 / std::max(aco::euclidean(p.points[cur], p.points[j]), 1e-9), beta);
        total += w[j];
      }
      double r = u(rng) * total;
      std::size_t next = 0;
      for (std::size_t j = 0; j < n; ++j) {
        if (visited[j]) continue;
        next = j;
        r -= w[j];
        if (r < 0) break;
      }
      visited[next] = 1;
      cur = next;
    }
    benchmark::DoNotOptimize(cur);
  }
}

// --- One local-search pass from a nearest-neighbour tour -------------------

// One pass from a nearest-neighbour tour; the route is rebuilt every iteration
// so no state carries over.
void local_search_pass(benchmark::State& state, aco::detail::Moves moves) {
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  aco::detail::Space space(p);
  auto cand = aco::detail::build_candidates(space, 12);
  aco::Order nn = aco::nearest_neighbor(p);
  aco::detail::LocalSearcher ls(space, cand);
  for (auto _ : state) {
    std::vector<aco::HoleIndex> route(nn.begin(), nn.end());
    ls.improve(route, moves);
    benchmark::DoNotOptimize(route.data());
  }
}

void BM_two_opt_neighbour_lists(benchmark::State& state) { local_search_pass(state, aco::detail::Moves::TwoOpt); }
void BM_two_opt_or_opt_neighbour_lists(benchmark::State& state) { local_search_pass(state, aco::detail::Moves::OrOpt); }
void BM_three_opt_neighbour_lists(benchmark::State& state) { local_search_pass(state, aco::detail::Moves::ThreeOpt); }

void BM_two_opt_reference_full_scan(benchmark::State& state) {
  // First-improvement 2-opt over all pairs until no move gains: the textbook O(n²) per pass.
  aco::Problem p = make_problem(static_cast<std::size_t>(state.range(0)));
  aco::Order nn = aco::nearest_neighbor(p);
  const auto& pt = p.points;
  for (auto _ : state) {
    std::vector<aco::HoleIndex> t(nn.begin(), nn.end());
    const std::size_t n = t.size();
    bool improved = true;
    while (improved) {
      improved = false;
      for (std::size_t i = 0; i + 2 < n; ++i) {
        for (std::size_t j = i + 2; j < n; ++j) {
          const std::size_t jn = (j + 1) % n;
          if (jn == i) continue;
          const double delta = aco::euclidean(pt[t[i]], pt[t[j]]) + aco::euclidean(pt[t[i + 1]], pt[t[jn]]) -
                               aco::euclidean(pt[t[i]], pt[t[i + 1]]) - aco::euclidean(pt[t[j]], pt[t[jn]]);
          if (delta < -1e-9) {
            std::reverse(t.begin() + static_cast<long>(i) + 1, t.begin() + static_cast<long>(j) + 1);
            improved = true;
          }
        }
      }
    }
    benchmark::DoNotOptimize(t);
  }
}

// --- Pheromone update: evaporation and deposit on n x k candidate edges vs a dense n x n matrix

void BM_pheromone_update_candidate_edges(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0)), k = 12;
  std::vector<double> tau(n * k, 1.0), eta(n * k, 0.5), choice(n * k);
  for (auto _ : state) {
    for (auto& t : tau) t *= 0.8;
    for (std::size_t i = 0; i < n; ++i) tau[i * k + (i % k)] += 0.01;
    for (std::size_t e = 0; e < tau.size(); ++e) choice[e] = tau[e] * eta[e];
    benchmark::DoNotOptimize(choice.data());
  }
}

void BM_pheromone_update_reference_dense(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<float> tau(n * n, 1.0f), eta(n * n, 0.5f), choice(n * n);
  for (auto _ : state) {
    for (auto& t : tau) t *= 0.8f;
    for (std::size_t i = 0; i + 1 < n; ++i) tau[i * n + i + 1] += 0.01f;
    for (std::size_t e = 0; e < tau.size(); ++e) choice[e] = std::pow(tau[e], 1.0f) * eta[e];
    benchmark::DoNotOptimize(choice.data());
  }
}

}  // namespace

BENCHMARK(BM_candidates_kdtree)->RangeMultiplier(4)->Range(64, 16384)->Complexity();
BENCHMARK(BM_candidates_reference_n2)->RangeMultiplier(4)->Range(64, 4096)->Complexity();
BENCHMARK(BM_alpha_candidates_100_ascent_steps)->RangeMultiplier(4)->Range(1024, 16384)->Complexity();
BENCHMARK(BM_one_ant_tour_ours)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_one_ant_tour_reference)->RangeMultiplier(4)->Range(64, 4096);
BENCHMARK(BM_two_opt_neighbour_lists)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_two_opt_or_opt_neighbour_lists)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_three_opt_neighbour_lists)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_two_opt_reference_full_scan)->RangeMultiplier(4)->Range(64, 1024);
BENCHMARK(BM_pheromone_update_candidate_edges)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_pheromone_update_reference_dense)->RangeMultiplier(4)->Range(64, 4096);
