#pragma once
/**
 * The drills of a job: a tool table given (--tools) or generated, one tool per
 * diameter, with feeds and speeds for the material and the machine.
 */
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "aco/hole_set.h"
#include "gcode/program.h"
#include "planning/machine.h"
#include "planning/owned_tools.h"

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
  // Owned tools: exactly the designed diameters this drill or end mill makes
  // (to 0.0005 mm); when given, they decide instead of [min, max].
  std::vector<double> takes_mm;
  // What a tool table gave; the rest comes from a generated tool of the same
  // diameter (complete_tool_table).
  bool has_rpm = true, has_feed = true, has_depth = true, has_cycle = true;
  // Issue 82: the operation holes this tool makes (aco::Hole::operation); 0: drilled holes.
  std::uint32_t operation = 0;
  bool takes(double hole_mm) const;
};

// How a designed diameter is made, for the summary, the report and the setup sheet.
struct DrillMapping {
  double designed_mm = 0.0;
  std::size_t holes = 0;
  int tool = 0;              // its tool number
  double tool_mm = 0.0;      // the drill's or the end mill's diameter
  bool milled = false;       // by a helix (or plunged, when the end mill is its size)
  bool slots = false;        // slots of this width milled along their length (`holes`: how many slots)
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

// The generated tool of one diameter (as generate_tool_table makes it), number 1.
gcode::Tool generated_drill(double diameter_mm, Material material, double thickness_mm, const Machine& machine);
// A generated end mill: carbide, two flutes; speed from the material's
// cutting speed within the machine's spindle, feed per revolution from
// makers' chip loads, through the part and 0.3 mm more (a flat bottom needs
// no point allowance), and a helix of at most half its diameter a turn in a
// board (a quarter in aluminium, a tenth in steel).
gcode::Tool generated_end_mill(double diameter_mm, Material material, double thickness_mm, const Machine& machine);

// The spindle speed that gives a cutting speed (m/min) at a diameter, within
// [min_rpm, the machine's maximum].
int spindle_rpm_for(double vc_m_min, double diameter_mm, int max_rpm, double min_rpm = 100.0);

// The tool table of the tools the user owns: the drills choose_drills picks,
// ascending, then the end mill for what they leave; each takes exactly its
// designed diameters; `mapping` says what went where. Throws
// formats::InputError (file `source`) for a diameter nothing can make.
ToolTable owned_tool_table(const aco::HoleSet& holes, const Tooling& tooling, Material material, double thickness_mm,
                           const Machine& machine, const std::string& source, std::vector<DrillMapping>& mapping);

// Fills what each entry of a tool table leaves out (rpm, feed, depth, cycle)
// from a generated tool of its diameter for this job — never a plate's
// cycle on a board.
void complete_tool_table(ToolTable& table, Material material, double thickness_mm, const Machine& machine);

// Where feeds begin above the part: the machine's r_plane_mm, else 1 mm over
// a board (a PCB drill starts its stroke close: every millimetre above the
// board is fed through air) and 2.5 mm (0.1 in, the mill standard) over a plate.
double r_plane_mm(const Machine& machine, Material material);

// The life of a carbide micro drill in FR-4 by diameter, in hits (drill
// makers' figures for one 1.6 mm board per stack: the smallest wear first).
int default_max_hits(double diameter_mm);

}  // namespace planning
