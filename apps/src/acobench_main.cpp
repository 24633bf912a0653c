// acobench: sweeps algorithms and their parameters over instances, writes one
// CSV row per run, a summary per cell, the thesis's tables and SVG charts.
#include <omp.h>
#include <unistd.h>  // isatty; MinGW has it too
#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#endif
#ifndef _WIN32
#include <sys/wait.h>
#endif

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdlib>
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

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=/.,:@%") == std::string::npos) {
    return s;
  }
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The sweep's own options from the command line: without the subcommand, the
// options of `slurm` and where the merge writes (those go to the merge job).
std::vector<std::string> sweep_arguments(int argc, char** argv) {
  static const std::set<std::string> with_value = {"--shards", "--partition", "--time", "--cpus-per-task", "--out",
                                                   "--summary", "--plots", "--shard"};
  static const std::set<std::string> flags = {"--submit"};
  std::vector<std::string> kept;
  bool subcommand_seen = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const std::string name = a.substr(0, a.find('='));
    if (a == "slurm" && !subcommand_seen) {
      subcommand_seen = true;
      continue;
    }
    if (with_value.count(name)) {
      if (a.find('=') == std::string::npos) ++i;
      continue;
    }
    if (flags.count(a)) continue;
    kept.push_back(a);
  }
  return kept;
}

// Runs a command; its standard output (its errors go to ours as they come),
// or a UserError when it fails.
std::string run_command(const std::string& command) {
#ifdef _WIN32
  throw app::UserError("cannot run " + command + ": Slurm's sbatch is not on Windows; write the scripts here and submit them on the cluster");
#else
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) throw app::UserError("cannot run " + command);
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = ::pclose(p);
  if (status != 0) {
    throw app::UserError(command + " failed (exit " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                         "; its message is above)");
  }
  return out;
#endif
}

}  // namespace

int main(int argc, char** argv) {
#ifdef _WIN32
  ::_setmode(::_fileno(stdout), _O_BINARY);  // output as in a file: LF, not CRLF
#endif
  // Every name as UTF-8, on Windows too (issue 68): the arguments as the system holds them.
  app::Utf8Argv utf8(argc, argv);
  argc = utf8.argc();
  argv = utf8.argv();
  CLI::App cli{"acobench runs a grid of solver settings over instances: every combination of the listed values, "
               "each with seeds 1..N, one CSV row per run.\n\n"
               "Examples:\n"
               "  acobench --instances pcb442.tsp,d198.tsp --algorithm acs,mmas,nn2opt --time-limit 0.5,1,2 "
               "--seeds 5 --out runs.csv --summary summary.csv --plots plots/\n"
               "  acobench --instances samples/plate70.dxf --algorithm as --alpha 1,2,2.5 --beta 4,4.5 --ants 125 "
               "--iterations 125 --local-search none --threads 1,2 --seeds 30 --out runs.csv\n"
               "  acobench --preset thesis --quick --out thesis.csv     the thesis's experiments 1-5, tables 4.1-4.15\n\n"
               "On a cluster: the same sweep in N independent shards, joined again with exactly the rows of one process:\n"
               "  acobench SWEEP-OPTIONS --shard 0/4 --out part-0.csv    ... up to --shard 3/4, anywhere, in any order\n"
               "  acobench merge part-0.csv part-1.csv part-2.csv part-3.csv --out all.csv --summary summary.csv\n"
               "  acobench slurm SWEEP-OPTIONS --shards 4 --out all.csv --partition P --time 1:00:00 --submit\n"
               "                         a Slurm job array (one task a shard) and a merge job that waits for it\n",
               "acobench"};
  cli.set_version_flag("--version", std::string("acobench ") + ACO_VERSION);
  std::vector<std::string> instances, algorithms{"focused"}, local_search{"auto"};
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
  cli.add_option("--local-search", local_search, "none, 2opt, 2opt+oropt, 3opt, 5opt, auto (default auto: 5opt from 3000 to 200000 holes, else 3opt; 3opt: 2-opt, Or-opt and 3-opt with deeper Lin-Kernighan steps; 5opt: LKH's sequential 5-opt step, on penalised costs up to 20000 holes and plain lengths above, in place of the 3-opt one)")->delimiter(',');
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
  std::string shard_text;
  cli.add_option("--shard", shard_text,
                 "K/N: run only the K-th (0-based) of N slices of the sweep's runs (run i of the sweep is in shard i mod N); "
                 "join the shards' CSVs with acobench merge");
  // acobench merge PARTS... --out all.csv [--summary S] [--plots DIR]
  std::vector<std::string> merge_parts;
  CLI::App* merge_cmd = cli.add_subcommand("merge", "Join the shards of one sweep (--out, --summary, --plots as for a sweep); "
                                                    "refuses a missing, repeated or foreign shard");
  merge_cmd->add_option("parts", merge_parts, "The shards' runs CSVs")->required();
  merge_cmd->fallthrough();
  // acobench slurm SWEEP-OPTIONS --shards N --out all.csv [...]
  std::size_t shards = 0;
  int cpus_per_task = 0;
  std::string partition, slurm_time;
  bool submit = false;
  CLI::App* slurm_cmd = cli.add_subcommand(
      "slurm", "Write (and with --submit submit) a Slurm job array running the sweep in --shards tasks, each "
               "acobench ... --shard $SLURM_ARRAY_TASK_ID/N, and a merge job that runs after it; --out, --summary and "
               "--plots are the merge's");
  slurm_cmd->add_option("--shards", shards, "Tasks of the job array (N)")->required()->check(CLI::Range(1, 100000));
  slurm_cmd->add_option("--partition", partition, "Slurm partition (sbatch --partition); default: the cluster's");
  slurm_cmd->add_option("--time", slurm_time, "Time limit of each task (sbatch --time, e.g. 2:00:00)");
  slurm_cmd->add_option("--cpus-per-task", cpus_per_task,
                        "CPUs of each task (default: the sweep's largest thread count, which without --threads is "
                        "this machine's cores); inside a task the sweep's default threads follow SLURM_CPUS_PER_TASK")
      ->check(CLI::Range(1, 4096));
  slurm_cmd->add_flag("--submit", submit, "Submit both jobs with sbatch (else print how)");
  slurm_cmd->fallthrough();
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
    if (*merge_cmd) {
      if (out.empty()) throw app::UserError("merge: --out is required: the CSV of the whole sweep");
      std::vector<app::BenchRun> runs = app::merge_shards(merge_parts);
      app::write_file_atomic(out, app::runs_csv(runs));
      if (!summary.empty()) app::write_file_atomic(summary, app::summary_csv(runs));
      if (!plots.empty()) {
        for (const std::string& f : app::write_plots(runs, plots)) std::fprintf(stderr, "acobench: chart %s\n", f.c_str());
      }
      std::fprintf(stderr, "acobench: merged %zu shards, %zu runs of sweep %s into %s\n", merge_parts.size(), runs.size(),
                   runs.empty() ? "" : runs.front().sweep_id.c_str(), out.c_str());
      return 0;
    }
    // In a Slurm task "all cores" are the task's, not the node's.
    int cores = std::max(1, omp_get_num_procs());
    if (const char* slurm_cpus = std::getenv("SLURM_CPUS_PER_TASK")) {
      const int c = std::atoi(slurm_cpus);
      if (c >= 1) cores = c;
    }
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

    std::vector<app::SweepRun> sweep;
    for (const Job& j : jobs) sweep.push_back({j.cell, j.seed});
    const std::string sweep_id = app::sweep_fingerprint(sweep, ACO_VERSION);

    if (*slurm_cmd) {
      if (out.empty()) throw app::UserError("slurm: --out is required: where the merge job writes the whole sweep");
      if (shards > jobs.size()) {
        throw app::UserError("slurm: --shards " + std::to_string(shards) + " is more than the sweep's " +
                             std::to_string(jobs.size()) + " runs");
      }
      int cpus = cpus_per_task;
      if (cpus == 0) cpus = threads.empty() ? 1 : *std::max_element(threads.begin(), threads.end());
      std::error_code ec;
      const std::string self = std::filesystem::canonical("/proc/self/exe", ec).string();
      const std::string here = std::filesystem::current_path().string();
      const std::string stem = std::filesystem::path(out).stem().string();
      const std::string parts_dir = out + ".parts";
      const std::string array_script = "acobench-" + stem + ".sbatch", merge_script = "acobench-" + stem + "-merge.sbatch";
      std::string args;
      for (const std::string& a : sweep_arguments(argc, argv)) args += " " + shell_quote(a);
      const std::string n = std::to_string(shards);
      std::string common = "#SBATCH --cpus-per-task=" + std::to_string(cpus) + "\n";
      if (!partition.empty()) common += "#SBATCH --partition=" + partition + "\n";
      if (!slurm_time.empty()) common += "#SBATCH --time=" + slurm_time + "\n";
      const std::string preamble =
          "# Written by acobench " ACO_VERSION " (acobench slurm): sweep " + sweep_id + ", " + std::to_string(jobs.size()) +
          " runs in " + n + " shards.\n# On a cluster, load what acobench needs here (e.g. `module load gcc`) and keep\n"
          "# the instances and this folder on a file system the nodes share.\nset -euo pipefail\ncd " + shell_quote(here) + "\n";
      const std::string array_text =
          "#!/bin/bash\n#SBATCH --job-name=acobench-" + stem + "\n#SBATCH --array=0-" + std::to_string(shards - 1) + "\n" + common +
          "#SBATCH --output=" + parts_dir + "/slurm-%A_%a.log\n" + preamble + "mkdir -p " + shell_quote(parts_dir) + "\n" +
          "exec " + shell_quote(self) + args + " --shard \"${SLURM_ARRAY_TASK_ID}/" + n + "\" --out " + shell_quote(parts_dir) +
          "/part-\"${SLURM_ARRAY_TASK_ID}\".csv\n";
      std::string merge_args = " --out " + shell_quote(out);
      if (!summary.empty()) merge_args += " --summary " + shell_quote(summary);
      if (!plots.empty()) merge_args += " --plots " + shell_quote(plots);
      std::string part_list;
      for (std::size_t k = 0; k < shards; ++k) part_list += " " + shell_quote(parts_dir) + "/part-" + std::to_string(k) + ".csv";
      std::string merge_common = "#SBATCH --cpus-per-task=1\n";
      if (!partition.empty()) merge_common += "#SBATCH --partition=" + partition + "\n";
      const std::string merge_text = "#!/bin/bash\n#SBATCH --job-name=acobench-" + stem + "-merge\n" + merge_common +
                                     "#SBATCH --output=" + parts_dir + "/slurm-merge-%j.log\n" + preamble + "exec " +
                                     shell_quote(self) + " merge" + part_list + merge_args + "\n";
      std::filesystem::create_directories(parts_dir);
      app::write_file_atomic(array_script, array_text);
      app::write_file_atomic(merge_script, merge_text);
      std::fprintf(stderr, "acobench: %zu runs of sweep %s in %zu shards: %s (job array), %s (merge, after it)\n", jobs.size(),
                   sweep_id.c_str(), shards, array_script.c_str(), merge_script.c_str());
      if (!submit) {
        std::printf("jid=$(sbatch --parsable %s) && sbatch --dependency=afterok:${jid%%%%;*} %s\n", array_script.c_str(),
                    merge_script.c_str());
        return 0;
      }
      std::string array_id = run_command("sbatch --parsable " + shell_quote(array_script));
      array_id = array_id.substr(0, array_id.find_first_of(";\r\n"));
      std::string merge_id = run_command("sbatch --parsable --dependency=afterok:" + array_id + " " + shell_quote(merge_script));
      merge_id = merge_id.substr(0, merge_id.find_first_of(";\r\n"));
      std::printf("array %s\nmerge %s\n", array_id.c_str(), merge_id.c_str());
      std::fprintf(stderr, "acobench: submitted job array %s and merge job %s; squeue shows them, %s will hold the sweep\n",
                   array_id.c_str(), merge_id.c_str(), out.c_str());
      return 0;
    }

    const app::Shard shard = shard_text.empty() ? app::Shard{} : app::parse_shard(shard_text);
    std::vector<std::size_t> sweep_index;
    {
      std::vector<Job> mine;
      for (std::size_t i = 0; i < jobs.size(); ++i) {
        if (!shard.holds(i)) continue;
        mine.push_back(jobs[i]);
        sweep_index.push_back(i);
      }
      if (!shard.whole()) {
        std::fprintf(stderr, "acobench: shard %s: %zu of the sweep's %zu runs (sweep %s)\n", shard.text().c_str(), mine.size(),
                     jobs.size(), sweep_id.c_str());
      }
      jobs.swap(mine);
    }

    // A sweep takes hours: an output that can never be written is said now.
    app::check_output_path(out);
    app::check_output_path(summary);
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
    sweep_index.resize(runs.size());
    app::stamp_sweep(runs, sweep_index, sweep_id, sweep.size(), shard, ACO_VERSION);
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
