#include "app/bench.h"

#include <algorithm>
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

namespace app {

namespace {

std::string fmt(double v, int decimals) { return gcode::format_number(v, decimals); }

// Shortest text that reads back to the same double: parameters in CSV keys.
std::string param(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

double mean(const std::vector<double>& v) { return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

double stddev(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

bool is_baseline(const std::string& a) {
  return a == "input" || a == "nn" || a == "greedy" || a == "raster" || a == "nn2opt";
}

// The cell without its thread count: runs that differ only in threads compare for speedup.
std::string key_without_threads(const BenchRun& r) {
  const BenchCell& c = r.cell;
  return c.instance + "|" + c.algorithm + "|" + param(r.alpha) + "|" + param(r.beta) + "|" + param(r.rho) + "|" +
         std::to_string(r.ants) + "|" + std::to_string(c.iterations) + "|" + param(c.time_limit_s) + "|" + c.local_search;
}

std::string key(const BenchRun& r) { return key_without_threads(r) + "|" + std::to_string(r.cell.threads); }

}  // namespace

aco::Params solver_params(const std::string& algorithm, const std::string& local_search) {
  aco::Params p;
  auto alg = aco::algorithm_from_string(algorithm);
  if (!alg) throw UserError("--algorithm must be one of focused, acs, mmas, as (got \"" + algorithm + "\")");
  auto ls = aco::local_search_from_string(local_search);
  if (!ls) throw UserError("--local-search must be one of none, 2opt, 2opt+oropt, 3opt (got \"" + local_search + "\")");
  p.algorithm = *alg;
  p.local_search = *ls;
  return p;
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
         "local_search,time_limit_s,iterations_done,time_to_1pct_s,busy_s\n";
  for (const BenchRun& r : runs) {
    const bool base = is_baseline(r.cell.algorithm);
    out << r.name << ',' << r.n << ',' << r.cell.algorithm << ',' << (base ? "" : param(r.alpha)) << ','
        << (base ? "" : param(r.beta)) << ',' << (base ? "" : param(r.rho)) << ',' << (base ? "" : std::to_string(r.ants))
        << ',' << (base ? "" : std::to_string(r.cell.iterations)) << ',' << r.cell.threads << ',' << r.seed << ','
        << fmt(r.length, 3) << ',' << (r.optimum ? fmt(100.0 * (r.length - *r.optimum) / *r.optimum, 4) : "") << ','
        << fmt(r.wall_s, 6) << ',' << (base ? "" : r.cell.local_search) << ',' << param(r.cell.time_limit_s) << ','
        << r.iterations_done << ',' << (r.time_to_1pct_s ? fmt(*r.time_to_1pct_s, 6) : "") << ',';
    for (std::size_t k = 0; k < r.busy_s.size(); ++k) out << (k ? ";" : "") << fmt(r.busy_s[k], 6);
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

namespace {

struct Series {
  std::string name;
  std::vector<std::pair<double, double>> points;
  bool dashed = false;
};

const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return o;
}

std::string chart(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                  const std::vector<Series>& series, bool log_x = false) {
  const double W = 760, H = 480, L = 70, R = 230, T = 40, B = 55;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Series& s : series) {
    for (auto [x, y] : s.points) {
      const double xv = log_x ? std::log10(std::max(x, 1e-9)) : x;
      x0 = std::min(x0, xv);
      x1 = std::max(x1, xv);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  if (x0 > x1) x0 = 0, x1 = 1;
  if (y0 > y1) y0 = 0, y1 = 1;
  if (x1 - x0 < 1e-12) x1 = x0 + 1;
  if (y1 - y0 < 1e-12) y1 = y0 + 1;
  const double ypad = (y1 - y0) * 0.05;
  y0 -= ypad;
  y1 += ypad;
  auto X = [&](double x) { return L + ((log_x ? std::log10(std::max(x, 1e-9)) : x) - x0) / (x1 - x0) * (W - L - R); };
  auto Y = [&](double y) { return T + (y1 - y) / (y1 - y0) * (H - T - B); };
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W
    << "\" height=\"" << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
    << "fill=\"#ffffff\"/>\n<text x=\"" << L << "\" y=\"24\" font-size=\"15\" font-weight=\"bold\">" << escape(title)
    << "</text>\n<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - R << "\" height=\"" << H - T - B
    << "\" fill=\"none\" stroke=\"#999\"/>\n";
  for (int i = 0; i <= 5; ++i) {
    const double yv = y0 + (y1 - y0) * i / 5;
    o << "<text x=\"" << L - 6 << "\" y=\"" << fmt(Y(yv) + 4, 1) << "\" text-anchor=\"end\">" << fmt(yv, std::fabs(y1 - y0) < 10 ? 2 : 0)
      << "</text><line x1=\"" << L << "\" x2=\"" << W - R << "\" y1=\"" << fmt(Y(yv), 1) << "\" y2=\"" << fmt(Y(yv), 1)
      << "\" stroke=\"#eee\"/>\n";
    const double xv = x0 + (x1 - x0) * i / 5;
    const double shown = log_x ? std::pow(10.0, xv) : xv;
    o << "<text x=\"" << fmt(L + (xv - x0) / (x1 - x0) * (W - L - R), 1) << "\" y=\"" << H - B + 18
      << "\" text-anchor=\"middle\">" << fmt(shown, std::fabs(shown) < 10 ? 2 : 0) << "</text>\n";
  }
  o << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">" << escape(xlabel)
    << "</text>\n<text transform=\"translate(16," << (T + H - B) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << escape(ylabel) << "</text>\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    const char* c = s.dashed ? "#888888" : kColours[i % 8];
    o << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6 4\"" : "")
      << " points=\"";
    for (auto [x, y] : s.points) o << fmt(X(x), 1) << "," << fmt(Y(y), 1) << " ";
    o << "\"/>\n";
    for (auto [x, y] : s.points) {
      if (s.points.size() < 30) o << "<circle cx=\"" << fmt(X(x), 1) << "\" cy=\"" << fmt(Y(y), 1) << "\" r=\"3\" fill=\"" << c << "\"/>\n";
    }
    o << "<rect x=\"" << W - R + 12 << "\" y=\"" << T + 18 * i << "\" width=\"12\" height=\"12\" fill=\"" << c
      << "\"/><text x=\"" << W - R + 30 << "\" y=\"" << T + 18 * i + 10 << "\">" << escape(s.name) << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace

std::vector<std::string> write_plots(const std::vector<BenchRun>& runs, const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  // Speedup against threads, one line per cell, with the ideal line.
  {
    std::map<std::string, std::map<int, std::vector<double>>> walls;
    std::map<std::string, std::string> names;
    for (const BenchRun& r : runs) {
      if (is_baseline(r.cell.algorithm)) continue;
      walls[key_without_threads(r)][r.cell.threads].push_back(r.wall_s);
      names[key_without_threads(r)] = r.name + " " + r.cell.algorithm + " a" + param(r.alpha) + " b" + param(r.beta);
    }
    std::vector<Series> series;
    int max_threads = 1;
    for (const auto& [k, by_threads] : walls) {
      if (by_threads.size() < 2 || !by_threads.count(1)) continue;
      const double t1 = median(by_threads.at(1));
      Series s{names[k], {}};
      for (const auto& [t, w] : by_threads) {
        s.points.push_back({static_cast<double>(t), t1 / median(w)});
        max_threads = std::max(max_threads, t);
      }
      series.push_back(s);
    }
    if (!series.empty()) {
      series.push_back({"ideal", {{1, 1}, {static_cast<double>(max_threads), static_cast<double>(max_threads)}}, true});
      write_file_atomic(dir + "/speedup.svg", chart("Speedup against threads (median wall time)", "threads", "speedup", series));
      written.push_back(dir + "/speedup.svg");
    }
  }
  // Convergence: best length against time, per algorithm, on the largest instance, seed 1.
  {
    const BenchRun* largest = nullptr;
    for (const BenchRun& r : runs) {
      if (!largest || r.n > largest->n) largest = &r;
    }
    std::vector<Series> series;
    std::map<std::string, bool> seen;
    for (const BenchRun& r : runs) {
      if (!largest || r.cell.instance != largest->cell.instance || is_baseline(r.cell.algorithm) || r.trace.empty()) continue;
      const std::string name = r.cell.algorithm + " (" + r.cell.local_search + ")";
      if (seen[name]) continue;
      seen[name] = true;
      Series s{name, {}};
      for (std::size_t i = 0; i < r.trace.size(); ++i) {
        if (i > 0) s.points.push_back({r.trace[i].wall_s, r.trace[i - 1].best_length});  // a step
        s.points.push_back({r.trace[i].wall_s, r.trace[i].best_length});
      }
      s.points.push_back({r.wall_s, r.trace.back().best_length});
      series.push_back(s);
    }
    if (!series.empty()) {
      write_file_atomic(dir + "/convergence.svg",
                        chart("Convergence on " + largest->name + " (best length by wall time)", "seconds", "best length", series));
      written.push_back(dir + "/convergence.svg");
    }
  }
  // Gap against the time budget, per algorithm, on instances with a known optimum.
  {
    std::map<std::string, std::map<double, std::vector<double>>> gaps;
    for (const BenchRun& r : runs) {
      if (!r.optimum || r.cell.time_limit_s <= 0) continue;
      gaps[r.name + " " + r.cell.algorithm][r.cell.time_limit_s].push_back(100.0 * (r.length - *r.optimum) / *r.optimum);
    }
    std::vector<Series> series;
    for (const auto& [name, by_budget] : gaps) {
      if (by_budget.size() < 2) continue;
      Series s{name, {}};
      for (const auto& [budget, g] : by_budget) s.points.push_back({budget, median(g)});
      series.push_back(s);
    }
    if (!series.empty()) {
      write_file_atomic(dir + "/gap_vs_time.svg",
                        chart("Gap to the optimum against the time budget (median)", "time budget, s (log)", "gap %", series, true));
      written.push_back(dir + "/gap_vs_time.svg");
    }
  }
  return written;
}

}  // namespace app
