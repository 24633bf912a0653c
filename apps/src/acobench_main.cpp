// acobench: sweeps algorithms and their parameters over instances, writes one
// CSV row per run, a summary per cell, the thesis's tables and SVG charts.
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

#include "aco/error.h"
#include "app/bench.h"
#include "app/errors.h"
#include "app/files.h"

namespace {

std::string samples_dir(const char* argv0) {
  // build/bin/acobench → samples/ of the checkout, else ./samples.
  std::error_code ec;
  auto exe = std::filesystem::canonical("/proc/self/exe", ec);
  if (!ec) {
    auto candidate = exe.parent_path().parent_path().parent_path() / "samples";
    if (std::filesystem::exists(candidate / "plate70.dxf")) return candidate.string();
  }
  (void)argv0;
  return "samples";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"acobench runs a grid of solver settings over instances: every combination of the listed values, "
               "each with seeds 1..N, one CSV row per run.\n\n"
               "Examples:\n"
               "  acobench --instances pcb442.tsp,d198.tsp --algorithm acs,mmas,nn2opt --time-limit 0.5,1,2 "
               "--seeds 5 --out runs.csv --summary summary.csv --plots plots/\n"
               "  acobench --instances samples/plate70.dxf --algorithm as --alpha 1,2,2.5 --beta 4,4.5 --ants 125 "
               "--iterations 125 --local-search none --threads 1,2 --seeds 30 --out runs.csv\n"
               "  acobench --preset thesis --quick --out thesis.csv     the thesis's experiments 1-5, tables 4.1-4.15\n",
               "acobench"};
  cli.set_version_flag("--version", std::string("acobench ") + ACO_VERSION);
  std::vector<std::string> instances, algorithms{"focused"}, local_search{"3opt"};
  std::vector<double> alphas{1.0}, betas{-1.0}, rhos{-1.0}, time_limits{0.0};
  std::vector<int> ants{0}, iterations{0}, threads;
  int seeds = 1, first_seed = 1;
  std::string out, summary, plots, preset, tables;
  bool quick = false;
  double budget = 0;
  cli.add_option("--instances", instances, "Inputs acodrill reads (TSPLIB, DXF, Excellon, CSV, XML), comma-separated")->delimiter(',');
  cli.add_option("--algorithm", algorithms, "focused (default), acs, mmas, as, or baselines input, nn, greedy, raster, nn2opt")->delimiter(',');
  cli.add_option("--alpha", alphas, "Pheromone weights")->delimiter(',');
  cli.add_option("--beta", betas, "Heuristic weights (default per algorithm)")->delimiter(',');
  cli.add_option("--rho", rhos, "Evaporation rates (default per algorithm)")->delimiter(',');
  cli.add_option("--ants", ants, "Ant counts (default per algorithm)")->delimiter(',');
  cli.add_option("--iterations", iterations, "Iteration counts (default: 300 or until the time limit)")->delimiter(',');
  cli.add_option("--threads", threads, "Thread counts (default: 1 and all cores)")->delimiter(',');
  cli.add_option("--time-limit", time_limits, "Time limits per run in seconds (0 = none)")->delimiter(',');
  cli.add_option("--local-search", local_search, "none, 2opt, 2opt+oropt, 3opt (default: 2-opt, Or-opt and 3-opt with deeper Lin-Kernighan steps)")->delimiter(',');
  cli.add_option("--seeds", seeds, "Runs per cell, seeds 1..N (default 1)")->check(CLI::Range(1, 100000));
  cli.add_option("--first-seed", first_seed,
                 "Seeds K..K+N-1 instead of 1..N: one seed at a time, between other runs")
      ->check(CLI::Range(1, 100000));
  cli.add_option("--out", out, "runs.csv: one row per run (required for a grid; optional with --preset)");
  cli.add_option("--summary", summary, "summary.csv: one row per cell");
  cli.add_option("--plots", plots, "Directory for SVG charts (speedup, convergence, gap against time)");
  cli.add_option("--preset", preset, "thesis: experiments 1-5 of the thesis on the sample plates");
  cli.add_flag("--quick", quick, "With --preset thesis: 5 repetitions instead of 30");
  cli.add_option("--tables", tables, "With --preset thesis: write the tables here (default: stdout)");
  cli.add_option("--time-budget", budget, "Stop starting runs after this many seconds for the whole sweep");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (char& c : msg) if (c == '\n') c = ' ';
    std::cerr << "acobench: error: " << msg << " (see acobench --help)\n";
    return 2;
  }

  try {
    const int cores = std::max(1, omp_get_num_procs());
    if (threads.empty()) threads = cores > 1 ? std::vector<int>{1, cores} : std::vector<int>{1};
    struct Job {
      app::BenchCell cell;
      std::uint64_t seed;
      std::size_t instance;
    };
    std::vector<app::BenchInstance> loaded;
    std::vector<Job> jobs;
    if (!preset.empty()) {
      if (preset != "thesis") throw app::UserError("--preset must be thesis");
      // Experiments 1-5 (thesis tables 3.1-3.5): plate, ants = iterations.
      const std::vector<std::pair<std::string, int>> experiments = {
          {"plate10", 30}, {"plate27", 30}, {"plate45", 70}, {"plate65", 100}, {"plate70", 125}};
      const std::vector<std::pair<double, double>> sets = {{1, 4}, {2, 4.5}, {2.5, 4}};
      const int reps = quick ? 5 : 30;
      std::vector<int> all_threads;
      for (int t = 1; t <= cores; ++t) all_threads.push_back(t);
      const std::string dir = samples_dir(argv[0]);
      for (const auto& [plate, m] : experiments) {
        loaded.push_back(app::load_instance(dir + "/" + plate + ".dxf"));
        for (const auto& [a, b] : sets) {
          for (int t : all_threads) {
            for (int s = 1; s <= reps; ++s) {
              app::BenchCell c;
              c.instance = loaded.back().path;
              c.algorithm = "as";
              c.alpha = a;
              c.beta = b;
              c.ants = m;
              c.iterations = m;
              c.threads = t;
              c.local_search = "none";
              jobs.push_back({c, static_cast<std::uint64_t>(s), loaded.size() - 1});
            }
          }
        }
        // ... and beside it, in the same run, what acodrill does by default, and nearest neighbour.
        for (const char* alg : {"focused", "nn2opt", "nn"}) {
          for (int s = 1; s <= reps; ++s) {
            app::BenchCell c;
            c.instance = loaded.back().path;
            c.algorithm = alg;
            c.iterations = m;
            c.threads = cores;
            jobs.push_back({c, static_cast<std::uint64_t>(s), loaded.size() - 1});
          }
        }
      }
    } else {
      if (instances.empty()) throw app::UserError("--instances is required (or --preset thesis)");
      if (out.empty()) throw app::UserError("--out is required: the CSV file for one row per run");
      for (const std::string& path : instances) {
        loaded.push_back(app::load_instance(path));
        for (const std::string& alg : algorithms)
          for (const std::string& ls : local_search)
            for (double a : alphas)
              for (double b : betas)
                for (double r : rhos)
                  for (int m : ants)
                    for (int it : iterations)
                      for (double tl : time_limits)
                        // Seeds outside threads: runs of one seed on 1, 2, ... threads
                        // follow each other, so a speedup compares runs made under the
                        // same conditions on a machine whose speed drifts.
                        for (int s = first_seed; s < first_seed + seeds; ++s)
                          for (int t : threads) {
                            app::BenchCell c;
                            c.instance = path;
                            c.algorithm = alg;
                            c.local_search = ls;
                            c.alpha = a;
                            c.beta = b;
                            c.rho = r;
                            c.ants = m;
                            c.iterations = it;
                            c.time_limit_s = tl;
                            c.threads = t;
                            jobs.push_back({c, static_cast<std::uint64_t>(s), loaded.size() - 1});
                          }
      }
    }
    for (const Job& j : jobs) {
      static const std::set<std::string> known = {"as", "mmas", "acs", "focused", "input", "nn", "greedy", "raster", "nn2opt"};
      if (!known.count(j.cell.algorithm)) {
        throw app::UserError("--algorithm: \"" + j.cell.algorithm + "\" is none of as, mmas, acs, focused, input, nn, greedy, raster, nn2opt");
      }
      if (j.cell.alpha < 0 || (j.cell.rho != -1.0 && !(j.cell.rho > 0 && j.cell.rho <= 1)) || j.cell.threads < 1 ||
          j.cell.time_limit_s < 0 || j.cell.ants < 0 || j.cell.iterations < 0) {
        throw app::UserError("a grid value is out of range (alpha >= 0, 0 < rho <= 1, threads >= 1, ants/iterations >= 1)");
      }
    }

    const bool tty = ::isatty(STDERR_FILENO);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<app::BenchRun> runs;
    runs.reserve(jobs.size());
    std::size_t done = 0;
    bool budget_hit = false;
    for (const Job& j : jobs) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (budget > 0 && elapsed >= budget) {
        budget_hit = true;
        break;
      }
      runs.push_back(app::run_cell(loaded[j.instance], j.cell, j.seed));
      ++done;
      if (tty || done % std::max<std::size_t>(1, jobs.size() / 10) == 0 || done == jobs.size()) {
        std::fprintf(stderr, "%sacobench: %zu/%zu runs, %.1f s: %s %s threads %d seed %llu length %.1f%s", tty ? "\r" : "",
                     done, jobs.size(), elapsed, runs.back().name.c_str(), j.cell.algorithm.c_str(), j.cell.threads,
                     static_cast<unsigned long long>(j.seed), runs.back().length, tty ? "   " : "\n");
      }
    }
    if (tty) std::fprintf(stderr, "\n");
    if (budget_hit) std::fprintf(stderr, "acobench: time budget reached after %zu of %zu runs\n", done, jobs.size());
    app::fill_time_to_target(runs);
    if (!out.empty()) app::write_file_atomic(out, app::runs_csv(runs));
    if (!summary.empty()) app::write_file_atomic(summary, app::summary_csv(runs));
    if (!plots.empty()) {
      for (const std::string& f : app::write_plots(runs, plots)) std::fprintf(stderr, "acobench: chart %s\n", f.c_str());
    }
    if (preset == "thesis") {
      // The published tables travel with the program's source (bench/thesis-results.csv).
      std::string published;
      const std::string beside = samples_dir(argv[0]) + "/../bench/thesis-results.csv";
      if (std::filesystem::exists(beside)) published = app::read_file(beside);
      const std::string text = app::thesis_tables(runs, published);
      if (tables.empty()) std::cout << text;
      else app::write_file_atomic(tables, text);
    }
    return 0;
  } catch (const app::UserError& e) {
    std::cerr << "acobench: error: " << e.where_what() << "\n";
    return 2;
  } catch (const aco::Error& e) {
    std::cerr << "acobench: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "acobench: error: internal: " << e.what() << "\n";
    return 3;
  }
}
