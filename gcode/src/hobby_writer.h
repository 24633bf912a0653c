#pragma once
// The lines of a program for a control without canned cycles, tool changer
// or length offsets: GRBL 1.1 (also grblHAL, FluidNC) and Marlin. Both the
// planner's emitter and the reordered-program writer write through it, so the
// two rules that keep such a machine safe live in one place: the spindle
// never moves in X/Y until it is known to be above the part (Z > 0), and a
// tool change is a pause that tells the operator which drill to put in and
// to zero Z on it again (nothing measures its length).
//
// Only words both controls accept are written: G0 G1 G4 G17 G20 G21 G90 G94
// G54-G59, M0 M2 M3 M4 M5 M8 M9, T (GRBL keeps it and does nothing), F and S.
// GRBL (doc/markdown/commands.md) refuses G81-G89, G43 H, G98/G99, M6, M7
// and '%'; Marlin has no T for a spindle (it selects an extruder), no M2/M30
// (M30 deletes a file on its SD card), reads comments after ';' only, shows
// `M0 text` on its screen, and runs G0 at the last F given.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "gcode/drilling.h"
#include "milling.h"

namespace gcode {

class HobbyWriter {
 public:
  // `decimals`: of lengths in program units; `travel_feed_mm_min`: Marlin's G0 feed (0: none given).
  HobbyWriter(std::ostream& out, Dialect dialect, bool inch, int decimals, double travel_feed_mm_min);

  void comment(const std::string& text);
  // The program's title ("NAME - FOR GRBL 1.1") and its header comments.
  void header(const std::string& program_name, const std::vector<std::string>& comments);
  // One line of the tool list: "T2 D=1.000 MM - 1.000 MM DRILL - 14 HOLES" (`what` may be empty).
  void tool_line(int tool, std::optional<double> diameter_mm, const std::string& what, std::size_t holes);
  // "1.000 MM" or "0.0394 IN": a size as the operator reads it in the program's units.
  std::string size(double mm) const;
  void start();                                 // units, absolute, plane
  void work_offset(int g);                      // written when it changes (G54, the default, is not written first)
  // Spindle off, up to `clear_z`, the message, the pause: the whole
  // instruction in "(MSG, ...)" lines (grblHAL and LinuxCNC show them;
  // Marlin: "; " comments), then the short one on the pause line itself
  // ("M0 (PUT IN T1 0.6 MM DRILL, ZERO Z)"; Marlin "M0 PUT IN ..."), which
  // is what most senders show at the pause (CNCjs, gSender, Candle,
  // OpenBuilds CONTROL); never a word cut.
  void pause_for(const std::string& message, const std::string& short_message, double clear_z_mm);
  // The tool change pause for tool `number` (its name, diameter, kind: "DRILL",
  // "END MILL", "COUNTERSINK", ...), with or without a touch plate.
  void pause_for_tool(int number, const std::string& name, std::optional<double> diameter_mm, const std::string& kind,
                      bool touch_plate, double clear_z_mm);
  // The header's account of every tool change, for senders that show no message at all.
  void tool_change_sequence(bool touch_plate);
  void select_tool(int tool);                   // GRBL: T<n>; Marlin: none
  void spindle_on(int direction, double rpm, double start_s);  // M3/M4 S, then a dwell while it comes to speed
  void spindle_off();
  void coolant_on();                            // M8 (GRBL has no M7 unless built with it)
  void coolant_off();
  void rapid_z(double z_mm);
  // Over a hole: up to at least `travel_z_mm` where lower (or not known), a
  // rapid to X Y, then the hole's moves. Throws std::invalid_argument for a
  // travel plane at or below the top of the part (Z 0).
  void hole(aco::Point2 at, const std::vector<ZMove>& moves, double travel_z_mm);
  // Over a hole's helix start: up to at least `travel_z_mm`, a rapid there,
  // then the milling moves (G2 arcs with I J; Marlin needs ARC_SUPPORT).
  void milled_hole(aco::Point2 start, const std::vector<PathMove>& moves, double travel_z_mm);
  // Z probed on a touch plate `plate_mm` thick lying on the part's top: down
  // at most `travel_mm` until it touches (G38.2), that point set as Z
  // plate_mm (G10 L20 on GRBL, G92 on Marlin), up 5 mm above the plate,
  // then a pause to take the clip off.
  void probe_plate(double plate_mm, double feed_mm_min, double travel_mm);
  // Spindle off, up to `clear_z`, to `home` if given, and the end (M2 on GRBL).
  void end(double clear_z_mm, std::optional<aco::Point2> home);

 private:
  std::string plain(const std::string& text) const;  // comment_text, and no ';' for Marlin
  std::string n(double mm) const;
  std::string f(double mm_min) const;
  void line(const std::string& text);
  void dwell(double seconds);
  void message_pause(const std::string& message, const std::string& short_message);

  std::ostream& out_;
  Dialect dialect_;
  bool inch_;
  int decimals_;
  double travel_feed_;
  std::optional<double> z_;      // where the spindle is (program Z, mm); nullopt: not known
  std::optional<double> feed_;   // the F in force
  bool spindle_ = false, coolant_ = false;
  int work_offset_ = 54;  // in force (work_offset_text)
};

}  // namespace gcode
