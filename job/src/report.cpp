#include "job/report.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "aco/hole_set.h"

namespace job {

// The planning model's values (planning/) are what these pages and reports show.
using namespace planning;

namespace {
double round6(double v) { return std::round(v * 1e6) / 1e6; }
double pct_saved(double before, double after) { return before > 0 ? round6(100.0 * (before - after) / before) : 0.0; }
}  // namespace

std::string report_json(const aco::HoleSet& holes, const PlanResult& plan, const ReportContext& ctx) {
  nlohmann::ordered_json j;
  // Issue 82: the holes drilled; a hole feature's other operations (taps,
  // counterbores, ...) made at them are counted apart.
  const auto operations = aco::count_operations(holes);
  j["holes"] = holes.size() - operations;
  j["operations"] = operations;
  j["tools"] = nlohmann::ordered_json::array();
  for (const ToolGroup& g : plan.groups) {
    nlohmann::ordered_json t;
    t["tool"] = g.tool.number;
    t["diameter_mm"] = round6(g.tool.diameter_mm);
    t["holes"] = g.optimized.size();
    t["cycle"] = gcode::cycle_description(g.tool, ctx.dialect);
    t["kind"] = g.tool.end_mill ? "end_mill" : gcode::to_string(g.tool.operation);  // drill, tap, counterbore, ...
    t["spindle_rpm"] = g.tool.spindle_rpm;
    t["feed_mm_min"] = round6(g.tool.feed_mm_min);
    t["depth_mm"] = round6(g.tool.depth_mm);
    t["iterations"] = g.solution.iterations;
    t["stop_reason"] = g.solution.stop_reason;
    t["path_mm"] = round6(g.solution.length);
    j["tools"].push_back(t);
  }
  // Each physical drill (a sister tool is its own) with the holes it makes and its life.
  j["drills"] = nlohmann::ordered_json::array();
  for (const ToolGroup& g : plan.groups) {
    j["drills"].push_back({{"tool", g.tool.number},
                           {"diameter_mm", round6(g.tool.diameter_mm)},
                           {"hits", g.optimized.size()},
                           {"max_hits", g.tool.max_hits}});
  }
  // The tools the user owns: what each designed diameter is made with, and by how much it differs.
  if (!plan.drill_map.empty()) {
    j["drill_map"] = nlohmann::ordered_json::array();
    for (const DrillMapping& d : plan.drill_map) {
      j["drill_map"].push_back({{"designed_mm", round6(d.designed_mm)},
                                {"holes", d.holes},
                                {"tool", d.tool},
                                {"tool_diameter_mm", round6(d.tool_mm)},
                                {"made_as", d.milled ? "milled" : "drilled"},
                                {"oversize_mm", d.milled ? 0.0 : round6(d.tool_mm - d.designed_mm)}});
    }
  }
  j["travel_mm"] = {{"input_order", round6(plan.input_order.travel_mm)},
                    {"nearest_neighbor", round6(plan.nearest_neighbor.travel_mm)},
                    {"optimized", round6(plan.optimized.travel_mm)}};
  j["machining_time_s"] = {{"input_order", round6(plan.input_order.time_s)},
                           {"nearest_neighbor", round6(plan.nearest_neighbor.time_s)},
                           {"optimized", round6(plan.optimized.time_s)}};
  auto split = [](const TimeSplit& t) {
    return nlohmann::ordered_json{{"moves", round6(t.moves_s)},
                                  {"drilling", round6(t.drilling_s)},
                                  {"tool_changes", round6(t.tool_changes_s)},
                                  {"pauses", round6(t.pauses_s)}};
  };
  j["time_split_s"] = {{"input_order", split(plan.input_order.split)},
                       {"nearest_neighbor", split(plan.nearest_neighbor.split)},
                       {"optimized", split(plan.optimized.split)}};
  j["savings"] = {{"travel_pct_vs_input_order", pct_saved(plan.input_order.travel_mm, plan.optimized.travel_mm)},
                  {"travel_pct_vs_nearest_neighbor", pct_saved(plan.nearest_neighbor.travel_mm, plan.optimized.travel_mm)},
                  {"time_s_vs_input_order", round6(plan.input_order.time_s - plan.optimized.time_s)},
                  {"time_pct_vs_input_order", pct_saved(plan.input_order.time_s, plan.optimized.time_s)}};
  nlohmann::ordered_json busy = nlohmann::ordered_json::array();
  for (double b : plan.thread_busy_s) busy.push_back(round6(b));
  j["solver"] = {{"algorithm", aco::to_string(plan.solver.algorithm)},
                 {"threads", plan.solver.threads},
                 {"seed", plan.solver.seed},
                 {"iterations", plan.iterations},
                 {"wall_s", round6(plan.solver_wall_s)},
                 {"ants", plan.solver.ants},
                 {"alpha", plan.solver.alpha},
                 {"beta", plan.solver.beta},
                 {"rho", plan.solver.rho},
                 {"local_search", aco::to_string(plan.solver.local_search)},
                 {"thread_busy_s", busy}};
  const Placement& pl = ctx.placement;
  j["origin"] = {{"mode", to_string(pl.origin)},
                 {"zero_in_input_mm", {{"x", round6(pl.zero.x)}, {"y", round6(pl.zero.y)}}}};
  j["extent_mm"] = {{"x_min", round6(pl.extent.x_min)},
                    {"x_max", round6(pl.extent.x_max)},
                    {"y_min", round6(pl.extent.y_min)},
                    {"y_max", round6(pl.extent.y_max)}};
  if (ctx.input) {
    j["slots"] = {{"drilled", ctx.input->slots_drilled}, {"holes", ctx.input->slot_holes}, {"milled", ctx.input->slots_milled}};
    nlohmann::ordered_json skipped = nlohmann::ordered_json::array();
    for (const formats::Note& n : ctx.input->skipped) skipped.push_back({{"line", n.line}, {"what", n.message}});
    j["not_drilled"] = skipped;
  }
  if (ctx.program_input) {
    // travel_mm.input_order and machining_time_s.input_order are the input program's own.
    const auto& pi = *ctx.program_input;
    j["program_input"] = {{"runs", pi.runs},
                          {"overlapping_holes_in_input_order", pi.overlapping_holes},
                          {"overlap_groups", pi.overlap_groups},
                          {"style", pi.style},
                          {"milling_lines_kept", pi.milling_lines}};
  }
  // The minutes a shop pays for: one panel (one run of the program) and a batch of them, beside the input order's.
  j["panel"] = {{"copies", ctx.panel_copies}, {"holes_per_copy", ctx.panel_copies ? holes.size() / ctx.panel_copies : 0}};
  j["batch"] = {{"panels", ctx.batch},
                {"time_s", {{"input_order", round6(plan.input_order.time_s * static_cast<double>(ctx.batch))},
                            {"optimized", round6(plan.optimized.time_s * static_cast<double>(ctx.batch))}}}};
  nlohmann::ordered_json sources = nlohmann::ordered_json::array();
  for (const auto& [file, count] : ctx.sources) sources.push_back({{"file", file}, {"holes", count}});
  if (ctx.sources.empty()) sources.push_back({{"file", ctx.source}, {"holes", holes.size()}});
  j["sources"] = sources;
  // Issue 82: every hole feature that is more than a plain hole, and what became of it.
  if (ctx.input && !ctx.input->features.empty()) {
    nlohmann::ordered_json features = nlohmann::ordered_json::array();
    for (const formats::HoleFeature& f : ctx.input->features) {
      if (f.kind == formats::FeatureKind::Plain) continue;
      nlohmann::ordered_json one = {{"x_mm", round6(f.center.x)},
                                    {"y_mm", round6(f.center.y)},
                                    {"kind", formats::to_string(f.kind)},
                                    {"diameter_mm", round6(f.diameter_mm)},
                                    {"drill_mm", round6(f.drill_mm)},
                                    {"outer_diameter_mm", round6(f.outer_diameter_mm)},
                                    {"thread", f.thread},
                                    {"layer", f.layer},
                                    {"evidence", f.evidence},
                                    {"line", f.line}};
      if (f.pitch_mm > 0) one["pitch_mm"] = round6(f.pitch_mm);
      if (f.depth_mm > 0) one["depth_mm"] = round6(f.depth_mm);
      if (f.angle_deg > 0) one["angle_deg"] = round6(f.angle_deg);
      if (!f.undecided_mm.empty()) {
        nlohmann::ordered_json d = nlohmann::ordered_json::array();
        for (double v : f.undecided_mm) d.push_back(round6(v));
        one["not_machined_mm"] = d;
      }
      features.push_back(one);
    }
    j["features"] = features;
    j["features_summary"] = formats::features_summary(ctx.input->features);
  }
  // What a reader assumed because the input did not say (Excellon units and number format).
  if (ctx.input && !ctx.input->assumptions.empty()) j["input_assumptions"] = ctx.input->assumptions;
  // DXF: round closed contours drawn without a CIRCLE, read as holes or only counted.
  if (ctx.input && ctx.input->round_contours > 0) {
    j["round_contours"] = {{"found", ctx.input->round_contours},
                           {"read_as_holes", ctx.input->round_contour_holes},
                           {"drawn_with", ctx.input->round_contour_kinds}};
  }
  j["source"] = ctx.source;
  j["program"] = ctx.program;
  return j.dump(2) + "\n";
}

std::string convergence_csv(const PlanResult& plan) {
  std::ostringstream out;
  out << "tool,iteration,wall_s,best_length_mm\n";
  out.precision(10);
  for (const ToolGroup& g : plan.groups) {
    for (const aco::TracePoint& t : g.solution.trace) {
      out << g.tool.number << ',' << t.iteration << ',' << t.wall_s << ',' << t.best_length << '\n';
    }
  }
  return out.str();
}

namespace {

// A CSV field: quoted where it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::string features_csv(const formats::LoadedHoles& loaded) {
  std::string out = "x_mm,y_mm,kind,diameter_mm,outer_diameter_mm,thread,layer,evidence\n";
  auto n6 = [](double v) { return gcode::format_number(v, 6); };
  if (loaded.features.empty()) {  // an input that draws no features: each hole a plain one
    for (const aco::Hole& h : loaded.holes) {
      out += n6(h.center.x) + "," + n6(h.center.y) + ",plain," + n6(h.diameter) + ",,," + csv_field(h.layer) + ",\n";
    }
    return out;
  }
  for (const formats::HoleFeature& f : loaded.features) {
    out += n6(f.center.x) + "," + n6(f.center.y) + "," + formats::to_string(f.kind) + "," + n6(f.diameter_mm) + "," +
           (f.outer_diameter_mm > 0 ? n6(f.outer_diameter_mm) : std::string()) + "," + csv_field(f.thread) + "," +
           csv_field(f.layer) + "," + csv_field(f.evidence) + "\n";
  }
  return out;
}

std::string holes_csv(const aco::HoleSet& holes) {
  std::string out = "x_mm,y_mm,diameter_mm,layer\n";
  out.reserve(holes.size() * 40 + 32);
  for (const aco::Hole& h : holes) {
    out += gcode::format_number(h.center.x, 6) + "," + gcode::format_number(h.center.y, 6) + "," +
           gcode::format_number(h.diameter, 6) + ",";
    if (h.layer.find_first_of(",\"\n") != std::string::npos) {
      std::string q = "\"";
      for (char c : h.layer) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
      out += q + "\"";
    } else {
      out += h.layer;
    }
    out += "\n";
  }
  return out;
}

}  // namespace job
