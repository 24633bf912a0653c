#include "planning/tools.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "json.h"

namespace planning {

std::optional<Material> material_from_string(const std::string& name) {
  for (Material m : {Material::Steel, Material::Aluminium, Material::Pcb}) {
    if (name == to_string(m)) return m;
  }
  if (name == "aluminum") return Material::Aluminium;
  return std::nullopt;
}

const char* to_string(Material m) {
  switch (m) {
    case Material::Steel: return "steel";
    case Material::Aluminium: return "aluminium";
    case Material::Pcb: return "pcb";
  }
  return "?";
}

ToolTable parse_tool_table(const std::string& text, const std::string& path) {
  json j = parse_json_text(text, path);
  const json* list = &j;
  if (j.is_object() && j.contains("tools")) list = &j["tools"];
  if (!list->is_array() || list->empty()) throw UserError(path, 1, "a tool table is {\"tools\": [ ... ]} with at least one tool");
  ToolTable t;
  int position = 0;
  for (const json& e : *list) {
    ++position;
    const std::string where = path + " (tool " + std::to_string(position) + ")";
    if (!e.is_object()) throw UserError(where, 0, "each tool is a JSON object");
    ToolTableEntry entry;
    gcode::Tool& tool = entry.tool;
    tool.number = static_cast<int>(json_number(e, "number", position, where));
    tool.diameter_mm = json_number(e, "diameter_mm", -1, where);
    if (!(tool.diameter_mm > 0)) throw UserError(where, 0, "\"diameter_mm\" must be given and positive");
    if (e.contains("name") && e["name"].is_string()) tool.name = e["name"].get<std::string>();
    // Left out, these come from a generated tool of the diameter (complete_tool_table).
    entry.has_rpm = e.contains("rpm");
    entry.has_feed = e.contains("feed_mm_min");
    entry.has_depth = e.contains("depth_mm");
    entry.has_cycle = e.contains("cycle");
    tool.spindle_rpm = static_cast<int>(json_number(e, "rpm", 3000, where));
    tool.feed_mm_min = json_number(e, "feed_mm_min", 250, where);
    tool.depth_mm = json_number(e, "depth_mm", -8, where);
    tool.peck_mm = json_number(e, "peck_mm", 0, where);
    tool.dwell_s = json_number(e, "dwell_s", 0, where);
    const double hits = json_number(e, "max_hits", 0, where);
    if (!(hits >= 0 && hits <= 1e9) || hits != std::floor(hits)) throw UserError(where, 0, "\"max_hits\" must be a whole number >= 0 (0: no limit)");
    tool.max_hits = static_cast<int>(hits);
    if (e.contains("cycle")) {
      auto c = e["cycle"].is_string() ? gcode::cycle_from_string(e["cycle"].get<std::string>()) : std::nullopt;
      if (!c) throw UserError(where, 0, "\"cycle\" must be one of G81, G82, G83, G73, G84, G74, G85");
      tool.cycle = *c;
    }
    if (e.contains("operation")) {
      // Issue 82: a tool of a hole feature's operation (a tap, a countersink, ...).
      auto op = e["operation"].is_string() ? gcode::operation_from_string(e["operation"].get<std::string>()) : std::nullopt;
      if (!op) throw UserError(where, 0, "\"operation\" must be one of spot, drill, ream, countersink, counterbore, tap");
      tool.operation = *op;
    }
    tool.pitch_mm = json_number(e, "pitch_mm", 0, where);
    tool.angle_deg = json_number(e, "angle_deg", 0, where);
    if (tool.pitch_mm < 0 || (tool.pitch_mm > 0 && tool.operation != gcode::Operation::Tap)) {
      throw UserError(where, 0, "\"pitch_mm\" is a tap's (\"operation\": \"tap\"), and positive");
    }
    if (!(tool.angle_deg >= 0 && tool.angle_deg < 180)) throw UserError(where, 0, "\"angle_deg\" must be below 180");
    entry.min_hole_mm = json_number(e, "min_hole_mm", tool.diameter_mm - 0.0005, where);
    entry.max_hole_mm = json_number(e, "max_hole_mm", tool.diameter_mm + 0.0005, where);
    if (tool.number < 1 || tool.number > 200) throw UserError(where, 0, "tool numbers are 1..200");
    if (tool.spindle_rpm < 1) throw UserError(where, 0, "\"rpm\" must be >= 1");
    if (!(tool.feed_mm_min > 0)) throw UserError(where, 0, "\"feed_mm_min\" must be positive");
    if (!(tool.depth_mm < 0)) throw UserError(where, 0, "\"depth_mm\" is the Z of the drill tip and must be below 0");
    if ((tool.cycle == gcode::Cycle::G83 || tool.cycle == gcode::Cycle::G73) && !(tool.peck_mm > 0)) {
      throw UserError(where, 0, "G83/G73 need \"peck_mm\" > 0");
    }
    if (tool.cycle == gcode::Cycle::G82 && !(tool.dwell_s > 0)) throw UserError(where, 0, "G82 needs \"dwell_s\" > 0");
    t.entries.push_back(entry);
  }
  return t;
}

namespace {

// Cutting speed (m/min) and feed per revolution as a fraction of the
// diameter, for HSS drills (Machinery's Handbook ranges, conservative end).
void hss_data(Material material, double& vc, double& feed_per_d) {
  switch (material) {
    case Material::Steel: vc = 20.0; feed_per_d = 0.015; return;
    case Material::Aluminium: vc = 60.0; feed_per_d = 0.025; return;
    case Material::Pcb: vc = 100.0; feed_per_d = 0.02; return;
  }
}

}  // namespace

int spindle_rpm_for(double vc_m_min, double diameter_mm, int max_rpm, double min_rpm) {
  return static_cast<int>(
      std::clamp(std::round(1000.0 * vc_m_min / (M_PI * diameter_mm)), min_rpm, std::max(min_rpm, double(max_rpm))));
}

gcode::Tool generated_drill(double diameter_mm, Material material, double thickness_mm, const Machine& machine) {
  // A board is drilled with carbide PCB drills in one stroke unless the
  // machine says it uses something else; a plate with HSS twist drills.
  const bool carbide = machine.drills == "carbide" || (machine.drills.empty() && material == Material::Pcb);
  double vc = 20.0, feed_per_d = 0.015;
  hss_data(material, vc, feed_per_d);
  gcode::Tool tool;
  tool.diameter_mm = diameter_mm;
  const double d = std::max(tool.diameter_mm, 0.1);
  if (carbide) {
    // Solid carbide micro drills in FR-4 (drill makers' charts, e.g. Union
    // Tool's and Kyocera's PCB drilling conditions): about 150 m/min at the
    // edge, and a feed per revolution growing with the diameter from about
    // 0.01 mm at 0.2 mm to 0.05 mm at 2 mm and above; one stroke, no pecks.
    const double vc_carbide = material == Material::Pcb ? 150.0 : vc * 2.0;
    tool.spindle_rpm = spindle_rpm_for(vc_carbide, d, machine.max_rpm);
    const double per_rev = std::clamp(0.006 + 0.022 * d, 0.008, 0.05);
    tool.feed_mm_min = std::max(10.0, std::round(tool.spindle_rpm * per_rev));
    if (material == Material::Pcb) {
      // Through the board, the 130-degree point of a PCB drill (0.233 D) and
      // 0.3 mm into the spoilboard, at most 1.4 mm below the board: the full
      // diameter is through for drills up to 4.7 mm, and a 1.6 mm board is
      // never drilled deeper than 3 mm.
      tool.depth_mm = -(thickness_mm + std::min(0.5 * d / std::tan(65.0 * M_PI / 180.0) + 0.3, 1.4));
    } else {
      tool.depth_mm = -(thickness_mm + 0.3 * d + 0.5);
    }
    tool.max_hits = default_max_hits(tool.diameter_mm);
    return tool;
  }
  tool.spindle_rpm = spindle_rpm_for(vc, d, machine.max_rpm);
  tool.feed_mm_min = std::max(10.0, std::round(tool.spindle_rpm * feed_per_d * d));
  // Through the plate, plus the 118° point (0.3 D) and 0.5 mm to break through.
  tool.depth_mm = -(thickness_mm + 0.3 * d + 0.5);
  if (-tool.depth_mm > 4.0 * d) {
    tool.cycle = gcode::Cycle::G83;  // deep hole: peck to clear chips
    tool.peck_mm = std::max(0.5, std::round(d * 10.0) / 10.0);
  }
  return tool;
}

gcode::Tool generated_end_mill(double diameter_mm, Material material, double thickness_mm, const Machine& machine) {
  gcode::Tool tool;
  tool.diameter_mm = diameter_mm;
  tool.end_mill = true;
  const double d = std::max(diameter_mm, 0.1);
  // Carbide end mills, two flutes: cutting speed and chip load per tooth
  // from makers' charts for small end mills (conservative end for the light
  // machines that mill boards at home), and depth a helix turn.
  double vc = 150.0, chip_per_d = 0.015, pitch_per_d = 0.5;
  switch (material) {
    case Material::Steel: vc = 60.0; chip_per_d = 0.005; pitch_per_d = 0.1; break;
    case Material::Aluminium: vc = 200.0; chip_per_d = 0.01; pitch_per_d = 0.25; break;
    case Material::Pcb: break;
  }
  tool.spindle_rpm = spindle_rpm_for(vc, d, machine.max_rpm);
  tool.feed_mm_min = std::max(10.0, std::round(tool.spindle_rpm * 2.0 * std::clamp(chip_per_d * d, 0.002, 0.05)));
  tool.depth_mm = -(thickness_mm + 0.3);
  tool.helix_pitch_mm = pitch_per_d * d;
  return tool;
}

ToolTable generate_tool_table(const aco::HoleSet& holes, Material material, double thickness_mm, const Machine& machine) {
  std::vector<long long> keys;  // diameters in micrometres
  keys.reserve(holes.size());
  for (const aco::Hole& h : holes) keys.push_back(std::llround(h.diameter * 1000.0));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  ToolTable t;
  t.generated = true;
  int number = 0;
  for (long long k : keys) {
    ToolTableEntry e;
    e.tool = generated_drill(static_cast<double>(k) / 1000.0, material, thickness_mm, machine);
    e.tool.number = ++number;
    e.min_hole_mm = e.tool.diameter_mm - 0.0005;
    e.max_hole_mm = e.tool.diameter_mm + 0.0005;
    t.entries.push_back(e);
  }
  return t;
}

bool ToolTableEntry::takes(double hole_mm) const {
  if (takes_mm.empty()) return hole_mm >= min_hole_mm - 1e-9 && hole_mm <= max_hole_mm + 1e-9;
  return std::any_of(takes_mm.begin(), takes_mm.end(), [&](double d) { return std::fabs(d - hole_mm) <= 0.0005 + 1e-9; });
}

ToolTable owned_tool_table(const aco::HoleSet& holes, const Tooling& tooling, Material material, double thickness_mm,
                           const Machine& machine, const std::string& source, std::vector<DrillMapping>& mapping) {
  std::map<long long, std::size_t> count;  // designed diameter (µm) → holes
  std::map<long long, std::size_t> slots;  // milled slots' widths (µm) → slots
  for (const aco::Hole& h : holes) ++(h.slot_end ? slots : count)[std::llround(h.diameter * 1000.0)];
  std::vector<std::pair<double, std::size_t>> diameters;
  for (const auto& [k, n] : count) diameters.push_back({static_cast<double>(k) / 1000.0, n});
  const std::vector<DiameterChoice> choices = choose_drills(diameters, tooling, source);
  ToolTable t;
  t.generated = true;
  std::map<std::size_t, std::size_t> entry_of_drill;  // drills are ascending: so are their entries
  for (const DiameterChoice& c : choices) {
    if (c.drill) entry_of_drill.emplace(*c.drill, 0);
  }
  for (auto& [drill, entry] : entry_of_drill) {
    entry = t.entries.size();
    ToolTableEntry e;
    e.tool = generated_drill(tooling.drills[drill].diameter_mm, material, thickness_mm, machine);
    e.tool.number = static_cast<int>(t.entries.size()) + 1;
    t.entries.push_back(e);
  }
  const bool milled = !slots.empty() || std::any_of(choices.begin(), choices.end(), [](const DiameterChoice& c) { return !c.drill; });
  if (!slots.empty() && !tooling.end_mill_mm) {
    throw UserError(source, 0, "--slots mill mills slots with the end mill: give --end-mill DIA");
  }
  if (milled) {
    ToolTableEntry e;
    e.tool = generated_end_mill(*tooling.end_mill_mm, material, thickness_mm, machine);
    e.tool.number = static_cast<int>(t.entries.size()) + 1;
    t.entries.push_back(e);
  }
  mapping.clear();
  for (const DiameterChoice& c : choices) {
    ToolTableEntry& e = c.drill ? t.entries[entry_of_drill.at(*c.drill)] : t.entries.back();
    e.takes_mm.push_back(c.designed_mm);
    mapping.push_back({c.designed_mm, c.holes, e.tool.number, e.tool.diameter_mm, !c.drill, false});
  }
  for (const auto& [k, n] : slots) {
    const double width = static_cast<double>(k) / 1000.0;
    if (width < *tooling.end_mill_mm + 2 * gcode::kPlungeRadiusMm) {
      throw UserError(source, 0, "--slots mill: slots " + gcode::format_number(width, 3) + " mm wide need an end mill narrower than that (this one is " +
                                     gcode::format_number(*tooling.end_mill_mm, 3) + " mm); --slots drill drills them as rows of holes");
    }
    mapping.push_back({width, n / 2, t.entries.back().tool.number, t.entries.back().tool.diameter_mm, true, true});
  }
  return t;
}

void complete_tool_table(ToolTable& table, Material material, double thickness_mm, const Machine& machine) {
  for (ToolTableEntry& e : table.entries) {
    if (e.has_rpm && e.has_feed && e.has_depth && e.has_cycle) continue;
    // An operation's tool (a tap, a countersink, ...) is completed from the
    // operation it is given (plan.cpp: the operation's own defaults).
    if (e.tool.operation != gcode::Operation::Drill) continue;
    const gcode::Tool g = generated_drill(e.tool.diameter_mm, material, thickness_mm, machine);
    if (!e.has_rpm) e.tool.spindle_rpm = g.spindle_rpm;
    if (!e.has_feed) e.tool.feed_mm_min = g.feed_mm_min;
    if (!e.has_depth) e.tool.depth_mm = g.depth_mm;
    if (!e.has_cycle && e.tool.peck_mm == 0 && e.tool.dwell_s == 0) {
      // A peck or a dwell given says which cycle was meant; otherwise the generated one.
      e.tool.cycle = g.cycle;
      e.tool.peck_mm = g.peck_mm;
    }
  }
}

double r_plane_mm(const Machine& machine, Material material) {
  return machine.r_plane_mm.value_or(material == Material::Pcb ? 1.0 : 2.5);
}

int default_max_hits(double d) {
  // Carbide micro drills in FR-4, one 1.6 mm board a stack: makers give
  // 1000-3000 hits for 0.2-0.3 mm drills, more for larger ones.
  if (d <= 0.3) return 1500;
  if (d <= 0.6) return 2000;
  if (d <= 1.2) return 3000;
  return 4000;
}

}  // namespace planning
