#include "formats/writers.h"

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

}  // namespace formats
