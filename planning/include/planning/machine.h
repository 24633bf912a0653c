#pragma once
/**
 * The machine a job runs on: its profile (rapids, acceleration, spindle,
 * tool changes, travel, clamps, the dialect its control reads) and the
 * built-in classes `acodrill machines` lists, each the JSON a --machine FILE
 * would hold.
 */
#include <optional>
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "aco/hole_set.h"
#include "gcode/motion_time.h"
#include "gcode/program.h"

namespace planning {

// A machine profile (JSON, see README "Machine profile"); defaults describe a
// HAAS VF-2-class vertical mill. `acodrill machines` lists the built-in classes.
struct Machine {
  std::string name = "HAAS VF-2 class";
  // The dialect its control reads, used when --dialect is not given.
  gcode::Dialect dialect = gcode::Dialect::Haas;
  // False: the operator changes drills by hand at a pause (tool_change_s is
  // then that manual change, re-zeroing Z included).
  bool tool_changer = true;
  double spindle_start_s = 0.0;      // a control that does not wait for its spindle waits this long after M3
  // A PCB drilling machine's single-stroke hit: the seconds one hole costs at
  // the spot, Z down and up (its data sheet's "hits per minute"); 0: timed
  // from the tool's feed, pecks and dwell instead.
  double hit_s = 0.0;
  // The drills it uses: "hss" twist drills or "carbide" micro drills, which a
  // PCB drilling machine runs at high speed in one stroke. Empty: the profile
  // does not say, and the material decides (carbide PCB drills for a board,
  // HSS twist drills for a plate), as a hobbyist drills FR-4 on a router.
  std::string drills;
  // Height above the part where feeds begin (the canned cycles' R plane).
  // Unset: 1 mm over a board, 2.5 mm (0.1 in) over a plate.
  std::optional<double> r_plane_mm;
  double rapid_xy_mm_min = 25400.0;  // 1000 in/min
  double rapid_z_mm_min = 25400.0;
  double accel_mm_s2 = 2500.0;       // per axis
  bool linear_rapids = false;        // HAAS G00 moves each axis at its own rate ("dogleg")
  // Issue 82: this shop spots every drilled hole first (as --spot).
  bool spot = false;
  // Issue 82: the spindle has an encoder, so LinuxCNC taps by G33.1 (the Z
  // motion synchronized with the spindle, rigid tapping) instead of G84,
  // which a LinuxCNC without spindle sync runs only with a floating tap holder.
  bool spindle_encoder = false;
  // How fast the control takes a corner (GRBL $11: the junction deviation;
  // GRBL's default 0.01 mm where the profile says none) and how finely it
  // cuts arcs into chords ($12, default 0.002 mm): issue 66's time model.
  double junction_deviation_mm = 0.01;
  double arc_tolerance_mm = 0.002;
  double tool_change_s = 4.2;        // chip to chip
  int max_rpm = 8100;                // spindle limit; generated tools stay under it
  aco::Point2 start{0.0, 0.0};       // where the spindle is at the start and returns to (program XY)
  // The table's travel in machine coordinates (VF-2: 30 x 16 in). Without a
  // work offset only its size is known to matter: the machinist sets program
  // zero (G54) where the part is clamped, so only the holes' extent is checked.
  double x_min = 0.0, x_max = 762.0, y_min = 0.0, y_max = 406.0;
  // Where program zero (G54) sits in machine coordinates, when the profile
  // says; then every hole's absolute position is checked against the travel.
  std::optional<aco::Point2> work_offset;
  // Clamps and fixtures sticking up above the R plane (work XY rectangles):
  // a move across one retracts to the initial plane first; a hole in one is an error.
  struct Rect {
    double x_min, y_min, x_max, y_max;
  };
  std::vector<Rect> clamps;
  // The tools on the bench, as --drills, --end-mill and --probe-plate give
  // them (the options win): the drills owned ("0.6,0.8:-0.05:+0.1,1.0"), an
  // end mill, a touch plate's thickness, and how its probing runs.
  std::string drills_owned;
  std::optional<double> end_mill_mm, probe_plate_mm;
  double probe_feed_mm_min = 100.0, probe_travel_mm = 30.0;
};

// True when the straight move a → b passes over any clamp of the machine.
bool crosses_clamp(aco::Point2 a, aco::Point2 b, const Machine& machine);

// The built-in machine classes: a name, one line saying what it is, and its
// profile as JSON (the same keys a --machine FILE has, with the sources of
// its figures under "sources").
struct MachineClass {
  std::string name, description, profile_json;
};
const std::vector<MachineClass>& machine_classes();

// The built-in class of that name, if there is one.
std::optional<Machine> builtin_machine(const std::string& name);
// A profile from its JSON text (`source` names it in errors, a file or a
// class); throws formats::InputError with the line for bad JSON.
Machine parse_machine(const std::string& json_text, const std::string& source);
// "vf2, router, pcb-drill": the built-in classes, for messages.
std::string machine_class_names();

// Checks that the holes (in program coordinates) fit the machine: their
// extent, tool edges included, against the size of its travel; absolute
// positions too when the profile gives the work offset. Throws formats::InputError.
void check_travel(const aco::HoleSet& holes, const Machine& machine, const std::string& source);

// The machine's motion as the program timer (gcode/motion_time.h) takes it, for a program in `dialect`.
gcode::Kinematics kinematics_of(const Machine& machine, gcode::Dialect dialect);

}  // namespace planning
