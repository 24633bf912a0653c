// acodrill's commands other than plan: holes, tsp, verify and machines,
// and what the commands share (inputs read once, the input summary line,
// a machine or panel named or given as a file).
#include "commands.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <cctype>
#include <map>
#include <regex>
#include <sstream>

#include "aco/solve.h"
#include "app/errors.h"
#include "app/files.h"
#include "gcode/interpreter.h"
#include "job/report.h"
#include "job/verify.h"
#include "planning/machine.h"
#include "planning/operations.h"

namespace cli {

namespace {
// --time-limit bounds the whole run: the time spent reading the inputs comes
// off the solver's share (100 000 holes of TSPLIB text: 45-71 ms from process
// start to the holes read, and a 5 s run took 5.06-5.19 s of wall time).
const std::chrono::steady_clock::time_point kStarted = std::chrono::steady_clock::now();
}  // namespace

double seconds_since_start() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - kStarted).count();
}

job::InputSettings read_input_settings(const InputArgs& a) {
  job::InputSettings s = a.settings;
  if (!a.apertures.empty()) s.apertures = job::NamedText{a.apertures, app::read_file(a.apertures)};
  if (!a.processes.empty()) s.processes = job::NamedText{a.processes, app::read_file(a.processes)};
  return s;
}

void resolve_machine(const std::string& name_or_path, std::string& name, std::optional<job::NamedText>& profile) {
  const bool plain = name_or_path.find_first_of("/.") == std::string::npos;
  if (plain && !std::filesystem::exists(app::fs_path(name_or_path))) {
    name = name_or_path;
    return;
  }
  profile = job::NamedText{name_or_path, app::read_file(name_or_path)};
}

void resolve_panel(const std::string& panel, std::string& grid, std::optional<job::NamedText>& file) {
  const bool is_file = !panel.empty() && (panel.find_first_of("/.") != std::string::npos || std::filesystem::exists(app::fs_path(panel)));
  if (is_file) file = job::NamedText{panel, app::read_file(panel)};
  else grid = panel;
}

std::vector<std::string> read_once(const std::vector<std::string>& paths, bool quiet) {
  std::vector<std::string> repeated;
  std::vector<std::string> kept = app::distinct_inputs(paths, repeated);
  if (!quiet) {
    for (const std::string& r : repeated) {
      std::fprintf(stderr, "acodrill: warning: %s is given more than once; it is read once\n", r == "-" ? "<stdin>" : r.c_str());
    }
  }
  return kept;
}

void print_warnings(const formats::LoadedHoles& loaded, const std::string& path, bool quiet, const char* skipped_label,
                    std::optional<std::size_t> holes) {
  if (quiet) return;
  std::string summary = std::to_string(holes.value_or(loaded.holes.size())) + " holes from " + std::string(formats::to_string(loaded.format));
  if (loaded.duplicates_removed) summary += ", " + std::to_string(loaded.duplicates_removed) + " duplicates removed";
  if (loaded.drilled_again) {
    summary += ", " + std::to_string(loaded.drilled_again) + " drilled again at the same place (kept, as the program drills them)";
  }
  if (loaded.skipped_by_filter) summary += ", " + std::to_string(loaded.skipped_by_filter) + " filtered out";
  if (!loaded.drill_function.empty()) summary += " (" + loaded.drill_function + ")";
  if (loaded.slots_drilled) {
    summary += ", " + std::to_string(loaded.slots_drilled) + " slot(s) drilled as " + std::to_string(loaded.slot_holes) + " holes";
  }
  if (loaded.slots_milled) summary += ", " + std::to_string(loaded.slots_milled) + " slot(s) milled along their length";
  if (!loaded.description.empty()) summary += "; " + loaded.description;
  const std::string features = formats::features_summary(loaded.features);
  if (!features.empty()) summary += "; hole features: " + features;
  if (!loaded.skipped.empty()) {
    const formats::Note& n = loaded.skipped.front();
    summary += std::string("; ") + skipped_label + ": " + std::to_string(loaded.skipped.size()) + " feature(s), first: " +
               (n.line ? "line " + std::to_string(n.line) + ": " : "") + n.message;
  }
  if (!loaded.assumptions.empty()) {
    std::string assumed;
    for (const std::string& a : loaded.assumptions) assumed += (assumed.empty() ? "" : ", ") + a;
    summary += "; assumed " + assumed;
  }
  std::size_t warnings = 0;
  std::string first;
  for (const formats::Note& n : loaded.warnings) {
    if (warnings++ == 0) first = (n.line ? std::to_string(n.line) + ": " : "") + n.message;
  }
  if (warnings == 1) summary += "; warning: " + first;
  if (warnings > 1) summary += "; " + std::to_string(warnings) + " warnings, first: " + first;
  std::cerr << "acodrill: " << (path == "-" ? "<stdin>" : path) << ": " << summary << "\n";
  for (const formats::Note& n : loaded.feature_warnings) {
    std::cerr << "acodrill: " << (path == "-" ? "<stdin>" : path) << (n.line ? ":" + std::to_string(n.line) : std::string())
              << ": warning: " << n.message << "\n";
  }
}

int cmd_holes(const std::string& input, const InputArgs& in, const std::string& format, bool features, bool quiet) {
  if (format != "csv") throw app::UserError("--format must be csv");
  if (in.settings.slots == "mill") throw app::UserError("--slots mill is for plan and verify; holes lists what the input holds");
  app::LoadedHoles loaded = app::load_holes(input, job::input_options(read_input_settings(in)));
  if (loaded.program) {
    // The listing has each position once, as for every other format.
    loaded.duplicates_removed = aco::remove_duplicate_holes(loaded.holes);
    loaded.drilled_again = 0;
  }
  const std::string out = features ? job::features_csv(loaded) : job::holes_csv(loaded.holes);
  std::cout << out;
  std::cout.flush();
  print_warnings(loaded, input, quiet,
                 loaded.slots.empty() && !loaded.features.empty() ? "plan does not make"
                                                                    : "not listed (slots and routes; plan drills slots unless --slots skip)");
  return 0;
}

int cmd_tsp(const std::string& input, const std::string& tour, const job::SolverSettings& s, bool quiet) {
  aco::Params params = job::solver_params(s);
  app::InputOptions io;
  app::LoadedHoles loaded = app::load_holes(input, io);
  if (loaded.holes.empty()) throw app::UserError(input, 0, "no nodes");
  app::check_output_path(tour);
  params.time_limit_s = app::time_left(params.time_limit_s, seconds_since_start());
  aco::Problem p;
  p.metric = formats::tsplib_metric(loaded);  // the instance's own rounding: EUC_2D, CEIL_2D, ATT
  p.shape = aco::Shape::ClosedTour;
  for (const aco::Hole& h : loaded.holes) p.points.push_back(h.center);
  if (!quiet && ::isatty(STDERR_FILENO)) {
    params.on_iteration = [](const aco::Progress& pr) {
      if (pr.wall_s >= 1.0) std::fprintf(stderr, "\racodrill: iteration %d, %.1f s, best %.0f   ", pr.iteration, pr.wall_s, pr.best_length);
    };
  }
  aco::Solution sol = aco::solve(p, params);
  if (params.on_iteration) std::fprintf(stderr, "\r%60s\r", "");
  if (!tour.empty()) {
    std::ostringstream t;
    t << "NAME : " << loaded.name << ".tour\nCOMMENT : length " << static_cast<long long>(std::llround(sol.length))
      << ", acodrill " << aco::to_string(sol.algorithm) << " seed " << s.seed << "\nTYPE : TOUR\nDIMENSION : "
      << sol.order.size() << "\nTOUR_SECTION\n";
    for (aco::HoleIndex h : sol.order) t << (h + 1) << "\n";
    t << "-1\nEOF\n";
    app::write_file_atomic(tour, t.str());
  }
  std::printf("length %lld\n", static_cast<long long>(std::llround(sol.length)));
  if (!quiet) {
    std::fprintf(stderr, "acodrill: %s, %zu nodes, %d iterations, %.2f s, %d threads (%s)\n", loaded.name.c_str(),
                 p.points.size(), sol.iterations, sol.wall_s, sol.threads, sol.stop_reason.c_str());
  }
  return 0;
}

namespace {

int print_faults(const std::vector<std::string>& faults, const std::string& program_path, bool quiet) {
  std::printf("faults %zu\n", faults.size());
  for (const auto& f : faults) std::printf("fault: %s\n", f.c_str());
  if (!quiet) std::fprintf(stderr, "acodrill: %s: %zu fault(s), first: %s\n", program_path.c_str(), faults.size(), faults[0].c_str());
  return 1;
}

}  // namespace

int cmd_verify(const VerifyArgs& a, const InputArgs& in, bool quiet) {
  planning::Tooling tooling;
  if (!a.bench.drills.empty()) tooling.drills = planning::parse_owned_drills(a.bench.drills, "--drills");
  tooling.end_mill_mm = a.bench.end_mill_mm;
  job::parse_mirror_axis(a.bench);
  const std::string text = app::read_file(a.program);
  const auto read_program = [&](bool keeping_milling) {
    try {
      return keeping_milling ? gcode::interpret_keeping_milling(text) : gcode::interpret(text);
    } catch (const gcode::ProgramError& e) {
      throw app::UserError(a.program, e.line(), e.what());
    }
  };
  gcode::Interpretation run = read_program(false);
  std::string holes_path;
  for (const std::string& p : a.holes) holes_path += (holes_path.empty() ? "" : " + ") + p;
  formats::InputOptions in_options = job::input_options(read_input_settings(in));
  in_options.keep_milling = true;  // an input program that also mills: its drilling is what is compared
  std::optional<app::LoadedHoles> loaded;
  if (!a.holes.empty()) {
    loaded = app::load_job(a.holes, in_options).holes;
    // It mills too (plan --keep-milling): this one is read so as well, a cut's plunge no hole.
    if (loaded->program && !loaded->program->milling_lines.empty()) run = read_program(true);
  }
  std::map<int, std::size_t> per_tool;
  for (const auto& h : run.holes) per_tool[h.tool]++;
  std::printf("holes %zu\n", run.holes.size());
  for (const auto& [tool, count] : per_tool) {
    auto d = run.tool_diameter_mm.find(tool);
    std::printf("tool %d holes %zu diameter_mm %s\n", tool, count,
                d == run.tool_diameter_mm.end() ? "unknown" : gcode::format_number(d->second, 3).c_str());
  }
  std::printf("rapid_xy_mm %s\n", gcode::format_number(run.rapid_xy_mm, 3).c_str());
  if (!loaded) return 0;
  app::LoadedHoles& expected = *loaded;
  std::vector<planning::OperationSpec> operations;  // the features' operations, in their order
  {
    // Issue 82: the operations plan makes of the hole features: taps where the
    // program has canned cycles (GRBL and Marlin leave them to the operator).
    // Depths are not checked here, so no thickness can make one contradict.
    static const std::regex canned(R"((^|[^0-9.])G(8[1-5]|7[34]|33\.1)([^0-9.]|$))");
    std::string code;
    for (std::size_t at = 0, depth = 0; at < text.size(); ++at) {
      if (text[at] == '(') ++depth;
      else if (text[at] == ')' && depth > 0) --depth;
      else if (depth == 0) code += static_cast<char>(std::toupper(static_cast<unsigned char>(text[at])));
    }
    const bool cycles = std::regex_search(code, canned);
    std::vector<std::uint32_t> no_sources;
    planning::OperationSettings settings;
    settings.thickness_mm = 1e9;
    settings.can_tap = settings.can_counterbore = cycles;
    settings.spot = a.spot;
    settings.end_mill_mm = a.bench.end_mill_mm;
    settings.processes = in_options.processes.get();
    const planning::Operations ops = planning::add_operations(expected.holes, no_sources, expected.features, settings, holes_path);
    operations = ops.specs;
  }
  if (!a.panel.empty() || !a.pitch.empty()) {
    std::string grid;
    std::optional<job::NamedText> file;
    resolve_panel(a.panel, grid, file);
    std::vector<std::uint32_t> no_sources;
    expected.holes = planning::panelize(expected.holes, job::panel_copies(grid, a.pitch, file), no_sources);
  }
  if (expected.program) {
    // Another program as the hole source: the same holes, tools and depths, where it put them.
    const std::vector<std::string> faults = job::check_same_holes(run, *expected.program);
    if (!faults.empty()) return print_faults(faults, a.program, quiet);
    std::printf("ok: %zu holes of %s drilled once each with the same tool and depth\n", expected.program->hole_count(),
                holes_path.c_str());
    return 0;
  }
  // The holes as the program should drill them: moved to the program zero
  // --origin names, else the one the program states (acodrill writes it in its
  // header), else where they are (another CAM's program).
  // Turned over and pinned as plan was told (--side, --alignment-pins).
  planning::Placement placement;
  if (!a.origin.empty()) {
    const planning::Origin origin = job::parse_origin(a.origin);
    job::turn_and_place(expected.holes, a.bench, &origin, &placement, nullptr);
  } else if (auto zero = planning::stated_zero(text)) {
    const planning::Origin origin{planning::OriginKind::Point, *zero};
    job::turn_and_place(expected.holes, a.bench, &origin, &placement, nullptr);
  } else {
    job::turn_and_place(expected.holes, a.bench, nullptr, nullptr, nullptr);
  }
  const std::vector<std::string> faults = job::check_drilled(run, expected.holes, tooling, operations);
  if (!faults.empty()) return print_faults(faults, a.program, quiet);
  std::printf("ok: %zu input holes drilled once each with the right tool\n", expected.holes.size());
  return 0;
}

int cmd_machines(const std::string& show) {
  for (const planning::MachineClass& c : planning::machine_classes()) {
    if (show.empty()) {
      std::printf("%s\t%s\n", c.name.c_str(), c.description.c_str());
    } else if (c.name == show) {
      std::printf("%s\n", c.profile_json.c_str());
      return 0;
    }
  }
  if (!show.empty()) {
    // Names the classes there are.
    std::string name;
    std::optional<job::NamedText> profile;
    resolve_machine(show, name, profile);
    job::machine_of(name, profile);
  }
  return 0;
}

}  // namespace cli
