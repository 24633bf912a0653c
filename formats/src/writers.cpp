#include "formats/writers.h"

#include <cmath>
#include <sstream>

namespace formats {

namespace {
constexpr double kInch = 25.4;
}  // namespace

std::string write_excellon(const std::vector<gcode::ToolPass>& passes, bool metric, const std::string& source) {
  // Explicit decimal points: every reader agrees on them, whatever it assumes about zeros.
  const int decimals = metric ? 3 : 4;
  const double scale = metric ? 1.0 : 1.0 / kInch;
  std::ostringstream out;
  out << "M48\n";
  out << ";FILE_FORMAT=" << (metric ? "3:3" : "2:4") << "\n";
  out << ";DRILL ORDER OPTIMIZED BY ACODRILL FROM " << source << "\n";
  out << (metric ? "METRIC,TZ" : "INCH,TZ") << "\n";
  for (const auto& p : passes) {
    out << "T" << p.tool.number << "C" << gcode::format_number(p.tool.diameter_mm * scale, decimals) << "\n";
  }
  out << "%\nG90\nG05\n";
  for (const auto& p : passes) {
    out << "T" << p.tool.number << "\n";
    for (const aco::Point2& h : p.holes) {
      out << "X" << gcode::format_number(h.x * scale, decimals) << "Y" << gcode::format_number(h.y * scale, decimals)
          << "\n";
    }
  }
  out << "T0\nM30\n";
  return out.str();
}

std::string write_gerber(const std::vector<gcode::ToolPass>& passes, const std::string& source,
                         const std::string& file_function) {
  std::ostringstream out;
  // Comments and attributes may not hold '*' or '%'.
  std::string src;
  for (char c : source) src += (c == '*' || c == '%' || static_cast<unsigned char>(c) < 32) ? '_' : c;
  out << "G04 Drill order optimized by acodrill from " << src << "*\n";
  out << "%TF.GenerationSoftware,acodrill,acodrill," << ACO_VERSION << "*%\n";
  if (!file_function.empty()) out << "%TF.FileFunction," << file_function << "*%\n";
  out << "%TF.FilePolarity,Positive*%\n%FSLAX46Y46*%\n%MOMM*%\n";
  for (std::size_t i = 0; i < passes.size(); ++i) {
    out << "%ADD" << (10 + i) << "C," << gcode::format_number(passes[i].tool.diameter_mm, 6) << "*%\n";
  }
  out << "G01*\n%LPD*%\n";
  auto coord = [](double mm) { return std::to_string(static_cast<long long>(std::llround(mm * 1e6))); };
  for (std::size_t i = 0; i < passes.size(); ++i) {
    out << "D" << (10 + i) << "*\n";
    for (const aco::Point2& h : passes[i].holes) out << "X" << coord(h.x) << "Y" << coord(h.y) << "D03*\n";
  }
  out << "M02*\n";
  return out.str();
}

}  // namespace formats
