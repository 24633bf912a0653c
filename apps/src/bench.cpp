#include "app/bench.h"

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

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= kFnvPrime;
  }
  return h;
}

std::uint64_t fnv1a(std::uint64_t h, const std::string& text) { return fnv1a(h, text.data(), text.size() + 1); }

std::uint64_t tour_hash(const aco::Order& order) {
  std::uint64_t h = kFnvOffset;
  for (aco::HoleIndex i : order) {
    const std::uint32_t v = static_cast<std::uint32_t>(i);
    h = fnv1a(h, &v, sizeof v);
  }
  return h;
}

std::string hex(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// The shortest text that reads back to the same double (a trace's lengths).
std::string exact(double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& v) {
  if (v.find_first_of(",\"\n\r") == std::string::npos) return v;
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

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

std::string Shard::text() const { return std::to_string(k) + "/" + std::to_string(n); }

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  auto number = [&](const std::string& part, std::size_t& v) {
    auto r = std::from_chars(part.data(), part.data() + part.size(), v);
    return !part.empty() && r.ec == std::errc() && r.ptr == part.data() + part.size();
  };
  Shard sh;
  if (slash == std::string::npos || !number(text.substr(0, slash), sh.k) || !number(text.substr(slash + 1), sh.n) ||
      sh.n < 1 || sh.k >= sh.n || sh.n > 1000000) {
    throw UserError("--shard must be K/N with 0 <= K < N, the K-th (0-based) of N slices (got \"" + text + "\")");
  }
  return sh;
}

std::string sweep_fingerprint(const std::vector<SweepRun>& sweep, const std::string& version) {
  std::uint64_t h = fnv1a(kFnvOffset, "acobench " + version);
  for (const SweepRun& r : sweep) {
    const BenchCell& c = r.cell;
    h = fnv1a(h, c.instance + "|" + c.algorithm + "|" + c.local_search + "|" + exact(c.alpha) + "|" + exact(c.beta) + "|" +
                     exact(c.rho) + "|" + std::to_string(c.ants) + "|" + std::to_string(c.iterations) + "|" +
                     std::to_string(c.threads) + "|" + exact(c.time_limit_s) + "|" + std::to_string(r.seed));
  }
  return hex(h);
}

void stamp_sweep(std::vector<BenchRun>& runs, const std::vector<std::size_t>& sweep_index, const std::string& sweep_id,
                 std::size_t sweep_runs, const Shard& shard, const std::string& version) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].sweep_index = sweep_index[i];
    runs[i].sweep_id = sweep_id;
    runs[i].sweep_runs = sweep_runs;
    runs[i].shard = shard.whole() ? "" : shard.text();
    runs[i].version = version;
  }
}

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  if (text.empty()) return parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  return parts;
}

}  // namespace

std::vector<BenchRun> read_runs_csv(const std::string& text, const std::string& path) {
  std::vector<BenchRun> runs;
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0;
  std::map<std::string, std::size_t> col;
  const auto optima = known_optima();
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> f = split_csv_line(line);
    if (col.empty()) {
      for (std::size_t k = 0; k < f.size(); ++k) col[f[k]] = k;
      for (const char* needed : {"instance", "n", "algorithm", "alpha", "beta", "rho", "ants", "iterations", "threads", "seed",
                                 "length", "gap_pct", "wall_s", "local_search", "time_limit_s", "iterations_done", "busy_s",
                                 "tour_hash", "trace", "instance_path", "sweep_index", "sweep_runs", "sweep", "shard", "version"}) {
        if (!col.count(needed)) {
          throw UserError(path, line_no, "not a runs CSV of acobench " + std::string("(no column \"") + needed +
                                             "\"; shards and merges need this version's columns)");
        }
      }
      continue;
    }
    auto field = [&](const char* name) -> const std::string& {
      const std::size_t k = col.at(name);
      if (k >= f.size()) throw UserError(path, line_no, "the row has " + std::to_string(f.size()) + " fields, the header more");
      return f[k];
    };
    auto number = [&](const char* name, double empty_value) {
      const std::string& v = field(name);
      if (v.empty()) return empty_value;
      double x = 0;
      auto r = std::from_chars(v.data(), v.data() + v.size(), x);
      if (r.ec != std::errc() || r.ptr != v.data() + v.size()) {
        throw UserError(path, line_no, std::string("column ") + name + ": \"" + v + "\" is not a number");
      }
      return x;
    };
    auto whole = [&](const char* name) {
      const double x = number(name, 0);
      if (x < 0 || x != std::floor(x) || x > 1e15) {
        throw UserError(path, line_no, std::string("column ") + name + ": \"" + field(name) + "\" is not a whole number");
      }
      return static_cast<std::uint64_t>(x);
    };
    BenchRun r;
    r.name = field("instance");
    r.n = whole("n");
    r.cell.instance = field("instance_path");
    r.cell.algorithm = field("algorithm");
    r.alpha = r.cell.alpha = number("alpha", 1);
    r.beta = r.cell.beta = number("beta", -1);
    r.rho = r.cell.rho = number("rho", -1);
    r.ants = r.cell.ants = static_cast<int>(whole("ants"));
    r.cell.iterations = static_cast<int>(whole("iterations"));
    r.cell.threads = static_cast<int>(whole("threads"));
    r.cell.local_search = field("local_search");
    r.cell.time_limit_s = number("time_limit_s", 0);
    r.seed = whole("seed");
    r.length = number("length", 0);
    if (!field("gap_pct").empty()) {
      auto it = optima.find(r.name);
      r.optimum = it != optima.end() ? it->second : r.length / (1.0 + number("gap_pct", 0) / 100.0);
    }
    r.wall_s = number("wall_s", 0);
    r.iterations_done = static_cast<int>(whole("iterations_done"));
    for (const std::string& b : split(field("busy_s"), ';')) {
      double x = 0;
      std::from_chars(b.data(), b.data() + b.size(), x);
      r.busy_s.push_back(x);
    }
    const std::string& h = field("tour_hash");
    auto hr = std::from_chars(h.data(), h.data() + h.size(), r.tour_hash, 16);
    if (h.size() != 16 || hr.ec != std::errc()) throw UserError(path, line_no, "column tour_hash: \"" + h + "\" is not 16 hex digits");
    for (const std::string& point : split(field("trace"), ';')) {
      const std::vector<std::string> t = split(point, ':');
      aco::TracePoint tp;
      if (t.size() != 3 || std::from_chars(t[0].data(), t[0].data() + t[0].size(), tp.iteration).ec != std::errc() ||
          std::from_chars(t[1].data(), t[1].data() + t[1].size(), tp.wall_s).ec != std::errc() ||
          std::from_chars(t[2].data(), t[2].data() + t[2].size(), tp.best_length).ec != std::errc()) {
        throw UserError(path, line_no, "column trace: \"" + point + "\" is not ITERATION:SECONDS:LENGTH");
      }
      r.trace.push_back(tp);
    }
    r.sweep_index = whole("sweep_index");
    r.sweep_runs = whole("sweep_runs");
    r.sweep_id = field("sweep");
    r.shard = field("shard");
    r.version = field("version");
    runs.push_back(std::move(r));
  }
  if (col.empty()) throw UserError(path, 0, "empty: not a runs CSV of acobench");
  return runs;
}

std::vector<BenchRun> merge_shards(const std::vector<std::string>& paths) {
  if (paths.empty()) throw UserError("merge needs the shards' CSV files");
  struct Part {
    std::string path;
    Shard shard;
    std::vector<BenchRun> runs;
  };
  std::vector<Part> parts;
  for (const std::string& p : paths) {
    Part part{p, {}, read_runs_csv(read_file(p), p)};
    if (part.runs.empty()) throw UserError(p, 0, "no runs: a shard with no rows (was it cut short?)");
    const BenchRun& first = part.runs.front();
    part.shard = first.shard.empty() ? Shard{} : parse_shard(first.shard);
    for (const BenchRun& r : part.runs) {
      if (r.sweep_id != first.sweep_id || r.shard != first.shard || r.version != first.version) {
        throw UserError(p, 0, "rows of different sweeps or shards in one file");
      }
    }
    parts.push_back(std::move(part));
  }
  const Part& ref = parts.front();
  const BenchRun& r0 = ref.runs.front();
  std::vector<const Part*> by_k(ref.shard.n, nullptr);
  for (const Part& part : parts) {
    const BenchRun& r = part.runs.front();
    if (r.version != r0.version) {
      throw UserError(part.path, 0, "written by acobench " + r.version + ", " + ref.path + " by acobench " + r0.version +
                                        ": shards of one sweep come from one version");
    }
    if (r.sweep_id != r0.sweep_id || r.sweep_runs != r0.sweep_runs) {
      throw UserError(part.path, 0, "a shard of another sweep (sweep " + r.sweep_id + ", " + ref.path + " is of sweep " +
                                        r0.sweep_id + "): its instances, options or seeds differ");
    }
    if (part.shard.n != ref.shard.n) {
      throw UserError(part.path, 0, "shard " + part.shard.text() + " of a split into " + std::to_string(part.shard.n) + ", " +
                                        ref.path + " is of a split into " + std::to_string(ref.shard.n));
    }
    if (by_k[part.shard.k]) {
      throw UserError(part.path, 0, "shard " + part.shard.text() + " is given twice (also " + by_k[part.shard.k]->path + ")");
    }
    by_k[part.shard.k] = &part;
  }
  for (std::size_t k = 0; k < by_k.size(); ++k) {
    if (!by_k[k]) {
      throw UserError("shard " + Shard{k, ref.shard.n}.text() + " of sweep " + r0.sweep_id + " is missing (" +
                      std::to_string(parts.size()) + " of " + std::to_string(ref.shard.n) + " shards given)");
    }
  }
  std::vector<BenchRun> all(r0.sweep_runs);
  std::vector<char> seen(r0.sweep_runs, 0);
  for (const Part& part : parts) {
    std::size_t expected = 0;
    for (std::size_t i = part.shard.k; i < r0.sweep_runs; i += part.shard.n) ++expected;
    for (const BenchRun& r : part.runs) {
      if (r.sweep_index >= r0.sweep_runs || !part.shard.holds(r.sweep_index) || seen[r.sweep_index]) {
        throw UserError(part.path, 0, "run " + std::to_string(r.sweep_index) + " does not belong to shard " + part.shard.text() +
                                          " or is there twice");
      }
      seen[r.sweep_index] = 1;
      all[r.sweep_index] = r;
      all[r.sweep_index].shard.clear();  // the merge is the whole sweep
    }
    if (part.runs.size() != expected) {
      throw UserError(part.path, 0, "shard " + part.shard.text() + " has " + std::to_string(part.runs.size()) + " of its " +
                                        std::to_string(expected) + " runs: it was cut short (a time limit or --time-budget?)");
    }
  }
  fill_time_to_target(all);
  return all;
}

}  // namespace app
