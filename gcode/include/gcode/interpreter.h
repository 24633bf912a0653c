#pragma once
/**
 * A reader of drilling programs: the subset acodrill writes and what typical
 * posts emit (G0/G1, G81/G82/G83/G73/G80, G98/G99, G90/G91, G20/G21, G53,
 * G28, modal X Y Z R F, T/M06, N-numbers, comments). It lists every hole
 * drilled, with its tool, and the rapid XY travel. Used by `acodrill verify`.
 */
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gcode {

class ProgramError : public std::runtime_error {
 public:
  ProgramError(std::uint32_t line, const std::string& message) : std::runtime_error(message), line_(line) {}
  std::uint32_t line() const { return line_; }

 private:
  std::uint32_t line_;
};

struct DrilledHole {
  int tool = 0;            // tool in the spindle (0 = none loaded)
  double x_mm = 0.0, y_mm = 0.0;
  double bottom_z_mm = 0.0;
  std::uint32_t line = 0;
};

struct Interpretation {
  std::vector<DrilledHole> holes;
  double rapid_xy_mm = 0.0;   // XY length of rapid moves, including moves between cycle holes
  double feed_xy_mm = 0.0;    // XY length of G1 moves (not expected in a drilling program)
  std::map<int, double> tool_diameter_mm;  // from "(T1 D=..." comments, where present
  bool inch = false;
  std::size_t tool_changes = 0;
};

Interpretation interpret(std::string_view program);

}  // namespace gcode
