#pragma once
/**
 * How long a control takes to run a program (issue 66): the program's own
 * moves — every rapid, feed, arc and dwell, canned cycles expanded — as a
 * control plans them: each move at the rate and acceleration its direction
 * allows (the axes' limits combined, as GRBL's planner does), corners
 * passed at the speed the junction deviation allows (GRBL, grblHAL,
 * FluidNC, LinuxCNC in G64) with a lookahead of GRBL's 16 blocks, arcs cut
 * into GRBL's chords, and a full stop wherever the control waits for the
 * moves to end (a dwell, a pause, a spindle or coolant command, a tool
 * change, a probe). What the time is spent on is told by what each move
 * does, so the parts add up to the motion:
 *   moves:    rapids that move in X or Y, and Z rapids from at or above the
 *             part's top (to and from the clearance, a tool's first approach)
 *   drilling: feeds (every cycle's and helix's cut) and Z rapids from inside
 *             a hole (out of it, between pecks), dwells outside a spindle start
 * A tool change, a pause or a probe is counted, and a probe's way down timed
 * at its feed; what a person or a tool changer takes there is the caller's.
 */
#include <cstddef>
#include <string_view>
#include <vector>

namespace gcode {

struct Kinematics {
  double rate_mm_min[3] = {5000, 5000, 5000};  // each axis's maximum rate (GRBL $110-$112)
  double accel_mm_s2[3] = {400, 400, 400};     // each axis's acceleration ($120-$122)
  double junction_deviation_mm = 0.01;         // $11; GRBL's default where a profile says none
  double arc_tolerance_mm = 0.002;             // $12
  // false: rapids move each axis at its own rate (a dogleg), stopping at
  // their ends; feeds stay straight lines.
  bool linear_rapids = true;
  // Where machine Z0 (G53 Z0, G28 Z) is above work Z0: the control's own
  // tool change height, which a program does not state.
  double machine_z0_mm = 100.0;
  // A G83 peck's rapid back down stops this far above the depth reached,
  // a G73 peck retracts this far (LinuxCNC's 0.010 in; HAAS's setting 22).
  double peck_clearance_mm = 0.254;
  // G84/G74 (issue 82): the spindle stops and turns the other way at the
  // bottom of each tapped hole; a VF-2-class spindle's reversal, a tenth of a
  // second for a small tap, is taken at 0.3 s (the slow end).
  double tap_reverse_s = 0.3;
  bool dwell_p_in_ms = false;  // G4 P in milliseconds (Marlin), else seconds
  // A canned cycle's P without a decimal point is milliseconds (HAAS and
  // Fanuc: G82 P500 is half a second); LinuxCNC's is always seconds.
  bool cycle_p_integer_ms = false;
};

struct ProgramTime {
  double moves_s = 0.0, drilling_s = 0.0;  // motion, as the header says
  double probe_s = 0.0;         // probing moves at their feed (G38.x)
  double spindle_wait_s = 0.0;  // dwells right after a spindle start
  double dwell_s = 0.0;         // other dwells (in drilling_s too)
  std::size_t tool_changes = 0;  // M6 or a T word
  std::size_t pauses = 0;        // M0, M1
  std::size_t probes = 0;        // G38.x
  // Time from each tool change (or the start) to the next, motion and dwells: the first
  // entry is before any tool.
  std::vector<double> per_tool_s;
  double motion_s() const { return moves_s + drilling_s; }
};

// Throws ProgramError (interpreter.h) for what it cannot read.
ProgramTime time_program(std::string_view program, const Kinematics& kinematics);

}  // namespace gcode
