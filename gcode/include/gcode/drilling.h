#pragma once
/**
 * Another CAM's drilling program, read as a control would run it: tool runs
 * (one tool, spindle and the holes it makes, between two tool changes), and
 * for every hole how it is made — a canned cycle with its words (G81/G82/G83/
 * G73, tapping G84/G74, boring G85-G89; R, Z, Q, P, F, G98/G99) or the Z moves
 * of expanded drilling (a rapid to X Y, feed down, back up). Everything a
 * reordered program needs to drill the same holes the same way; `verify` reads
 * programs with it too.
 *
 * **Example**:
 *   gcode::DrillingProgram p = gcode::read_drilling(text, {});
 *   for (const gcode::ToolRun& run : p.runs) use(run.tool, run.holes.size());
 */
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"
#include "gcode/interpreter.h"
#include "gcode/program.h"

namespace gcode {

// One Z move made over a hole (expanded drilling), or a dwell there.
struct ZMove {
  enum Kind { Rapid, Feed, Dwell } kind = Rapid;
  double z_mm = 0.0;           // Rapid, Feed: absolute work Z
  double feed_mm_min = 0.0;    // Feed: the feed rate in force
  std::string dwell;           // Dwell: P as written ("1.0", "500"); a Marlin "G4 S3": "3.0", seconds
  double dwell_s = 0.0;        // Dwell: the same in seconds (dwell_seconds)
  std::string dwell_as_written;  // Dwell: Marlin's "S3" (kept so in the input's own style); empty: P
};

// A dwell's P as seconds. With a decimal point P is seconds on every control;
// without one, HAAS and Fanuc count milliseconds where LinuxCNC and GRBL count
// seconds: a canned cycle's integer P (a HAAS/Fanuc habit) and an integer G4 P
// of 100 or more are read as milliseconds, a smaller G4 P as seconds.
double dwell_seconds(std::string_view p, bool canned_cycle);

struct HoleCycle;
// The moves a control makes for one canned-cycle hole once it is over the
// hole at or above R, as LinuxCNC runs them (../shared/gcode.md): a rapid to
// R, then G81 feed down; G82 feed down and dwell; G83 pecks of Q, each back
// to R and rapidly down again to 0.254 mm (0.010 in) above the depth reached;
// G73 pecks of Q backing off 0.254 mm; G85 feed down and feed out; G89 feed
// down, dwell, feed out; then a rapid out to `retract_z_mm` (R for G99, the
// initial plane for G98). Written out this way a control without canned
// cycles (GRBL, Marlin) drills the same hole. Throws ProgramError (`line`)
// for the cycles that cannot be made of moves: tapping (G84, G74), back
// boring (G87), G86 and G88 (spindle stops and manual moves).
// With `part_top_z_mm` (below R), G83/G73 pecks count from the top of the
// part instead: the first stroke feeds from R through the air to Q below
// the top, so no peck is cut in air. acodrill's own programs for controls
// without canned cycles drill so; another CAM's cycles keep LinuxCNC's way.
std::vector<ZMove> expand_cycle(const HoleCycle& cycle, double retract_z_mm, std::uint32_t line,
                                std::optional<double> part_top_z_mm = std::nullopt);

// How one hole is made. Positions and lengths in mm, work coordinates.
struct HoleCycle {
  // The canned cycle's G number (81, 82, 83, 73, 84, 74, 85..89); 0: expanded;
  // 331: LinuxCNC's G33.1 rigid tap, from R (where Z was) to Z at pitch_mm a turn and back.
  int code = 0;
  // Canned cycles: the words as in force at the hole.
  double z_mm = 0.0, r_mm = 0.0;
  std::optional<double> q_mm;  // peck
  std::string p;               // dwell as written ("" = none): its unit is the control's
  double feed_mm_min = 0.0;
  std::string extra;           // other cycle words as written, e.g. "I0.1 J0.05 K0.2" (HAAS pecks)
  bool retract_initial = false;  // G98 (else G99)
  bool rigid = false;          // M29 before the cycle (rigid tapping); G33.1
  double pitch_mm = 0.0;       // G33.1: its K (feed_mm_min is K times the spindle's speed)
  // Expanded drilling: the Z moves made over the hole, from arriving there to leaving.
  std::vector<ZMove> moves;

  double bottom_mm() const;    // the deepest Z the tool reaches
  // Seconds it dwells at the hole: a canned cycle's P (dwell_seconds), or the
  // G4s of expanded drilling made while the tool is in it, added up.
  double dwell_s() const;
  // A tap's pitch (issue 82): G33.1's K, or G84's and G74's feed over the
  // spindle's speed in force; nullopt for any other hole, or with no speed.
  std::optional<double> tap_pitch_mm(double spindle_rpm) const;
  bool same_words(const HoleCycle& other) const;  // canned: the same cycle and words
};

struct ProgramHole {
  aco::Point2 at;
  HoleCycle cycle;
  // Z of the spindle when it moved over the hole (the plane it travelled at);
  // nullopt when it came from machine Z home (G53/G28).
  std::optional<double> arrive_z_mm;
  std::uint32_t line = 0;      // the line that drills it (the cycle line, or the first feed down)
  std::uint32_t first_line = 0, last_line = 0;  // the lines that make it, XY approach to last Z move
  // Milled by arcs about `at` (lenient reading only): the radius of the
  // tool's centre path; the hole is that twice, plus the tool's diameter.
  std::optional<double> milled_radius_mm;
  // Z of the spindle after last_line: where the hole leaves it (a cycle's retract, an expanded hole's last move).
  std::optional<double> leave_z_mm;
};

// A work offset as ToolRun::work_offset holds it: 54..59 (G54-G59), 591..593
// (G59.1-G59.3), kExtendedWorkOffset + n (G54.1 Pn, HAAS and Fanuc).
constexpr int kExtendedWorkOffset = 1000;
std::string work_offset_text(int offset);  // "G55", "G59.1", "G54.1 P7"

// One tool's holes between two tool changes (or spindle or work offset changes), in program order.
struct ToolRun {
  int tool = 0;                          // the T word in force (0: none)
  std::optional<double> diameter_mm;     // from the program's comments, where it says
  double spindle_rpm = 0.0;              // S in force (0: never given)
  int spindle = 0;                       // 3 (M3), 4 (M4) or 0 (not on)
  bool tool_change = false;              // an M6 came before the holes
  bool pause = false;                    // an M0/M1 came before the holes (manual tool change)
  std::string message;                   // the last comment before the holes (what the operator was told)
  int work_offset = 54;                  // the work offset in force (work_offset_text)
  int length_offset = 0;                 // H of the G43 in force (0: none)
  int coolant = 0;                       // 7 (M7), 8 (M8) or 0 (off)
  // ReadOptions::keep_milling: a cut follows the run's last hole (in program
  // order) with no rapid in X/Y between, so it begins where that hole left the
  // spindle; a reordered run returns there (write_drilling).
  bool cut_follows = false;
  std::vector<ProgramHole> holes;
};

struct DrillingProgram {
  bool inch = false;                     // the units in force at the first hole
  int decimals = 3;                      // the most decimals of any X, Y or Z word
  std::vector<ToolRun> runs;
  std::map<int, double> tool_diameter_mm;  // from comments
  // Where the spindle went in XY after the last hole, when it moved on (a park position).
  std::optional<aco::Point2> end;
  bool uses_line_numbers = false;
  // Every G90 (false) and G91 (true) by its line, in order: the distance
  // mode a kept line runs in, which the keep-style writer restores.
  std::vector<std::pair<std::uint32_t, bool>> incremental_from;
  bool incremental_after(std::uint32_t line) const;  // G91 in force once `line` has run
  // Where reading stopped: the line of the program's end (M2, M30 or the
  // closing %), what ended it, and how many lines of code came after it
  // (not read). 0 / empty: the text ran out.
  std::uint32_t end_line = 0;
  std::string end_reason;
  std::size_t code_lines_after_end = 0;
  // What a user should know about how the program was read, by line.
  struct Note {
    std::uint32_t line = 0;
    std::string message;
  };
  std::vector<Note> notes;
  // ReadOptions::keep_milling: the lines that cut (a G1 in X/Y below where
  // the last hole's feed began, arcs, G41/G42), in order.
  std::vector<std::uint32_t> milling_lines;
  std::string text;                      // the program as read: what keep-style copies
  double rapid_xy_mm = 0.0;              // XY length of rapid moves, from X0 Y0
  std::size_t tool_changes = 0;
  std::size_t hole_count() const;
};

struct ReadOptions {
  // Refuse what is not drilling — G1 moves in XY, arcs, probing, subprogram
  // calls, other axes, another plane — naming the line (ProgramError). Off,
  // they are read past (verify lists what a program drills, whatever else it does).
  bool drilling_only = true;
  // With drilling_only: a program that also mills (FreeCAD Jobs with a
  // profile or pocket beside their drilling). Its cutting moves — a G1 in X/Y
  // below where the last hole's feed began, arcs, cutter compensation — are not
  // refused but kept where they are (DrillingProgram::milling): each ends
  // the tool run it is in, so reordering stays between them, and the feed
  // down it began from (a plunge) is not a hole. Only the input's own style
  // can carry them (write_drilling's keep_style).
  bool keep_milling = false;
};

// A hole as verify compares it (interpreter.h): its place, tool, depth, offset,
// peck, dwell and a tap's pitch, as the run it is in makes it.
DrilledHole drilled_hole(const ToolRun& run, const ProgramHole& hole);

// Reads the whole program. Throws ProgramError with the line for what it cannot read.
DrillingProgram read_drilling(std::string_view text, const ReadOptions& options = {});

struct DrillingWriteSettings {
  Dialect dialect = Dialect::Haas;
  bool inch = false;                       // program units
  int decimals = 3;                        // of every length and feed
  int program_number = 1001;
  std::string program_name = "ACODRILL";
  std::vector<std::string> header_comments;
  // Keep the input's own style: every line of the program's text outside the
  // stretches where a run drills is copied as it is; each stretch is written
  // anew, in the new order, canned holes canned and expanded ones expanded.
  bool keep_style = false;
  // GRBL and Marlin (as in ProgramSettings): the spindle's time to come to
  // speed, and the feed of Marlin's G0 moves.
  double spindle_start_s = 0.0;
  double travel_feed_mm_min = 0.0;
};

// Writes `program` (the input's runs, each with its holes reordered): the
// dialect's skeleton around them, or the input's own lines (keep_style).
// Every hole keeps its cycle words or its Z moves (GRBL and Marlin: canned
// cycles written out as their moves, expand_cycle); between holes the spindle
// travels at the highest plane the input travelled at between that run's
// holes (G98 to it), or at R where the input did so throughout (G99).
void write_drilling(std::ostream& out, const DrillingProgram& program, const DrillingWriteSettings& settings);

// True when the text reads as a G-code program rather than another hole file:
// blocks of G/M words with Z moves, no Excellon header, no Gerber '*' blocks.
bool looks_like_gcode(std::string_view head);

}  // namespace gcode
