#pragma once
/**
 * Drilling programs: tools, passes and the settings of one program, and the
 * emitter that writes them as HAAS-style G-code with canned cycles.
 *
 * **Example**:
 *   gcode::Tool t;  t.number = 1;  t.diameter_mm = 6.35;
 *   gcode::ToolPass pass{t, {{10, 10}, {20, 10}}, {1, 2}};
 *   gcode::write_program(std::cout, {pass}, gcode::ProgramSettings{});
 */
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "aco/geometry.h"

namespace gcode {

// Haas, Fanuc and LinuxCNC drill with canned cycles and change tools with M6;
// GRBL (1.1, grblHAL, FluidNC) and Marlin have neither: every hole is written
// out as moves, and a tool change is a pause with a message to the operator.
enum class Dialect { Haas, Fanuc, LinuxCnc, Grbl, Marlin };
enum class Units { Mm, Inch };
// G84 tapping (right hand; G74 left hand): feed down at the pitch times the
// spindle speed, the spindle reversed at the bottom, feed out; G85 reaming:
// feed down, feed out.
enum class Cycle { G81, G82, G83, G73, G84, G74, G85 };

// What a tool makes (issue 82), in the order a hole feature's operations
// come: spot, drill, ream, countersink or counterbore, tap.
enum class Operation { Spot, Drill, Ream, Countersink, Counterbore, Tap };

struct Tool {
  int number = 1;              // T and H number
  double diameter_mm = 0.0;    // the drill's diameter
  std::string name;            // shown in comments; generated from the diameter when empty
  int spindle_rpm = 3000;
  double feed_mm_min = 250.0;
  double depth_mm = -8.0;      // absolute Z of the drill tip at the bottom, drill-point allowance included
  Cycle cycle = Cycle::G81;
  double peck_mm = 0.0;        // Q for G83/G73
  double dwell_s = 0.0;        // P for G82
  int max_hits = 0;            // the drill's life in holes (0: no limit); a worn drill is replaced by a sister tool
  // An end mill: each hole is milled by a helix about its centre (G2 with I J,
  // helix_pitch_mm of depth a turn at most, a full circle at the depth, out
  // through the centre) instead of drilled with the canned cycle.
  bool end_mill = false;
  double helix_pitch_mm = 0.0;
  // Issue 82: a tool of a hole feature's operation. A tap's diameter is its
  // thread's major, its cycle G84 (G74 left hand) at pitch x rpm; a
  // countersink's the diameter it makes at the top, to its angle; a
  // counterbore's its own. Drills and end mills are Operation::Drill.
  Operation operation = Operation::Drill;
  double pitch_mm = 0.0;   // tap
  double angle_deg = 0.0;  // countersink, spot drill: the included angle
  std::string thread;      // tap: "M3", "1/4-20 UNC"
  // A tap on a spindle with an encoder (Machine::spindle_encoder): LinuxCNC
  // taps it by G33.1, Z synchronized with the spindle at pitch_mm a turn.
  bool spindle_synchronized = false;
};

// One tool's holes in drilling order. `index` gives each hole's 1-based number
// in the whole program (shown as its N-number, used by --resume-from).
struct ToolPass {
  Tool tool;
  std::vector<aco::Point2> holes;  // mm, work coordinates
  std::vector<std::size_t> index;
  // clear_after[i]: the move from hole i to the next crosses a clamp, so hole i
  // retracts to the initial plane (G98). Empty = no clamps.
  std::vector<bool> clear_after;
  // An end mill's pass: the diameter each hole is milled to (empty: drilled).
  std::vector<double> mill_diameter;
  // slot_to_next[i]: holes i and i+1 are the two ends of a slot of width
  // mill_diameter[i], milled along it as one (empty: none).
  std::vector<bool> slot_to_next;
};

struct ProgramSettings {
  Dialect dialect = Dialect::Haas;
  Units units = Units::Mm;
  int program_number = 1001;               // O-number, 1..99999
  std::string program_name = "ACODRILL";
  std::vector<std::string> header_comments;  // source, holes and tools, estimated time
  double initial_z_mm = 25.0;  // G43 H Z: clearance plane above the part (work Z)
  double r_plane_mm = 2.5;     // R: where feeding starts
  bool retract_to_r = true;    // G99 between holes (G98 on each tool's last hole); false: G98 always
  std::size_t resume_from = 1; // first hole (1-based program index) to drill
  std::optional<aco::Point2> home;  // XY to return to at the end (work coordinates)
  // GRBL and Marlin only: seconds to wait after the spindle starts (neither
  // control waits for it), and the feed Marlin's G0 moves run at (Marlin
  // moves G0 at the last F given, so every G0 names it; 0: leave it out).
  double spindle_start_s = 0.0;
  double travel_feed_mm_min = 0.0;
  // A touch plate this thick (mm) on the part's top: after each tool change
  // Z is probed on it (G38.2) and set to its thickness, on GRBL, Marlin and
  // LinuxCNC. Probing runs down at most probe_travel_mm at probe_feed_mm_min.
  std::optional<double> probe_plate_mm;
  double probe_feed_mm_min = 100.0;
  double probe_travel_mm = 30.0;
  // Issue 82: what the operator does by hand at the end (GRBL and Marlin
  // cannot tap): each line a comment before one last pause. Empty: none.
  std::vector<std::string> final_pause;
};

// How a hole is milled by a helix: about its centre on a circle of
// `path_radius_mm` (hole radius less the end mill's), down from the top of
// the part (Z 0) in `turns` equal turns of at most the tool's pitch.
struct Helix {
  double path_radius_mm = 0.0;
  int turns = 0;
  double depth_per_turn_mm = 0.0;
  // Cutting length: the helix, the full circle at the depth, the way to the centre.
  double length_mm() const;
};
// Below this path radius the end mill is plunged straight: the hole is its size.
constexpr double kPlungeRadiusMm = 0.002;
Helix helix_for(double hole_diameter_mm, const Tool& end_mill);
// The cutting length of a slot `width_mm` wide from `a` to `b` milled along
// its length (its laps down, one at the depth, the way to the middle).
double milled_slot_length_mm(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& end_mill);

const char* to_string(Dialect d);
// Why this dialect's programs do not probe a touch plate (HAAS, Fanuc: their
// controls measure tools with their own cycles); nullopt where they do.
std::optional<std::string> probe_plate_refusal(Dialect d);
// False for GRBL and Marlin: no canned cycles, no M6, no G43, no G98/G99.
bool has_canned_cycles(Dialect d);
std::optional<Dialect> dialect_from_string(const std::string& name);
const char* to_string(Cycle c);
std::optional<Cycle> cycle_from_string(const std::string& name);
const char* to_string(Operation o);  // "spot", "drill", "ream", "countersink", "counterbore", "tap"
std::optional<Operation> operation_from_string(const std::string& name);
// The cycle a canned-cycle control makes a tool's holes with: tapping G84 or G74.
bool is_tapping(Cycle c);
// True where the program taps the tool's holes by LinuxCNC's G33.1 (a tap on a
// spindle with an encoder, Tool::spindle_synchronized) rather than by G84/G74.
bool taps_by_g33_1(const Tool& tool, Dialect dialect);

// The tool's name, or "6.350 MM DRILL" ("1.000 MM END MILL") made from its diameter.
std::string tool_name(const Tool& tool);

// How the program this dialect is written in makes the tool's holes, as the
// operator finds it in the program: "G81", "G83" for a canned-cycle control;
// "G1 down, G0 out" or "G1 pecks, G0 out between" where there are no canned
// cycles (GRBL, Marlin); "G2 helix" for an end mill.
std::string cycle_description(const Tool& tool, Dialect dialect);

// Text made safe for a "(...)" comment: one line, uppercase ASCII for the
// control, parentheses become '/'. From UTF-8 (issue 85): a Latin letter with
// diacritics becomes its base letter (Ł → L, ü → U, ç → C; Æ → AE, ß → SS,
// Œ → OE, Þ → TH, Ĳ → IJ: Latin-1 Supplement, Latin Extended-A and
// Romanian's Ș Ț), any other character outside ASCII, and each malformed
// byte, one '?'. Never shortened: a long one is wrapped (wrap_words).
std::string comment_text(std::string text);

// The text in lines of at most `width` characters, broken between words
// only (a single word longer than the width stands alone on its line).
std::vector<std::string> wrap_words(const std::string& text, std::size_t width);

// Every line acodrill writes stays within this many characters, comments
// included: GRBL's line buffer holds 80 (LINE_BUFFER_SIZE), and senders cut
// or refuse longer lines (Universal G-code Sender: 70 after comments and
// blanks are stripped).
constexpr std::size_t kMaxLineChars = 78;

// The text as "(...)" comment lines within kMaxLineChars, words whole.
std::vector<std::string> comment_lines(const std::string& text);
// "CODE (TEXT)" where it fits on one line; else the text's comment lines, then the code alone.
std::vector<std::string> code_with_comment(const std::string& code, const std::string& text);

// The block that takes Z to machine home: "G53 G00 Z0." (HAAS, LinuxCNC) or
// "G91 G28 Z0." and "G90" (Fanuc).
std::string z_home_block(Dialect d);

// Locale-independent fixed-point text: always a decimal point, never "-0.000".
std::string format_number(double value, int decimals);
// format_number's text appended to `out`, without a string of its own: the
// writers of 10^6-hole files call it tens of millions of times (issue 84).
void append_number(std::string& out, double value, int decimals);

// A number as a person reads it, for messages and comments: 6.5 not 6.500,
// 3 not 3.000 (format_number's rounding, trailing zeros dropped).
std::string format_short(double value, int decimals = 3);

// The first hole of a pass that the program makes at all, given
// --resume-from (a milled slot resumed at its second end is milled whole again).
std::size_t first_written(const ToolPass& pass, std::size_t resume_from);

// Writes the whole program. Throws std::invalid_argument for settings it cannot honour.
void write_program(std::ostream& out, const std::vector<ToolPass>& passes, const ProgramSettings& settings);

}  // namespace gcode
