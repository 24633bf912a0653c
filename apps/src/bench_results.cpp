// The benchmark harness's result files: the plots, the shards of a sweep
// run in pieces (Slurm) and their merge, runs read back from CSV.
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
