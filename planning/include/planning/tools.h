#pragma once
/**
 * The drills of a job: a tool table given (--tools) or generated, one tool per
 * diameter, with feeds and speeds for the material and the machine.
 */
#include <optional>
#include <string>
#include <vector>

#include "aco/hole_set.h"
#include "gcode/program.h"
#include "planning/machine.h"

namespace planning {

// Cutting data presets for generated tool tables.
enum class Material { Steel, Aluminium, Pcb };
std::optional<Material> material_from_string(const std::string& name);
const char* to_string(Material m);

struct ToolTableEntry {
  gcode::Tool tool;
  double min_hole_mm = 0.0;   // holes in [min, max] are drilled with this tool
  double max_hole_mm = 0.0;
  int source = -1;            // only the holes of this input (PlanOptions::hole_source); -1: any
};

struct ToolTable {
  std::vector<ToolTableEntry> entries;  // drilling order
  bool generated = false;
};

// A tool table (--tools) from its JSON text; `source` names it in errors.
ToolTable parse_tool_table(const std::string& json_text, const std::string& source);
// One tool per distinct diameter (to 0.001 mm), ascending, feeds and speeds
// from the material and the machine: HSS twist drills (pecked where deep), or
// carbide micro drills — on a machine whose profile says "carbide", and on a
// board (Material::Pcb) when the profile names no drill kind — in single
// strokes at the carbide's speed and feed per revolution; spindle speeds
// within the machine's.
ToolTable generate_tool_table(const aco::HoleSet& holes, Material material, double thickness_mm, const Machine& machine);

// Where feeds begin above the part: the machine's r_plane_mm, else 1 mm over
// a board (a PCB drill starts its stroke close: every millimetre above the
// board is fed through air) and 2.5 mm (0.1 in, the mill standard) over a plate.
double r_plane_mm(const Machine& machine, Material material);

// The life of a carbide micro drill in FR-4 by diameter, in hits (drill
// makers' figures for one 1.6 mm board per stack: the smallest wear first).
int default_max_hits(double diameter_mm);

}  // namespace planning
