#pragma once
// Small helpers of the benchmark harness shared by bench.cpp (running and
// summarising) and bench_results.cpp (plots, shards, result files).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "app/bench.h"
#include "gcode/program.h"

namespace app::bench_util {

inline std::string fmt(double v, int decimals) { return gcode::format_number(v, decimals); }

// Shortest text that reads back to the same double: parameters in CSV keys.
inline std::string param(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

inline double mean(const std::vector<double>& v) { return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size(); }

inline double stddev(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

inline bool is_baseline(const std::string& a) {
  return a == "input" || a == "nn" || a == "greedy" || a == "raster" || a == "nn2opt";
}

// The cell without its thread count: runs that differ only in threads compare for speedup.
inline std::string key_without_threads(const BenchRun& r) {
  const BenchCell& c = r.cell;
  return c.instance + "|" + c.algorithm + "|" + param(r.alpha) + "|" + param(r.beta) + "|" + param(r.rho) + "|" +
         std::to_string(r.ants) + "|" + std::to_string(c.iterations) + "|" + param(c.time_limit_s) + "|" + c.local_search;
}

inline std::string key(const BenchRun& r) { return key_without_threads(r) + "|" + std::to_string(r.cell.threads); }

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

inline std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= kFnvPrime;
  }
  return h;
}

inline std::uint64_t fnv1a(std::uint64_t h, const std::string& text) { return fnv1a(h, text.data(), text.size() + 1); }

inline std::uint64_t tour_hash(const aco::Order& order) {
  std::uint64_t h = kFnvOffset;
  for (aco::HoleIndex i : order) {
    const std::uint32_t v = static_cast<std::uint32_t>(i);
    h = fnv1a(h, &v, sizeof v);
  }
  return h;
}

inline std::string hex(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// The shortest text that reads back to the same double (a trace's lengths).
inline std::string exact(double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& v) {
  if (v.find_first_of(",\"\n\r") == std::string::npos) return v;
  std::string q = "\"";
  for (char c : v) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace app::bench_util
