// The job (issue 64): settings checked, inputs parsed, the holes turned,
// placed and tooled, each tool routed by the colony (in slices when the
// front end asks), the program written and read back, and the outputs made,
// all in memory. What a G-code program input takes instead is in
// program_job.cpp.
#include "job/plan.h"

#include <chrono>
#include <cmath>
#include <map>
#include <new>
#include <sstream>

#include "aco/error.h"
#include "aco/hole_set.h"
#include "formats/error.h"
#include "formats/writers.h"
#include "gcode/program.h"
#include "job/setup_sheet.h"
#include "job/svg.h"
#include "job/verify.h"
#include "pipeline.h"

namespace job {

using UserError = formats::InputError;

std::string drill_map_line(const planning::DrillMapping& d) {
  std::string line = "D" + gcode::format_number(d.designed_mm, 3) + " MM, " + std::to_string(d.holes) +
                     (d.holes == 1 ? " HOLE: T" : " HOLES: T") + std::to_string(d.tool) + " ";
  if (d.milled) return line + gcode::format_number(d.tool_mm, 3) + " MM END MILL, MILLED TO SIZE";
  const double over = d.tool_mm - d.designed_mm;
  return line + gcode::format_number(d.tool_mm, 3) + " MM DRILL, " +
         (std::fabs(over) < 0.0005 ? std::string("EXACT") : (over > 0 ? "+" : "") + gcode::format_number(over, 3) + " MM");
}

namespace detail {

void check_own_program(const std::vector<std::string>& faults, const std::string& program_name) {
  if (faults.empty()) return;
  throw aco::InternalError("the program for " + (program_name == "-" ? std::string("<stdout>") : program_name) +
                           " fails acodrill's own check (" + std::to_string(faults.size()) + " fault" +
                           (faults.size() == 1 ? "" : "s") + ", first: " + faults.front() +
                           "); nothing was written. This is a fault in acodrill, not in the input: please report it");
}

std::string broken_for_test(std::string text) {
  std::size_t end = text.size();
  while (end > 0) {
    const std::size_t start = text.rfind('\n', end - 1) == std::string::npos ? 0 : text.rfind('\n', end - 1) + 1;
    std::size_t code = start;
    if (code < end && text[code] == 'N') {
      code = text.find(' ', code);
      code = code == std::string::npos || code > end ? end : code + 1;
    }
    if (code < end && text[code] == 'X') {
      text.erase(start, text.find('\n', start) - start + 1);
      break;
    }
    end = start == 0 ? 0 : start - 1;
  }
  return text;
}

void make_outputs(Result& r, const PlanSettings& s, const planning::PlanOptions& o, const ReportContext& ctx,
                  const std::vector<gcode::ToolPass>& passes) {
  const Wanted& w = s.wanted;
  const planning::Placement& placement = ctx.placement;
  const std::string source_name = formats::file_name(ctx.source);
  // A drill file written back stays in the input's coordinates, registered
  // with the board's other layers, wherever program zero is.
  auto in_input_coordinates = [&] {
    std::vector<gcode::ToolPass> out = passes;
    for (gcode::ToolPass& p : out) {
      for (aco::Point2& h : p.holes) h = {h.x + placement.zero.x, h.y + placement.zero.y};
    }
    return out;
  };
  if (w.report) r.files.report = report_json(r.holes, r.plan, ctx);
  if (w.convergence) r.files.convergence = convergence_csv(r.plan);
  if (w.route_svg) r.files.route_svg = route_svg(r.holes, r.plan, o, placement, ctx.name);
  if (w.compare_svg) r.files.compare_svg = compare_svg(r.holes, r.plan, o, placement, ctx.name);
  if (w.setup_sheet) r.files.setup_sheet = setup_sheet_html(r.holes, r.plan, o, ctx, r.files.route_svg);
  if (w.excellon) {
    // The input's own units when it is Excellon, unless --units chose others.
    const bool metric = s.units.empty() ? ctx.input->metric.value_or(true) : o.program.units == gcode::Units::Mm;
    r.files.excellon = formats::write_excellon(in_input_coordinates(), metric, source_name);
  }
  if (w.gerber) r.files.gerber = formats::write_gerber(in_input_coordinates(), source_name, ctx.input->drill_function);
}

}  // namespace detail

namespace {

std::string format_minutes(double seconds) { return gcode::format_number(seconds / 60.0, 2) + " min"; }

// The holes a program resumed at hole `resume_from` makes: all of them,
// less those its passes leave out (matched by place and pass).
aco::HoleSet holes_written(const aco::HoleSet& holes, const std::vector<gcode::ToolPass>& passes, std::size_t resume_from) {
  if (resume_from <= 1) return holes;
  std::map<std::pair<long long, long long>, std::size_t> left_out;  // place (µm) -> holes there not made
  auto key = [](aco::Point2 p) { return std::make_pair(std::llround(p.x * 1000.0), std::llround(p.y * 1000.0)); };
  for (const gcode::ToolPass& p : passes) {
    const std::size_t first = gcode::first_written(p, resume_from);
    for (std::size_t i = 0; i < first; ++i) ++left_out[key(p.holes[i])];
  }
  aco::HoleSet out;
  for (const aco::Hole& h : holes) {
    auto it = left_out.find(key(h.center));
    if (it != left_out.end() && it->second > 0) {
      --it->second;
      continue;
    }
    out.push_back(h);
  }
  return out;
}

}  // namespace

void PlanJob::Impl::prepare(std::vector<InputFile> files) {
  if (files.empty()) throw UserError("no input to plan");
  o.solver = solver_params(s.solver);
  origin = parse_origin(s.origin.empty() ? "lower-left" : s.origin);
  std::optional<gcode::Dialect> dialect;
  if (!s.dialect.empty()) {
    dialect = gcode::dialect_from_string(s.dialect);
    if (!dialect) throw UserError("--dialect must be haas, fanuc, linuxcnc, grbl or marlin (got \"" + s.dialect + "\")");
  }
  // The machine decides the dialect unless one is given; a GRBL or Marlin
  // program without a --machine is for the desktop router those controls drive.
  const std::string machine = !s.machine.empty() ? s.machine
                              : dialect && !gcode::has_canned_cycles(*dialect) ? "router"
                                                                               : "vf2";
  o.machine = machine_of(machine, s.machine_profile);
  o.program.dialect = dialect.value_or(o.machine.dialect);
  o.program.spindle_start_s = o.machine.spindle_start_s;
  o.program.travel_feed_mm_min = o.machine.rapid_xy_mm_min;
  if (s.units.empty() || s.units == "mm") o.program.units = gcode::Units::Mm;
  else if (s.units == "inch" || s.units == "in") o.program.units = gcode::Units::Inch;
  else throw UserError("--units must be mm or inch (got \"" + s.units + "\")");
  if (!s.material.empty()) {
    auto material = planning::material_from_string(s.material);
    if (!material) throw UserError("--material must be steel, aluminium or pcb (got \"" + s.material + "\")");
    o.material = *material;
  }
  if (s.thickness_mm && !(*s.thickness_mm > 0 && *s.thickness_mm < 1000)) throw UserError("--thickness must be in (0, 1000) mm");
  if (s.objective == "distance") o.objective = planning::Objective::Distance;
  else if (s.objective == "time") o.objective = planning::Objective::Time;
  else throw UserError("--objective must be distance or time (got \"" + s.objective + "\")");
  if (s.tools) o.tools = planning::parse_tool_table(s.tools->text, s.tools->name);
  // The tools on the bench; a tool table names its own instead.
  if (s.tools && (!s.bench.drills.empty() || s.bench.end_mill_mm)) {
    throw UserError("--drills and --end-mill plan the tools you own; a --tools table names its own: drop one of them");
  }
  if (!s.tools) o.tooling = tooling_of(s.bench, o.machine);
  parse_mirror_axis(s.bench);
  o.program.probe_plate_mm = s.probe_plate_mm ? s.probe_plate_mm : o.machine.probe_plate_mm;
  o.program.probe_feed_mm_min = o.machine.probe_feed_mm_min;
  o.program.probe_travel_mm = o.machine.probe_travel_mm;
  // Refused before any work, not when the program is written.
  if (o.program.probe_plate_mm) {
    if (auto refusal = gcode::probe_plate_refusal(o.program.dialect)) throw UserError(*refusal);
  }
  for (const InputFile& f : files) source += (source.empty() ? "" : " + ") + (f.name == "-" ? std::string("<stdin>") : f.name);
  const formats::InputOptions in_options = input_options(s.input);
  processes = in_options.processes;
  r.inputs = read_inputs(files, in_options);
  files.clear();
  o.solver.time_limit_s = time_left(o.solver.time_limit_s, seconds());
  o.solver.stop = stop_flag;
  if (on_progress) o.solver.on_iteration = [this](const aco::Progress& p) { report(p); };
  r.dialect = o.program.dialect;
  if (r.inputs.holes.program) {
    prepare_program();
    return;
  }
  prepare_holes();
}

void PlanJob::Impl::prepare_holes() {
  formats::LoadedHoles& loaded = r.inputs.holes;
  if (s.keep_style || s.min_spacing_mm > 0) {
    throw UserError("--keep-style and --min-spacing apply to a drilling program input (G-code)");
  }
  if (s.input.keep_milling) throw UserError("--keep-milling applies to a drilling program input (G-code) that also mills");
  const std::string first_input = r.inputs.sources.front().file == "-" ? "<stdin>" : r.inputs.sources.front().file;
  o.hole_source = r.inputs.hole_source;
  o.keep_sources_apart = s.keep_files_apart;
  // PCB drill data is a circuit board unless the user says otherwise: PCB
  // feeds and speeds through a 1.6 mm board, not a quarter inch of steel.
  const bool board = std::any_of(r.inputs.parts.begin(), r.inputs.parts.end(), [](const formats::LoadedHoles& p) {
    return p.format == formats::InputFormat::Excellon || p.format == formats::InputFormat::Gerber ||
           p.format == formats::InputFormat::Ipc2581 || p.format == formats::InputFormat::Odb;
  });
  if (s.material.empty() && board) o.material = planning::Material::Pcb;
  o.thickness_mm = s.thickness_mm.value_or(o.material == planning::Material::Pcb ? 1.6 : 6.35);
  o.program.r_plane_mm = planning::r_plane_mm(o.machine, o.material);
  if (loaded.holes.empty() && loaded.round_contours > 0) {
    throw UserError(first_input, 0,
                    "no CIRCLE to drill, but " + std::to_string(loaded.round_contours) +
                        " round closed contour(s) drawn without one (" + loaded.round_contour_kinds +
                        "): --round-contours reads them as holes");
  }
  if (loaded.holes.empty()) throw UserError(first_input, 0, "no holes to drill");
  // Issue 82: each hole feature's operations (taps, counterbores,
  // countersinks), holes of their own made by tools of their own.
  const bool canned = gcode::has_canned_cycles(o.program.dialect);
  planning::OperationSettings op_settings;
  op_settings.material = o.material;
  op_settings.thickness_mm = o.thickness_mm;
  op_settings.can_tap = op_settings.can_counterbore = canned;
  op_settings.spot = s.spot || o.machine.spot;
  op_settings.processes = processes.get();
  op_settings.end_mill_mm = o.tooling.end_mill_mm;
  planning::Operations ops = planning::add_operations(loaded.holes, o.hole_source, loaded.features, op_settings, first_input);
  o.operations = std::move(ops.specs);
  loaded.feature_warnings.insert(loaded.feature_warnings.end(), ops.warnings.begin(), ops.warnings.end());
  loaded.skipped.insert(loaded.skipped.end(), ops.not_made.begin(), ops.not_made.end());
  o.program.final_pause = std::move(ops.by_hand);
  // A panel: every copy of the board, in drawing coordinates, before program zero is chosen on the whole.
  if (!s.panel.empty() || s.panel_file || !s.pitch.empty()) {
    const std::vector<planning::PanelCopy> placements = panel_copies(s.panel, s.pitch, s.panel_file);
    r.panel_copies = placements.size();
    if (loaded.holes.size() * r.panel_copies > s.input.max_holes) {
      throw UserError("--panel: " + std::to_string(r.panel_copies) + " copies of " + std::to_string(loaded.holes.size()) +
                      " holes exceed " + std::to_string(s.input.max_holes) + " holes (" + s.input.max_holes_named + ")");
    }
    loaded.holes = planning::panelize(loaded.holes, placements, o.hole_source);
  }
  // Program zero where the machinist will set the work offset.
  if (s.default_diameter_mm) planning::fill_missing_diameters(loaded.holes, *s.default_diameter_mm);
  o.first_holes = turn_and_place(loaded.holes, s.bench, &origin, &r.placement, &side_notes);
  if (!o.hole_source.empty()) o.hole_source.resize(loaded.holes.size(), 0);
  r.holes = std::move(loaded.holes);
  loaded.holes.clear();
  r.plan = planning::group_holes(r.holes, o, source);
  router = std::make_unique<planning::GroupRouter>(r.holes, r.plan, o);
  if (s.solver.time_limit_covers_outputs && o.solver.time_limit_s > 0) budget_routing();
}

void PlanJob::Impl::budget_routing() {
  // What the work around the colony costs is measured, not guessed: the
  // input order's program written and timed (needed anyway) is one unit,
  // on this machine and for these holes. What comes after the routing is
  // about seven such units (the plan's own program timed, written, read back
  // and checked, the picture, the setup sheet, the drill files, and the
  // page copying and showing them), the colony's set-up up to four (the
  // candidate lists and the first route, tool by tool); measured in the
  // page, Chromium, at 10^5 and 10^6 holes.
  constexpr double kFinishingUnits = 7.0, kSetUpUnits = 4.0;
  const double before = seconds();
  router->count_input_order();
  const double unit = seconds() - before;
  const double routing = s.solver.time_limit_s - seconds() - kFinishingUnits * unit;
  if (routing < kSetUpUnits * unit) {
    // No time for the colony: each tool's holes in nearest-neighbour order.
    router->stop("time limit");
    r.no_time_for_colony = true;
    return;
  }
  o.solver.time_limit_s = routing;
}

void PlanJob::Impl::report(const aco::Progress& p) {
  const std::size_t tool = router ? router->group() : 0;
  const bool fresh = tool != progress_tool;
  const bool improved = fresh || p.best_length < progress_best;
  const double now = seconds();
  // Every improvement, and otherwise at least every 200 ms: a call when
  // 100 ms have passed leaves room for an iteration of up to 100 ms.
  if (!improved && now - progress_at < 0.1) return;
  progress_tool = tool;
  progress_best = p.best_length;
  progress_at = now;
  Progress out;
  out.tool = tool;
  out.tools = r.plan.groups.size();
  if (tool < r.plan.groups.size()) {
    const planning::ToolGroup& g = r.plan.groups[tool];
    out.tool_number = g.tool.number;
    out.tool_diameter_mm = g.tool.diameter_mm;
    out.holes = g.input_order.size();
  }
  out.iteration = p.iteration;
  out.iterations = router ? router->group_iterations() : r.plan.solver.iterations;
  out.best_length = p.best_length;
  out.elapsed_s = now;
  out.improved = improved;
  on_progress(out);
}

void PlanJob::Impl::write_hole_program() {
  planning::settle_plan(r.holes, r.plan, o);
  for (const planning::ToolGroup& g : r.plan.groups) r.stopped = r.stopped || g.solution.stop_reason == "stopped";
  const planning::PlanResult& plan = r.plan;
  const formats::LoadedHoles& loaded = r.inputs.holes;
  const planning::Placement& placement = r.placement;
  std::string source_name;
  for (const Inputs::Source& src : r.inputs.sources) {
    source_name += (source_name.empty() ? "" : " + ") + formats::file_name(src.file);
  }
  const std::size_t copies = r.panel_copies;
  gcode::ProgramSettings& ps = o.program;
  ps.program_number = s.program_number;
  ps.program_name = loaded.name;
  ps.home = o.machine.start;
  ps.resume_from = s.resume_from;
  const std::size_t n_tools = plan.groups.size();
  // Issue 82: a hole feature's other operations are counted apart from the holes.
  const auto operations = aco::count_operations(r.holes);
  ps.header_comments = {
      "SOURCE: " + source_name,
      std::to_string(r.holes.size() - operations) + " HOLES" +
          (operations ? " AND " + std::to_string(operations) + " OPERATIONS" : std::string()) + ", " + std::to_string(n_tools) +
          (n_tools == 1 ? " TOOL" : " TOOLS"),
      "EST. TIME " + format_minutes(plan.optimized.time_s) + ", TRAVEL " + gcode::format_number(plan.optimized.travel_mm, 1) + " MM",
      "ORDER: ACODRILL " + std::string(aco::to_string(plan.solver.algorithm)) + " SEED " + std::to_string(plan.solver.seed),
      planning::origin_comment(placement),
      planning::extent_comment(placement, ps.units),
      planning::zero_comment(placement)};
  ps.header_comments.insert(ps.header_comments.end(), side_notes.begin(), side_notes.end());
  // Which drill makes which designed diameter, and by how much it differs.
  for (const planning::DrillMapping& d : plan.drill_map) ps.header_comments.push_back(drill_map_line(d));
  if (copies > 1) {
    ps.header_comments.push_back("PANEL: " + std::to_string(copies) + " COPIES OF " + std::to_string(r.holes.size() / copies) +
                                 " HOLES, EACH TOOL ACROSS THE WHOLE PANEL");
  }
  if (loaded.slots_milled) {
    ps.header_comments.push_back("SLOTS: " + std::to_string(loaded.slots_milled) + " MILLED ALONG THEIR LENGTH BY THE END MILL");
  }
  if (loaded.slots_drilled) {
    ps.header_comments.push_back("SLOTS: " + std::to_string(loaded.slots_drilled) + " DRILLED AS " +
                                 std::to_string(loaded.slot_holes) + " HOLES");
  }
  // What the input asks for and this program does not do, never only on stderr.
  constexpr std::size_t kListed = 20;
  for (std::size_t i = 0; i < loaded.skipped.size() && i < kListed; ++i) {
    const formats::Note& n = loaded.skipped[i];
    ps.header_comments.push_back("NOT MADE: " + (n.line ? "LINE " + std::to_string(n.line) + ": " : std::string()) + n.message);
  }
  if (loaded.skipped.size() > kListed) {
    ps.header_comments.push_back("NOT MADE: " + std::to_string(loaded.skipped.size() - kListed) + " MORE (SEE THE REPORT)");
  }
  std::ostringstream program;
  const std::vector<gcode::ToolPass> passes = planning::to_passes(r.holes, plan, o.machine);
  try {
    gcode::write_program(program, passes, ps);
  } catch (const std::invalid_argument& e) {
    throw UserError(e.what());
  }
  std::string text = program.str();
  if (s.break_writer_for_test) text = detail::broken_for_test(std::move(text));
  detail::check_own_program(self_check(text, holes_written(r.holes, passes, s.resume_from),
                                       o.tools ? tooling_of_table(*o.tools) : o.tooling, o.operations),
                            s.program_name);
  r.files.program = std::move(text);
  ReportContext ctx{source, s.program_name, placement, loaded.name, &loaded, {}, 1, 1, std::nullopt};
  for (const Inputs::Source& src : r.inputs.sources) ctx.sources.push_back({src.file, src.holes});
  ctx.panel_copies = copies;
  ctx.batch = s.batch;
  ctx.dialect = o.program.dialect;
  detail::make_outputs(r, s, o, ctx, passes);
}

PlanJob::PlanJob(std::vector<InputFile> inputs, PlanSettings settings, ProgressFn progress, const std::atomic<bool>* stop)
  : impl_(std::make_unique<Impl>(std::move(inputs), std::move(settings), std::move(progress), stop)) {}
PlanJob::~PlanJob() = default;
PlanJob::PlanJob(PlanJob&&) noexcept = default;
PlanJob& PlanJob::operator=(PlanJob&&) noexcept = default;

bool PlanJob::advance(int iterations, double seconds) {
  Impl& j = *impl_;
  if (j.done) return true;
  j.guard([&] {
    if (j.router) {
      if (!j.router->advance(iterations, seconds)) return;
      j.write_hole_program();
    } else {
      j.reorder_and_write();
    }
    j.done = true;
  });
  return j.done;
}

Result PlanJob::finish() {
  Impl& j = *impl_;
  if (!j.done) {
    j.guard([&] {
      if (j.router) {
        j.router->stop();
        j.write_hole_program();
      } else {
        j.reorder_and_write();
      }
      j.done = true;
    });
  }
  return std::move(j.r);
}

const Result& PlanJob::state() const { return impl_->r; }

std::vector<aco::Order> PlanJob::routes_so_far() const {
  const Impl& j = *impl_;
  if (j.router) return j.router->orders_so_far();
  std::vector<aco::Order> out;
  for (const planning::ToolGroup& g : j.r.plan.groups) out.push_back(g.optimized.empty() ? g.input_order : g.optimized);
  return out;
}

Result plan(std::vector<InputFile> inputs, const PlanSettings& settings, ProgressFn progress, const std::atomic<bool>* stop) {
  PlanJob job(std::move(inputs), settings, std::move(progress), stop);
  job.advance();
  return job.finish();
}

}  // namespace job
