// acodrill: the command line. Its argument tables, bound to the job's
// settings (job/settings.h); the commands themselves are in plan_command.cpp
// and commands.cpp. Argument parsing is CLI11 (Debian libcli11-dev):
// subcommands, typed options and generated --help in a few lines each, where
// hand-written parsing would be a few hundred lines of error-prone code.
#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#endif

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "aco/error.h"
#include "app/errors.h"
#include "app/files.h"
#include "commands.h"

namespace {

constexpr const char* kVersion = "acodrill " ACO_VERSION;

void add_solver_options(CLI::App* cmd, job::SolverSettings& a) {
  cmd->add_option("--threads", a.threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--seed", a.seed, "Random seed; same input, options and seed give the same output (default 1)");
  cmd->add_option("--time-limit", a.time_limit_s, "Stop after S seconds of the whole run, reading the input included (0 = no limit); plan shares S among its tools by hole count")->check(CLI::Range(0.0, 1e7));
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
  cmd->add_option("--local-search", a.local_search, "none | 2opt | 2opt+oropt | 3opt | 5opt | auto (default auto: 5opt from 3000 to 200000 holes, else 3opt; 3opt: 2-opt, Or-opt, and sequential 3-opt moves that go deeper, Lin-Kernighan style, when none gains; 5opt: 2-opt, Or-opt, then LKH's sequential 5-opt step on the ascent's penalised costs (plain lengths above 20000 holes), chained when none gains)");
  cmd->add_option("--focus-edges", a.focus_edges,
                  "focused: new edges an ant makes on the best route before it copies the rest (default 16)")
      ->check(CLI::Range(1, 1000000));
}

void add_input_options(CLI::App* cmd, cli::InputArgs& args) {
  job::InputSettings& a = args.settings;
  cmd->add_option("--layer", a.layers, "Only holes on these layers (repeatable; * and ? wildcards)");
  cmd->add_option("--min-diameter", a.min_diameter_mm, "Only holes at least this wide (mm)")->check(CLI::Range(0.0, 1e9));
  cmd->add_option("--max-diameter", a.max_diameter_mm, "Only holes at most this wide (mm)")->check(CLI::Range(0.0, 1e9));
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
  cmd->add_option("--concentric", a.concentric,
                  "features (default) | separate: how a DXF's concentric circles are read. features: one hole feature, "
                  "the smallest circle the hole, drilled through; a larger one a counterbore or countersink (its layer "
                  "CBORE, CSK, ... or a hole callout says which), never drilled through; a circle with a thread's arc "
                  "(about 3/4 of a turn at a standard major diameter) a tapped hole, drilled at the tap drill. "
                  "separate: every circle a hole of its own, drilled through");
  cmd->add_option("--step", a.step,
                  "ODB++ and IPC-2581: the step to drill, by name (default: the panel step, which places the others "
                  "with its step-and-repeat, if there is one, else the only step)");
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
  cmd->add_option("--slot-pitch", a.slot_pitch_mm, "Distance between a drilled slot's holes in mm (default: a quarter of its width)")
      ->check(CLI::Range(0.0, 1e4));
  cmd->add_option("--apertures", args.apertures,
                  "Aperture list of an RS-274D Gerber file: rows \"D10 C 0.032\" (D code, shape C/R/O, size; inch unless "
                  "a suffix MM/MIL or a line UNITS MM|INCH|MILS says), or RS-274X %FS/%MO/%AD lines");
  cmd->add_option("--processes", args.processes,
                  "Process table (JSON): which hole features get which operations, first rule that selects one wins. "
                  "{\"processes\": [{\"layer\": \"M6\", \"operations\": [\"spot\", \"drill\", {\"operation\": \"tap\", "
                  "\"thread\": \"M6\"}]}]}; a rule selects by layer, kind, diameter_mm (N or [min, max]) and thread; "
                  "operations: spot, drill, ream, countersink, counterbore, tap (README: Holes as drawn)");
  cmd->add_option("--max-expansion", a.max_expansion,
                  "Refuse DXF files whose blocks expand to more references than this (default 10000000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1'000'000'000}));
}

// `plan`: the options default to the machine profile's keys (verify has no machine; it takes what plan was given).
void add_bench_options(CLI::App* cmd, job::BenchSettings& a, bool plan) {
  cmd->add_option("--drills", a.drills,
                  "The drills you own, mm, comma-separated, each DIA or DIA:-MINUS:+PLUS (how much smaller and larger "
                  "than a hole it may be; default -0.05 and +0.10: leads need clearance, and larger is the safe side). "
                  "Each hole goes to a drill that fits it, using the fewest drills that cover every hole, then the "
                  "closest fit" + std::string(plan ? " (default: the machine profile's drills_owned, else one drill per diameter)"
                                                   : "; give verify what plan was given"));
  cmd->add_option("--end-mill", a.end_mill_mm,
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
  cmd->add_option("--alignment-pins", a.alignment_pins_mm,
                  "Add two pin holes of DIA mm on the mirror line, 10 mm beyond the outermost holes, drilled before "
                  "everything else, to register the board when it is turned over")
      ->check(CLI::Range(0.1, 50.0));
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

  cli::InputArgs in_args;
  cli::PlanArgs plan;
  job::PlanSettings& ps = plan.settings;
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
      "  acodrill plan pcb2gcode-drill.ngc -o shorter.ngc\n"
      "                                                            another CAM's program, its holes reordered per tool\n"
      "  acodrill plan job.tgz -o job.nc                           a board house's ODB++ job (a folder, .tgz or .zip;\n"
      "                                                            --step NAME), or IPC-2581: plated and non-plated apart\n"
      "Inputs: DXF, Excellon, Gerber (RS-274X/X2; RS-274D with --apertures), IPC-2581, ODB++, XML hole map,\n"
      "CSV (x,y,diameter mm), TSPLIB, a G-code drilling program (canned or expanded: its tools, cycles and depths\n"
      "are kept); '-' reads stdin.");
  plan_cmd->add_option("input", plan.inputs,
                       "Input files, one job (DXF, Excellon, Gerber, IPC-2581, ODB++, XML, CSV, TSPLIB, any mix; holes of one diameter "
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
  plan_cmd->add_option("--origin", ps.origin,
                       "Program zero (X0 Y0) on the part: lower-left (default) | center | upper-left of the holes' "
                       "bounding box, drawing (keep CAD coordinates) or X,Y (a point of the drawing, mm). The "
                       "machinist sets the work offset (G54) there; the program header says where it is");
  plan_cmd->add_option("--dialect", ps.dialect,
                       "haas | fanuc | linuxcnc: canned cycles, M6 tool changes; grbl (GRBL 1.1, grblHAL, FluidNC) | "
                       "marlin: every hole written out as G0/G1 moves (pecks and dwells too), each tool a pause (M0) "
                       "with a message naming the drill, Z zeroed again on it. Default: the machine's (vf2: haas, "
                       "router: grbl); grbl or marlin without --machine plans for the router class");
  plan_cmd->add_flag("--keep-style", ps.keep_style,
                     "Program input: keep the input's own lines and style (canned stays canned, expanded stays "
                     "expanded; line numbers renumbered), rewriting only where its holes are drilled. The default "
                     "for a program unless --dialect (or --units) is given");
  plan_cmd->add_flag("--keep-milling", in_args.settings.keep_milling,
                     "Program input that also mills (a FreeCAD Job with a profile or pocket): its cuts (a G1 in X/Y "
                     "anywhere but at the height where the last hole's feed began, arcs, cutter compensation) stay as "
                     "written and where they are, and only the drilling between them is reordered, in the input's own "
                     "style. Without it such a program is refused at its first cut");
  plan_cmd->add_option("--min-spacing", ps.min_spacing_mm,
                       "Program input: holes of a tool closer than MM (or than the drill, where the program names "
                       "its diameter) overlap and are drilled together in their input order (default 0)")
      ->check(CLI::Range(0.0, 1e4));
  plan_cmd->add_option("--units", ps.units, "Program units: mm (default; a program input keeps its own) | inch");
  plan_cmd->add_option("--tools", plan.tools, "Tool table (JSON); default: one tool per diameter");
  plan_cmd->add_option("--machine", plan.machine,
                       "A built-in machine class (acodrill machines: vf2, router, pcb-drill, pcb-proto) or a profile file (JSON): rapids, "
                       "acceleration, spindle range, tool change, travel; sets the time estimate, the generated "
                       "tools' speeds and the default dialect. Default: vf2");
  plan_cmd->add_option("--material", ps.material, "steel | aluminium | pcb: feeds and speeds of generated tools (default steel; pcb for Excellon, Gerber, IPC-2581 and ODB++ input)");
  plan_cmd->add_option("--thickness", ps.thickness_mm, "Part thickness in mm for generated tools (default 6.35, or 1.6 for pcb)");
  plan_cmd->add_flag("--spot", ps.spot,
                     "Spot every drilled hole first with one 90-degree spot drill (6 mm; 10 mm when a hole is larger), "
                     "to a cone as wide as the smallest hole; off by default (a machine profile's \"spot\": true turns it on)");
  plan_cmd->add_option("--default-diameter", ps.default_diameter_mm,
                       "Diameter in mm of holes the input gives none (CSV rows without one, TSPLIB nodes)")
      ->check(CLI::Range(1e-6, 1e4));
  plan_cmd->add_option("--objective", ps.objective,
                       "distance (default) | time: minimise travel or rapid time. Distance is the default for every "
                       "class: where rapids move in a straight line (router, pcb-drill) the two are the same route; "
                       "on the vf2's dogleg rapids, time changed the moving time by -0.1 to +1.9 % (under 0.3 s a board) "
                       "on the real boards we measured while making the travel up to 11 % longer");
  plan_cmd->add_option("--resume-from", ps.resume_from, "Drill holes N, N+1, ... of the same order (default 1)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}));
  plan_cmd->add_option("--program-number", ps.program_number, "O-number (default 1001)")->check(CLI::Range(1, 99999));
  plan_cmd->add_option("--panel", plan.panel,
                       "Drill copies of the board as one job: COLSxROWS with --pitch DX,DY (copy (c,r) moved by "
                       "(c*DX, r*DY) mm), or a panel file {\"copies\": [{\"x_mm\", \"y_mm\", \"rotate_deg\" 0|90|180|270, "
                       "\"mirror\"}, ...]}. Each tool is routed across the whole panel, not board after board");
  plan_cmd->add_option("--pitch", ps.pitch, "DX,DY in mm between panel copies (with --panel COLSxROWS)");
  plan_cmd->add_option("--batch", ps.batch, "Report the time for N panels (or parts) run one after another (default 1)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}));
  plan_cmd->add_flag("--keep-files-apart", ps.keep_files_apart,
                     "Several inputs: each file's holes get tools of their own, drilled file after file (plated and "
                     "non-plated holes at different steps of the process)");
  plan_cmd->add_option("--probe-plate", ps.probe_plate_mm,
                       "Thickness (mm) of a touch plate: after each tool change GRBL, Marlin and LinuxCNC programs probe Z "
                       "on it (G38.2), set Z to its thickness and pause to take the clip off (default: the profile's "
                       "probe_plate_mm; refused for HAAS and Fanuc)")
      ->check(CLI::Range(0.01, 50.0));
  add_bench_options(plan_cmd, ps.bench, true);
  plan_cmd->add_flag("--filter-progress", plan.filter_progress,
                     "Print the progress as FILTER_PROGRESS=N lines (N percent) on stderr, as LinuxCNC's AXIS reads "
                     "them from a filter program (acodrill-linuxcnc-filter)");
  plan_cmd->add_flag("-q,--quiet", plan.quiet, "Print nothing on success");
  add_solver_options(plan_cmd, ps.solver);
  add_input_options(plan_cmd, in_args);

  std::string holes_input, holes_format = "csv";
  auto* holes_cmd = cli.add_subcommand("holes", "Print the holes an input holds (mm, world coordinates)");
  holes_cmd->footer("Examples:\n  acodrill holes plate.dxf --format csv --layer 'DRILL*' > holes.csv\n"
                    "  acodrill holes plate.dxf --features      what each hole is: plain, tapped, counterbore, ...");
  holes_cmd->add_option("input", holes_input, "Input file or - for stdin")->required();
  holes_cmd->add_option("--format", holes_format, "Output format: csv (the default)");
  holes_cmd->add_flag("-q,--quiet", quiet, "No summary on stderr");
  bool holes_features = false;
  holes_cmd->add_flag("--features", holes_features,
                      "One row a hole feature instead of one a hole: x_mm,y_mm,kind,diameter_mm,outer_diameter_mm,thread,"
                      "layer,evidence; kind is plain, tapped, counterbore, countersink or undecided (a DXF's concentric "
                      "circles and thread arcs; other inputs' holes are plain)");
  // `holes` lists the holes the input holds (the contract: every hit, every
  // round flash), so slots are not made into rows of holes here unless asked.
  cli::InputArgs holes_in;
  holes_in.settings.slots = "skip";
  add_input_options(holes_cmd, holes_in);

  std::string tsp_input, tsp_tour;
  job::SolverSettings tsp_solver;
  auto* tsp_cmd = cli.add_subcommand("tsp", "Solve a TSPLIB instance as a closed tour and print its length");
  tsp_cmd->footer("Example:\n  acodrill tsp pcb442.tsp --time-limit 1 --tour pcb442.tour");
  tsp_cmd->add_option("instance", tsp_input, "TSPLIB .tsp file (EUC_2D, CEIL_2D or ATT; its length is printed in that rounding)")->required();
  tsp_cmd->add_option("--tour", tsp_tour, "Write the tour in TSPLIB TOUR format");
  tsp_cmd->add_flag("-q,--quiet", quiet, "Print only the length");
  add_solver_options(tsp_cmd, tsp_solver);

  cli::VerifyArgs verify;
  cli::InputArgs verify_in;
  auto* verify_cmd = cli.add_subcommand("verify", "Read a drilling program back: what it drills, with which tool");
  verify_cmd->footer("Exit 1 when --holes is given and a hole is missed, repeated, moved or drilled with the wrong tool.\n"
                     "Example:\n  acodrill verify plate.nc --holes plate.dxf");
  verify_cmd->add_option("program", verify.program, "G-code program")->required();
  verify_cmd->add_option("--holes", verify.holes,
                         "The input(s) the program should drill: the same list as plan was given (--holes a.drl b.drl)")
      ->expected(1, 1000);
  verify_cmd->add_option("--origin", verify.origin,
                         "Where the program's zero sits on the --holes input (as for plan); default: what the "
                         "program's header states, else the input's own coordinates");
  verify_cmd->add_option("--panel", verify.panel, "The panel plan was given (COLSxROWS with --pitch, or a panel file)");
  verify_cmd->add_option("--pitch", verify.pitch, "DX,DY in mm, with --panel COLSxROWS");
  verify_cmd->add_flag("--spot", verify.spot, "plan was given --spot: every drilled hole is spotted first");
  verify_cmd->add_flag("-q,--quiet", quiet, "No summary on stderr");
  add_bench_options(verify_cmd, verify.bench, false);
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
      plan.inputs = cli::read_once(plan.inputs, plan.quiet);
      return cli::cmd_plan(plan, in_args);
    }
    if (*holes_cmd) return cli::cmd_holes(holes_input, holes_in, holes_format, holes_features, quiet);
    if (*tsp_cmd) return cli::cmd_tsp(tsp_input, tsp_tour, tsp_solver, quiet);
    if (*verify_cmd) {
      verify.holes = cli::read_once(verify.holes, quiet);
      return cli::cmd_verify(verify, verify_in, quiet);
    }
    if (*machines_cmd) return cli::cmd_machines(machines_show);
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
