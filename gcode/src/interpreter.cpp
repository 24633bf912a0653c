// verify's view of a program: every hole the drilling reader finds (canned or
// expanded), read leniently — milling moves are counted, not refused.
#include "gcode/interpreter.h"

#include "gcode/drilling.h"

namespace gcode {

DrilledHole drilled_hole(const ToolRun& run, const ProgramHole& h) {
  DrilledHole d{run.tool, h.at.x, h.at.y, h.cycle.bottom_mm(), h.line, h.milled_radius_mm.value_or(0.0), run.work_offset, {}, {}, {}};
  d.dwell_s = h.cycle.dwell_s();
  d.pitch_mm = h.cycle.tap_pitch_mm(run.spindle_rpm);
  if (h.cycle.code == 83 || h.cycle.code == 73) d.peck_mm = h.cycle.q_mm;
  return d;
}

namespace {

Interpretation interpretation_of(const DrillingProgram& p) {
  Interpretation out;
  for (const ToolRun& run : p.runs) {
    for (const ProgramHole& h : run.holes) out.holes.push_back(drilled_hole(run, h));
  }
  out.rapid_xy_mm = p.rapid_xy_mm;
  out.tool_diameter_mm = p.tool_diameter_mm;
  out.inch = p.inch;
  out.tool_changes = p.tool_changes;
  return out;
}

}  // namespace

Interpretation interpret(std::string_view program) {
  ReadOptions lenient;
  lenient.drilling_only = false;
  return interpretation_of(read_drilling(program, lenient));
}

Interpretation interpret_keeping_milling(std::string_view program) {
  ReadOptions keeping;
  keeping.keep_milling = true;
  return interpretation_of(read_drilling(program, keeping));
}

}  // namespace gcode
