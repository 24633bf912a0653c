#pragma once
/**
 * What `acodrill verify` needs of a program: every hole it drills (canned or
 * expanded), with its tool and depth, and the rapid XY travel. A flat view of
 * gcode::read_drilling (drilling.h) read leniently: moves that are not
 * drilling are read past, not refused.
 */
#include <cstdint>
#include <map>
#include <optional>
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
  // A hole milled by a helix: the radius of the tool's path about the centre
  // (the hole is 2 r plus the tool's diameter); 0: drilled or plunged.
  double milled_radius_mm = 0.0;
  int work_offset = 54;    // the work offset it is drilled in (drilling.h, work_offset_text)
  // How it is made (issue 83: verify compares them): a canned cycle's peck
  // (G83, G73 Q; nullopt for others and for expanded drilling), and the
  // seconds it dwells there (HoleCycle::dwell_s: its P, or its G4s).
  std::optional<double> peck_mm, dwell_s;
  // A tapped hole's pitch (issue 82: verify checks it): G33.1's K, or G84's
  // and G74's feed over the spindle's speed; nullopt for any other hole.
  std::optional<double> pitch_mm;
};

struct Interpretation {
  std::vector<DrilledHole> holes;
  double rapid_xy_mm = 0.0;   // XY length of rapid moves, including moves between cycle holes
  std::map<int, double> tool_diameter_mm;  // from "(T1 D=..." comments, where present
  bool inch = false;
  std::size_t tool_changes = 0;
};

Interpretation interpret(std::string_view program);
// The same, read as a drilling program whose milling is kept in place
// (ReadOptions::keep_milling): a plunge a cut goes on from is no hole. How
// acodrill checks the programs it writes from such an input.
Interpretation interpret_keeping_milling(std::string_view program);

}  // namespace gcode
