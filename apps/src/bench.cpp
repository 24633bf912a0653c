#include "app/bench.h"
#include "bench_util.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <sstream>

#include "aco/baselines.h"
#include "aco/solve.h"
#include "app/errors.h"
#include "app/files.h"
#include "app/inputs.h"
#include "gcode/program.h"
#include "job/settings.h"

namespace app {


using namespace bench_util;

aco::Params solver_params(const std::string& algorithm, const std::string& local_search) {
  job::SolverSettings s;
  s.algorithm = algorithm;
  s.local_search = local_search;
  return job::solver_params(s);
}

std::map<std::string, double> known_optima() {
  // TSPLIB proven optima (Reinelt's TSPLIB95 "Optimal solutions for symmetric TSPs").
  return {{"d198", 15780},     {"pcb442", 50778},  {"d493", 35002},  {"u574", 36905},   {"d657", 48912},
          {"u724", 41910},     {"pcb1173", 56892}, {"d1291", 50801}, {"fl1400", 20127}, {"d1655", 62128},
          {"pcb3038", 137694}, {"fnl4461", 182566}, {"d15112", 1573084}, {"rat783", 8806}, {"pr1002", 259045},
          {"a280", 2579},      {"lin318", 42029},  {"att532", 27686}, {"rat575", 6773},  {"u1060", 224094},
          {"pla7397", 23260728}, {"brd14051", 469385}};
}

BenchInstance load_instance(const std::string& path) {
  InputOptions options;
  LoadedHoles loaded = load_holes(path, options);
  BenchInstance inst;
  inst.path = path;
  inst.name = loaded.name;
  inst.tsplib = loaded.format == InputFormat::Tsplib;
  inst.tsplib_metric = formats::tsplib_metric(loaded);
  for (const aco::Hole& h : loaded.holes) inst.points.push_back(h.center);
  if (inst.points.empty()) throw UserError(path, 0, "no holes");
  auto optima = known_optima();
  if (inst.tsplib) {
    auto it = optima.find(inst.name);
    if (it != optima.end() && static_cast<std::size_t>(inst.points.size()) > 0) inst.optimum = it->second;
  }
  return inst;
}

BenchRun run_cell(const BenchInstance& inst, const BenchCell& cell, std::uint64_t seed) {
  aco::Problem p;
  p.points = inst.points;
  // The thesis and TSPLIB solve closed tours; TSPLIB lengths use rounded distances.
  p.metric = inst.tsplib ? inst.tsplib_metric : aco::Metric::Euclidean;
  p.shape = aco::Shape::ClosedTour;
  BenchRun run;
  run.cell = cell;
  run.name = inst.name;
  run.n = inst.points.size();
  run.seed = seed;
  run.optimum = inst.optimum;
  if (is_baseline(cell.algorithm)) {
    const auto t0 = std::chrono::steady_clock::now();
    aco::Order order;
    if (cell.algorithm == "input") order = aco::input_order(p);
    else if (cell.algorithm == "nn") order = aco::nearest_neighbor(p);
    else if (cell.algorithm == "greedy") order = aco::greedy_edge(p);
    else if (cell.algorithm == "raster") order = aco::raster(p);
    else order = aco::nearest_neighbor_2opt(p);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.length = aco::route_length(p, order);
    run.tour_hash = tour_hash(order);
    run.trace.push_back({0, run.wall_s, run.length});
    return run;
  }
  aco::Params params = solver_params(cell.algorithm, cell.local_search);
  params.alpha = cell.alpha;
  params.beta = cell.beta;
  params.rho = cell.rho;
  params.ants = cell.ants;
  params.iterations = cell.iterations;
  params.threads = cell.threads;
  params.time_limit_s = cell.time_limit_s;
  params.seed = seed;
  const aco::Params used = aco::resolve(params, p.points.size());
  aco::Solution s = aco::solve(p, params);
  run.length = s.length;
  run.tour_hash = tour_hash(s.order);
  run.wall_s = s.wall_s;
  run.iterations_done = s.iterations;
  run.busy_s = s.thread_busy_s;
  run.trace = s.trace;
  run.alpha = used.alpha;
  run.beta = used.beta;
  run.rho = used.rho;
  run.ants = used.ants;
  return run;
}

void fill_time_to_target(std::vector<BenchRun>& runs) {
  std::map<std::string, double> best;
  for (const BenchRun& r : runs) {
    const double b = r.optimum.value_or(r.length);
    auto it = best.find(r.cell.instance);
    if (it == best.end() || b < it->second) best[r.cell.instance] = b;
  }
  for (BenchRun& r : runs) {
    const double target = 1.01 * best[r.cell.instance];
    r.time_to_1pct_s.reset();
    for (const aco::TracePoint& t : r.trace) {
      if (t.best_length <= target + 1e-9) {
        r.time_to_1pct_s = t.wall_s;
        break;
      }
    }
  }
}

std::string runs_csv(const std::vector<BenchRun>& runs) {
  std::ostringstream out;
  out << "instance,n,algorithm,alpha,beta,rho,ants,iterations,threads,seed,length,gap_pct,wall_s,"
         "local_search,time_limit_s,iterations_done,time_to_1pct_s,busy_s,"
         "tour_hash,trace,instance_path,sweep_index,sweep_runs,sweep,shard,version\n";
  for (const BenchRun& r : runs) {
    const bool base = is_baseline(r.cell.algorithm);
    out << r.name << ',' << r.n << ',' << r.cell.algorithm << ',' << (base ? "" : param(r.alpha)) << ','
        << (base ? "" : param(r.beta)) << ',' << (base ? "" : param(r.rho)) << ',' << (base ? "" : std::to_string(r.ants))
        << ',' << (base ? "" : std::to_string(r.cell.iterations)) << ',' << r.cell.threads << ',' << r.seed << ','
        << fmt(r.length, 3) << ',' << (r.optimum ? fmt(100.0 * (r.length - *r.optimum) / *r.optimum, 4) : "") << ','
        << fmt(r.wall_s, 6) << ',' << (base ? "" : r.cell.local_search) << ',' << param(r.cell.time_limit_s) << ','
        << r.iterations_done << ',' << (r.time_to_1pct_s ? fmt(*r.time_to_1pct_s, 6) : "") << ',';
    for (std::size_t k = 0; k < r.busy_s.size(); ++k) out << (k ? ";" : "") << fmt(r.busy_s[k], 6);
    // What a merge of shards needs to give the one-process sweep's rows, summary and charts.
    out << ',' << hex(r.tour_hash) << ',';
    for (std::size_t k = 0; k < r.trace.size(); ++k) {
      out << (k ? ";" : "") << r.trace[k].iteration << ':' << fmt(r.trace[k].wall_s, 6) << ':' << exact(r.trace[k].best_length);
    }
    out << ',' << csv_field(r.cell.instance) << ',' << r.sweep_index << ',' << r.sweep_runs << ',' << r.sweep_id << ','
        << r.shard << ',' << r.version;
    out << '\n';
  }
  return out.str();
}

std::string summary_csv(const std::vector<BenchRun>& runs) {
  std::map<std::string, std::vector<const BenchRun*>> cells;
  std::vector<std::string> order;
  for (const BenchRun& r : runs) {
    auto [it, inserted] = cells.try_emplace(key(r));
    if (inserted) order.push_back(key(r));
    it->second.push_back(&r);
  }
  std::map<std::string, double> one_thread_wall;  // median wall of the 1-thread cell
  for (const auto& [k, rs] : cells) {
    if (rs.front()->cell.threads != 1) continue;
    std::vector<double> w;
    for (const BenchRun* r : rs) w.push_back(r->wall_s);
    one_thread_wall[key_without_threads(*rs.front())] = median(w);
  }
  std::ostringstream out;
  out << "instance,n,algorithm,alpha,beta,rho,ants,iterations,threads,local_search,time_limit_s,runs,"
         "length_median,length_mean,length_sd,length_min,gap_median_pct,gap_min_pct,"
         "wall_median_s,wall_mean_s,wall_sd_s,wall_min_s,speedup,efficiency\n";
  for (const std::string& k : order) {
    const auto& rs = cells[k];
    const BenchRun& r = *rs.front();
    std::vector<double> len, wall;
    for (const BenchRun* x : rs) {
      len.push_back(x->length);
      wall.push_back(x->wall_s);
    }
    const bool base = is_baseline(r.cell.algorithm);
    out << r.name << ',' << r.n << ',' << r.cell.algorithm << ',' << (base ? "" : param(r.alpha)) << ','
        << (base ? "" : param(r.beta)) << ',' << (base ? "" : param(r.rho)) << ',' << (base ? "" : std::to_string(r.ants))
        << ',' << (base ? "" : std::to_string(r.cell.iterations)) << ',' << r.cell.threads << ','
        << (base ? "" : r.cell.local_search) << ',' << param(r.cell.time_limit_s) << ',' << rs.size() << ','
        << fmt(median(len), 3) << ',' << fmt(mean(len), 3) << ',' << fmt(stddev(len), 3) << ','
        << fmt(*std::min_element(len.begin(), len.end()), 3) << ',';
    if (r.optimum) {
      out << fmt(100.0 * (median(len) - *r.optimum) / *r.optimum, 4) << ','
          << fmt(100.0 * (*std::min_element(len.begin(), len.end()) - *r.optimum) / *r.optimum, 4);
    } else {
      out << ',';
    }
    out << ',' << fmt(median(wall), 6) << ',' << fmt(mean(wall), 6) << ',' << fmt(stddev(wall), 6) << ','
        << fmt(*std::min_element(wall.begin(), wall.end()), 6) << ',';
    auto one = one_thread_wall.find(key_without_threads(r));
    if (one != one_thread_wall.end() && median(wall) > 0) {
      const double speedup = one->second / median(wall);
      out << fmt(speedup, 4) << ',' << fmt(speedup / r.cell.threads, 4);
    } else {
      out << ',';
    }
    out << '\n';
  }
  return out.str();
}

std::string thesis_tables(const std::vector<BenchRun>& runs, const std::string& published_csv) {
  // published: experiment,set,holes,ants,iterations,alpha,beta,processors,time_ms,speedup,efficiency
  struct Published {
    double time_ms, speedup, efficiency;
  };
  std::map<std::tuple<int, char, int>, Published> pub;
  std::istringstream in(published_csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
    if (f.size() < 9) continue;
    pub[{std::stoi(f[0]), f[1][0], std::stoi(f[7])}] = {std::stod(f[8]), f.size() > 9 && !f[9].empty() ? std::stod(f[9]) : 1.0,
                                                        f.size() > 10 && !f[10].empty() ? std::stod(f[10]) : 1.0};
  }
  const std::map<std::size_t, int> experiment_of = {{10, 1}, {27, 2}, {45, 3}, {65, 4}, {70, 5}};
  auto set_of = [](double a, double b) -> char {
    if (a == 1 && b == 4) return 'A';
    if (a == 2 && b == 4.5) return 'B';
    if (a == 2.5 && b == 4) return 'C';
    return '?';
  };
  // Median wall time per (experiment, set, threads).
  std::map<std::tuple<int, char, int>, std::vector<double>> ours;
  std::map<std::pair<int, char>, std::pair<int, int>> ants_iters;
  for (const BenchRun& r : runs) {
    auto e = experiment_of.find(r.n);
    const char set = set_of(r.alpha, r.beta);
    if (e == experiment_of.end() || set == '?' || r.cell.algorithm != "as") continue;
    ours[{e->second, set, r.cell.threads}].push_back(r.wall_s * 1000.0);
    ants_iters[{e->second, set}] = {r.ants, r.cell.iterations};
  }
  std::ostringstream out;
  for (int exp = 1; exp <= 5; ++exp) {
    for (char set : {'A', 'B', 'C'}) {
      auto ai = ants_iters.find({exp, set});
      if (ai == ants_iters.end()) continue;
      const int table = 3 * (exp - 1) + (set - 'A') + 1;
      const double alpha = set == 'A' ? 1 : set == 'B' ? 2 : 2.5, beta = set == 'B' ? 4.5 : 4;
      out << "Table 4." << table << ": experiment " << exp << ", set " << set << " (alpha " << param(alpha) << ", beta "
          << param(beta) << "), " << ai->second.first << " ants, " << ai->second.second << " iterations\n\n"
          << "| processors | time ms | speedup | efficiency | thesis time ms | thesis speedup | thesis efficiency |\n"
          << "|---:|---:|---:|---:|---:|---:|---:|\n";
      auto base = ours.find({exp, set, 1});
      const double t1 = base == ours.end() ? 0 : median(base->second);
      for (int p = 1; p <= 6; ++p) {
        auto o = ours.find({exp, set, p});
        auto th = pub.find({exp, set, p});
        if (o == ours.end() && th == pub.end()) continue;
        out << "| " << p << " | ";
        if (o != ours.end()) {
          const double t = median(o->second);
          out << fmt(t, 2) << " | " << (t1 > 0 ? fmt(t1 / t, 2) : "") << " | " << (t1 > 0 ? fmt(t1 / t / p, 2) : "") << " | ";
        } else {
          out << "- | - | - | ";
        }
        if (th != pub.end()) {
          out << static_cast<long long>(std::llround(th->second.time_ms)) << " | " << fmt(th->second.speedup, 2) << " | " << fmt(th->second.efficiency, 2) << " |\n";
        } else {
          out << "- | - | - |\n";
        }
      }
      out << "\n";
    }
  }
  // Beside the thesis's algorithm, in the same run: what acodrill does by default.
  std::map<std::pair<int, std::string>, std::vector<double>> lengths;
  for (const BenchRun& r : runs) {
    auto e = experiment_of.find(r.n);
    if (e == experiment_of.end()) continue;
    std::string column = r.cell.algorithm;
    if (column == "as") column = std::string("as ") + set_of(r.alpha, r.beta);
    lengths[{e->second, column}].push_back(r.length);
  }
  if (!lengths.empty()) {
    const std::vector<std::string> columns = {"as A", "as B", "as C", "focused", "nn2opt", "nn"};
    out << "Closed-tour length in mm (median over runs): the thesis's Ant System (sets A, B, C), acodrill's\n"
        << "default (ACS with 2-opt and Or-opt, same iterations), nearest neighbour with 2-opt, nearest neighbour\n\n"
        << "| experiment | holes |";
    for (const auto& c : columns) out << " " << c << " |";
    out << " focused vs best as |\n|---:|---:|";
    for (std::size_t i = 0; i <= columns.size(); ++i) out << "---:|";
    out << "\n";
    for (int exp = 1; exp <= 5; ++exp) {
      std::size_t holes = 0;
      for (const auto& [n, e] : experiment_of) if (e == exp) holes = n;
      bool any = false;
      std::string row = "| " + std::to_string(exp) + " | " + std::to_string(holes) + " |";
      double best_as = 1e300, default_colony = 0;
      for (const auto& c : columns) {
        auto it = lengths.find({exp, c});
        if (it == lengths.end()) {
          row += " - |";
          continue;
        }
        any = true;
        const double m = median(it->second);
        if (c.rfind("as ", 0) == 0) best_as = std::min(best_as, m);
        if (c == "focused") default_colony = m;
        row += " " + fmt(m, 1) + " |";
      }
      if (!any) continue;
      row += (default_colony > 0 && best_as < 1e300) ? " " + fmt(100.0 * (default_colony - best_as) / best_as, 2) + " % |" : " - |";
      out << row << "\n";
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace app
