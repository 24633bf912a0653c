#include <algorithm>
#include <cmath>
#include <string>

#include "aco/error.h"
#include "aco/params.h"
#include "aco/problem.h"

namespace aco {

double route_length(const Problem& problem, const Order& order) {
  if (order.empty()) {
    if (problem.shape == Shape::OpenPath && problem.end) return distance(problem.metric, problem.start, *problem.end);
    return 0.0;
  }
  double total = 0.0;
  const auto& p = problem.points;
  for (std::size_t i = 0; i + 1 < order.size(); ++i) total += distance(problem.metric, p[order[i]], p[order[i + 1]]);
  if (problem.shape == Shape::ClosedTour) {
    if (order.size() > 1) total += distance(problem.metric, p[order.back()], p[order.front()]);
  } else {
    total += distance(problem.metric, problem.start, p[order.front()]);
    if (problem.end) total += distance(problem.metric, p[order.back()], *problem.end);
  }
  return total;
}

bool is_permutation_of(const Problem& problem, const Order& order) {
  if (order.size() != problem.points.size()) return false;
  std::vector<char> seen(order.size(), 0);
  for (HoleIndex h : order) {
    if (h >= order.size() || seen[h]) return false;
    seen[h] = 1;
  }
  return true;
}

const char* to_string(Metric metric) {
  switch (metric) {
    case Metric::Euclidean: return "euclidean";
    case Metric::Chebyshev: return "chebyshev";
    case Metric::Manhattan: return "manhattan";
    case Metric::TsplibEuc2d: return "euc2d";
    case Metric::TsplibCeil2d: return "ceil2d";
    case Metric::TsplibAtt: return "att";
  }
  return "?";
}

std::optional<Metric> metric_from_string(const std::string& name) {
  for (Metric m : {Metric::Euclidean, Metric::Chebyshev, Metric::Manhattan, Metric::TsplibEuc2d, Metric::TsplibCeil2d,
                   Metric::TsplibAtt}) {
    if (name == to_string(m)) return m;
  }
  return std::nullopt;
}

const char* to_string(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::AntSystem: return "as";
    case Algorithm::MaxMinAntSystem: return "mmas";
    case Algorithm::AntColonySystem: return "acs";
    case Algorithm::FocusedAcs: return "focused";
  }
  return "?";
}

const char* to_string(LocalSearch local_search) {
  switch (local_search) {
    case LocalSearch::None: return "none";
    case LocalSearch::TwoOpt: return "2opt";
    case LocalSearch::TwoOptOrOpt: return "2opt+oropt";
    case LocalSearch::ThreeOpt: return "3opt";
    case LocalSearch::FiveOpt: return "5opt";
    case LocalSearch::Auto: return "auto";
  }
  return "?";
}

std::optional<Algorithm> algorithm_from_string(const std::string& name) {
  for (Algorithm a : {Algorithm::AntSystem, Algorithm::MaxMinAntSystem, Algorithm::AntColonySystem, Algorithm::FocusedAcs}) {
    if (name == to_string(a)) return a;
  }
  return std::nullopt;
}

std::optional<LocalSearch> local_search_from_string(const std::string& name) {
  for (LocalSearch l : {LocalSearch::None, LocalSearch::TwoOpt, LocalSearch::TwoOptOrOpt, LocalSearch::ThreeOpt, LocalSearch::FiveOpt, LocalSearch::Auto}) {
    if (name == to_string(l)) return l;
  }
  if (name == "oropt" || name == "or-opt" || name == "2opt+or-opt") return LocalSearch::TwoOptOrOpt;
  return std::nullopt;
}

void Params::validate() const {
  auto bad = [](const std::string& what) { throw InputError(what); };
  if (!(alpha >= 0.0) || !std::isfinite(alpha)) bad("--alpha must be a number >= 0, got " + std::to_string(alpha));
  // Negative beta and rho stand for "the algorithm's default" (see resolve()).
  if (std::isnan(beta) || std::isinf(beta)) bad("--beta must be a number >= 0");
  if (std::isnan(rho) || rho == 0.0 || rho > 1.0) bad("--rho must be in (0, 1], got " + std::to_string(rho));
  if (ants < 0) bad("--ants must be >= 1, got " + std::to_string(ants));
  if (iterations < 0) bad("--iterations must be >= 1, got " + std::to_string(iterations));
  if (!(time_limit_s >= 0.0) || !std::isfinite(time_limit_s)) bad("--time-limit must be >= 0 seconds");
  if (threads < 0) bad("--threads must be >= 1, got " + std::to_string(threads));
  if (threads > 1024) bad("--threads must be at most 1024");
  if (!(q0 >= 0.0 && q0 <= 1.0)) bad("q0 must be in [0, 1]");
  if (candidates < 0) bad("--candidates must be >= 1");
  if (focus_edges < 0) bad("--focus-edges must be >= 1");
}

}  // namespace aco
