// Issue 14: another CAM's drilling program, reordered within each tool run;
// its coordinates, tools, cycles and depths stay exactly as they are.
#include <algorithm>
#include <sstream>

#include "gcode/drilling.h"
#include "job/verify.h"
#include "pipeline.h"
#include "planning/reorder.h"

namespace job {

using UserError = formats::InputError;

void PlanJob::Impl::prepare_program() {
  const formats::LoadedHoles& loaded = r.inputs.holes;
  const gcode::DrillingProgram& input = *loaded.program;
  // What only makes sense for hole files.
  if (!s.input.layers.empty() || s.input.min_diameter_mm || s.input.max_diameter_mm) {
    throw UserError("--layer, --min-diameter and --max-diameter select holes of hole files; a program is reordered whole");
  }
  if (!s.origin.empty() && s.origin != "drawing") {
    throw UserError("--origin: a program's coordinates stay as they are (the machinist set the work offset for them)");
  }
  for (const auto& [given, name] :
       {std::pair{s.tools.has_value(), "--tools"}, {s.resume_from != 1, "--resume-from"}, {!s.material.empty(), "--material"},
        {s.thickness_mm.has_value(), "--thickness"}, {s.default_diameter_mm.has_value(), "--default-diameter"},
        {!s.panel.empty() || s.panel_file.has_value(), "--panel"}, {!s.bench.drills.empty(), "--drills"},
        {s.bench.end_mill_mm.has_value(), "--end-mill"}, {s.bench.side != "front", "--side"},
        {s.bench.alignment_pins_mm.has_value(), "--alignment-pins"}}) {
    if (given) throw UserError(std::string(name) + " does not apply to a program: its tools, cycles and depths are kept");
  }
  if (input.hole_count() == 0) {
    // Say why: reading may have stopped early, at an end with more code after it.
    if (input.code_lines_after_end > 0) {
      throw UserError(source, input.end_line, "no holes to drill before the program ends here (" + input.end_reason + "); " +
                                                  std::to_string(input.code_lines_after_end) +
                                                  " line(s) of code after it are not read");
    }
    throw UserError(source, 0, "no holes to drill: the program has no drilling move (no canned cycle, no feed down in Z)");
  }
  if (s.input.keep_milling && !keeps_style()) {
    throw UserError("--keep-milling writes the program in its own style, its milling as written: drop --dialect and --units");
  }
  const bool inch = s.units.empty() ? input.inch : o.program.units == gcode::Units::Inch;
  if (keeps_style() && inch != input.inch) {
    throw UserError("--keep-style keeps the input's units (" + std::string(input.inch ? "inch" : "mm") + "); drop --units");
  }
  if (inch != input.inch) {
    for (const gcode::ToolRun& run : input.runs) {
      for (const gcode::ProgramHole& h : run.holes) {
        if (!h.cycle.extra.empty()) {
          throw UserError(source, h.line, "cycle words \"" + h.cycle.extra + "\" stay in the input's units; drop --units");
        }
      }
    }
  }
  planning::check_travel(loaded.holes, o.machine, source);  // before the colony's work, not after
}

void PlanJob::Impl::reorder_and_write() {
  const formats::LoadedHoles& loaded = r.inputs.holes;
  const gcode::DrillingProgram& input = *loaded.program;
  const bool inch = s.units.empty() ? input.inch : o.program.units == gcode::Units::Inch;
  planning::ReorderOptions ro;
  ro.min_spacing_mm = s.min_spacing_mm;
  planning::ReorderResult reordered = planning::reorder_program(input, o, ro);

  const std::string source_name = formats::file_name(source);
  gcode::DrillingWriteSettings ws;
  ws.dialect = o.program.dialect;
  ws.inch = inch;
  ws.decimals = std::clamp(input.decimals + (inch == input.inch ? 0 : inch ? 1 : -1), inch ? 4 : 3, 6);
  ws.program_number = s.program_number;
  ws.program_name = loaded.name;
  ws.keep_style = keeps_style();
  ws.spindle_start_s = o.program.spindle_start_s;
  ws.travel_feed_mm_min = o.program.travel_feed_mm_min;
  ws.header_comments = {
      "SOURCE: " + source_name + " (A DRILLING PROGRAM, REORDERED)",
      std::to_string(reordered.holes.size()) + " HOLES IN " + std::to_string(reordered.plan.groups.size()) + " TOOL RUNS",
      "TRAVEL " + gcode::format_number(reordered.plan.optimized.travel_mm, 1) + " MM, INPUT " +
          gcode::format_number(reordered.plan.input_order.travel_mm, 1) + " MM",
      "ORDER: ACODRILL " + std::string(aco::to_string(reordered.plan.solver.algorithm)) + " SEED " +
          std::to_string(reordered.plan.solver.seed),
      "COORDINATES, TOOLS, CYCLES AND DEPTHS AS IN THE INPUT"};
  std::ostringstream program;
  try {
    gcode::write_drilling(program, reordered.program, ws);
  } catch (const std::invalid_argument& e) {
    throw UserError(source, 0, e.what());
  } catch (const gcode::ProgramError& e) {
    throw UserError(source, e.line(), e.what());
  }
  std::string text = program.str();
  if (s.break_writer_for_test) text = detail::broken_for_test(std::move(text));
  detail::check_own_program(self_check(text, input), s.program_name);
  r.files.program = std::move(text);
  r.holes = std::move(reordered.holes);
  r.plan = std::move(reordered.plan);
  for (const planning::ToolGroup& g : r.plan.groups) r.stopped = r.stopped || g.solution.stop_reason == "stopped";
  r.placement.origin = planning::Origin{planning::OriginKind::Drawing, {}};
  r.placement.extent = planning::extent_of(r.holes);
  r.program_input = ReportContext::ProgramInput{r.plan.groups.size(), reordered.overlapping_holes,
                                                reordered.overlap_groups, keeps_style() ? "keep" : "dialect",
                                                input.milling_lines.size(),
                                                input.milling_lines.empty() ? 0 : input.milling_lines.front()};
  ReportContext ctx{source, s.program_name, r.placement, loaded.name, &loaded, {}, 1, 1, r.program_input};
  ctx.dialect = o.program.dialect;
  detail::make_outputs(r, s, o, ctx, planning::to_passes(r.holes, r.plan, o.machine));
}

}  // namespace job
