// The browser's door to the job (issue 65): C functions the page's worker
// calls, taking the inputs' bytes and the settings as JSON and giving back
// JSON. One job at a time, driven in slices (job::PlanJob): the worker runs
// a slice, posts the progress and the route so far, and handles its
// messages (Stop) before the next, since a worker inside C++ sees none.
#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <new>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "formats/error.h"
#include "job/plan.h"

namespace {

using nlohmann::json;

struct Session {
  std::vector<job::InputFile> files;
  std::unique_ptr<job::PlanJob> job;
  json progress = json::array();  // the progress since the last slice
  std::string out;                // the last answer, alive until the next call
  // The last answer's large parts, kept here (not written into its JSON) until
  // the next call: the worker copies them out of memory by the places the JSON
  // gives. At 10^6 holes, writing and parsing them as JSON text took 9 s of
  // the page's 48 (issue 84).
  // (Deques: a part never moves once made, so the addresses given stay true.)
  std::deque<std::vector<double>> f64;
  std::deque<std::vector<std::int32_t>> i32;
  std::deque<std::string> texts;
  std::string failure;  // what ended the job inside a slice (its memory ran out): aco_finish says it
};

// The most holes the page takes (issue 84): at 10^6 random holes its memory
// (the module's heap) reached 1.05 GB, and a browser gives it 4 GB at most; a
// 3 x 10^6-hole file once failed after minutes with a bare number.
constexpr std::size_t kPageMaxHoles = 2'000'000;
const char* const kOutOfMemory =
    "the job needs more memory than the browser gives this page: plan it with the command line (acodrill plan)";

// The hole limit as the page names it in its messages.
const std::string kPageHoleLimitNamed = "the most this page plans in a browser's memory; the command line, acodrill plan, takes up to " +
                                        std::to_string(job::InputSettings{}.max_holes);

Session& session() {
  static Session s;
  return s;
}

// Called first by every answering function: the previous answer's parts go.
void new_answer() {
  Session& s = session();
  s.f64.clear();
  s.i32.clear();
  s.texts.clear();
}

// {"$f64": [address, count]}: numbers the worker reads as a Float64Array.
json f64_part(std::vector<double> v) {
  Session& s = session();
  s.f64.push_back(std::move(v));
  return {{"$f64", {reinterpret_cast<std::uintptr_t>(s.f64.back().data()), s.f64.back().size()}}};
}
// {"$i32": [address, count]}: hole indices, as an Int32Array.
template <class Ints>
json i32_part(const Ints& v) {
  Session& s = session();
  s.i32.emplace_back(v.begin(), v.end());
  return {{"$i32", {reinterpret_cast<std::uintptr_t>(s.i32.back().data()), s.i32.back().size()}}};
}
// {"$text": [address, bytes]}: a file's text (UTF-8), as a string.
json text_part(std::string text) {
  Session& s = session();
  s.texts.push_back(std::move(text));
  return {{"$text", {reinterpret_cast<std::uintptr_t>(s.texts.back().data()), s.texts.back().size()}}};
}

const char* answer(const json& j) {
  Session& s = session();
  s.out = j.dump(-1, ' ', false, json::error_handler_t::replace);
  return s.out.c_str();
}

// The page's settings, named as its controls; an empty or missing value is
// the option's default.
job::PlanSettings settings_of(const json& j) {
  job::PlanSettings s;
  auto text = [&](const char* key, std::string& field) {
    if (j.contains(key) && j[key].is_string()) field = j[key].get<std::string>();
  };
  auto number = [&](const char* key) -> std::optional<double> {
    if (!j.contains(key)) return std::nullopt;
    if (j[key].is_number()) return j[key].get<double>();
    if (j[key].is_string() && !j[key].get<std::string>().empty()) {
      const std::string v = j[key].get<std::string>();
      char* end = nullptr;
      const double d = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0') throw formats::InputError("\"" + v + "\" is not a number (" + key + ")");
      return d;
    }
    return std::nullopt;
  };
  text("machine", s.machine);
  text("dialect", s.dialect);
  text("units", s.units);
  text("origin", s.origin);
  text("material", s.material);
  text("objective", s.objective);
  text("drills", s.bench.drills);
  text("side", s.bench.side);
  if (s.bench.side.empty()) s.bench.side = "front";
  text("mirror_axis", s.bench.mirror_axis);
  text("panel", s.panel);
  text("pitch", s.pitch);
  text("algorithm", s.solver.algorithm);
  if (s.solver.algorithm.empty()) s.solver.algorithm = "focused";
  text("local_search", s.solver.local_search);
  if (s.solver.local_search.empty()) s.solver.local_search = "auto";
  text("program_name", s.program_name);
  text("dxf_units", s.input.dxf_units);
  s.input.round_contours = j.contains("round_contours") && j["round_contours"].is_string() && j["round_contours"] == "on";
  if (j.contains("processes") && j["processes"].is_string() && !j["processes"].get<std::string>().empty()) {
    std::string name = "processes.json";
    text("processes_name", name);
    s.input.processes = job::NamedText{name, j["processes"].get<std::string>()};
  }
  s.thickness_mm = number("thickness");
  s.default_diameter_mm = number("default_diameter");
  s.bench.end_mill_mm = number("end_mill");
  s.probe_plate_mm = number("probe_plate");
  s.bench.alignment_pins_mm = number("alignment_pins");
  // What the command line refuses, the page says by its control's name (issue 84: Seed -3 and Iterations 0 went through).
  auto whole = [&](const char* key, const char* control, double least) -> std::optional<double> {
    const std::optional<double> v = number(key);
    if (v && !(*v >= least && *v <= 2e9 && *v == std::floor(*v))) {
      throw formats::InputError(std::string(control) + ": a whole number from " + std::to_string(static_cast<int>(least)) +
                                " (empty: the default)");
    }
    return v;
  };
  if (auto v = number("time_limit")) {
    if (!(*v > 0)) throw formats::InputError("Time limit: a number of seconds above 0 (empty: none)");
    s.solver.time_limit_s = *v;
  }
  if (auto v = whole("iterations", "Iterations", 1)) s.solver.iterations = static_cast<int>(*v);
  if (auto v = whole("seed", "Seed", 0)) s.solver.seed = static_cast<std::uint64_t>(*v);
  if (auto v = whole("ants", "Ants", 1)) s.solver.ants = static_cast<int>(*v);
  if (auto v = number("alpha")) s.solver.alpha = *v;
  s.solver.beta = number("beta");
  s.solver.threads = 1;  // no threads in a file:// page (no cross-origin isolation)
  s.solver.time_limit_covers_outputs = true;  // Plan to the files to save, within the "Time limit" (issue 84)
  // What the page saves (aco_finish): no comparison picture, no convergence
  // table; at 10^6 holes the comparison alone took 2.5 s (issue 84).
  s.wanted.report = s.wanted.route_svg = s.wanted.setup_sheet = s.wanted.excellon = s.wanted.gerber = true;
  s.input.max_holes = kPageMaxHoles;
  s.input.max_holes_named = kPageHoleLimitNamed;
  return s;
}

json error_of(const job::Result& r) { return {{"error", r.error}, {"exit_code", r.exit_code}}; }

json stats_of(const planning::RouteStats& st) {
  return {{"travel_mm", st.travel_mm},
          {"time_s", st.time_s},
          {"moves_s", st.split.moves_s},
          {"drilling_s", st.split.drilling_s},
          {"tool_changes_s", st.split.tool_changes_s},
          {"pauses_s", st.split.pauses_s}};
}

// The holes as the page draws them: x, y, diameter flat, and each tool with its holes.
json holes_of(const job::Result& r) {
  const aco::HoleSet& holes = r.holes.empty() ? r.inputs.holes.holes : r.holes;
  std::vector<double> xyd;
  xyd.reserve(holes.size() * 3);
  for (const aco::Hole& h : holes) {
    xyd.push_back(std::round(h.center.x * 1e4) / 1e4);
    xyd.push_back(std::round(h.center.y * 1e4) / 1e4);
    xyd.push_back(h.diameter);
  }
  json tools = json::array();
  for (const planning::ToolGroup& g : r.plan.groups) {
    tools.push_back({{"number", g.tool.number},
                     {"name", gcode::tool_name(g.tool)},
                     {"diameter_mm", g.tool.diameter_mm},
                     {"end_mill", g.tool.end_mill},
                     {"operation", gcode::to_string(g.tool.operation)},
                     {"holes", i32_part(g.input_order)}});
  }
  const bool program = r.inputs.holes.program != nullptr;
  if (program && r.plan.groups.empty()) {
    // Another CAM's program before it is reordered (issue 84): its tool runs
    // are the tools, the holes in program order as program_holes lists them.
    std::size_t next = 0;
    for (const gcode::ToolRun& run : r.inputs.holes.program->runs) {
      std::vector<std::size_t> at(run.holes.size());
      for (std::size_t& k : at) k = next++;
      gcode::Tool t;
      t.number = run.tool;
      t.diameter_mm = run.diameter_mm.value_or(0.0);
      tools.push_back({{"number", run.tool},
                       {"name", run.diameter_mm ? gcode::tool_name(t) : "T" + std::to_string(run.tool)},
                       {"diameter_mm", t.diameter_mm},
                       {"end_mill", false},
                       {"operation", "drill"},
                       {"holes", i32_part(at)}});
    }
  }
  json inputs = json::array();
  for (std::size_t k = 0; k < r.inputs.sources.size(); ++k) {
    const formats::LoadedHoles& part = program ? r.inputs.holes : r.inputs.parts[k];
    json notes = json::array();
    for (const formats::Note& n : part.warnings) notes.push_back({{"line", n.line}, {"what", n.message}});
    for (const formats::Note& n : part.feature_warnings) notes.push_back({{"line", n.line}, {"what", n.message}});
    if (k == 0 && !program) {  // the job's own: what it makes of the hole features (issue 82)
      for (const formats::Note& n : r.inputs.holes.feature_warnings) notes.push_back({{"line", n.line}, {"what", n.message}});
    }
    json skipped = json::array();
    for (const formats::Note& n : part.skipped) skipped.push_back({{"line", n.line}, {"what", n.message}});
    inputs.push_back({{"file", r.inputs.sources[k].file},
                      {"format", formats::to_string(part.format)},
                      {"holes", program ? part.holes.size() : r.inputs.sources[k].holes},
                      {"warnings", notes},
                      {"not_drilled", skipped},
                      {"assumptions", part.assumptions},
                      {"description", part.description},  // issue 86: a board job's step, drill layers, size
                      {"slots_drilled", part.slots_drilled},
                      {"slot_holes", part.slot_holes},  // issue 84: what the command line says, the page says
                      {"slots_milled", part.slots_milled},
                      {"duplicates_removed", part.duplicates_removed},
                      {"round_contours", part.round_contours},
                      {"features", formats::features_summary(part.features)}});
  }
  // A program's holes stay where it has them: their extent as they are.
  const planning::Extent e = program ? planning::extent_of(holes) : r.placement.extent;
  return {{"holes", f64_part(std::move(xyd))},
          {"tools", tools},
          {"inputs", inputs},
          {"program_input", program},
          {"extent", {e.x_min, e.y_min, e.x_max, e.y_max}},
          {"drill_map", [&] {
             json m = json::array();
             for (const planning::DrillMapping& d : r.plan.drill_map) m.push_back(job::drill_map_line(d));
             return m;
           }()}};
}

}  // namespace

extern "C" {

// A new job's inputs: call once a file, then aco_open.
EMSCRIPTEN_KEEPALIVE void aco_add_file(const char* name, const std::uint8_t* bytes, int size) {
  session().files.push_back({name, std::string(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size)), ""});
}

// The settings checked alone, without reading the files again: {} or the
// error (a colony setting changed, which leaves the holes as they are).
EMSCRIPTEN_KEEPALIVE const char* aco_check(const char* settings_json) {
  new_answer();
  try {
    settings_of(json::parse(settings_json));
  } catch (const formats::InputError& e) {
    return answer({{"error", e.where_what()}, {"exit_code", 2}});
  } catch (const std::exception& e) {
    return answer({{"error", e.what()}, {"exit_code", 2}});
  }
  return answer(json::object());
}

// Reads the files with the settings: the holes, their tools and what the
// inputs say, or the error. The job then waits for aco_advance.
EMSCRIPTEN_KEEPALIVE const char* aco_open(const char* settings_json) {
  new_answer();
  Session& s = session();
  s.job.reset();
  s.failure.clear();
  s.progress = json::array();
  std::vector<job::InputFile> files = std::move(s.files);
  s.files.clear();
  try {
    const job::PlanSettings settings = settings_of(json::parse(settings_json));
    s.job = std::make_unique<job::PlanJob>(std::move(files), settings, [](const job::Progress& p) {
      session().progress.push_back({{"tool", p.tool},
                                    {"tools", p.tools},
                                    {"tool_number", p.tool_number},
                                    {"iteration", p.iteration},
                                    {"iterations", p.iterations},
                                    {"best", p.best_length},
                                    {"elapsed_s", p.elapsed_s},
                                    {"improved", p.improved}});
    });
  } catch (const formats::InputError& e) {
    return answer({{"error", e.where_what()}, {"exit_code", 2}});
  } catch (const std::bad_alloc&) {
    s.job.reset();
    return answer({{"error", kOutOfMemory}, {"exit_code", 2}});
  } catch (const std::exception& e) {
    return answer({{"error", e.what()}, {"exit_code", 2}});
  }
  const job::Result& r = s.job->state();
  if (r.exit_code != 0) return answer(error_of(r));
  return answer(holes_of(r));
}

// Routes for `seconds` (or `iterations`): whether the job is done, the
// progress heard, and (when it changed and `with_routes`) each tool's route as it stands.
EMSCRIPTEN_KEEPALIVE const char* aco_advance(int iterations, double seconds, int with_routes) {
  new_answer();
  Session& s = session();
  if (!s.job) return answer({{"done", true}});
  bool done = false;
  try {
    done = s.job->advance(iterations, seconds);
  } catch (const std::bad_alloc&) {
    s.job.reset();
    s.failure = kOutOfMemory;
    return answer({{"done", true}});
  }
  json out = {{"done", done}, {"progress", s.progress}};
  bool improved = false;
  for (const json& p : s.progress) improved = improved || p["improved"].get<bool>();
  s.progress = json::array();
  if (improved && !done && with_routes) {
    json routes = json::array();
    for (const aco::Order& o : s.job->routes_so_far()) routes.push_back(i32_part(o));
    out["routes"] = routes;
  }
  return answer(out);
}

// The outputs (the routing ends here if it has not): files, summary, or the error.
EMSCRIPTEN_KEEPALIVE const char* aco_finish() {
  new_answer();
  Session& s = session();
  if (!s.failure.empty()) {
    const std::string failure = std::move(s.failure);
    s.failure.clear();
    return answer({{"error", failure}, {"exit_code", 2}});
  }
  if (!s.job) return answer({{"error", "no job"}, {"exit_code", 2}});
  job::Result r;
  try {
    r = s.job->finish();
  } catch (const std::bad_alloc&) {
    s.job.reset();
    return answer({{"error", kOutOfMemory}, {"exit_code", 2}});
  }
  s.job.reset();
  if (r.exit_code != 0) return answer(error_of(r));
  json routes = json::array(), input_routes = json::array();
  for (const planning::ToolGroup& g : r.plan.groups) {
    routes.push_back(i32_part(g.optimized));
    input_routes.push_back(i32_part(g.input_order));
  }
  json out = holes_of(r);
  out["files"] = {{"program", text_part(std::move(r.files.program))},     {"report", text_part(std::move(r.files.report))},
                  {"setup_sheet", text_part(std::move(r.files.setup_sheet))}, {"route_svg", text_part(std::move(r.files.route_svg))},
                  {"excellon", text_part(std::move(r.files.excellon))},   {"gerber", text_part(std::move(r.files.gerber))}};
  out["routes"] = routes;
  out["input_routes"] = input_routes;
  out["stopped"] = r.stopped;
  out["no_time_for_colony"] = r.no_time_for_colony;
  out["iterations"] = r.plan.iterations;
  out["solver_wall_s"] = r.plan.solver_wall_s;
  out["input_order"] = stats_of(r.plan.input_order);
  out["nearest_neighbor"] = stats_of(r.plan.nearest_neighbor);
  out["optimized"] = stats_of(r.plan.optimized);
  out["dialect"] = gcode::to_string(r.dialect);
  out["kept_style"] = r.program_input && r.program_input->style == "keep";  // a program input written in its own style
  return answer(out);
}

}  // extern "C"
