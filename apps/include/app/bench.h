#pragma once
/**
 * The benchmark harness behind acobench: a grid of solver settings over
 * instances, one row per run, a summary per cell (median, mean, standard
 * deviation, minimum; speedup and efficiency against one thread), the thesis's
 * tables, and SVG charts.
 */
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "aco/params.h"
#include "aco/problem.h"
#include "aco/solution.h"

namespace app {

struct BenchCell {
  std::string instance;   // path as given
  std::string algorithm;  // as, mmas, acs; or a baseline: input, nn, greedy, raster, nn2opt
  double alpha = 1, beta = -1, rho = -1;  // -1: the algorithm's default
  int ants = 0, iterations = 0, threads = 1;
  double time_limit_s = 0;
  std::string local_search = "auto";
};

struct BenchRun {
  BenchCell cell;
  std::string name;  // instance name (file stem)
  std::size_t n = 0;
  std::uint64_t seed = 1;
  double length = 0;
  std::optional<double> optimum;
  double wall_s = 0;
  int iterations_done = 0;
  std::optional<double> time_to_1pct_s;  // first time within 1 % of the best known length
  std::vector<double> busy_s;
  std::vector<aco::TracePoint> trace;
  // Resolved parameters actually used.
  double alpha = 0, beta = 0, rho = 0;
  int ants = 0;
  std::uint64_t tour_hash = 0;  // FNV-1a of the route's order: the same tour, the same hash
  // Where the run sits in its sweep (shards, merge): its position in the
  // one-process order, the sweep's fingerprint and size, and the shard that
  // ran it ("K/N"; empty for a whole sweep).
  std::size_t sweep_index = 0;
  std::string sweep_id, shard, version;
  std::size_t sweep_runs = 0;
};

// One run of a sweep: a cell and a seed.
struct SweepRun {
  BenchCell cell;
  std::uint64_t seed = 1;
};

// The K-th (0-based) of N slices of a sweep's runs: run i of the one-process
// order belongs to shard i mod N, so a run always lands in the same shard,
// each in exactly one, and the shards are within one run of each other in size.
struct Shard {
  std::size_t k = 0, n = 1;
  bool whole() const { return n == 1; }
  bool holds(std::size_t sweep_index) const { return sweep_index % n == k; }
  std::string text() const;  // "K/N"
};
// "K/N" with 0 <= K < N; throws UserError naming --shard.
Shard parse_shard(const std::string& text);

// A sweep's fingerprint: the program's version and every run (cell and seed)
// in order, so two shards share it only when they split the same sweep.
std::string sweep_fingerprint(const std::vector<SweepRun>& sweep, const std::string& version);

// Marks runs with their place in the sweep (call before writing rows).
void stamp_sweep(std::vector<BenchRun>& runs, const std::vector<std::size_t>& sweep_index, const std::string& sweep_id,
                 std::size_t sweep_runs, const Shard& shard, const std::string& version);

// Reads a runs CSV that runs_csv wrote (a shard, or a whole sweep) back into
// runs; throws UserError naming the file and line of a row it cannot read.
std::vector<BenchRun> read_runs_csv(const std::string& text, const std::string& path);

// The shards of one sweep joined, in the one-process order, with the time to
// 1 % recomputed over all of them. Throws UserError, naming the file, for a
// shard of another sweep or version, a shard given twice, a missing shard and
// a shard that lacks runs (cut short).
std::vector<BenchRun> merge_shards(const std::vector<std::string>& paths);

struct BenchInstance {
  std::string path, name;
  std::vector<aco::Point2> points;
  bool tsplib = false;
  aco::Metric tsplib_metric = aco::Metric::TsplibEuc2d;  // its EDGE_WEIGHT_TYPE
  std::optional<double> optimum;
};

// Params for an algorithm and a local search named on a command line; throws
// UserError naming the option and its choices. Numbers are the caller's to set.
aco::Params solver_params(const std::string& algorithm, const std::string& local_search);

// Known optima: TSPLIB's proven optimal lengths by instance name.
std::map<std::string, double> known_optima();

BenchInstance load_instance(const std::string& path);

// One run of one cell with one seed.
BenchRun run_cell(const BenchInstance& instance, const BenchCell& cell, std::uint64_t seed);

// After all runs: time to 1 % of the best known (the optimum, or the best any run found).
void fill_time_to_target(std::vector<BenchRun>& runs);

std::string runs_csv(const std::vector<BenchRun>& runs);
std::string summary_csv(const std::vector<BenchRun>& runs);

// The thesis's tables 4.1-4.15 from runs of the thesis preset, with the
// published times (thesis-results.csv content) beside ours.
std::string thesis_tables(const std::vector<BenchRun>& runs, const std::string& published_csv);

// SVG charts into `dir`: speedup.svg, convergence.svg, gap_vs_time.svg (when
// the runs allow them). Returns the files written.
std::vector<std::string> write_plots(const std::vector<BenchRun>& runs, const std::string& dir);

}  // namespace app
