#pragma once
// The check behind `acodrill verify --holes`: every input hole drilled
// exactly once, at its place, with a tool of its diameter.
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "gcode/drilling.h"
#include "gcode/interpreter.h"
#include "planning/operations.h"
#include "planning/owned_tools.h"
#include "planning/tools.h"

namespace job {

// One line per fault, in a stable order; empty when the program is right.
// Positions match within the program's printed precision; where the program
// names its tools' diameters ("(T1 D=...)"), concentric holes are told apart
// by them and a hole drilled with a tool of another diameter is a fault.
// With the tools the user owns (`tooling`, as plan was given them), a hole
// may be drilled by an owned drill that fits it, and one milled by a helix
// counts as a hole of 2r + the end mill's diameter (within 0.01 mm) at the
// helix's centre.
// Hole features (issue 82): a hole whose aco::Hole::operation is k > 0 is
// made by operations[k - 1] at its hole's place, with a tool of its
// diameter (a tap at its thread's pitch, within 1 %, where the program
// says: G33.1's K, G84's F over S); the operations at one place come in
// their order (spot, drill, ream, countersink or counterbore, tap).
std::vector<std::string> check_drilled(const gcode::Interpretation& run, const aco::HoleSet& expected,
                                       const planning::Tooling& tooling = {},
                                       const std::vector<planning::OperationSpec>& operations = {});
// Within this of the designed diameter, a milled hole is made to size.
constexpr double kMilledToleranceMm = 0.01;

// The same check against another drilling program (issue 14: `verify
// better.nc --holes PROGRAM.nc`): every hole it drills is drilled as often,
// at its place, with the same tool number and to the same depth.
std::vector<std::string> check_same_holes(const gcode::Interpretation& run, const gcode::DrillingProgram& expected);

// plan's check of its own program before the program is written (issue
// 72): the text read back as verify reads it must drill exactly the holes
// plan read (`expected`, where the program puts them), each once, with a
// tool that makes it; or, for another CAM's program reordered, exactly the
// input program's holes with their tools and depths. Returns the faults
// (empty: the program may be written).
// A tool table's tools make the holes in their [min, max] range, as plan chose them.
planning::Tooling tooling_of_table(const planning::ToolTable& table);
std::vector<std::string> self_check(const std::string& program_text, const aco::HoleSet& expected,
                                    const planning::Tooling& tooling,
                                    const std::vector<planning::OperationSpec>& operations = {});
std::vector<std::string> self_check(const std::string& program_text, const gcode::DrillingProgram& input);

}  // namespace job
