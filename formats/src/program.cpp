// Another CAM's drilling program as a hole source: the reader is gcode's
// (the one verify uses); here its holes become a hole set, one layer a tool.
#include <memory>

#include "formats/error.h"
#include "formats/readers.h"

namespace formats {

aco::HoleSet program_holes(const gcode::DrillingProgram& program) {
  aco::HoleSet holes;
  for (const gcode::ToolRun& run : program.runs) {
    for (const gcode::ProgramHole& h : run.holes) {
      aco::Hole hole;
      hole.center = h.at;
      hole.diameter = run.diameter_mm.value_or(0.0);
      // A second fixture's holes are other holes at the same X, Y (issue 83): its offset names them apart.
      hole.layer = "T" + std::to_string(run.tool) + (run.work_offset == 54 ? "" : " " + gcode::work_offset_text(run.work_offset));
      hole.source_line = h.line;
      holes.push_back(std::move(hole));
    }
  }
  return holes;
}

LoadedHoles parse_program(const std::string& path, std::string_view data, bool keep_milling) {
  LoadedHoles out;
  out.format = InputFormat::Program;
  try {
    out.program = std::make_shared<const gcode::DrillingProgram>(gcode::read_drilling(data, {true, keep_milling}));
  } catch (const gcode::ProgramError& e) {
    throw InputError(path, e.line(), e.what());
  }
  out.metric = !out.program->inch;
  for (const gcode::DrillingProgram::Note& n : out.program->notes) out.warnings.push_back({n.line, n.message});
  out.holes = program_holes(*out.program);
  return out;
}

}  // namespace formats
