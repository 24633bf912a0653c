#pragma once
/**
 * Hole features into operations (issue 82). A feature's hole is drilled (the
 * hole set's own hole); a tapped hole is then tapped, a counterbore
 * counterbored, a countersink countersunk: each such operation is one more
 * hole of the job's hole set at the same place (aco::Hole::operation), made
 * by a tool of its own, routed by the colony with that tool's other holes.
 * Tools go in the order a hole's operations come (spot, drill, ream,
 * countersink or counterbore, tap), so every hole's are made in order.
 *
 * Defaults, from the standards:
 *  - tap: the thread's pitch, through the part and 3 pitches beyond (a plug
 *    tap's lead) but no deeper than the tap drill's tip; G84 at pitch x rpm;
 *    HSS tapping speeds (8 m/min in steel, 15 in aluminium).
 *  - counterbore: the callout's depth, else ISO 4762 socket head cap screws'
 *    counterbores (DIN 974-1): the head's height (k = d) and 0.4 mm (M3-M6)
 *    or 0.6 mm (M8-M20) for the row whose counterbore diameter the drawing's
 *    is; none, not made (a warning names it). G82, 0.5 s dwell.
 *  - countersink: the callout's angle, else 90 degrees (ISO 10642) in a
 *    metric drawing and 82 (ASME B18.3) in an inch one, its tip as deep as
 *    the drawn diameter needs: (D / 2) / tan(angle / 2). G82, 0.3 s dwell.
 *  - what contradicts (a counterbore or a countersink as deep as the part or
 *    deeper): formats::InputError naming the feature.
 * GRBL and Marlin cannot tap: taps become lines for a last pause (tap by
 * hand); their counterbores are milled by the end mill's helix (--end-mill),
 * and without one the job is refused (formats::InputError).
 */
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "formats/features.h"
#include "formats/holes.h"
#include "formats/processes.h"
#include "gcode/program.h"
#include "planning/machine.h"
#include "planning/tools.h"

namespace planning {

// One operation a tool makes, with what decides the tool: a hole of
// aco::Hole::operation k is made as specs[k - 1].
struct OperationSpec {
  gcode::Operation kind = gcode::Operation::Drill;
  double diameter_mm = 0.0;  // the tool's: the tap's major, the countersink's top, the counterbore's
  double depth_mm = 0.0;     // Z of the tool's tip at the bottom (below 0)
  double pitch_mm = 0.0;     // tap
  double angle_deg = 0.0;    // countersink
  std::string thread;        // tap: "M3"
  bool left_hand = false;    // tap: G74
  double end_mill_mm = 0.0;  // counterbore: > 0, milled by this end mill's helix (GRBL, Marlin)
  // A process table's cutting data and name for the tool (unset: the defaults).
  std::optional<int> rpm;
  std::optional<double> feed_mm_min, dwell_s;
  std::string name;
};

struct OperationSettings {
  Material material = Material::Steel;
  double thickness_mm = 6.35;
  bool can_tap = true;        // the dialect has canned cycles (G84)
  bool can_counterbore = true;  // with a counterbore tool (G82); else with `end_mill_mm`'s helix, or refused
  std::optional<double> end_mill_mm;
  // --spot: every drilled hole is spotted first, with one 90-degree spot
  // drill, to a cone the diameter of the smallest spotted hole (a spot no
  // wider than any of its holes: it centres the drill and leaves no chamfer).
  bool spot = false;
  // --processes: the rules features were matched to (HoleFeature::rule);
  // without features (Excellon, CSV, ...), each hole is matched as plain.
  const formats::ProcessTable* processes = nullptr;
};

struct Operations {
  std::vector<OperationSpec> specs;
  std::vector<std::string> by_hand;      // taps left to the operator, a line each (GRBL, Marlin)
  std::vector<formats::Note> warnings;   // one line a kind
  std::vector<formats::Note> not_made;   // each one the program does not make (header, report, sheet)
};

// Appends each feature's operations to `holes` as operation holes (after
// them, feature by feature), with `hole_source` (when not empty) carried
// along from the feature's hole. A feature is found among `holes` by its
// place and drill; one that is not there (filtered out) makes nothing.
// Throws formats::InputError (file `source`) for a contradiction.
Operations add_operations(aco::HoleSet& holes, std::vector<std::uint32_t>& hole_source,
                          const std::vector<formats::HoleFeature>& features, const OperationSettings& settings,
                          const std::string& source);

// The tool that makes an operation, for the job's material and machine
// (number 1; group_holes numbers them after the drills).
gcode::Tool operation_tool(const OperationSpec& spec, Material material, const Machine& machine);

// Reads a process table (formats/processes.h); what it cannot read is one
// formats::InputError naming `path` and the rule's line.
formats::ProcessTable parse_process_table(const std::string& text, const std::string& path);

// ISO 4762 / DIN 974-1: the depth of the counterbore of that diameter for a
// socket head cap screw, or 0 where the table has none.
double socket_head_counterbore_depth_mm(double counterbore_mm);

}  // namespace planning
