#pragma once
/**
 * The main job as pure stages: holes → tool groups → an ordered open path per
 * tool → G-code passes, with the travel and machining time of the optimized
 * order and of the baselines. The CLI only reads files, calls these and writes.
 */
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"
#include "aco/problem.h"
#include "aco/solve.h"
#include "gcode/program.h"

namespace app {

// A machine profile (JSON, see README "Machine profile"); defaults describe a
// HAAS VF-2-class vertical mill. `acodrill machines` lists the built-in classes.
struct Machine {
  std::string name = "HAAS VF-2 class";
  // The dialect its control reads, used when --dialect is not given.
  gcode::Dialect dialect = gcode::Dialect::Haas;
  // False: the operator changes drills by hand at a pause (tool_change_s is
  // then that manual change, re-zeroing Z included).
  bool tool_changer = true;
  double spindle_start_s = 0.0;      // a control that does not wait for its spindle waits this long after M3
  // A PCB drilling machine's single-stroke hit: the seconds one hole costs at
  // the spot, Z down and up (its data sheet's "hits per minute"); 0: timed
  // from the tool's feed, pecks and dwell instead.
  double hit_s = 0.0;
  // The drills it uses: "hss" twist drills (the default) or "carbide" micro
  // drills, which a PCB drilling machine runs at high speed in one stroke.
  std::string drills = "hss";
  double rapid_xy_mm_min = 25400.0;  // 1000 in/min
  double rapid_z_mm_min = 25400.0;
  double accel_mm_s2 = 2500.0;       // per axis
  bool linear_rapids = false;        // HAAS G00 moves each axis at its own rate ("dogleg")
  double tool_change_s = 4.2;        // chip to chip
  int max_rpm = 8100;                // spindle limit; generated tools stay under it
  aco::Point2 start{0.0, 0.0};       // where the spindle is at the start and returns to (program XY)
  // The table's travel in machine coordinates (VF-2: 30 x 16 in). Without a
  // work offset only its size is known to matter: the machinist sets program
  // zero (G54) where the part is clamped, so only the holes' extent is checked.
  double x_min = 0.0, x_max = 762.0, y_min = 0.0, y_max = 406.0;
  // Where program zero (G54) sits in machine coordinates, when the profile
  // says; then every hole's absolute position is checked against the travel.
  std::optional<aco::Point2> work_offset;
  // Clamps and fixtures sticking up above the R plane (work XY rectangles):
  // a move across one retracts to the initial plane first; a hole in one is an error.
  struct Rect {
    double x_min, y_min, x_max, y_max;
  };
  std::vector<Rect> clamps;
};

// True when the straight move a → b passes over any clamp of the machine.
bool crosses_clamp(aco::Point2 a, aco::Point2 b, const Machine& machine);

// The built-in machine classes: a name, one line saying what it is, and its
// profile as JSON (the same keys a --machine FILE has, with the sources of
// its figures under "sources").
struct MachineClass {
  std::string name, description, profile_json;
};
const std::vector<MachineClass>& machine_classes();

// A built-in class by name, or a profile file; throws UserError naming the
// file (and line, for bad JSON) or the classes there are.
Machine load_machine(const std::string& name_or_path);
// A profile from its JSON text (`source` names it in errors).
Machine parse_machine(const std::string& json_text, const std::string& source);

// Cutting data presets for generated tool tables.
enum class Material { Steel, Aluminium, Pcb };
std::optional<Material> material_from_string(const std::string& name);
const char* to_string(Material m);

struct ToolTableEntry {
  gcode::Tool tool;
  double min_hole_mm = 0.0;   // holes in [min, max] are drilled with this tool
  double max_hole_mm = 0.0;
  int source = -1;            // only the holes of this input (PlanOptions::hole_source); -1: any
};

struct ToolTable {
  std::vector<ToolTableEntry> entries;  // drilling order
  bool generated = false;
};

ToolTable load_tool_table(const std::string& path);
// One tool per distinct diameter (to 0.001 mm), ascending, feeds and speeds
// from the material and the machine: HSS twist drills (pecked where deep), or
// on a machine with carbide micro drills (a PCB drill) single strokes at the
// carbide's speed and feed per revolution; spindle speeds within the machine's.
ToolTable generate_tool_table(const aco::HoleSet& holes, Material material, double thickness_mm, const Machine& machine);

enum class Objective { Distance, Time };

// Where program zero sits on the part (--origin): the drawing's own zero, a
// corner or the centre of the holes' bounding box, or a point of the drawing.
enum class OriginKind { Drawing, LowerLeft, Center, UpperLeft, Point };
struct Origin {
  OriginKind kind = OriginKind::LowerLeft;
  aco::Point2 point;  // OriginKind::Point: in input coordinates, mm
};
// "drawing", "lower-left", "center" (or "centre"), "upper-left" or "X,Y" in mm.
std::optional<Origin> origin_from_string(const std::string& text);
std::string to_string(const Origin& origin);      // as the option is written: "lower-left", "12.500,-3.000"
std::string describe(const Origin& origin);       // for the operator: "LOWER-LEFT OF HOLES"

// The bounding box of the hole centres.
struct Extent {
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
  double width() const { return x_max - x_min; }
  double height() const { return y_max - y_min; }
};
Extent extent_of(const aco::HoleSet& holes);

// Where the holes were put: program zero in the input's coordinates and the
// hole centres' extent in program coordinates.
struct Placement {
  Origin origin;
  aco::Point2 zero;  // program X0 Y0, in input coordinates (mm)
  Extent extent;     // program coordinates (mm)
};
// Moves the holes so that the origin's point becomes X0 Y0.
Placement place_holes(aco::HoleSet& holes, const Origin& origin);

// The program header comment that tells the operator where zero is and what
// the holes span, in program units:
// "ORIGIN: LOWER-LEFT OF HOLES; EXTENT X0.000..150.000 Y0.000..240.000 MM".
std::string origin_comment(const Placement& placement, gcode::Units units);

// The program header comment that records program zero in the input's
// coordinates ("PROGRAM ZERO AT DRAWING X21.100 Y25.500 MM"), and its reader:
// `verify --holes` moves the input holes by what the program states.
std::string zero_comment(const Placement& placement);
std::optional<aco::Point2> stated_zero(std::string_view program);

// One copy of a board on a panel: the board mirrored (X negated) if asked,
// turned about the drawing's zero by 0, 90, 180 or 270 degrees
// anticlockwise, then moved by `offset` (mm, drawing coordinates).
struct PanelCopy {
  aco::Point2 offset;
  int rotate_deg = 0;
  bool mirror = false;
};
// --panel COLSxROWS --pitch DX,DY: copy (c, r) moved by (c·DX, r·DY), row by row.
std::vector<PanelCopy> panel_grid(const std::string& cols_x_rows, const std::string& pitch);
// --panel FILE.json: {"copies": [{"x_mm": 0, "y_mm": 0, "rotate_deg": 0, "mirror": false}, ...]}.
std::vector<PanelCopy> load_panel(const std::string& path);
// Every copy's holes, copy after copy, each copy's slot chains its own;
// `hole_source` (per hole, may be empty) is repeated to match.
aco::HoleSet panelize(const aco::HoleSet& board, const std::vector<PanelCopy>& copies,
                      std::vector<std::uint32_t>& hole_source);

struct PlanOptions {
  aco::Params solver;
  Objective objective = Objective::Distance;
  Machine machine;
  std::optional<ToolTable> tools;  // nullopt: generated
  Material material = Material::Steel;
  double thickness_mm = 6.35;      // the thesis's 1/4" plate
  gcode::ProgramSettings program;
  // After the last hole the spindle returns to `finish` (default: the
  // machine's start) — or, for a program that ends over its last hole, stays.
  bool return_at_end = true;
  std::optional<aco::Point2> finish;
  // Several inputs: per hole, the input it came from (empty: one input). With
  // keep_sources_apart each input's holes get tools of their own, drilled
  // input after input (plated and non-plated holes at different steps);
  // otherwise holes of one diameter share a tool whatever file they are in.
  std::vector<std::uint32_t> hole_source;
  bool keep_sources_apart = false;
};

struct ToolGroup {
  gcode::Tool tool;
  std::vector<aco::HoleIndex> input_order;  // indices into the hole set, in input order
  aco::Order optimized;                     // the same indices, in drilling order
  aco::Order nearest_neighbor;              // baseline
  aco::Solution solution;
};

// Where the machine's time goes: moving between holes (XY rapids, and Z to
// and from the clearance), drilling (each hole's cycle at its spot), changing
// tools, and waiting (spindle run-up). The parts add up to the total.
struct TimeSplit {
  double moves_s = 0.0, drilling_s = 0.0, tool_changes_s = 0.0, pauses_s = 0.0;
  double total() const { return moves_s + drilling_s + tool_changes_s + pauses_s; }
};

struct RouteStats {
  double travel_mm = 0.0;   // XY, start → every hole of every tool → start
  double time_s = 0.0;      // machining time estimate
  TimeSplit split;          // the same time by what it is spent on
  std::vector<double> tool_time_s;  // per tool group: its tool change, moves and cycles (the return home is in none)
};

struct PlanResult {
  std::vector<ToolGroup> groups;
  RouteStats input_order, nearest_neighbor, optimized;
  int iterations = 0;       // summed over tool groups
  double solver_wall_s = 0.0;
  std::vector<double> thread_busy_s;
  aco::Params solver;       // with defaults resolved
};

// Gives every hole without a diameter (0: a CSV row without one, a TSPLIB
// node) the one the user chose (--default-diameter); returns how many.
std::size_t fill_missing_diameters(aco::HoleSet& holes, double diameter_mm);

// Checks that the holes (in program coordinates) fit the machine: their
// extent, tool edges included, against the size of its travel; absolute
// positions too when the profile gives the work offset. Throws UserError.
void check_travel(const aco::HoleSet& holes, const Machine& machine, const std::string& source);

// Groups the holes (in program coordinates) by tool and orders every group.
// Throws UserError (file `source`) for a hole without a diameter that no tool
// of the table takes, a hole no tool fits, one under a clamp
// or holes that do not fit the machine's travel (check_travel).
PlanResult plan_job(const aco::HoleSet& holes, const PlanOptions& options, const std::string& source);

// The life of a carbide micro drill in FR-4 by diameter, in hits (drill
// makers' figures for one 1.6 mm board per stack: the smallest wear first).
int default_max_hits(double diameter_mm);

// Drills that wear out: a group with more holes than its tool's max_hits is
// cut, in drilling order, into runs of at most max_hits, each run a physical
// drill of its own — a sister tool with the next free tool number — and the
// travel and time of every variant counted again with the extra changes.
void split_worn_drills(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options);

// Orders every group of `result` (its input_order set): each an open path
// from where the previous one ended, the last back to the finish; fills the
// orders, the solutions and the travel and time of each variant.
void order_groups(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options);

// The drilling passes of a plan, ready for gcode::write_program (with the
// G98 retracts the machine's clamps need).
std::vector<gcode::ToolPass> to_passes(const aco::HoleSet& holes, const PlanResult& plan, const Machine& machine);

// XY travel and time of drilling the groups in the given orders.
RouteStats route_stats(const aco::HoleSet& holes, const std::vector<ToolGroup>& groups,
                       const std::vector<const aco::Order*>& orders, const PlanOptions& options);

// Time of one rapid move of `distance` mm at `rate_mm_min` with acceleration `accel` (trapezoidal profile).
double rapid_time_s(double distance, double rate_mm_min, double accel_mm_s2);

}  // namespace app
