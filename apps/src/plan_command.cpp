// `acodrill plan`: the files read, the job called (job/plan.h), every
// output written atomically, the summary printed.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "aco/error.h"
#include "aco/hole_set.h"
#include "app/errors.h"
#include "app/files.h"
#include "commands.h"
#include "job/plan.h"

namespace cli {

namespace {

// The summary on stderr: the inputs, the tools, travel and time of each order, where the files went.
void print_summary(const PlanArgs& a, const job::Result& r) {
  const planning::PlanResult& plan = r.plan;
  const std::size_t n_tools = plan.groups.size();
  if (r.program_input) {
    print_warnings(r.inputs.holes, a.inputs.front(), a.quiet);
  } else {
    for (std::size_t k = 0; k < r.inputs.parts.size(); ++k) {
      print_warnings(r.inputs.parts[k], r.inputs.sources[k].file, a.quiet, "NOT MADE", r.inputs.sources[k].holes);
    }
    if (r.inputs.parts.size() > 1 && r.inputs.holes.duplicates_removed) {
      std::fprintf(stderr, "acodrill: %zu hole(s) in more than one input drilled once\n", r.inputs.holes.duplicates_removed);
    }
    // What the job makes of the hole features, and what it cannot (issue 82).
    for (const formats::Note& n : r.inputs.holes.feature_warnings) std::fprintf(stderr, "acodrill: warning: %s\n", n.message.c_str());
  }
  const auto& in = plan.input_order;
  const auto& nn = plan.nearest_neighbor;
  const auto& op = plan.optimized;
  auto pct = [](double before, double after) {
    return before > 0 ? gcode::format_number(100.0 * (before - after) / before, 1) + " %" : std::string("-");
  };
  const auto operations = aco::count_operations(r.holes);
  const std::string made = operations == 0 ? "" : " and " + std::to_string(operations) + " operation" + (operations == 1 ? "" : "s") + " at them";
  std::fprintf(stderr, "acodrill: %zu holes%s, %zu tool%s, %d iterations in %.2f s on %d thread%s%s\n", r.holes.size() - operations, made.c_str(), n_tools,
               n_tools == 1 ? "" : "s", plan.iterations, plan.solver_wall_s, plan.solver.threads,
               plan.solver.threads == 1 ? "" : "s", r.stopped ? " (stopped: the best routes so far)" : "");
  if (!plan.drill_map.empty()) {
    std::fprintf(stderr, "  the tools you own:\n");
    for (const planning::DrillMapping& d : plan.drill_map) {
      std::string l = job::drill_map_line(d);
      for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      std::fprintf(stderr, "    %s\n", l.c_str());
    }
  }
  const char* input_label = r.program_input ? "input program" : "input order";
  std::fprintf(stderr, "  %-18s %12s %12s\n", "order", "travel mm", "time min");
  std::fprintf(stderr, "  %-18s %12.1f %12.2f\n", input_label, in.travel_mm, in.time_s / 60);
  std::fprintf(stderr, "  %-18s %12.1f %12.2f\n", "nearest neighbour", nn.travel_mm, nn.time_s / 60);
  std::fprintf(stderr, "  %-18s %12.1f %12.2f\n", "optimized", op.travel_mm, op.time_s / 60);
  // Where the time goes: the route changes only the moves.
  std::fprintf(stderr, "  %-18s %12s %12s %12s %12s\n", "time split min", "moves", "drilling", "tool changes", "pauses");
  for (const auto& [label, st] : {std::pair{input_label, &in}, {"optimized", &op}}) {
    std::fprintf(stderr, "  %-18s %12.2f %12.2f %12.2f %12.2f\n", label, st->split.moves_s / 60, st->split.drilling_s / 60,
                 st->split.tool_changes_s / 60, st->split.pauses_s / 60);
  }
  if (r.program_input && r.program_input->overlapping_holes) {
    std::fprintf(stderr, "  %zu overlapping holes (%zu groups) drilled together in their input order\n",
                 r.program_input->overlapping_holes, r.program_input->overlap_groups);
  }
  std::fprintf(stderr, "  saved vs input order: %s travel, %s time; vs nearest neighbour: %s travel\n",
               pct(in.travel_mm, op.travel_mm).c_str(), pct(in.time_s, op.time_s).c_str(), pct(nn.travel_mm, op.travel_mm).c_str());
  for (const auto& [label, path] : {std::pair{"program", a.output == "-" ? std::string() : a.output}, {"report", a.report},
                                    {"convergence", a.convergence}, {"excellon", a.excellon}, {"gerber", a.gerber},
                                    {"picture", a.svg}, {"comparison", a.svg_compare}, {"setup sheet", a.setup_sheet}}) {
    if (!path.empty()) std::fprintf(stderr, "  %s: %s\n", label, path.c_str());
  }
  const planning::Placement& placement = r.placement;
  const planning::Extent& e = placement.extent;
  auto f3 = [](double v) { return gcode::format_number(v, 3); };
  if (r.program_input) {
    std::fprintf(stderr, "  coordinates as in the input program (its work offset); holes X%s..%s Y%s..%s mm\n",
                 f3(e.x_min).c_str(), f3(e.x_max).c_str(), f3(e.y_min).c_str(), f3(e.y_max).c_str());
    if (r.program_input->milling_lines) {
      std::fprintf(stderr, "  %zu line(s) of milling from line %u kept as written and where they were; the drilling between them reordered (times are the drilling's)\n",
                   r.program_input->milling_lines, static_cast<unsigned>(r.program_input->first_milling_line));
    }
    if (r.program_input->style == "keep") {
      std::fprintf(stderr, "  written in the input program's own style (--keep-style; --dialect NAME writes another)\n");
    } else {
      std::fprintf(stderr, "  written for %s (--dialect)\n", gcode::to_string(r.dialect));
    }
    return;
  }
  std::fprintf(stderr, "  program zero: %s (drawing X%s Y%s mm); holes X%s..%s Y%s..%s mm\n",
               planning::describe(placement.origin).c_str(), f3(placement.zero.x).c_str(), f3(placement.zero.y).c_str(),
               f3(e.x_min).c_str(), f3(e.x_max).c_str(), f3(e.y_min).c_str(), f3(e.y_max).c_str());
}

// What the user sees while the colony works: a line on a terminal, or
// LinuxCNC AXIS's FILTER_PROGRESS=N lines from its filter program.
job::ProgressFn progress_printer(const PlanArgs& a) {
  if (a.filter_progress) {
    const double limit = a.settings.solver.time_limit_s;
    auto last = std::make_shared<int>(-1);
    return [limit, last](const job::Progress& p) {
      const double tool_share = p.iterations > 0 ? static_cast<double>(p.iteration) / p.iterations : 0.0;
      const double done = limit > 0 ? seconds_since_start() / limit
                                     : (static_cast<double>(p.tool) + std::min(1.0, tool_share)) / std::max<std::size_t>(1, p.tools);
      const int percent = std::clamp(static_cast<int>(100.0 * done), 0, 99);
      if (percent <= *last) return;
      *last = percent;
      std::fprintf(stderr, "FILTER_PROGRESS=%d\n", percent);
      std::fflush(stderr);
    };
  }
  if (a.quiet || !::isatty(STDERR_FILENO)) return {};
  return [](const job::Progress& p) {
    if (p.elapsed_s < 1.0) return;
    std::fprintf(stderr, "\racodrill: tool %zu of %zu, iteration %d, %.1f s, best %.3f mm   ", p.tool + 1, p.tools, p.iteration,
                 p.elapsed_s, p.best_length);
  };
}

}  // namespace

int cmd_plan(PlanArgs& a, const InputArgs& in) {
  // Refuse, before doing any work, an output that can never be written (a
  // directory) or that would overwrite an input.
  for (const std::string* out : {&a.output, &a.report, &a.svg, &a.svg_compare, &a.convergence, &a.excellon, &a.gerber, &a.setup_sheet}) {
    app::check_output_path(*out);
    for (const std::string& input : a.inputs) {
      if (!out->empty() && app::same_file(input, *out)) throw app::UserError(*out, 0, "output would overwrite the input file " + input);
    }
  }
  job::PlanSettings& s = a.settings;
  if (!a.machine.empty()) resolve_machine(a.machine, s.machine, s.machine_profile);
  if (!a.tools.empty()) s.tools = job::NamedText{a.tools, app::read_file(a.tools)};
  resolve_panel(a.panel, s.panel, s.panel_file);
  s.input = read_input_settings(in);
  s.program_name = a.output;
  s.wanted = {!a.report.empty(), !a.svg.empty(), !a.svg_compare.empty(), !a.setup_sheet.empty(),
              !a.excellon.empty(), !a.gerber.empty(), !a.convergence.empty()};
  // A test hook, and only that: see job::PlanSettings::break_writer_for_test.
  const char* hook = std::getenv("ACODRILL_TEST_BREAK_WRITER");
  s.break_writer_for_test = hook != nullptr && std::string(hook) == "1";
  std::vector<job::InputFile> files;
  for (const std::string& path : a.inputs) files.push_back(app::read_input_file(path));
  job::ProgressFn progress = progress_printer(a);  // AXIS's percentages count the whole run's limit
  // The job's own clock starts now: what reading the files took comes off the limit.
  s.solver.time_limit_s = app::time_left(s.solver.time_limit_s, seconds_since_start());
  const bool line = progress && !a.filter_progress;
  job::Result r = job::plan(std::move(files), s, progress);
  if (line) std::fprintf(stderr, "\r%60s\r", "");
  if (r.exit_code != 0) {
    std::fprintf(stderr, "acodrill: error: %s\n", r.error.c_str());
    return r.exit_code;
  }
  // Everything is computed; now write, each file complete or not at all.
  app::write_file_atomic(a.output, r.files.program);
  for (const auto& [path, text] : {std::pair{&a.report, &r.files.report}, {&a.convergence, &r.files.convergence},
                                   {&a.svg, &r.files.route_svg}, {&a.svg_compare, &r.files.compare_svg},
                                   {&a.setup_sheet, &r.files.setup_sheet}, {&a.excellon, &r.files.excellon},
                                   {&a.gerber, &r.files.gerber}}) {
    if (!path->empty()) app::write_file_atomic(*path, *text);
  }
  if (!a.quiet) print_summary(a, r);
  return 0;
}

}  // namespace cli
