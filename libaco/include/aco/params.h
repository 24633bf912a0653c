#pragma once
/**
 * How to solve. Zero or negative fields mean "the algorithm's default"; see
 * resolve() for the values chosen. validate() throws aco::InputError naming the
 * first bad field.
 */
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace aco {

enum class Algorithm {
  AntSystem,        // the thesis: Dorigo's Ant System, every ant deposits 1/C_k
  MaxMinAntSystem,  // Stützle & Hoos 2000: best ant deposits, trails clamped to [tau_min, tau_max]
  AntColonySystem,  // Dorigo & Gambardella 1997: pseudo-random proportional rule, local update
  // ACS's rules with focused construction (after Skinderowicz 2022): each ant
  // keeps the best route and changes a bounded number of its edges, and local
  // search looks only where it changed, so an ant costs what it changes.
  FocusedAcs
};

// ThreeOpt adds sequential 3-opt moves to 2-opt and Or-opt; FiveOpt adds
// LKH's sequential 5-opt step instead. Auto, the default, is FiveOpt from
// 3000 to 200 000 holes, where it measured better, and ThreeOpt below
// (measured better there) and above (not measured; resolve(),
// libaco/src/solve.cpp).
enum class LocalSearch { None, TwoOpt, TwoOptOrOpt, ThreeOpt, FiveOpt, Auto };

struct Progress {
  int iteration = 0;
  double wall_s = 0.0;
  double best_length = 0.0;
};

struct Params {
  // The default is what measured best (docs/benchmarks.md): the focused colony
  // with 2-opt, Or-opt and 3-opt, ahead of whole-route ACS on every TSPLIB row measured.
  Algorithm algorithm = Algorithm::FocusedAcs;
  LocalSearch local_search = LocalSearch::Auto;
  int ants = 0;             // 0: default for the algorithm and size
  int iterations = 0;       // 0: default; the run stops at whichever limit comes first
  double time_limit_s = 0;  // 0: none
  int stall_iterations = 0; // stop after this many iterations without improvement; 0: default, <0: never
  double alpha = 1.0;       // pheromone weight
  double beta = -1.0;       // heuristic weight; <0: default (AS 4, MMAS/ACS 2)
  double rho = -1.0;        // evaporation; <0: default (AS 0.5, MMAS 0.2, ACS 0.1)
  double q0 = 0.9;          // ACS exploitation probability
  int candidates = 0;       // candidate list length (alpha-nearest with local search); 0: default
  int focus_edges = 0;      // FocusedAcs: new edges an ant makes before it copies the rest; 0: default
  std::uint64_t seed = 1;
  int threads = 0;          // 0: all cores
  // Called after every iteration from the calling thread (progress lines); may be empty.
  std::function<void(const Progress&)> on_iteration;
  // Set (from any thread) to end the run after the iteration under way, with
  // the best route so far (stop_reason "stopped"); may be null.
  const std::atomic<bool>* stop = nullptr;

  void validate() const;
};

const char* to_string(Algorithm algorithm);
const char* to_string(LocalSearch local_search);
std::optional<Algorithm> algorithm_from_string(const std::string& name);
std::optional<LocalSearch> local_search_from_string(const std::string& name);

}  // namespace aco
