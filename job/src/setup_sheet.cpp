#include "job/setup_sheet.h"

#include <sstream>

#include "aco/hole_set.h"
#include "job/svg.h"
#include "gcode/program.h"
#include "text.h"

namespace job {

// The planning model's values (planning/) are what these pages and reports show.
using namespace planning;

namespace {

constexpr double kMmPerInch = 25.4;

std::string minutes(double seconds) { return gcode::format_number(seconds / 60.0, 2) + " min"; }

}  // namespace

std::string setup_sheet_html(const aco::HoleSet& holes, const PlanResult& plan, const PlanOptions& options,
                             const ReportContext& ctx, std::string svg) {
  const gcode::ProgramSettings& ps = options.program;
  const bool inch = ps.units == gcode::Units::Inch;
  const std::string unit = inch ? "in" : "mm";
  // Lengths in the program's units, as the operator reads them on the control.
  auto len = [&](double mm) { return gcode::format_number(inch ? mm / kMmPerInch : mm, inch ? 4 : 3); };
  auto feed = [&](double mm_min) { return gcode::format_number(inch ? mm_min / kMmPerInch : mm_min, inch ? 2 : 1); };
  const Placement& pl = ctx.placement;
  // Issue 82: a hole feature's other operations are no holes to the operator.
  const auto operations = aco::count_operations(holes);
  const Extent& e = pl.extent;
  auto esc = [](const std::string& s) { return xml_escape(s); };

  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<title>Setup sheet: " << esc(ctx.name) << "</title>\n<style>\n"
    << "@page { size: A4; margin: 12mm; }\n"
    << "body { font-family: sans-serif; font-size: 10pt; color: #000; margin: 0 auto; max-width: 190mm; }\n"
    << "h1 { font-size: 16pt; margin: 0 0 4pt 0; } h2 { font-size: 12pt; margin: 10pt 0 4pt 0; }\n"
    << "table { border-collapse: collapse; width: 100%; }\n"
    << "th, td { border: 1px solid #999; padding: 2pt 4pt; text-align: left; }\n"
    << "td.n, th.n { text-align: right; } th { background: #eee; }\n"
    << ".zero { font-size: 12pt; font-weight: bold; border: 2px solid #C00000; padding: 4pt; margin: 6pt 0; }\n"
    << ".picture svg { width: 100%; height: auto; max-height: 150mm; }\n"
    << ".picture { break-inside: avoid; }\n"
    << "</style>\n</head>\n<body>\n";
  h << "<h1>Setup sheet: " << esc(ctx.name) << "</h1>\n";
  h << "<table class=\"job\">\n"
    << "<tr><th>Job</th><td>" << esc(ctx.name) << "</td><th>Source file</th><td>" << esc(ctx.source) << "</td></tr>\n"
    // Only what the program holds: GRBL and Marlin programs have no O-number.
    << "<tr><th>Program</th><td>"
    << (gcode::has_canned_cycles(ps.dialect) ? "O" + std::to_string(ps.program_number) + " (" + esc(ps.program_name) + ")"
                                             : esc(ps.program_name))
    << "</td><th>Program file</th><td>"
    << esc(ctx.program == "-" ? std::string("standard output") : ctx.program) << "</td></tr>\n"
    << "<tr><th>Dialect</th><td>" << gcode::to_string(ps.dialect) << "</td><th>Units</th><td>" << (inch ? "inch (G20)" : "mm (G21)")
    << "</td></tr>\n"
    << "<tr><th>Machine</th><td>" << esc(options.machine.name) << "</td><th>Holes / tools</th><td>" << holes.size() - operations
    << (operations ? " and " + std::to_string(operations) + " operations at them" : std::string()) << " / " << plan.groups.size()
    << "</td></tr>\n"
    << "</table>\n";
  // Several files, one job; a panel of copies.
  if (ctx.sources.size() > 1) {
    h << "<p>Inputs:";
    for (const auto& [file, count] : ctx.sources) h << " " << esc(file) << " (" << count << " holes);";
    h << " holes of one diameter share a tool unless the files were kept apart.</p>\n";
  }
  if (ctx.panel_copies > 1) {
    h << "<p>Panel: " << ctx.panel_copies << " copies of " << holes.size() / ctx.panel_copies
      << " holes, each tool routed across the whole panel; program zero below is the panel's.</p>\n";
  }

  h << "<div class=\"zero\">Program zero (G54 X0 Y0): " << esc(describe(pl.origin)) << " &#8212; drawing X"
    << gcode::format_number(pl.zero.x, 3) << " Y" << gcode::format_number(pl.zero.y, 3) << " mm. Holes span X"
    << len(e.x_min) << ".." << len(e.x_max) << " Y" << len(e.y_min) << ".." << len(e.y_max) << " " << unit << " ("
    << len(e.width()) << " x " << len(e.height()) << " " << unit << "). Z0 is the top of the part; R plane Z"
    << len(ps.r_plane_mm) << ", initial plane Z" << len(ps.initial_z_mm) << " " << unit << ".</div>\n";

  if (ctx.input && (ctx.input->slots_drilled || ctx.input->slots_milled || !ctx.input->skipped.empty())) {
    h << "<h2>Slots and features not made</h2>\n<ul>\n";
    if (ctx.input->slots_milled) {
      h << "<li>" << ctx.input->slots_milled << " slot(s) milled along their length by the end mill.</li>\n";
    }
    if (ctx.input->slots_drilled) {
      h << "<li>" << ctx.input->slots_drilled << " slot(s) drilled as rows of " << ctx.input->slot_holes
        << " overlapping holes, ends first.</li>\n";
    }
    for (const formats::Note& n : ctx.input->skipped) {
      h << "<li><b>Not made</b>: " << (n.line ? "line " + std::to_string(n.line) + ": " : std::string()) << esc(n.message)
        << "</li>\n";
    }
    h << "</ul>\n";
  }
  h << "<h2>Tools</h2>\n<table class=\"tools\">\n<tr><th>T</th><th>Tool</th><th class=\"n\">Diameter " << unit
    << "</th><th>Cycle</th><th class=\"n\">Depth Z " << unit << "</th><th class=\"n\">Peck " << unit
    << "</th><th class=\"n\">Dwell s</th><th class=\"n\">Feed " << unit << "/min</th><th class=\"n\">rpm</th><th class=\"n\">Holes</th>"
    << "<th class=\"n\">Life</th><th class=\"n\">Time</th></tr>\n";
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    const gcode::Tool& t = plan.groups[g].tool;
    const bool pecks = t.cycle == gcode::Cycle::G83 || t.cycle == gcode::Cycle::G73;
    const double tool_time = g < plan.optimized.tool_time_s.size() ? plan.optimized.tool_time_s[g] : 0.0;
    h << "<tr><td>T" << t.number << "</td><td>" << esc(gcode::tool_name(t)) << "</td><td class=\"n\">" << len(t.diameter_mm)
      << "</td><td>" << esc(gcode::cycle_description(t, ps.dialect)) << (t.end_mill ? ", " + len(t.helix_pitch_mm) + " a turn" : std::string())
      << "</td><td class=\"n\">" << len(t.depth_mm) << "</td><td class=\"n\">"
      << (pecks ? len(t.peck_mm) : std::string("&#8211;")) << "</td><td class=\"n\">"
      << (t.cycle == gcode::Cycle::G82 ? gcode::format_number(t.dwell_s, 2) : std::string("&#8211;"))
      << "</td><td class=\"n\">" << feed(t.feed_mm_min) << "</td><td class=\"n\">" << t.spindle_rpm << "</td><td class=\"n\">"
      << plan.groups[g].optimized.size() << "</td><td class=\"n\">"
      << (t.max_hits > 0 ? std::to_string(t.max_hits) : std::string("&#8211;")) << "</td><td class=\"n\">" << minutes(tool_time)
      << "</td></tr>\n";
  }
  h << "</table>\n";
  // The tools the user owns: which drill makes which designed diameter.
  if (!plan.drill_map.empty()) {
    h << "<h2>Designed holes and the tools that make them</h2>\n<table class=\"tools\">\n<tr><th class=\"n\">Designed "
      << unit << "</th><th class=\"n\">Holes</th><th>Made with</th><th class=\"n\">Over (+) / under (&#8722;) " << unit
      << "</th></tr>\n";
    for (const DrillMapping& d : plan.drill_map) {
      h << "<tr><td class=\"n\">" << len(d.designed_mm) << "</td><td class=\"n\">" << d.holes << "</td><td>T" << d.tool << " "
        << len(d.tool_mm) << " " << unit << (d.milled ? " end mill, milled to size" : " drill") << "</td><td class=\"n\">"
        << (d.milled ? std::string("&#8211;") : (d.tool_mm > d.designed_mm + 1e-9 ? "+" : "") + len(d.tool_mm - d.designed_mm))
        << "</td></tr>\n";
    }
    h << "</table>\n";
  }

  const RouteStats& in = plan.input_order;
  const RouteStats& nn = plan.nearest_neighbor;
  const RouteStats& op = plan.optimized;
  auto saved = [](double before, double after) {
    return before > 0 ? gcode::format_number(100.0 * (before - after) / before, 1) + " %" : std::string("&#8211;");
  };
  h << "<h2>Time and travel</h2>\n<table class=\"totals\">\n<tr><th>Order</th><th class=\"n\">XY travel " << unit
    << "</th><th class=\"n\">Estimated time</th></tr>\n"
    << "<tr><td>Input order</td><td class=\"n\">" << len(in.travel_mm) << "</td><td class=\"n\">" << minutes(in.time_s) << "</td></tr>\n"
    << "<tr><td>Nearest neighbour</td><td class=\"n\">" << len(nn.travel_mm) << "</td><td class=\"n\">" << minutes(nn.time_s)
    << "</td></tr>\n"
    << "<tr><th>This program (optimized)</th><th class=\"n\">" << len(op.travel_mm) << "</th><th class=\"n\">" << minutes(op.time_s)
    << "</th></tr>\n</table>\n"
    << "<p>Total estimated time: <b>" << minutes(op.time_s) << "</b>; travel " << saved(in.travel_mm, op.travel_mm)
    << " shorter and " << minutes(in.time_s - op.time_s) << " quicker than the input order.</p>\n";
  // Where the time goes: only the moves depend on the order.
  auto split_row = [&](const char* label, const TimeSplit& t, double total) {
    h << "<tr><td>" << label << "</td><td class=\"n\">" << minutes(t.moves_s) << "</td><td class=\"n\">" << minutes(t.drilling_s)
      << "</td><td class=\"n\">" << minutes(t.tool_changes_s) << "</td><td class=\"n\">" << minutes(t.pauses_s)
      << "</td><td class=\"n\">" << minutes(total) << "</td></tr>\n";
  };
  h << "<table class=\"totals\">\n<tr><th>Time split</th><th class=\"n\">Moves</th><th class=\"n\">Drilling</th>"
    << "<th class=\"n\">Tool changes</th><th class=\"n\">Pauses</th><th class=\"n\">Total</th></tr>\n";
  split_row("Input order", in.split, in.time_s);
  split_row("This program", op.split, op.time_s);
  h << "</table>\n";
  if (ctx.batch > 1) {
    const double n = static_cast<double>(ctx.batch);
    h << "<p>A batch of " << ctx.batch << (ctx.panel_copies > 1 ? " panels" : " parts") << ": <b>" << minutes(n * op.time_s)
      << "</b> (input order " << minutes(n * in.time_s) << ", " << minutes(n * (in.time_s - op.time_s)) << " saved).</p>\n";
  }

  // The route picture, to scale, in program coordinates with program zero marked.
  if (svg.empty()) svg = route_svg(holes, plan, options, pl, ctx.name);
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find('\n') + 1);
  h << "<h2>Route</h2>\n<div class=\"picture\">\n" << svg << "</div>\n";
  h << "<p>Made by acodrill, " << esc(aco::to_string(plan.solver.algorithm)) << " seed " << plan.solver.seed
    << ". Every hole line of the program carries its number (N); after a broken drill restart with --resume-from N.</p>\n";
  h << "</body>\n</html>\n";
  return h.str();
}

}  // namespace job
