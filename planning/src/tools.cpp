#include "planning/tools.h"

#include <algorithm>
#include <cmath>

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
      if (!c) throw UserError(where, 0, "\"cycle\" must be one of G81, G82, G83, G73");
      tool.cycle = *c;
    }
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

ToolTable generate_tool_table(const aco::HoleSet& holes, Material material, double thickness_mm, const Machine& machine) {
  const int max_rpm = machine.max_rpm;
  // A board is drilled with carbide PCB drills in one stroke unless the
  // machine says it uses something else; a plate with HSS twist drills.
  const bool carbide = machine.drills == "carbide" || (machine.drills.empty() && material == Material::Pcb);
  std::vector<long long> keys;  // diameters in micrometres
  keys.reserve(holes.size());
  for (const aco::Hole& h : holes) keys.push_back(std::llround(h.diameter * 1000.0));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  // Cutting speed (m/min) and feed per revolution as a fraction of the
  // diameter, for HSS drills (Machinery's Handbook ranges, conservative end).
  double vc = 20.0, feed_per_d = 0.015;
  switch (material) {
    case Material::Steel: vc = 20.0; feed_per_d = 0.015; break;
    case Material::Aluminium: vc = 60.0; feed_per_d = 0.025; break;
    case Material::Pcb: vc = 100.0; feed_per_d = 0.02; break;
  }
  ToolTable t;
  t.generated = true;
  int number = 0;
  for (long long k : keys) {
    ToolTableEntry e;
    gcode::Tool& tool = e.tool;
    tool.number = ++number;
    tool.diameter_mm = static_cast<double>(k) / 1000.0;
    const double d = std::max(tool.diameter_mm, 0.1);
    if (carbide) {
      // Solid carbide micro drills in FR-4 (drill makers' charts, e.g. Union
      // Tool's and Kyocera's PCB drilling conditions): about 150 m/min at the
      // edge, and a feed per revolution growing with the diameter from about
      // 0.01 mm at 0.2 mm to 0.05 mm at 2 mm and above; one stroke, no pecks.
      const double vc_carbide = material == Material::Pcb ? 150.0 : vc * 2.0;
      tool.spindle_rpm = static_cast<int>(std::clamp(std::round(1000.0 * vc_carbide / (M_PI * d)), 100.0, std::max(100.0, double(max_rpm))));
      const double per_rev = std::clamp(0.006 + 0.022 * d, 0.008, 0.05);
      tool.feed_mm_min = std::max(10.0, std::round(tool.spindle_rpm * per_rev));
      tool.depth_mm = -(thickness_mm + 0.3 * d + 0.5);
      tool.max_hits = default_max_hits(tool.diameter_mm);
      e.min_hole_mm = tool.diameter_mm - 0.0005;
      e.max_hole_mm = tool.diameter_mm + 0.0005;
      t.entries.push_back(e);
      continue;
    }
    tool.spindle_rpm = static_cast<int>(std::clamp(std::round(1000.0 * vc / (M_PI * d)), 100.0, std::max(100.0, double(max_rpm))));
    tool.feed_mm_min = std::max(10.0, std::round(tool.spindle_rpm * feed_per_d * d));
    // Through the plate, plus the 118° point (0.3 D) and 0.5 mm to break through.
    tool.depth_mm = -(thickness_mm + 0.3 * d + 0.5);
    if (-tool.depth_mm > 4.0 * d) {
      tool.cycle = gcode::Cycle::G83;  // deep hole: peck to clear chips
      tool.peck_mm = std::max(0.5, std::round(d * 10.0) / 10.0);
    }
    e.min_hole_mm = tool.diameter_mm - 0.0005;
    e.max_hole_mm = tool.diameter_mm + 0.0005;
    t.entries.push_back(e);
  }
  return t;
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
