// Input and output microbenchmarks: DXF parse per MB and G-code write, each
// beside a naive reference (getline + stod; iostream formatting).
#include <benchmark/benchmark.h>

#include <iomanip>
#include <sstream>
#include <string>

#include "dxf/reader.h"
#include "gcode/program.h"

namespace {

std::string make_dxf(std::size_t circles) {
  std::string s = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
  char buf[256];
  for (std::size_t i = 0; i < circles; ++i) {
    std::snprintf(buf, sizeof buf, "0\nCIRCLE\n5\n%zX\n8\nHOLES\n10\n%.6f\n20\n%.6f\n30\n0.0\n40\n%.4f\n", i + 100,
                  static_cast<double>(i % 1000) * 2.54, static_cast<double>(i / 1000) * 2.54, 0.4 + (i % 3) * 0.1);
    s += buf;
  }
  return s + "0\nENDSEC\n0\nEOF\n";
}

// As AutoCAD writes a circle in R2010: handle, owner, subclass markers, layer,
// colour, linetype, lineweight, thickness, extrusion: about 250 bytes each.
std::string make_realistic_dxf(std::size_t circles) {
  std::string s = "  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1024\n  9\n$INSUNITS\n 70\n     4\n  0\nENDSEC\n"
                  "  0\nSECTION\n  2\nENTITIES\n";
  s.reserve(circles * 260 + 200);
  char buf[512];
  for (std::size_t i = 0; i < circles; ++i) {
    std::snprintf(buf, sizeof buf,
                  "  0\nCIRCLE\n  5\n%zX\n330\n1F\n100\nAcDbEntity\n  8\nDRILL_%zu\n  6\nByLayer\n 62\n   256\n370\n    -1\n"
                  " 48\n1.0\n 60\n     0\n347\n2A7\n 67\n     0\n440\n33554687\n"
                  "100\nAcDbCircle\n 39\n0.0\n 10\n%.14f\n 20\n%.14f\n 30\n0.0\n 40\n%.14f\n210\n0.0\n220\n0.0\n230\n1.0\n",
                  i + 0x100, i % 4, static_cast<double>(i % 500) * 2.54 + 0.0123456789,
                  static_cast<double>(i / 500) * 2.54 + 0.0987654321, 0.4 + (i % 4) * 0.1);
    s += buf;
  }
  return s + "  0\nENDSEC\n  0\nEOF\n";
}

// The yardstick: a 50 MB file with 200 000 circles.
void BM_dxf_read_50MB_200k_circles(benchmark::State& state) {
  const std::string text = make_realistic_dxf(200000);
  std::size_t holes = 0;
  for (auto _ : state) holes = dxf::read_holes(text).holes.size();
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
  state.counters["holes"] = static_cast<double>(holes);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

void BM_dxf_read(benchmark::State& state) {
  const std::string text = make_dxf(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(dxf::read_holes(text));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

void BM_dxf_read_reference_getline_stod(benchmark::State& state) {
  // What a first version does: getline, compare strings, stod. No blocks, no OCS, no units.
  const std::string text = make_dxf(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    std::istringstream in(text);
    std::string code, value;
    std::vector<double> xs;
    bool circle = false;
    while (std::getline(in, code) && std::getline(in, value)) {
      const int c = std::stoi(code);
      if (c == 0) circle = value == "CIRCLE";
      else if (circle && (c == 10 || c == 20 || c == 40)) xs.push_back(std::stod(value));
    }
    benchmark::DoNotOptimize(xs);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

std::vector<gcode::ToolPass> make_passes(std::size_t n) {
  gcode::ToolPass pass;
  pass.tool.diameter_mm = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    pass.holes.push_back({static_cast<double>(i % 100) * 2.54, static_cast<double>(i / 100) * 2.54});
    pass.index.push_back(i + 1);
  }
  return {pass};
}

void BM_gcode_write(benchmark::State& state) {
  auto passes = make_passes(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    std::ostringstream out;
    gcode::write_program(out, passes, {});
    benchmark::DoNotOptimize(out.str());
  }
}

void BM_gcode_write_reference_iostream(benchmark::State& state) {
  auto passes = make_passes(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(3);
    for (const auto& h : passes[0].holes) out << "X" << h.x << " Y" << h.y << "\n";
    benchmark::DoNotOptimize(out.str());
  }
}

}  // namespace

BENCHMARK(BM_dxf_read)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_dxf_read_50MB_200k_circles)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_dxf_read_reference_getline_stod)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_gcode_write)->RangeMultiplier(4)->Range(64, 16384);
BENCHMARK(BM_gcode_write_reference_iostream)->RangeMultiplier(4)->Range(64, 16384);
