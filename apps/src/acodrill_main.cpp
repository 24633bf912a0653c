// acodrill: the command line. It parses options, reads files, calls the
// pure stages (readers → plan_job → write_program) and writes the outputs.
// Argument parsing is CLI11 (Debian libcli11-dev): subcommands, typed options
// and generated --help in a few lines each, where hand-written parsing would
// be a few hundred lines of error-prone code.
#include <unistd.h>
#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#endif

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "aco/error.h"
#include "aco/hole_set.h"
#include "aco/solve.h"
#include "app/bench.h"
#include "app/errors.h"
#include "formats/writers.h"
#include "app/files.h"
#include "app/inputs.h"
#include "app/report.h"
#include "app/setup_sheet.h"
#include "app/svg.h"
#include "app/verify.h"
#include "gcode/drilling.h"
#include "gcode/interpreter.h"
#include "gcode/program.h"
#include "planning/plan.h"
#include "planning/reorder.h"

namespace {

constexpr const char* kVersion = "acodrill " ACO_VERSION;

// --time-limit bounds the whole run: the time spent reading the inputs comes
// off the solver's share (100 000 holes of TSPLIB text: 45-71 ms from process
// start to the holes read, and a 5 s run took 5.06-5.19 s of wall time).
const std::chrono::steady_clock::time_point kStarted = std::chrono::steady_clock::now();
double seconds_since_start() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - kStarted).count();
}

struct SolverArgs {
  int threads = 0;
  std::uint64_t seed = 1;
  double time_limit = 0.0;
  int iterations = 0;
  std::string algorithm = "focused";
  int ants = 0;
  double alpha = 1.0;
  std::optional<double> beta, rho;
  std::string local_search = "auto";
  int focus_edges = 0;
};

void add_solver_options(CLI::App* cmd, SolverArgs& a) {
  cmd->add_option("--threads", a.threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--seed", a.seed, "Random seed; same input, options and seed give the same output (default 1)");
  cmd->add_option("--time-limit", a.time_limit, "Stop after S seconds of the whole run, reading the input included (0 = no limit); plan shares S among its tools by hole count")->check(CLI::Range(0.0, 1e7));
  cmd->add_option("--iterations", a.iterations, "Colony iterations (default: until the time limit; without one, fewer the more holes and ants: 3000 focused iterations of 10 ants up to 6667 holes, 300 acs/mmas/as)")
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--algorithm", a.algorithm,
                  "focused (default: ACS whose ants change a bounded number of the best route's edges, with a kick when "
                  "it stalls and a restart when kicks stop helping; measured best "
                  "from 198 to 15112 holes, docs/benchmarks.md), acs (Ant Colony System over whole routes), mmas "
                  "(MAX-MIN), as (the thesis's Ant System)");
  cmd->add_option("--ants", a.ants, "Ants per iteration (default: focused 10 up to 800 holes, 40 up to 10 000, 20 above; acs and mmas with local search 10; else min(n,100))")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--alpha", a.alpha, "Pheromone weight (default 1)")->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--beta", a.beta, "Distance weight (default: as 4, mmas/acs 2)")->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--rho", a.rho, "Evaporation rate in (0,1] (default: as 0.5, mmas 0.2, acs 0.1)");
  cmd->add_option("--local-search", a.local_search, "none | 2opt | 2opt+oropt | 3opt | 5opt | auto (default auto: 5opt from 3000 to 20000 holes, else 3opt, each where it measured better; 3opt: 2-opt, Or-opt, and sequential 3-opt moves that go deeper, Lin-Kernighan style, when none gains; 5opt: 2-opt, Or-opt, then LKH's sequential 5-opt step on the ascent's penalised costs, chained when none gains)");
  cmd->add_option("--focus-edges", a.focus_edges,
                  "focused: new edges an ant makes on the best route before it copies the rest (default 16)")
      ->check(CLI::Range(1, 1000000));
}

aco::Params to_params(const SolverArgs& a) {
  aco::Params p = app::solver_params(a.algorithm, a.local_search);
  if (a.rho && !(*a.rho > 0.0 && *a.rho <= 1.0)) throw app::UserError("--rho must be in (0, 1]");
  p.threads = a.threads;
  p.seed = a.seed;
  p.time_limit_s = a.time_limit;
  p.iterations = a.iterations;
  p.ants = a.ants;
  p.focus_edges = a.focus_edges;
  p.alpha = a.alpha;
  if (a.beta) p.beta = *a.beta;
  if (a.rho) p.rho = *a.rho;
  p.validate();
  return p;
}

struct InputArgs {
  std::vector<std::string> layers;
  std::optional<double> min_d, max_d;
  std::string input_units;
  std::size_t max_holes = 5'000'000;
  std::size_t max_expansion = 10'000'000;
  std::string slots = "drill";
  double slot_pitch = 0.0;
  std::string apertures;
  std::string excellon_format;
  bool round_contours = false;
  double round_tolerance_pct = 2.5;
  std::string dxf_units;
};

// "--excellon-format inch,2:4,lz": units, integer:decimal digits, the zeros kept.
formats::InputOptions::ExcellonFormat parse_excellon_format(const std::string& text) {
  const std::string usage = "--excellon-format must be UNITS,I:D,ZEROS: mm or inch, integer and decimal digits, lz (leading "
                            "zeros kept) or tz (trailing zeros kept), e.g. inch,2:4,lz (got \"" + text + "\")";
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t comma = text.find(','); ; comma = text.find(',', start)) {
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  formats::InputOptions::ExcellonFormat f;
  int a = 0, b = 0;
  char tail = 0;
  if (parts.size() != 3 || std::sscanf(parts[1].c_str(), "%d:%d%c", &a, &b, &tail) != 2 || a < 1 || a > 7 || b < 0 || b > 7) {
    throw app::UserError(usage);
  }
  if (parts[0] == "mm" || parts[0] == "metric") f.metric = true;
  else if (parts[0] != "inch" && parts[0] != "in") throw app::UserError(usage);
  if (parts[2] == "lz") f.leading_zeros_kept = true;
  else if (parts[2] != "tz") throw app::UserError(usage);
  f.int_digits = a;
  f.dec_digits = b;
  return f;
}

void add_input_options(CLI::App* cmd, InputArgs& a) {
  cmd->add_option("--layer", a.layers, "Only holes on these layers (repeatable; * and ? wildcards)");
  cmd->add_option("--min-diameter", a.min_d, "Only holes at least this wide (mm)")->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--max-diameter", a.max_d, "Only holes at most this wide (mm)")->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--input-units", a.input_units,
                  "mm | inch: units of inputs that do not say (default mm; an Excellon file that does not say is inch, "
                  "its format's own default)");
  cmd->add_flag("--round-contours", a.round_contours,
                "DXF: also read closed contours that are circles as holes: SPLINE loops (Fusion 360), polygons of LINEs "
                "or closed polylines (OpenSCAD, Inkscape), arc pairs, loops of LINEs and ARCs, full-circle ARCs, "
                "circular ELLIPSEs; each at its fitted centre, with the diameter of the circle through its points "
                "(a polygon's vertices). Without it they are counted in a warning, not read");
  cmd->add_option("--round-tolerance", a.round_tolerance_pct,
                  "How round a contour must be to be a hole: the largest gap between it and its circle, in percent of "
                  "the radius (default 2.5: polygons of 14 sides or more; 10 takes 8 sides)")
      ->check(CLI::Range(0.01, 30.0));
  cmd->add_option("--dxf-units", a.dxf_units,
                  "mm | cm | m | inch | feet: the unit a DXF is drawn in, whatever its $INSUNITS header says (Onshape "
                  "writes inch for drawings made in mm)");
  cmd->add_option("--excellon-format", a.excellon_format,
                  "UNITS,I:D,ZEROS: how an Excellon file's numbers are written, for a file that does not say or says it "
                  "wrong; wins over the file (e.g. inch,2:4,lz: inch, 2 integer and 4 decimal digits, leading zeros kept; "
                  "mm,3:3,tz: trailing zeros kept). Without it acodrill reads the file's header, its comments, Allegro's "
                  "nc_param.txt beside it and the numbers' shapes, says what it assumed, and stops when the holes so read "
                  "make no sense");
  cmd->add_option("--max-holes", a.max_holes, "Refuse inputs with more holes than this (default 5000000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}));
  cmd->add_option("--slots", a.slots,
                  "drill (default of plan and verify): each slot (Excellon G85 or routed oval, Gerber obround) becomes a row of holes of "
                  "its width, ends first then midpoints so the drill never cuts into one fresh hole alone; skip: "
                  "not drilled, and named in the program header, report and setup sheet (default of holes, which lists what the input holds); "
                  "mill (plan and verify, with --end-mill): milled along its length by the end mill, round its ends");
  cmd->add_option("--slot-pitch", a.slot_pitch, "Distance between a drilled slot's holes in mm (default: a quarter of its width)")
      ->check(CLI::Range(0.0, 1e4));
  cmd->add_option("--apertures", a.apertures,
                  "Aperture list of an RS-274D Gerber file: rows \"D10 C 0.032\" (D code, shape C/R/O, size; inch unless "
                  "a suffix MM/MIL or a line UNITS MM|INCH|MILS says), or RS-274X %FS/%MO/%AD lines");
  cmd->add_option("--max-expansion", a.max_expansion,
                  "Refuse DXF files whose blocks expand to more references than this (default 10000000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000'000}));
}

app::InputOptions to_input_options(const InputArgs& a) {
  app::InputOptions o;
  o.dxf.layers = a.layers;
  if (a.min_d) o.dxf.min_diameter_mm = *a.min_d;
  if (a.max_d) o.dxf.max_diameter_mm = *a.max_d;
  o.dxf.max_holes = a.max_holes;
  o.dxf.max_block_references = a.max_expansion;
  if (!a.input_units.empty()) {
    if (a.input_units == "mm") o.default_unit_mm = 1.0;
    else if (a.input_units == "inch" || a.input_units == "in") o.default_unit_mm = 25.4;
    else throw app::UserError("--input-units must be mm or inch (got \"" + a.input_units + "\")");
    o.input_units_given = true;
  }
  if (a.slots == "drill") o.slots.policy = formats::SlotPolicy::Drill;
  else if (a.slots == "skip") o.slots.policy = formats::SlotPolicy::Skip;
  else if (a.slots == "mill") o.slots.policy = formats::SlotPolicy::Mill;
  else throw app::UserError("--slots must be drill, skip or mill (got \"" + a.slots + "\")");
  o.slots.pitch_mm = a.slot_pitch;
  if (!a.apertures.empty()) {
    o.aperture_list = app::read_file(a.apertures);
    o.aperture_list_path = a.apertures;
  }
  if (!a.excellon_format.empty()) o.excellon_format = parse_excellon_format(a.excellon_format);
  o.dxf.round_contours = a.round_contours;
  o.dxf.round_tolerance = a.round_tolerance_pct / 100.0;
  if (!a.dxf_units.empty()) {
    const std::map<std::string, double> units = {{"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"inch", 25.4}, {"in", 25.4}, {"feet", 304.8}, {"ft", 304.8}};
    auto it = units.find(a.dxf_units);
    if (it == units.end()) throw app::UserError("--dxf-units must be mm, cm, m, inch or feet (got \"" + a.dxf_units + "\")");
    o.dxf.units_override_mm = it->second;
  }
  return o;
}

// The tools on the bench and the side of the board (plan and verify take the same).
struct BenchArgs {
  std::string drills;
  std::optional<double> end_mill;
  std::string side = "front";
  std::string mirror_axis;
  std::optional<double> alignment_pins;
};

// `plan`: the options default to the machine profile's keys (verify has no machine; it takes what plan was given).
void add_bench_options(CLI::App* cmd, BenchArgs& a, bool plan) {
  cmd->add_option("--drills", a.drills,
                  "The drills you own, mm, comma-separated, each DIA or DIA:-MINUS:+PLUS (how much smaller and larger "
                  "than a hole it may be; default -0.05 and +0.10: leads need clearance, and larger is the safe side). "
                  "Each hole goes to a drill that fits it, using the fewest drills that cover every hole, then the "
                  "closest fit" + std::string(plan ? " (default: the machine profile's drills_owned, else one drill per diameter)"
                                                   : "; give verify what plan was given"));
  cmd->add_option("--end-mill", a.end_mill,
                  "Diameter (mm) of an end mill for the holes no owned drill fits: each is milled by a helix about "
                  "its centre to its size, as one more tool routed like a drill" +
                      std::string(plan ? " (default: the profile's end_mill_mm)" : ""))
      ->check(CLI::Range(0.05, 100.0));
  cmd->add_option("--side", a.side,
                  "front (default) | back: drill the board from its back, the holes mirrored about the vertical line "
                  "through the centre of the holes' extent (or --mirror-axis)");
  cmd->add_option("--mirror-axis", a.mirror_axis,
                  "x=V (the vertical line X=V) or y=V (the horizontal line Y=V), mm in input coordinates: the line "
                  "--side back mirrors about and --alignment-pins sit on");
  cmd->add_option("--alignment-pins", a.alignment_pins,
                  "Add two pin holes of DIA mm on the mirror line, 10 mm beyond the outermost holes, drilled before "
                  "everything else, to register the board when it is turned over")
      ->check(CLI::Range(0.1, 50.0));
}

planning::MirrorAxis parse_mirror_axis(const BenchArgs& a) {
  if (a.side != "front" && a.side != "back") throw app::UserError("--side must be front or back (got \"" + a.side + "\")");
  if (a.mirror_axis.empty()) return {};
  if (a.side != "back" && !a.alignment_pins) throw app::UserError("--mirror-axis goes with --side back or --alignment-pins");
  auto axis = planning::mirror_axis_from_string(a.mirror_axis);
  if (!axis) throw app::UserError("--mirror-axis must be x=V or y=V in mm (got \"" + a.mirror_axis + "\")");
  return *axis;
}

// The owned tools: the options, else the machine profile's.
planning::Tooling tooling_of(const BenchArgs& a, const planning::Machine& machine) {
  planning::Tooling t;
  if (!a.drills.empty()) t.drills = planning::parse_owned_drills(a.drills, "--drills");
  else if (!machine.drills_owned.empty()) t.drills = planning::parse_owned_drills(machine.drills_owned, "drills_owned");
  t.end_mill_mm = a.end_mill ? a.end_mill : machine.end_mill_mm;
  return t;
}

// The board as the program drills it (plan) or should (verify): mirrored
// for --side back, then program zero, then the alignment pins (not part of
// the extent that places zero) at the end, in program coordinates. Returns
// the pins' indices.
std::vector<aco::HoleIndex> turn_and_place(aco::HoleSet& holes, const BenchArgs& a, const planning::Origin* origin,
                                           planning::Placement* placement, std::vector<std::string>* notes) {
  const planning::MirrorAxis axis = planning::resolve_mirror_axis(holes, parse_mirror_axis(a));
  const std::string line = std::string(axis.vertical ? "X=" : "Y=") + gcode::format_number(*axis.at, 3);
  if (a.side == "back") {
    planning::mirror_holes(holes, axis);
    if (notes) notes->push_back("SIDE: BACK, HOLES MIRRORED ABOUT " + line + " (DRAWING MM)");
  }
  aco::HoleSet pins = a.alignment_pins ? planning::alignment_pins(holes, axis, *a.alignment_pins) : aco::HoleSet{};
  aco::Point2 zero{0, 0};
  if (origin) {
    *placement = planning::place_holes(holes, *origin);
    zero = placement->zero;
  }
  std::vector<aco::HoleIndex> first;
  for (aco::Hole& pin : pins) {
    pin.center = {pin.center.x - zero.x, pin.center.y - zero.y};
    first.push_back(static_cast<aco::HoleIndex>(holes.size()));
    holes.push_back(pin);
  }
  if (notes && !pins.empty()) {
    notes->push_back("ALIGNMENT PINS: D" + gcode::format_number(*a.alignment_pins, 3) + " ON " + line + " AT X" +
                     gcode::format_number(pins[0].center.x, 3) + " Y" + gcode::format_number(pins[0].center.y, 3) + " AND X" +
                     gcode::format_number(pins[1].center.x, 3) + " Y" + gcode::format_number(pins[1].center.y, 3) + ", DRILLED FIRST");
  }
  return first;
}

// `skipped_label` says what became of what the input holds but the holes leave out.
// `holes`: how many holes to say the input gave (default: those it holds; a
// file of a several-file job has handed its holes to the job).
void print_warnings(const app::LoadedHoles& loaded, const std::string& path, bool quiet,
                    const char* skipped_label = "NOT DRILLED", std::optional<std::size_t> holes = std::nullopt) {
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
  if (!loaded.skipped.empty()) {
    const app::Note& n = loaded.skipped.front();
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
  for (const app::Note& n : loaded.warnings) {
    if (warnings++ == 0) first = (n.line ? std::to_string(n.line) + ": " : "") + n.message;
  }
  if (warnings == 1) summary += "; warning: " + first;
  if (warnings > 1) summary += "; " + std::to_string(warnings) + " warnings, first: " + first;
  std::cerr << "acodrill: " << (path == "-" ? "<stdin>" : path) << ": " << summary << "\n";
}

planning::Origin parse_origin(const std::string& text) {
  auto origin = planning::origin_from_string(text);
  if (!origin) {
    throw app::UserError("--origin must be drawing, lower-left, center, upper-left or X,Y in mm (got \"" + text + "\")");
  }
  return *origin;
}

// A drill file written back stays in the input's coordinates, registered with
// the board's other layers, wherever program zero is.
std::vector<gcode::ToolPass> in_input_coordinates(std::vector<gcode::ToolPass> passes, const planning::Placement& placement) {
  for (gcode::ToolPass& p : passes) {
    for (aco::Point2& h : p.holes) h = {h.x + placement.zero.x, h.y + placement.zero.y};
  }
  return passes;
}

std::string format_minutes(double seconds) {
  return gcode::format_number(seconds / 60.0, 2) + " min";
}

// --panel and --pitch, as plan and verify take them.
std::vector<planning::PanelCopy> panel_copies(const std::string& panel, const std::string& pitch) {
  if (!pitch.empty() && panel.empty()) throw app::UserError("--pitch goes with --panel COLSxROWS");
  const bool file = panel.find_first_of("/.") != std::string::npos || std::filesystem::exists(app::fs_path(panel));
  if (file && !pitch.empty()) throw app::UserError("--pitch goes with --panel COLSxROWS, not with a panel file");
  return file ? planning::parse_panel(app::read_file(panel), panel) : planning::panel_grid(panel, pitch);
}

// --machine: a built-in class by name, unless a file of that name is here, or a profile file.
planning::Machine load_machine(const std::string& name_or_path) {
  const bool plain = name_or_path.find_first_of("/.") == std::string::npos;
  if (plain && !std::filesystem::exists(app::fs_path(name_or_path))) {
    if (auto m = planning::builtin_machine(name_or_path)) return *m;
    throw app::UserError("--machine: no machine class \"" + name_or_path + "\" (built in: " +
                         planning::machine_class_names() + "; or give a profile file, see acodrill machines)");
  }
  return planning::parse_machine(app::read_file(name_or_path), name_or_path);
}

int cmd_holes(const std::string& input, const InputArgs& in_args, const std::string& format, bool quiet) {
  if (format != "csv") throw app::UserError("--format must be csv");
  if (in_args.slots == "mill") throw app::UserError("--slots mill is for plan and verify; holes lists what the input holds");
  app::LoadedHoles loaded = app::load_holes(input, to_input_options(in_args));
  if (loaded.program) {
    // The listing has each position once, as for every other format.
    loaded.duplicates_removed = aco::remove_duplicate_holes(loaded.holes);
    loaded.drilled_again = 0;
  }
  const std::string out = app::holes_csv(loaded.holes);
  std::cout << out;
  std::cout.flush();
  print_warnings(loaded, input, quiet, "not listed (slots and routes; plan drills slots unless --slots skip)");
  return 0;
}

// The inputs with each file once; a file given again is named in a warning.
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

struct PlanArgs {
  std::vector<std::string> inputs;  // one job; `input` is the first
  bool keep_files_apart = false;
  std::string panel, pitch;
  std::size_t batch = 1;
  std::string input, output, report, svg, svg_compare, convergence, excellon, gerber, setup_sheet;
  std::string dialect, units, tools, machine, material, objective = "distance", origin;
  bool keep_style = false;
  double min_spacing = 0.0;
  std::optional<double> thickness, default_diameter;
  std::size_t resume_from = 1;
  int program_number = 1001;
  bool quiet = false;
  BenchArgs bench;
  std::optional<double> probe_plate;
  bool filter_progress = false;
};

// "D0.750 MM, 12 HOLES: T2 0.800 MM DRILL, +0.050 MM": how a designed diameter is made.
std::string drill_map_line(const planning::DrillMapping& d) {
  std::string line = "D" + gcode::format_number(d.designed_mm, 3) + " MM, " + std::to_string(d.holes) +
                     (d.holes == 1 ? " HOLE: T" : " HOLES: T") + std::to_string(d.tool) + " ";
  if (d.milled) return line + gcode::format_number(d.tool_mm, 3) + " MM END MILL, MILLED TO SIZE";
  const double over = d.tool_mm - d.designed_mm;
  return line + gcode::format_number(d.tool_mm, 3) + " MM DRILL, " +
         (std::fabs(over) < 0.0005 ? std::string("EXACT") : (over > 0 ? "+" : "") + gcode::format_number(over, 3) + " MM");
}

// Issue 72: the program plan is about to write, read back as verify reads
// it, must drill what plan read; one that does not is never written (exit 3:
// the fault is acodrill's, not the input's).
void check_own_program(const std::vector<std::string>& faults, const std::string& output) {
  if (faults.empty()) return;
  throw aco::InternalError("the program for " + (output == "-" ? std::string("<stdout>") : output) + " fails acodrill's own check (" +
                           std::to_string(faults.size()) + " fault" + (faults.size() == 1 ? "" : "s") + ", first: " +
                           faults.front() + "); nothing was written. This is a fault in acodrill, not in the input: please report it");
}

// A test hook, and only that: ACODRILL_TEST_BREAK_WRITER=1 drops the last
// line that moves to a hole in a cycle ("X... Y...", "N4 X... Y...") before
// the check, so a test can see a faulty program refused and no file written.
std::string broken_for_test(std::string text) {
  const char* flag = std::getenv("ACODRILL_TEST_BREAK_WRITER");
  if (!flag || std::string(flag) != "1") return text;
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

// Writes the program and every asked-for output (each complete or not at
// all), then the summary on stderr.
int finish_plan(const PlanArgs& a, const std::string& program_text, const aco::HoleSet& holes, const planning::PlanResult& plan,
                const planning::PlanOptions& o, const app::ReportContext& ctx, const std::vector<gcode::ToolPass>& passes,
                const app::Job* job = nullptr) {
  const app::LoadedHoles& loaded = *ctx.input;
  const planning::Placement& placement = ctx.placement;
  const std::size_t n_tools = plan.groups.size();
  const std::string source_name = formats::file_name(ctx.source);
  // Everything is computed; now write, each file complete or not at all.
  app::write_file_atomic(a.output, program_text);
  if (!a.report.empty()) app::write_file_atomic(a.report, app::report_json(holes, plan, ctx));
  if (!a.convergence.empty()) app::write_file_atomic(a.convergence, app::convergence_csv(plan));
  if (!a.svg.empty()) app::write_file_atomic(a.svg, app::route_svg(holes, plan, o, placement, ctx.name));
  if (!a.svg_compare.empty()) {
    app::write_file_atomic(a.svg_compare, app::compare_svg(holes, plan, o, placement, ctx.name));
  }
  if (!a.setup_sheet.empty()) app::write_file_atomic(a.setup_sheet, app::setup_sheet_html(holes, plan, o, ctx));
  if (!a.excellon.empty()) {
    // The input's own units when it is Excellon, unless --units chose others.
    const bool metric = a.units.empty() ? loaded.metric.value_or(true) : o.program.units == gcode::Units::Mm;
    app::write_file_atomic(a.excellon, formats::write_excellon(in_input_coordinates(passes, placement), metric, source_name));
  }
  if (!a.gerber.empty()) {
    app::write_file_atomic(a.gerber, formats::write_gerber(in_input_coordinates(passes, placement), source_name,
                                                           loaded.drill_function));
  }

  if (!a.quiet) {
    if (job) {
      for (std::size_t k = 0; k < job->parts.size(); ++k) {
        print_warnings(job->parts[k], job->sources[k].file, a.quiet, "NOT DRILLED", job->sources[k].holes);
      }
      if (job->parts.size() > 1 && loaded.duplicates_removed) {
        std::fprintf(stderr, "acodrill: %zu hole(s) in more than one input drilled once\n", loaded.duplicates_removed);
      }
    } else {
      print_warnings(loaded, a.input, a.quiet);
    }
    const auto& in = plan.input_order;
    const auto& nn = plan.nearest_neighbor;
    const auto& op = plan.optimized;
    auto pct = [](double before, double after) {
      return before > 0 ? gcode::format_number(100.0 * (before - after) / before, 1) + " %" : std::string("-");
    };
    std::fprintf(stderr, "acodrill: %zu holes, %zu tool%s, %d iterations in %.2f s on %d thread%s\n",
                 holes.size(), n_tools, n_tools == 1 ? "" : "s", plan.iterations, plan.solver_wall_s,
                 plan.solver.threads, plan.solver.threads == 1 ? "" : "s");
    if (!plan.drill_map.empty()) {
      std::fprintf(stderr, "  the tools you own:\n");
      for (const planning::DrillMapping& d : plan.drill_map) {
        std::string l = drill_map_line(d);
        for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        std::fprintf(stderr, "    %s\n", l.c_str());
      }
    }
    std::fprintf(stderr, "  %-18s %12s %12s\n", "order", "travel mm", "time min");
    std::fprintf(stderr, "  %-18s %12.1f %12.2f\n", ctx.program_input ? "input program" : "input order", in.travel_mm,
                 in.time_s / 60);
    std::fprintf(stderr, "  %-18s %12.1f %12.2f\n", "nearest neighbour", nn.travel_mm, nn.time_s / 60);
    std::fprintf(stderr, "  %-18s %12.1f %12.2f\n", "optimized", op.travel_mm, op.time_s / 60);
    // Where the time goes: the route changes only the moves.
    std::fprintf(stderr, "  %-18s %12s %12s %12s %12s\n", "time split min", "moves", "drilling", "tool changes", "pauses");
    for (const auto& [label, st] : {std::pair{ctx.program_input ? "input program" : "input order", &in}, {"optimized", &op}}) {
      std::fprintf(stderr, "  %-18s %12.2f %12.2f %12.2f %12.2f\n", label, st->split.moves_s / 60, st->split.drilling_s / 60,
                   st->split.tool_changes_s / 60, st->split.pauses_s / 60);
    }
    if (ctx.program_input && ctx.program_input->overlapping_holes) {
      std::fprintf(stderr, "  %zu overlapping holes (%zu groups) drilled together in their input order\n",
                   ctx.program_input->overlapping_holes, ctx.program_input->overlap_groups);
    }
    std::fprintf(stderr, "  saved vs input order: %s travel, %s time; vs nearest neighbour: %s travel\n",
                 pct(in.travel_mm, op.travel_mm).c_str(), pct(in.time_s, op.time_s).c_str(),
                 pct(nn.travel_mm, op.travel_mm).c_str());
    if (a.output != "-") std::fprintf(stderr, "  program: %s\n", a.output.c_str());
    if (!a.report.empty()) std::fprintf(stderr, "  report: %s\n", a.report.c_str());
    if (!a.convergence.empty()) std::fprintf(stderr, "  convergence: %s\n", a.convergence.c_str());
    if (!a.excellon.empty()) std::fprintf(stderr, "  excellon: %s\n", a.excellon.c_str());
    if (!a.gerber.empty()) std::fprintf(stderr, "  gerber: %s\n", a.gerber.c_str());
    if (!a.svg.empty()) std::fprintf(stderr, "  picture: %s\n", a.svg.c_str());
    if (!a.svg_compare.empty()) std::fprintf(stderr, "  comparison: %s\n", a.svg_compare.c_str());
    if (!a.setup_sheet.empty()) std::fprintf(stderr, "  setup sheet: %s\n", a.setup_sheet.c_str());
    const planning::Extent& e = placement.extent;
    if (ctx.program_input) {
      std::fprintf(stderr, "  coordinates as in the input program (its work offset); holes X%s..%s Y%s..%s mm\n",
                   gcode::format_number(e.x_min, 3).c_str(), gcode::format_number(e.x_max, 3).c_str(),
                   gcode::format_number(e.y_min, 3).c_str(), gcode::format_number(e.y_max, 3).c_str());
      return 0;
    }
    std::fprintf(stderr, "  program zero: %s (drawing X%s Y%s mm); holes X%s..%s Y%s..%s mm\n",
                 planning::describe(placement.origin).c_str(), gcode::format_number(placement.zero.x, 3).c_str(),
                 gcode::format_number(placement.zero.y, 3).c_str(), gcode::format_number(e.x_min, 3).c_str(),
                 gcode::format_number(e.x_max, 3).c_str(), gcode::format_number(e.y_min, 3).c_str(),
                 gcode::format_number(e.y_max, 3).c_str());
  }
  return 0;
}

// Issue 14: another CAM's drilling program, reordered within each tool run;
// its coordinates, tools, cycles and depths stay exactly as they are.
int plan_program(const PlanArgs& a, planning::PlanOptions o, const app::LoadedHoles& loaded, const InputArgs& in_args) {
  const std::string source = a.input == "-" ? "<stdin>" : a.input;
  const gcode::DrillingProgram& input = *loaded.program;
  // What only makes sense for hole files.
  if (!in_args.layers.empty() || in_args.min_d || in_args.max_d) {
    throw app::UserError("--layer, --min-diameter and --max-diameter select holes of hole files; a program is reordered whole");
  }
  if (!a.origin.empty() && a.origin != "drawing") {
    throw app::UserError("--origin: a program's coordinates stay as they are (the machinist set the work offset for them)");
  }
  for (const auto& [given, name] : {std::pair{!a.tools.empty(), "--tools"}, {a.resume_from != 1, "--resume-from"},
                                    {!a.material.empty(), "--material"}, {a.thickness.has_value(), "--thickness"},
                                    {a.default_diameter.has_value(), "--default-diameter"}, {!a.panel.empty(), "--panel"},
                                    {!a.bench.drills.empty(), "--drills"}, {a.bench.end_mill.has_value(), "--end-mill"},
                                    {a.bench.side != "front", "--side"}, {a.bench.alignment_pins.has_value(), "--alignment-pins"}}) {
    if (given) throw app::UserError(std::string(name) + " does not apply to a program: its tools, cycles and depths are kept");
  }
  if (input.hole_count() == 0) {
    // Say why: reading may have stopped early, at an end with more code after it.
    if (input.code_lines_after_end > 0) {
      throw app::UserError(source, input.end_line, "no holes to drill before the program ends here (" + input.end_reason +
                                                       "); " + std::to_string(input.code_lines_after_end) +
                                                       " line(s) of code after it are not read");
    }
    throw app::UserError(source, 0, "no holes to drill: the program has no drilling move (no canned cycle, no feed down in Z)");
  }
  const bool inch = a.units.empty() ? input.inch : o.program.units == gcode::Units::Inch;
  if (a.keep_style && inch != input.inch) {
    throw app::UserError("--keep-style keeps the input's units (" + std::string(input.inch ? "inch" : "mm") + "); drop --units");
  }
  if (inch != input.inch) {
    for (const gcode::ToolRun& run : input.runs) {
      for (const gcode::ProgramHole& h : run.holes) {
        if (!h.cycle.extra.empty()) {
          throw app::UserError(source, h.line, "cycle words \"" + h.cycle.extra + "\" stay in the input's units; drop --units");
        }
      }
    }
  }
  planning::ReorderOptions ro;
  ro.min_spacing_mm = a.min_spacing;
  planning::check_travel(loaded.holes, o.machine, source);  // before the colony's work, not after
  planning::ReorderResult r = planning::reorder_program(input, o, ro);

  const std::string source_name = formats::file_name(source);
  gcode::DrillingWriteSettings ws;
  ws.dialect = o.program.dialect;
  ws.inch = inch;
  ws.decimals = std::clamp(input.decimals + (inch == input.inch ? 0 : inch ? 1 : -1), inch ? 4 : 3, 6);
  ws.program_number = a.program_number;
  ws.program_name = loaded.name;
  ws.keep_style = a.keep_style;
  ws.spindle_start_s = o.program.spindle_start_s;
  ws.travel_feed_mm_min = o.program.travel_feed_mm_min;
  ws.header_comments = {
      "SOURCE: " + source_name + " (A DRILLING PROGRAM, REORDERED)",
      std::to_string(r.holes.size()) + " HOLES IN " + std::to_string(r.plan.groups.size()) + " TOOL RUNS",
      "TRAVEL " + gcode::format_number(r.plan.optimized.travel_mm, 1) + " MM, INPUT " +
          gcode::format_number(r.plan.input_order.travel_mm, 1) + " MM",
      "ORDER: ACODRILL " + std::string(aco::to_string(r.plan.solver.algorithm)) + " SEED " + std::to_string(r.plan.solver.seed),
      "COORDINATES, TOOLS, CYCLES AND DEPTHS AS IN THE INPUT"};
  std::ostringstream program;
  try {
    gcode::write_drilling(program, r.program, ws);
  } catch (const std::invalid_argument& e) {
    throw app::UserError(source, 0, e.what());
  } catch (const gcode::ProgramError& e) {
    throw app::UserError(source, e.line(), e.what());
  }
  const std::string program_text = broken_for_test(program.str());
  check_own_program(app::self_check(program_text, input), a.output);
  planning::Placement placement;
  placement.origin = planning::Origin{planning::OriginKind::Drawing, {}};
  placement.extent = planning::extent_of(r.holes);
  app::ReportContext ctx{source, a.output, placement, loaded.name, &loaded, {}, 1, 1, std::nullopt};
  ctx.program_input = app::ReportContext::ProgramInput{r.plan.groups.size(), r.overlapping_holes, r.overlap_groups,
                                                       a.keep_style ? "keep" : "dialect"};
  ctx.dialect = o.program.dialect;
  return finish_plan(a, program_text, r.holes, r.plan, o, ctx, planning::to_passes(r.holes, r.plan, o.machine));
}

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

int cmd_plan(const PlanArgs& a, const SolverArgs& s, const InputArgs& in_args) {
  // Refuse to overwrite an input with the program before doing any work.
  for (const std::string* out : {&a.output, &a.report, &a.svg, &a.svg_compare, &a.convergence, &a.excellon, &a.gerber, &a.setup_sheet}) {
    for (const std::string& input : a.inputs) {
      if (!out->empty() && app::same_file(input, *out)) throw app::UserError(*out, 0, "output would overwrite the input file " + input);
    }
  }
  planning::PlanOptions o;
  o.solver = to_params(s);
  const planning::Origin origin = parse_origin(a.origin.empty() ? "lower-left" : a.origin);
  std::optional<gcode::Dialect> dialect;
  if (!a.dialect.empty()) {
    dialect = gcode::dialect_from_string(a.dialect);
    if (!dialect) {
      throw app::UserError("--dialect must be haas, fanuc, linuxcnc, grbl or marlin (got \"" + a.dialect + "\")");
    }
  }
  // The machine decides the dialect unless one is given; a GRBL or Marlin
  // program without a --machine is for the desktop router those controls drive.
  const std::string machine = !a.machine.empty() ? a.machine
                              : dialect && !gcode::has_canned_cycles(*dialect) ? "router"
                                                                               : "vf2";
  o.machine = load_machine(machine);
  o.program.dialect = dialect.value_or(o.machine.dialect);
  o.program.spindle_start_s = o.machine.spindle_start_s;
  o.program.travel_feed_mm_min = o.machine.rapid_xy_mm_min;
  if (a.units.empty() || a.units == "mm") o.program.units = gcode::Units::Mm;
  else if (a.units == "inch" || a.units == "in") o.program.units = gcode::Units::Inch;
  else throw app::UserError("--units must be mm or inch (got \"" + a.units + "\")");
  if (!a.material.empty()) {
    auto material = planning::material_from_string(a.material);
    if (!material) throw app::UserError("--material must be steel, aluminium or pcb (got \"" + a.material + "\")");
    o.material = *material;
  }
  if (a.thickness && !(*a.thickness > 0 && *a.thickness < 1000)) throw app::UserError("--thickness must be in (0, 1000) mm");
  if (a.objective == "distance") o.objective = planning::Objective::Distance;
  else if (a.objective == "time") o.objective = planning::Objective::Time;
  else throw app::UserError("--objective must be distance or time (got \"" + a.objective + "\")");
  if (!a.tools.empty()) o.tools = planning::parse_tool_table(app::read_file(a.tools), a.tools);
  // The tools on the bench; a tool table names its own instead.
  if (!a.tools.empty() && (!a.bench.drills.empty() || a.bench.end_mill)) {
    throw app::UserError("--drills and --end-mill plan the tools you own; a --tools table names its own: drop one of them");
  }
  if (a.tools.empty()) o.tooling = tooling_of(a.bench, o.machine);
  parse_mirror_axis(a.bench);
  o.program.probe_plate_mm = a.probe_plate ? a.probe_plate : o.machine.probe_plate_mm;
  o.program.probe_feed_mm_min = o.machine.probe_feed_mm_min;
  o.program.probe_travel_mm = o.machine.probe_travel_mm;
  // Refused before any work, not when the program is written.
  if (o.program.probe_plate_mm) {
    if (auto refusal = gcode::probe_plate_refusal(o.program.dialect)) throw app::UserError(*refusal);
  }

  app::Job job = app::load_job(a.inputs, to_input_options(in_args));
  o.solver.time_limit_s = app::time_left(o.solver.time_limit_s, seconds_since_start());
  app::LoadedHoles& loaded = job.holes;
  if (loaded.program) return plan_program(a, o, loaded, in_args);
  if (a.keep_style || a.min_spacing > 0) {
    throw app::UserError("--keep-style and --min-spacing apply to a drilling program input (G-code)");
  }
  o.hole_source = job.hole_source;
  o.keep_sources_apart = a.keep_files_apart;
  // PCB drill data is a circuit board unless the user says otherwise: PCB
  // feeds and speeds through a 1.6 mm board, not a quarter inch of steel.
  const bool board = std::any_of(job.parts.begin(), job.parts.end(), [](const app::LoadedHoles& p) {
    return p.format == app::InputFormat::Excellon || p.format == app::InputFormat::Gerber;
  });
  if (a.material.empty() && board) o.material = planning::Material::Pcb;
  o.thickness_mm = a.thickness.value_or(o.material == planning::Material::Pcb ? 1.6 : 6.35);
  o.program.r_plane_mm = planning::r_plane_mm(o.machine, o.material);
  if (loaded.holes.empty() && loaded.round_contours > 0) {
    throw app::UserError(a.input == "-" ? "<stdin>" : a.input, 0,
                         "no CIRCLE to drill, but " + std::to_string(loaded.round_contours) +
                             " round closed contour(s) drawn without one (" + loaded.round_contour_kinds +
                             "): --round-contours reads them as holes");
  }
  if (loaded.holes.empty()) throw app::UserError(a.input == "-" ? "<stdin>" : a.input, 0, "no holes to drill");
  std::string source;  // the job's inputs, as messages and the program's header name them
  for (const std::string& input : a.inputs) source += (source.empty() ? "" : " + ") + (input == "-" ? std::string("<stdin>") : input);

  const bool progress = !a.quiet && !a.filter_progress && ::isatty(STDERR_FILENO);
  if (a.filter_progress) {
    // LinuxCNC's AXIS moves its progress bar by "FILTER_PROGRESS=N" lines from a filter program.
    const double limit = s.time_limit;
    const int iterations = aco::resolve(o.solver, loaded.holes.size()).iterations;
    // Each tool's colony gets a copy of the callback: the last line printed is shared.
    auto last = std::make_shared<int>(-1);
    o.solver.on_iteration = [limit, iterations, last](const aco::Progress& p) {
      const double done = limit > 0 ? seconds_since_start() / limit : static_cast<double>(p.iteration) / std::max(1, iterations);
      const int percent = std::clamp(static_cast<int>(100.0 * done), 0, 99);
      if (percent <= *last) return;
      *last = percent;
      std::fprintf(stderr, "FILTER_PROGRESS=%d\n", percent);
      std::fflush(stderr);
    };
  }
  if (progress) {
    o.solver.on_iteration = [](const aco::Progress& p) {
      if (p.wall_s < 1.0) return;
      std::fprintf(stderr, "\racodrill: iteration %d, %.1f s, best %.3f mm   ", p.iteration, p.wall_s, p.best_length);
    };
  }
  std::string source_name;
  for (const std::string& input : a.inputs) {
    source_name += (source_name.empty() ? "" : " + ") + formats::file_name(input);
  }
  // A panel: every copy of the board, in drawing coordinates, before program zero is chosen on the whole.
  std::size_t copies = 1;
  if (!a.panel.empty()) {
    const std::vector<planning::PanelCopy> placements = panel_copies(a.panel, a.pitch);
    copies = placements.size();
    if (loaded.holes.size() * copies > in_args.max_holes) {
      throw app::UserError("--panel: " + std::to_string(copies) + " copies of " + std::to_string(loaded.holes.size()) +
                           " holes exceed the hole limit (--max-holes " + std::to_string(in_args.max_holes) + ")");
    }
    loaded.holes = planning::panelize(loaded.holes, placements, o.hole_source);
  }
  // Program zero where the machinist will set the work offset.
  if (a.default_diameter) planning::fill_missing_diameters(loaded.holes, *a.default_diameter);
  planning::Placement placement;
  std::vector<std::string> side_notes;
  o.first_holes = turn_and_place(loaded.holes, a.bench, &origin, &placement, &side_notes);
  if (!o.hole_source.empty()) o.hole_source.resize(loaded.holes.size(), 0);
  planning::PlanResult plan = planning::plan_job(loaded.holes, o, source);
  if (progress) std::fprintf(stderr, "\r%60s\r", "");

  gcode::ProgramSettings& ps = o.program;
  ps.program_number = a.program_number;
  ps.program_name = loaded.name;
  ps.home = o.machine.start;
  ps.resume_from = a.resume_from;
  std::size_t n_tools = plan.groups.size();
  ps.header_comments = {
      "SOURCE: " + source_name,
      std::to_string(loaded.holes.size()) + " HOLES, " + std::to_string(n_tools) + (n_tools == 1 ? " TOOL" : " TOOLS"),
      "EST. TIME " + format_minutes(plan.optimized.time_s) + ", TRAVEL " +
          gcode::format_number(plan.optimized.travel_mm, 1) + " MM",
      "ORDER: ACODRILL " + std::string(aco::to_string(plan.solver.algorithm)) + " SEED " +
          std::to_string(plan.solver.seed),
      planning::origin_comment(placement),
      planning::extent_comment(placement, ps.units),
      planning::zero_comment(placement)};
  ps.header_comments.insert(ps.header_comments.end(), side_notes.begin(), side_notes.end());
  // Which drill makes which designed diameter, and by how much it differs.
  for (const planning::DrillMapping& d : plan.drill_map) ps.header_comments.push_back(drill_map_line(d));
  if (copies > 1) {
    ps.header_comments.push_back("PANEL: " + std::to_string(copies) + " COPIES OF " + std::to_string(loaded.holes.size() / copies) +
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
    const app::Note& n = loaded.skipped[i];
    ps.header_comments.push_back("NOT DRILLED: " + (n.line ? "LINE " + std::to_string(n.line) + ": " : std::string()) + n.message);
  }
  if (loaded.skipped.size() > kListed) {
    ps.header_comments.push_back("NOT DRILLED: " + std::to_string(loaded.skipped.size() - kListed) + " MORE (SEE THE REPORT)");
  }
  std::ostringstream program;
  const std::vector<gcode::ToolPass> passes = planning::to_passes(loaded.holes, plan, o.machine);
  try {
    gcode::write_program(program, passes, ps);
  } catch (const std::invalid_argument& e) {
    throw app::UserError(e.what());
  }

  const std::string program_text = broken_for_test(program.str());
  check_own_program(app::self_check(program_text, holes_written(loaded.holes, passes, a.resume_from),
                                    o.tools ? app::tooling_of_table(*o.tools) : o.tooling),
                    a.output);

  app::ReportContext ctx{source, a.output, placement, loaded.name, &loaded, {}, 1, 1, std::nullopt};
  for (const app::Job::Source& src : job.sources) ctx.sources.push_back({src.file, src.holes});
  ctx.panel_copies = copies;
  ctx.batch = a.batch;
  ctx.dialect = o.program.dialect;
  return finish_plan(a, program_text, loaded.holes, plan, o, ctx, passes, &job);
}

int cmd_tsp(const std::string& input, const std::string& tour, const SolverArgs& s, bool quiet) {
  aco::Params params = to_params(s);
  app::InputOptions io;
  app::LoadedHoles loaded = app::load_holes(input, io);
  if (loaded.holes.empty()) throw app::UserError(input, 0, "no nodes");
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

int cmd_verify(const std::string& program_path, const std::vector<std::string>& holes_paths, const std::string& origin_text,
               const std::string& panel, const std::string& pitch, const InputArgs& in_args, const BenchArgs& bench, bool quiet) {
  planning::Tooling tooling;
  if (!bench.drills.empty()) tooling.drills = planning::parse_owned_drills(bench.drills, "--drills");
  tooling.end_mill_mm = bench.end_mill;
  parse_mirror_axis(bench);
  const std::string text = app::read_file(program_path);
  gcode::Interpretation run;
  try {
    run = gcode::interpret(text);
  } catch (const gcode::ProgramError& e) {
    throw app::UserError(program_path, e.line(), e.what());
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
  if (holes_paths.empty()) return 0;
  std::string holes_path;
  for (const std::string& p : holes_paths) holes_path += (holes_path.empty() ? "" : " + ") + p;
  app::LoadedHoles expected = app::load_job(holes_paths, to_input_options(in_args)).holes;
  if (!panel.empty() || !pitch.empty()) {
    std::vector<std::uint32_t> no_sources;
    expected.holes = planning::panelize(expected.holes, panel_copies(panel, pitch), no_sources);
  }
  if (expected.program) {
    // Another program as the hole source: the same holes, tools and depths, where it put them.
    const std::vector<std::string> faults = app::check_same_holes(run, *expected.program);
    if (faults.empty()) {
      std::printf("ok: %zu holes of %s drilled once each with the same tool and depth\n", expected.program->hole_count(),
                  holes_path.c_str());
      return 0;
    }
    std::printf("faults %zu\n", faults.size());
    for (const auto& f : faults) std::printf("fault: %s\n", f.c_str());
    if (!quiet) std::fprintf(stderr, "acodrill: %s: %zu fault(s), first: %s\n", program_path.c_str(), faults.size(), faults[0].c_str());
    return 1;
  }
  // The holes as the program should drill them: moved to the program zero
  // --origin names, else the one the program states (acodrill writes it in its
  // header), else where they are (another CAM's program).
  // Turned over and pinned as plan was told (--side, --alignment-pins).
  planning::Placement placement;
  if (!origin_text.empty()) {
    const planning::Origin origin = parse_origin(origin_text);
    turn_and_place(expected.holes, bench, &origin, &placement, nullptr);
  } else if (auto zero = planning::stated_zero(text)) {
    const planning::Origin origin{planning::OriginKind::Point, *zero};
    turn_and_place(expected.holes, bench, &origin, &placement, nullptr);
  } else {
    turn_and_place(expected.holes, bench, nullptr, nullptr, nullptr);
  }
  const std::vector<std::string> faults = app::check_drilled(run, expected.holes, tooling);
  if (faults.empty()) {
    std::printf("ok: %zu input holes drilled once each with the right tool\n", expected.holes.size());
    return 0;
  }
  std::printf("faults %zu\n", faults.size());
  for (const auto& f : faults) std::printf("fault: %s\n", f.c_str());
  if (!quiet) std::fprintf(stderr, "acodrill: %s: %zu fault(s), first: %s\n", program_path.c_str(), faults.size(), faults[0].c_str());
  return 1;
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
  if (!show.empty()) load_machine(show);  // names the classes there are
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef _WIN32
  // Programs and CSV on standard output byte for byte as in a file: LF, not CRLF.
  ::_setmode(::_fileno(stdout), _O_BINARY);
#endif
  // Every name as UTF-8, on Windows too (issue 68): the arguments as the system holds them.
  app::Utf8Argv utf8(argc, argv);
  argc = utf8.argc();
  argv = utf8.argv();
  CLI::App cli{"acodrill orders the drill holes of a part so the spindle travels as little as possible, "
               "and writes the G-code that drills them.\n\n"
               "Examples:\n"
               "  acodrill plan plate.dxf -o plate.nc --report plate.json\n"
               "  acodrill plan board.drl -o board.nc --dialect linuxcnc --units inch\n"
               "  acodrill holes plate.dxf --format csv > holes.csv\n"
               "  acodrill verify plate.nc --holes plate.dxf\n"
               "  acodrill tsp pcb442.tsp --time-limit 1\n"
               "  acodrill machines\n",
               "acodrill"};
  cli.set_version_flag("--version", kVersion);
  cli.set_help_all_flag("--help-all", "Print the help of every command and exit (the man page is made from it)");
  cli.require_subcommand(1);
  bool quiet = false;

  SolverArgs solver;
  InputArgs in_args;
  PlanArgs plan;
  auto* plan_cmd = cli.add_subcommand("plan", "Read holes, order them per tool and write a drilling program");
  plan_cmd->footer(
      "Examples:\n"
      "  acodrill plan plate.dxf -o plate.nc                       HAAS program, mm\n"
      "  acodrill plan plate.dxf -o - --quiet > plate.nc           program on stdout, nothing else\n"
      "  acodrill plan plate.dxf -o plate.nc --report r.json --convergence c.csv\n"
      "  acodrill plan plate.dxf -o plate.nc --tools tools.json --machine vf2.json\n"
      "  acodrill plan plate.dxf -o plate.nc --resume-from 37      restart at hole N37 after a broken drill\n"
      "  acodrill plan plate.dxf -o plate.nc --origin center --setup-sheet plate.html\n"
      "                                                            zero at the holes' centre; a sheet for the operator\n"
      "  acodrill plan plate.dxf -o plate.nc --algorithm as --local-search none --ants 125 --iterations 125\n"
      "                                                            the thesis's Ant System\n"
      "  acodrill plan board.drl -o board.nc --machine router      a desktop router on GRBL: every hole as G0/G1\n"
      "                                                            moves, a pause naming each drill (--dialect marlin)\n"
      "  acodrill plan board.drl -o board.gcode --machine router --drills 0.6,0.8,1.0,1.2 --end-mill 1.0 --probe-plate 0.5\n"
      "                                                            the drills you own, an end mill for the rest, Z probed\n"
      "                                                            on a 0.5 mm touch plate after each change\n"
      "  acodrill plan board.drl -o back.gcode --machine router --side back --alignment-pins 3\n"
      "                                                            the back of the board, mirrored, two pin holes first\n"
      "  acodrill plan board-PTH.drl board-NPTH.drl -o board.nc --machine pcb-drill\n"
      "                                                            plated and non-plated holes, one program\n"
      "  acodrill plan board.drl -o panel.nc --panel 3x2 --pitch 60,40 --batch 50\n"
      "                                                            six boards a panel, the time for 50 panels\n"
      "  acodrill plan pcb2gcode-drill.ngc -o shorter.ngc --keep-style\n"
      "                                                            another CAM's program, its holes reordered per tool\n"
      "Inputs: DXF, Excellon, Gerber (RS-274X/X2; RS-274D with --apertures), XML hole map, CSV (x,y,diameter mm),\n"
      "TSPLIB, a G-code drilling program (canned or expanded: its tools, cycles and depths are kept); '-' reads stdin.");
  plan_cmd->add_option("input", plan.inputs,
                       "Input files, one job (DXF, Excellon, Gerber, XML, CSV, TSPLIB, any mix; holes of one diameter "
                       "share a tool), or one G-code program to reorder; - reads stdin")
      ->required();
  plan_cmd->add_option("-o,--output", plan.output, "Program to write (- = stdout)")->required();
  plan_cmd->add_option("--report", plan.report, "Write a JSON report: holes, tools, travel, time, solver");
  plan_cmd->add_option("--svg", plan.svg, "Write a picture of the route (SVG)");
  plan_cmd->add_option("--svg-compare", plan.svg_compare, "Write input order and optimized route side by side (SVG)");
  plan_cmd->add_option("--convergence", plan.convergence, "Write best length by iteration and time (CSV)");
  plan_cmd->add_option("--excellon", plan.excellon, "Also write the optimized order as an Excellon drill file");
  plan_cmd->add_option("--gerber", plan.gerber, "Also write the optimized order as an RS-274X (Gerber X2) drill file");
  plan_cmd->add_option("--setup-sheet", plan.setup_sheet,
                       "Write a printable setup sheet (HTML): program zero, tools, times, route picture");
  plan_cmd->add_option("--origin", plan.origin,
                       "Program zero (X0 Y0) on the part: lower-left (default) | center | upper-left of the holes' "
                       "bounding box, drawing (keep CAD coordinates) or X,Y (a point of the drawing, mm). The "
                       "machinist sets the work offset (G54) there; the program header says where it is");
  plan_cmd->add_option("--dialect", plan.dialect,
                       "haas | fanuc | linuxcnc: canned cycles, M6 tool changes; grbl (GRBL 1.1, grblHAL, FluidNC) | "
                       "marlin: every hole written out as G0/G1 moves (pecks and dwells too), each tool a pause (M0) "
                       "with a message naming the drill, Z zeroed again on it. Default: the machine's (vf2: haas, "
                       "router: grbl); grbl or marlin without --machine plans for the router class");
  plan_cmd->add_flag("--keep-style", plan.keep_style,
                     "Program input: keep the input's own lines and style (canned stays canned, expanded stays "
                     "expanded; line numbers renumbered), rewriting only where its holes are drilled");
  plan_cmd->add_option("--min-spacing", plan.min_spacing,
                       "Program input: holes of a tool closer than MM (or than the drill, where the program names "
                       "its diameter) overlap and are drilled together in their input order (default 0)")
      ->check(CLI::Range(0.0, 1e4));
  plan_cmd->add_option("--units", plan.units, "Program units: mm (default; a program input keeps its own) | inch");
  plan_cmd->add_option("--tools", plan.tools, "Tool table (JSON); default: one tool per diameter");
  plan_cmd->add_option("--machine", plan.machine,
                       "A built-in machine class (acodrill machines: vf2, router, pcb-drill, pcb-proto) or a profile file (JSON): rapids, "
                       "acceleration, spindle range, tool change, travel; sets the time estimate, the generated "
                       "tools' speeds and the default dialect. Default: vf2");
  plan_cmd->add_option("--material", plan.material, "steel | aluminium | pcb: feeds and speeds of generated tools (default steel; pcb for Excellon and Gerber input)");
  plan_cmd->add_option("--thickness", plan.thickness, "Part thickness in mm for generated tools (default 6.35, or 1.6 for pcb)");
  plan_cmd->add_option("--default-diameter", plan.default_diameter,
                       "Diameter in mm of holes the input gives none (CSV rows without one, TSPLIB nodes)")
      ->check(CLI::Range(1e-6, 1e4));
  plan_cmd->add_option("--objective", plan.objective,
                       "distance (default) | time: minimise travel or rapid time. Distance is the default for every "
                       "class: where rapids move in a straight line (router, pcb-drill) the two are the same route; "
                       "on the vf2's dogleg rapids, time changed the moving time by -0.1 to +1.9 % (under 0.3 s a board) "
                       "on the real boards we measured while making the travel up to 11 % longer");
  plan_cmd->add_option("--resume-from", plan.resume_from, "Drill holes N, N+1, ... of the same order (default 1)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}));
  plan_cmd->add_option("--program-number", plan.program_number, "O-number (default 1001)")->check(CLI::Range(1, 99999));
  plan_cmd->add_option("--panel", plan.panel,
                       "Drill copies of the board as one job: COLSxROWS with --pitch DX,DY (copy (c,r) moved by "
                       "(c*DX, r*DY) mm), or a panel file {\"copies\": [{\"x_mm\", \"y_mm\", \"rotate_deg\" 0|90|180|270, "
                       "\"mirror\"}, ...]}. Each tool is routed across the whole panel, not board after board");
  plan_cmd->add_option("--pitch", plan.pitch, "DX,DY in mm between panel copies (with --panel COLSxROWS)");
  plan_cmd->add_option("--batch", plan.batch, "Report the time for N panels (or parts) run one after another (default 1)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}));
  plan_cmd->add_flag("--keep-files-apart", plan.keep_files_apart,
                     "Several inputs: each file's holes get tools of their own, drilled file after file (plated and "
                     "non-plated holes at different steps of the process)");
  plan_cmd->add_option("--probe-plate", plan.probe_plate,
                       "Thickness (mm) of a touch plate: after each tool change GRBL, Marlin and LinuxCNC programs probe Z "
                       "on it (G38.2), set Z to its thickness and pause to take the clip off (default: the profile's "
                       "probe_plate_mm; refused for HAAS and Fanuc)")
      ->check(CLI::Range(0.01, 50.0));
  add_bench_options(plan_cmd, plan.bench, true);
  plan_cmd->add_flag("--filter-progress", plan.filter_progress,
                     "Print the progress as FILTER_PROGRESS=N lines (N percent) on stderr, as LinuxCNC's AXIS reads "
                     "them from a filter program (acodrill-linuxcnc-filter)");
  plan_cmd->add_flag("-q,--quiet", plan.quiet, "Print nothing on success");
  add_solver_options(plan_cmd, solver);
  add_input_options(plan_cmd, in_args);

  std::string holes_input, holes_format = "csv";
  auto* holes_cmd = cli.add_subcommand("holes", "Print the holes an input holds (mm, world coordinates)");
  holes_cmd->footer("Example:\n  acodrill holes plate.dxf --format csv --layer 'DRILL*' > holes.csv");
  holes_cmd->add_option("input", holes_input, "Input file or - for stdin")->required();
  holes_cmd->add_option("--format", holes_format, "Output format: csv (the default)");
  holes_cmd->add_flag("-q,--quiet", quiet, "No summary on stderr");
  // `holes` lists the holes the input holds (the contract: every hit, every
  // round flash), so slots are not made into rows of holes here unless asked.
  InputArgs holes_in;
  holes_in.slots = "skip";
  add_input_options(holes_cmd, holes_in);

  std::string tsp_input, tsp_tour;
  SolverArgs tsp_solver;
  auto* tsp_cmd = cli.add_subcommand("tsp", "Solve a TSPLIB instance as a closed tour and print its length");
  tsp_cmd->footer("Example:\n  acodrill tsp pcb442.tsp --time-limit 1 --tour pcb442.tour");
  tsp_cmd->add_option("instance", tsp_input, "TSPLIB .tsp file (EUC_2D, CEIL_2D or ATT; its length is printed in that rounding)")->required();
  tsp_cmd->add_option("--tour", tsp_tour, "Write the tour in TSPLIB TOUR format");
  tsp_cmd->add_flag("-q,--quiet", quiet, "Print only the length");
  add_solver_options(tsp_cmd, tsp_solver);

  std::string verify_program, verify_origin, verify_panel, verify_pitch;
  std::vector<std::string> verify_holes;
  InputArgs verify_in;
  auto* verify_cmd = cli.add_subcommand("verify", "Read a drilling program back: what it drills, with which tool");
  verify_cmd->footer("Exit 1 when --holes is given and a hole is missed, repeated, moved or drilled with the wrong tool.\n"
                     "Example:\n  acodrill verify plate.nc --holes plate.dxf");
  verify_cmd->add_option("program", verify_program, "G-code program")->required();
  verify_cmd->add_option("--holes", verify_holes,
                         "The input(s) the program should drill: the same list as plan was given (--holes a.drl b.drl)")
      ->expected(1, 1000);
  verify_cmd->add_option("--origin", verify_origin,
                         "Where the program's zero sits on the --holes input (as for plan); default: what the "
                         "program's header states, else the input's own coordinates");
  verify_cmd->add_option("--panel", verify_panel, "The panel plan was given (COLSxROWS with --pitch, or a panel file)");
  verify_cmd->add_option("--pitch", verify_pitch, "DX,DY in mm, with --panel COLSxROWS");
  verify_cmd->add_flag("-q,--quiet", quiet, "No summary on stderr");
  BenchArgs verify_bench;
  add_bench_options(verify_cmd, verify_bench, false);
  add_input_options(verify_cmd, verify_in);

  std::string machines_show;
  auto* machines_cmd = cli.add_subcommand("machines", "List the built-in machine classes (NAME<TAB>description)");
  machines_cmd->footer("Examples:\n"
                       "  acodrill machines\n"
                       "  acodrill machines --show router > my-router.json    a profile to edit, then --machine my-router.json");
  machines_cmd->add_option("--show", machines_show, "Print the class's profile (JSON, with the sources of its figures)");

  // CLI11 would call an unknown command "a subcommand is required"; name it.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string first = argv[1];
    if (first != "plan" && first != "holes" && first != "tsp" && first != "verify" && first != "machines") {
      std::cerr << "acodrill: error: unknown command \"" << first
                << "\"; commands: plan, holes, tsp, verify, machines (see acodrill --help)\n";
      return 2;
    }
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (char& c : msg) if (c == '\n') c = ' ';
    std::cerr << "acodrill: error: " << msg << " (see acodrill --help)\n";
    return 2;
  }

  try {
    if (*plan_cmd) {
      plan.inputs = read_once(plan.inputs, plan.quiet);
      plan.input = plan.inputs.front();
      return cmd_plan(plan, solver, in_args);
    }
    if (*holes_cmd) return cmd_holes(holes_input, holes_in, holes_format, quiet);
    if (*tsp_cmd) return cmd_tsp(tsp_input, tsp_tour, tsp_solver, quiet);
    if (*verify_cmd) return cmd_verify(verify_program, read_once(verify_holes, quiet), verify_origin, verify_panel, verify_pitch, verify_in, verify_bench, quiet);
    if (*machines_cmd) return cmd_machines(machines_show);
  } catch (const app::UserError& e) {
    std::cerr << "acodrill: error: " << e.where_what() << "\n";
    return 2;
  } catch (const aco::Error& e) {
    std::cerr << "acodrill: error: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    std::cerr << "acodrill: error: out of memory\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "acodrill: error: internal: " << e.what() << "\n";
    return 3;
  }
  return 2;
}
