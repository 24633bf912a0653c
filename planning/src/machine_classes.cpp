// The built-in machine classes (`acodrill machines`, `--machine NAME`). Each
// is the JSON a --machine FILE would hold, so `acodrill machines --show NAME`
// prints a starting point for a profile of one's own; "sources" says where
// every figure comes from.
#include "planning/machine.h"

namespace planning {

const std::vector<MachineClass>& machine_classes() {
  static const std::vector<MachineClass> classes = {
      {"vf2", "HAAS VF-2-class vertical mill: 30 x 16 in table, 8100 rpm, tool changer (the default)",
       R"json({
  "name": "HAAS VF-2 class",
  "dialect": "haas",
  "rapid_xy_mm_min": 25400, "rapid_z_mm_min": 25400, "accel_mm_s2": 2500, "linear_rapids": false,
  "tool_change_s": 4.2, "tool_changer": true, "max_rpm": 8100,
  "x_min_mm": 0, "x_max_mm": 762, "y_min_mm": 0, "y_max_mm": 406,
  "sources": [
    "HAAS VF-2 specifications (haascnc.com): travels 30 x 16 x 20 in, rapids 1000 in/min on X, Y and Z, spindle 8100 rpm, tool change 4.2 s chip to chip (average)",
    "HAAS G00 moves each axis at its own rate (dogleg): HAAS mill operator's manual, G00 rapid motion",
    "accel_mm_s2: our estimate; HAAS publishes no figure"
  ]
})json"},
      {"router", "desktop CNC router on GRBL (Shapeoko 3 class): 425 x 465 mm, 10000 rpm, no tool changer",
       R"json({
  "name": "Desktop router (GRBL, Shapeoko 3 class)",
  "dialect": "grbl",
  "rapid_xy_mm_min": 5000, "rapid_z_mm_min": 5000, "accel_mm_s2": 400, "linear_rapids": true,
  "tool_change_s": 60, "tool_changer": false, "max_rpm": 10000, "spindle_start_s": 3,
  "x_min_mm": 0, "x_max_mm": 425, "y_min_mm": 0, "y_max_mm": 465,
  "sources": [
    "GRBL 1.1h grbl/defaults.h, DEFAULTS_SHAPEOKO_3: max rate 5000 mm/min and acceleration 400 mm/s^2 on X, Y and Z ($110-$112, $120-$122), travel 425 x 465 x 80 mm ($130-$132), spindle max 10000 rpm ($30)",
    "GRBL plans G0 as one straight move at the axes' rates (linear_rapids)",
    "tool_change_s: a manual change at a pause: spindle stops, the operator swaps the bit, zeroes Z on the part and resumes; our estimate of 60 s",
    "spindle_start_s: GRBL does not wait for the spindle to come to speed; 3 s covers a trim router's run-up (our estimate)"
  ]
})json"},
      {"pcb-drill", "PCB drilling machine (production class): 150000 rpm carbide micro drills, 300 hits/min, 610 x 610 mm",
       R"json({
  "name": "PCB drilling machine (production class)",
  "dialect": "haas",
  "rapid_xy_mm_min": 40000, "rapid_z_mm_min": 20000, "accel_mm_s2": 5000, "linear_rapids": true,
  "tool_change_s": 8, "tool_changer": true, "max_rpm": 150000, "hit_s": 0.2, "drills": "carbide",
  "x_min_mm": 0, "x_max_mm": 610, "y_min_mm": 0, "y_max_mm": 610,
  "sources": [
    "A class, not one model: production PCB drilling machines run spindles of 60000-250000 rpm, hit hundreds of holes a minute and move fast light axes (issue 25); we take the middle: 150000 rpm, 300 hits/min (hit_s 0.2), 40 m/min rapids at 0.5 g, an automatic change from the drill rack in 8 s, and a 24 x 24 in table for production panels",
    "No maker's data sheet was reachable from where this profile was written: every figure is our estimate of the class; print this profile (acodrill machines --show pcb-drill), put in your machine's figures and plan with --machine FILE",
    "drills: solid carbide micro drills; feeds per revolution from drill makers' PCB drilling charts (generate_tool_table)"
  ]
})json"},
      {"pcb-proto", "PCB prototyping mill (LPKF ProtoMat S64 class): 60000 rpm, 120 hits/min, 229 x 305 mm",
       R"json({
  "name": "PCB prototyping mill (LPKF ProtoMat S64 class)",
  "dialect": "haas",
  "rapid_xy_mm_min": 9000, "rapid_z_mm_min": 9000, "accel_mm_s2": 1000, "linear_rapids": true,
  "tool_change_s": 10, "tool_changer": true, "max_rpm": 60000, "hit_s": 0.5, "drills": "carbide",
  "x_min_mm": 0, "x_max_mm": 229, "y_min_mm": 0, "y_max_mm": 305,
  "sources": [
    "LPKF ProtoMat S64 product data (lpkf.com) as we know it: spindle up to 60000 rpm, drilling speed 120 holes/min (hit_s 0.5), travel speed up to 150 mm/s, working area 229 x 305 mm, automatic tool change with 15 positions; not checked against the data sheet from here",
    "accel_mm_s2 and tool_change_s: our estimates; the maker publishes neither",
    "drills: solid carbide micro drills; feeds per revolution from drill makers' PCB drilling charts (generate_tool_table)"
  ]
})json"},
  };
  return classes;
}

}  // namespace planning
