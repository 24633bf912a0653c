// The settings of a job, checked and turned into the stages' options; the
// messages name the command line's options, which the page's controls mirror.
#include "job/settings.h"

#include "planning/operations.h"

#include <cstdio>
#include <map>

#include "formats/error.h"
#include "gcode/program.h"

namespace job {

using UserError = formats::InputError;

aco::Params solver_params(const SolverSettings& s) {
  aco::Params p;
  auto alg = aco::algorithm_from_string(s.algorithm);
  if (!alg) throw UserError("--algorithm must be one of focused, acs, mmas, as (got \"" + s.algorithm + "\")");
  auto ls = aco::local_search_from_string(s.local_search);
  if (!ls) {
    throw UserError("--local-search must be one of none, 2opt, 2opt+oropt, 3opt, 5opt, auto (got \"" + s.local_search + "\")");
  }
  p.algorithm = *alg;
  p.local_search = *ls;
  if (s.rho && !(*s.rho > 0.0 && *s.rho <= 1.0)) throw UserError("--rho must be in (0, 1]");
  p.threads = s.threads;
  p.seed = s.seed;
  p.time_limit_s = s.time_limit_s;
  p.iterations = s.iterations;
  p.ants = s.ants;
  p.focus_edges = s.focus_edges;
  p.alpha = s.alpha;
  if (s.beta) p.beta = *s.beta;
  if (s.rho) p.rho = *s.rho;
  p.validate();
  return p;
}

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
    throw UserError(usage);
  }
  if (parts[0] == "mm" || parts[0] == "metric") f.metric = true;
  else if (parts[0] != "inch" && parts[0] != "in") throw UserError(usage);
  if (parts[2] == "lz") f.leading_zeros_kept = true;
  else if (parts[2] != "tz") throw UserError(usage);
  f.int_digits = a;
  f.dec_digits = b;
  return f;
}

formats::InputOptions input_options(const InputSettings& a) {
  formats::InputOptions o;
  o.dxf.layers = a.layers;
  if (a.min_diameter_mm) o.dxf.min_diameter_mm = *a.min_diameter_mm;
  if (a.max_diameter_mm) o.dxf.max_diameter_mm = *a.max_diameter_mm;
  o.dxf.max_holes = a.max_holes;
  o.dxf.max_holes_named = a.max_holes_named;
  o.dxf.max_block_references = a.max_expansion;
  if (!a.input_units.empty()) {
    if (a.input_units == "mm") o.default_unit_mm = 1.0;
    else if (a.input_units == "inch" || a.input_units == "in") o.default_unit_mm = 25.4;
    else throw UserError("--input-units must be mm or inch (got \"" + a.input_units + "\")");
    o.input_units_given = true;
  }
  if (a.slots == "drill") o.slots.policy = formats::SlotPolicy::Drill;
  else if (a.slots == "skip") o.slots.policy = formats::SlotPolicy::Skip;
  else if (a.slots == "mill") o.slots.policy = formats::SlotPolicy::Mill;
  else throw UserError("--slots must be drill, skip or mill (got \"" + a.slots + "\")");
  o.slots.pitch_mm = a.slot_pitch_mm;
  if (a.apertures) {
    o.aperture_list = a.apertures->text;
    o.aperture_list_path = a.apertures->name;
  }
  if (!a.excellon_format.empty()) o.excellon_format = parse_excellon_format(a.excellon_format);
  o.dxf.round_contours = a.round_contours;
  if (a.concentric != "features" && a.concentric != "separate") {
    throw UserError("--concentric must be features or separate (got \"" + a.concentric + "\")");
  }
  o.concentric_separate = a.concentric == "separate";
  o.step = a.step;
  o.keep_milling = a.keep_milling;
  if (a.processes) {
    o.processes = std::make_shared<const formats::ProcessTable>(planning::parse_process_table(a.processes->text, a.processes->name));
  }
  o.dxf.round_tolerance = a.round_tolerance_pct / 100.0;
  if (!a.dxf_units.empty()) {
    const std::map<std::string, double> units = {{"mm", 1.0},    {"cm", 10.0}, {"m", 1000.0},   {"inch", 25.4},
                                                 {"in", 25.4},   {"feet", 304.8}, {"ft", 304.8}};
    auto it = units.find(a.dxf_units);
    if (it == units.end()) throw UserError("--dxf-units must be mm, cm, m, inch or feet (got \"" + a.dxf_units + "\")");
    o.dxf.units_override_mm = it->second;
  }
  return o;
}

planning::Origin parse_origin(const std::string& text) {
  auto origin = planning::origin_from_string(text);
  if (!origin) {
    throw UserError("--origin must be drawing, lower-left, center, upper-left or X,Y in mm (got \"" + text + "\")");
  }
  return *origin;
}

planning::MirrorAxis parse_mirror_axis(const BenchSettings& a) {
  if (a.side != "front" && a.side != "back") throw UserError("--side must be front or back (got \"" + a.side + "\")");
  if (a.mirror_axis.empty()) return {};
  if (a.side != "back" && !a.alignment_pins_mm) throw UserError("--mirror-axis goes with --side back or --alignment-pins");
  auto axis = planning::mirror_axis_from_string(a.mirror_axis);
  if (!axis) throw UserError("--mirror-axis must be x=V or y=V in mm (got \"" + a.mirror_axis + "\")");
  return *axis;
}

planning::Machine machine_of(const std::string& name, const std::optional<NamedText>& profile) {
  if (profile) return planning::parse_machine(profile->text, profile->name);
  if (auto m = planning::builtin_machine(name)) return *m;
  throw UserError("--machine: no machine class \"" + name + "\" (built in: " + planning::machine_class_names() +
                  "; or give a profile file, see acodrill machines)");
}

std::vector<planning::PanelCopy> panel_copies(const std::string& panel, const std::string& pitch,
                                              const std::optional<NamedText>& panel_file) {
  if (panel_file) {
    if (!pitch.empty()) throw UserError("--pitch goes with --panel COLSxROWS, not with a panel file");
    return planning::parse_panel(panel_file->text, panel_file->name);
  }
  if (!pitch.empty() && panel.empty()) throw UserError("--pitch goes with --panel COLSxROWS");
  return planning::panel_grid(panel, pitch);
}

planning::Tooling tooling_of(const BenchSettings& a, const planning::Machine& machine) {
  planning::Tooling t;
  if (!a.drills.empty()) t.drills = planning::parse_owned_drills(a.drills, "--drills");
  else if (!machine.drills_owned.empty()) t.drills = planning::parse_owned_drills(machine.drills_owned, "drills_owned");
  t.end_mill_mm = a.end_mill_mm ? a.end_mill_mm : machine.end_mill_mm;
  return t;
}

std::vector<aco::HoleIndex> turn_and_place(aco::HoleSet& holes, const BenchSettings& a, const planning::Origin* origin,
                                           planning::Placement* placement, std::vector<std::string>* notes) {
  const planning::MirrorAxis axis = planning::resolve_mirror_axis(holes, parse_mirror_axis(a));
  const std::string line = std::string(axis.vertical ? "X=" : "Y=") + gcode::format_number(*axis.at, 3);
  if (a.side == "back") {
    planning::mirror_holes(holes, axis);
    if (notes) notes->push_back("SIDE: BACK, HOLES MIRRORED ABOUT " + line + " (DRAWING MM)");
  }
  aco::HoleSet pins = a.alignment_pins_mm ? planning::alignment_pins(holes, axis, *a.alignment_pins_mm) : aco::HoleSet{};
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
    notes->push_back("ALIGNMENT PINS: D" + gcode::format_number(*a.alignment_pins_mm, 3) + " ON " + line + " AT X" +
                     gcode::format_number(pins[0].center.x, 3) + " Y" + gcode::format_number(pins[0].center.y, 3) + " AND X" +
                     gcode::format_number(pins[1].center.x, 3) + " Y" + gcode::format_number(pins[1].center.y, 3) + ", DRILLED FIRST");
  }
  return first;
}

}  // namespace job
