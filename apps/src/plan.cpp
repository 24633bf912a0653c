#include "app/plan.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

#include "aco/baselines.h"
#include "app/errors.h"
#include "app/files.h"

namespace app {

namespace {

using nlohmann::json;

std::string fmt3(double v) { return gcode::format_number(v, 3); }

double json_number(const json& j, const char* key, double fallback, const std::string& path) {
  if (!j.contains(key)) return fallback;
  const json& v = j.at(key);
  if (!v.is_number()) throw UserError(path, 0, std::string("\"") + key + "\" must be a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw UserError(path, 0, std::string("\"") + key + "\" must be finite");
  return d;
}

json parse_json_text(const std::string& text, const std::string& path) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into a line.
    const std::size_t at = std::min<std::size_t>(e.byte, text.size());
    const auto line = static_cast<std::uint32_t>(1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    std::string what = e.what();
    if (auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw UserError(path, line, "invalid JSON: " + what);
  }
}

json parse_json_file(const std::string& path) { return parse_json_text(read_file(path), path); }

}  // namespace

Machine load_machine(const std::string& name_or_path) {
  // A name without a path separator or extension is a built-in class, unless a file of that name is here.
  const bool plain = name_or_path.find_first_of("/.") == std::string::npos;
  if (plain && !std::filesystem::exists(name_or_path)) {
    std::string names;
    for (const MachineClass& c : machine_classes()) {
      if (c.name == name_or_path) return parse_machine(c.profile_json, "machine class " + c.name);
      names += (names.empty() ? "" : ", ") + c.name;
    }
    throw UserError("--machine: no machine class \"" + name_or_path + "\" (built in: " + names +
                    "; or give a profile file, see acodrill machines)");
  }
  return parse_machine(read_file(name_or_path), name_or_path);
}

Machine parse_machine(const std::string& text, const std::string& path) {
  json j = parse_json_text(text, path);
  if (!j.is_object()) throw UserError(path, 1, "a machine profile is a JSON object");
  Machine m;
  if (j.contains("name") && j["name"].is_string()) m.name = j["name"].get<std::string>();
  if (j.contains("dialect")) {
    auto d = j["dialect"].is_string() ? gcode::dialect_from_string(j["dialect"].get<std::string>()) : std::nullopt;
    if (!d) throw UserError(path, 0, "\"dialect\" must be haas, fanuc, linuxcnc, grbl or marlin");
    m.dialect = *d;
  }
  if (j.contains("tool_changer")) {
    if (!j["tool_changer"].is_boolean()) throw UserError(path, 0, "\"tool_changer\" must be true or false");
    m.tool_changer = j["tool_changer"].get<bool>();
  }
  m.spindle_start_s = json_number(j, "spindle_start_s", m.spindle_start_s, path);
  m.hit_s = json_number(j, "hit_s", m.hit_s, path);
  if (j.contains("drills")) {
    if (!j["drills"].is_string() || (j["drills"] != "hss" && j["drills"] != "carbide")) {
      throw UserError(path, 0, "\"drills\" must be \"hss\" or \"carbide\"");
    }
    m.drills = j["drills"].get<std::string>();
  }
  if (!(m.hit_s >= 0 && m.hit_s <= 600)) throw UserError(path, 0, "hit_s must be 0..600");
  if (!(m.spindle_start_s >= 0 && m.spindle_start_s <= 600)) throw UserError(path, 0, "spindle_start_s must be 0..600");
  m.rapid_xy_mm_min = json_number(j, "rapid_xy_mm_min", m.rapid_xy_mm_min, path);
  m.rapid_z_mm_min = json_number(j, "rapid_z_mm_min", m.rapid_z_mm_min, path);
  m.accel_mm_s2 = json_number(j, "accel_mm_s2", m.accel_mm_s2, path);
  m.tool_change_s = json_number(j, "tool_change_s", m.tool_change_s, path);
  m.max_rpm = static_cast<int>(json_number(j, "max_rpm", m.max_rpm, path));
  if (m.max_rpm < 1) throw UserError(path, 0, "max_rpm must be >= 1");
  if (j.contains("linear_rapids")) {
    if (!j["linear_rapids"].is_boolean()) throw UserError(path, 0, "\"linear_rapids\" must be true or false");
    m.linear_rapids = j["linear_rapids"].get<bool>();
  }
  m.start.x = json_number(j, "start_x_mm", m.start.x, path);
  m.start.y = json_number(j, "start_y_mm", m.start.y, path);
  m.x_min = json_number(j, "x_min_mm", m.x_min, path);
  m.x_max = json_number(j, "x_max_mm", m.x_max, path);
  m.y_min = json_number(j, "y_min_mm", m.y_min, path);
  m.y_max = json_number(j, "y_max_mm", m.y_max, path);
  if (!(m.rapid_xy_mm_min > 0) || !(m.rapid_z_mm_min > 0) || !(m.accel_mm_s2 > 0)) {
    throw UserError(path, 0, "rapid rates and acceleration must be positive");
  }
  if (m.tool_change_s < 0) throw UserError(path, 0, "tool_change_s must be >= 0");
  if (!(m.x_min < m.x_max) || !(m.y_min < m.y_max)) throw UserError(path, 0, "travel limits are empty (min >= max)");
  const bool has_wx = j.contains("work_offset_x_mm"), has_wy = j.contains("work_offset_y_mm");
  if (has_wx != has_wy) throw UserError(path, 0, "give both work_offset_x_mm and work_offset_y_mm, or neither");
  if (has_wx) m.work_offset = aco::Point2{json_number(j, "work_offset_x_mm", 0, path), json_number(j, "work_offset_y_mm", 0, path)};
  if (j.contains("clamps")) {
    if (!j["clamps"].is_array()) throw UserError(path, 0, "\"clamps\" is a list of {x_min_mm, y_min_mm, x_max_mm, y_max_mm}");
    for (const json& c : j["clamps"]) {
      if (!c.is_object()) throw UserError(path, 0, "each clamp is {x_min_mm, y_min_mm, x_max_mm, y_max_mm}");
      Machine::Rect r{json_number(c, "x_min_mm", NAN, path), json_number(c, "y_min_mm", NAN, path),
                      json_number(c, "x_max_mm", NAN, path), json_number(c, "y_max_mm", NAN, path)};
      if (!(r.x_min < r.x_max) || !(r.y_min < r.y_max)) {
        throw UserError(path, 0, "a clamp needs x_min_mm < x_max_mm and y_min_mm < y_max_mm");
      }
      m.clamps.push_back(r);
    }
  }
  return m;
}

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

ToolTable load_tool_table(const std::string& path) {
  json j = parse_json_file(path);
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
  const bool carbide = machine.drills == "carbide";
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

std::optional<Origin> origin_from_string(const std::string& text) {
  Origin o;
  if (text == "drawing") o.kind = OriginKind::Drawing;
  else if (text == "lower-left") o.kind = OriginKind::LowerLeft;
  else if (text == "center" || text == "centre") o.kind = OriginKind::Center;
  else if (text == "upper-left") o.kind = OriginKind::UpperLeft;
  else {
    const auto comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    auto number = [](const std::string& s, double& out) {
      std::size_t used = 0;
      try {
        out = std::stod(s, &used);
      } catch (const std::exception&) {
        return false;
      }
      return used == s.size() && std::isfinite(out);
    };
    o.kind = OriginKind::Point;
    if (!number(text.substr(0, comma), o.point.x) || !number(text.substr(comma + 1), o.point.y)) return std::nullopt;
  }
  return o;
}

std::string to_string(const Origin& o) {
  switch (o.kind) {
    case OriginKind::Drawing: return "drawing";
    case OriginKind::LowerLeft: return "lower-left";
    case OriginKind::Center: return "center";
    case OriginKind::UpperLeft: return "upper-left";
    case OriginKind::Point: return fmt3(o.point.x) + "," + fmt3(o.point.y);
  }
  return "?";
}

std::string describe(const Origin& o) {
  switch (o.kind) {
    case OriginKind::Drawing: return "DRAWING ZERO";
    case OriginKind::LowerLeft: return "LOWER-LEFT OF HOLES";
    case OriginKind::Center: return "CENTER OF HOLES";
    case OriginKind::UpperLeft: return "UPPER-LEFT OF HOLES";
    case OriginKind::Point: return "DRAWING POINT X" + fmt3(o.point.x) + " Y" + fmt3(o.point.y);
  }
  return "?";
}

Extent extent_of(const aco::HoleSet& holes) {
  if (holes.empty()) return {};
  Extent e{holes[0].center.x, holes[0].center.x, holes[0].center.y, holes[0].center.y};
  for (const aco::Hole& h : holes) {
    e.x_min = std::min(e.x_min, h.center.x);
    e.x_max = std::max(e.x_max, h.center.x);
    e.y_min = std::min(e.y_min, h.center.y);
    e.y_max = std::max(e.y_max, h.center.y);
  }
  return e;
}

Placement place_holes(aco::HoleSet& holes, const Origin& origin) {
  Placement p;
  p.origin = origin;
  const Extent e = extent_of(holes);
  switch (origin.kind) {
    case OriginKind::Drawing: p.zero = {0.0, 0.0}; break;
    case OriginKind::LowerLeft: p.zero = {e.x_min, e.y_min}; break;
    case OriginKind::Center: p.zero = {(e.x_min + e.x_max) / 2, (e.y_min + e.y_max) / 2}; break;
    case OriginKind::UpperLeft: p.zero = {e.x_min, e.y_max}; break;
    case OriginKind::Point: p.zero = origin.point; break;
  }
  if (p.zero.x != 0.0 || p.zero.y != 0.0) {
    for (aco::Hole& h : holes) {
      h.center.x -= p.zero.x;
      h.center.y -= p.zero.y;
    }
  }
  p.extent = extent_of(holes);
  return p;
}

std::string origin_comment(const Placement& p, gcode::Units units) {
  const bool inch = units == gcode::Units::Inch;
  auto c = [&](double mm) { return gcode::format_number(inch ? mm / 25.4 : mm, inch ? 4 : 3); };
  const Extent& e = p.extent;
  return "ORIGIN: " + describe(p.origin) + "; EXTENT X" + c(e.x_min) + ".." + c(e.x_max) + " Y" + c(e.y_min) + ".." +
         c(e.y_max) + (inch ? " IN" : " MM");
}

std::string zero_comment(const Placement& p) {
  // Six decimals: verify moves the input holes by this, and must land within
  // the program's own rounding of each position.
  return "PROGRAM ZERO AT DRAWING X" + gcode::format_number(p.zero.x, 6) + " Y" + gcode::format_number(p.zero.y, 6) + " MM";
}

std::optional<aco::Point2> stated_zero(std::string_view program) {
  // "(PROGRAM ZERO AT ...)", or "; PROGRAM ZERO AT ..." in a Marlin program.
  static constexpr std::string_view kTag = "PROGRAM ZERO AT DRAWING X";
  const auto at = program.find(kTag);
  if (at == std::string_view::npos) return std::nullopt;
  // Locale-free, as the emitter wrote it: "<x> Y<y> MM".
  std::string_view rest = program.substr(at + kTag.size(), 80);
  double x = 0, y = 0;
  auto rx = std::from_chars(rest.data(), rest.data() + rest.size(), x);
  if (rx.ec != std::errc() || rest.substr(static_cast<std::size_t>(rx.ptr - rest.data()), 2) != " Y") return std::nullopt;
  rest.remove_prefix(static_cast<std::size_t>(rx.ptr - rest.data()) + 2);
  auto ry = std::from_chars(rest.data(), rest.data() + rest.size(), y);
  if (ry.ec != std::errc() || rest.substr(static_cast<std::size_t>(ry.ptr - rest.data()), 3) != " MM") return std::nullopt;
  if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  return aco::Point2{x, y};
}

std::vector<PanelCopy> panel_grid(const std::string& text, const std::string& pitch) {
  int cols = 0, rows = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &cols, &x, &rows, &rest) != 3 || (x != 'x' && x != 'X') || cols < 1 || rows < 1 ||
      static_cast<long long>(cols) * rows > 10000) {
    throw UserError("--panel must be COLSxROWS (e.g. 3x2, at most 10000 copies) or a panel file (got \"" + text + "\")");
  }
  double dx = 0, dy = 0;
  if (pitch.empty() || std::sscanf(pitch.c_str(), "%lf,%lf%c", &dx, &dy, &rest) != 2 || !std::isfinite(dx) || !std::isfinite(dy)) {
    throw UserError("--panel " + text + " needs --pitch DX,DY in mm (the distance from one copy to the next)");
  }
  std::vector<PanelCopy> copies;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) copies.push_back({{c * dx, r * dy}, 0, false});
  }
  return copies;
}

std::vector<PanelCopy> load_panel(const std::string& path) {
  const json j = parse_json_file(path);
  if (!j.is_object() || !j.contains("copies") || !j["copies"].is_array() || j["copies"].empty()) {
    throw UserError(path, 1, "a panel file is {\"copies\": [{\"x_mm\": 0, \"y_mm\": 0, \"rotate_deg\": 0, \"mirror\": false}, ...]}");
  }
  std::vector<PanelCopy> copies;
  int k = 0;
  for (const json& c : j["copies"]) {
    const std::string where = path + " (copy " + std::to_string(++k) + ")";
    if (!c.is_object()) throw UserError(where, 0, "each copy is a JSON object");
    PanelCopy copy;
    copy.offset = {json_number(c, "x_mm", 0.0, where), json_number(c, "y_mm", 0.0, where)};
    const double turn = json_number(c, "rotate_deg", 0.0, where);
    if (turn != 0 && turn != 90 && turn != 180 && turn != 270) throw UserError(where, 0, "rotate_deg must be 0, 90, 180 or 270");
    copy.rotate_deg = static_cast<int>(turn);
    if (c.contains("mirror")) {
      if (!c["mirror"].is_boolean()) throw UserError(where, 0, "\"mirror\" must be true or false");
      copy.mirror = c["mirror"].get<bool>();
    }
    copies.push_back(copy);
  }
  return copies;
}

aco::HoleSet panelize(const aco::HoleSet& board, const std::vector<PanelCopy>& copies, std::vector<std::uint32_t>& hole_source) {
  std::uint32_t chains = 0;
  for (const aco::Hole& h : board) chains = std::max(chains, h.chain);
  aco::HoleSet out;
  out.reserve(board.size() * copies.size());
  std::vector<std::uint32_t> sources;
  for (std::size_t k = 0; k < copies.size(); ++k) {
    const PanelCopy& c = copies[k];
    for (std::size_t i = 0; i < board.size(); ++i) {
      aco::Hole h = board[i];
      double x = c.mirror ? -h.center.x : h.center.x, y = h.center.y;
      // Quarter turns exactly: no sin/cos rounding on a copy's coordinates.
      for (int q = 0; q < c.rotate_deg / 90; ++q) {
        const double t = x;
        x = -y;
        y = t;
      }
      h.center = {x + c.offset.x, y + c.offset.y};
      if (h.chain != 0) h.chain += static_cast<std::uint32_t>(k) * chains;
      out.push_back(std::move(h));
      if (!hole_source.empty()) sources.push_back(hole_source[i]);
    }
  }
  if (!hole_source.empty()) hole_source = std::move(sources);
  return out;
}

std::size_t fill_missing_diameters(aco::HoleSet& holes, double diameter_mm) {
  std::size_t filled = 0;
  for (aco::Hole& h : holes) {
    if (!(h.diameter > 0)) {
      h.diameter = diameter_mm;
      ++filled;
    }
  }
  return filled;
}

void check_travel(const aco::HoleSet& holes, const Machine& m, const std::string& source) {
  if (holes.empty()) return;
  // The part's envelope: hole centres widened by each hole's radius (the tool's edge).
  Extent env{1e300, -1e300, 1e300, -1e300};
  for (const aco::Hole& h : holes) {
    const double r = h.diameter / 2;
    env.x_min = std::min(env.x_min, h.center.x - r);
    env.x_max = std::max(env.x_max, h.center.x + r);
    env.y_min = std::min(env.y_min, h.center.y - r);
    env.y_max = std::max(env.y_max, h.center.y + r);
  }
  const double travel_x = m.x_max - m.x_min, travel_y = m.y_max - m.y_min;
  constexpr double kSlack = 1e-6;  // mm: a part exactly as large as the travel fits
  if (env.width() > travel_x + kSlack || env.height() > travel_y + kSlack) {
    const bool turned = env.height() <= travel_x + kSlack && env.width() <= travel_y + kSlack;
    throw UserError(source, 0, "the holes span " + fmt3(env.width()) + " x " + fmt3(env.height()) +
                                   " mm (tool edges included) but the machine travels " + fmt3(travel_x) + " x " +
                                   fmt3(travel_y) + " mm" +
                                   (turned ? "; turned by 90 degrees the part would fit: rotate it in CAD"
                                           : "; use a --machine profile of a larger machine"));
  }
  if (!m.work_offset) return;
  // The profile says where program zero is on the machine: positions are known.
  const aco::Point2 w = *m.work_offset;
  if (env.x_min + w.x < m.x_min - kSlack || env.x_max + w.x > m.x_max + kSlack || env.y_min + w.y < m.y_min - kSlack ||
      env.y_max + w.y > m.y_max + kSlack) {
    throw UserError(source, 0, "with the work offset at X" + fmt3(w.x) + " Y" + fmt3(w.y) +
                                   " the holes reach machine X " + fmt3(env.x_min + w.x) + ".." + fmt3(env.x_max + w.x) +
                                   " Y " + fmt3(env.y_min + w.y) + ".." + fmt3(env.y_max + w.y) +
                                   " mm, outside the travel X " + fmt3(m.x_min) + ".." + fmt3(m.x_max) + " Y " +
                                   fmt3(m.y_min) + ".." + fmt3(m.y_max) + " mm");
  }
}

bool crosses_clamp(aco::Point2 a, aco::Point2 b, const Machine& machine) {
  // Liang-Barsky: clip the segment against each rectangle.
  for (const Machine::Rect& r : machine.clamps) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - r.x_min, r.x_max - a.x, a.y - r.y_min, r.y_max - a.y};
    bool outside = false;
    for (int k = 0; k < 4 && !outside; ++k) {
      if (p[k] == 0.0) {
        if (q[k] < 0.0) outside = true;
      } else {
        const double t = q[k] / p[k];
        if (p[k] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) outside = true;
      }
    }
    if (!outside) return true;
  }
  return false;
}

double rapid_time_s(double distance, double rate_mm_min, double accel) {
  if (distance <= 0.0) return 0.0;
  const double v = rate_mm_min / 60.0;
  // Trapezoid: accelerate to v, cruise, brake; a short move never reaches v (triangle).
  if (distance >= v * v / accel) return distance / v + v / accel;
  return 2.0 * std::sqrt(distance / accel);
}

namespace {

double xy_move_time(aco::Point2 a, aco::Point2 b, const Machine& m) {
  const double dx = std::fabs(a.x - b.x), dy = std::fabs(a.y - b.y);
  if (m.linear_rapids) return rapid_time_s(std::hypot(dx, dy), m.rapid_xy_mm_min, m.accel_mm_s2);
  return std::max(rapid_time_s(dx, m.rapid_xy_mm_min, m.accel_mm_s2), rapid_time_s(dy, m.rapid_xy_mm_min, m.accel_mm_s2));
}

// Z time of one hole's cycle at the R plane: feed down, pecks, dwell, rapid out.
double cycle_time_s(const gcode::Tool& t, const gcode::ProgramSettings& s, const Machine& m, bool retract_initial) {
  const double depth = s.r_plane_mm - t.depth_mm;
  double time = depth / t.feed_mm_min * 60.0;
  const auto zr = [&](double d) { return rapid_time_s(d, m.rapid_z_mm_min, m.accel_mm_s2); };
  if ((t.cycle == gcode::Cycle::G83 || t.cycle == gcode::Cycle::G73) && t.peck_mm > 0) {
    const int pecks = static_cast<int>(std::ceil(depth / t.peck_mm));
    for (int k = 1; k < pecks; ++k) {
      const double reached = k * t.peck_mm;
      // G83 retracts to R and comes back; G73 backs off a little.
      time += t.cycle == gcode::Cycle::G83 ? 2.0 * zr(reached) : 2.0 * zr(0.25);
    }
  }
  if (t.cycle == gcode::Cycle::G82) time += t.dwell_s;
  time += zr(depth);  // out of the hole to R
  if (retract_initial) time += 2.0 * zr(s.initial_z_mm - s.r_plane_mm);
  return time;
}

}  // namespace

RouteStats route_stats(const aco::HoleSet& holes, const std::vector<ToolGroup>& groups,
                       const std::vector<const aco::Order*>& orders, const PlanOptions& options) {
  RouteStats st;
  const Machine& m = options.machine;
  const auto& s = options.program;
  TimeSplit& split = st.split;
  // Each part is added to the total as it is added to its share, in the same order as ever.
  auto spend = [&](double& share, double seconds) {
    share += seconds;
    st.time_s += seconds;
  };
  const bool waits_for_spindle = !gcode::has_canned_cycles(s.dialect);
  aco::Point2 at = m.start;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const aco::Order& order = *orders[g];
    const double before = st.time_s;
    if (order.empty()) {
      st.tool_time_s.push_back(0.0);
      continue;
    }
    spend(split.tool_changes_s, m.tool_change_s);
    if (waits_for_spindle) spend(split.pauses_s, m.spindle_start_s);
    // Down from Z home to the initial plane, once per tool (approximate Z home as 100 mm up).
    spend(split.moves_s, rapid_time_s(100.0, m.rapid_z_mm_min, m.accel_mm_s2));
    for (std::size_t i = 0; i < order.size(); ++i) {
      const aco::Point2 p = holes[order[i]].center;
      st.travel_mm += aco::euclidean(at, p);
      spend(split.moves_s, xy_move_time(at, p, m));
      const bool last = i + 1 == order.size();
      const bool clear = !last && crosses_clamp(p, holes[order[i + 1]].center, m);
      spend(split.drilling_s, m.hit_s > 0 ? m.hit_s : cycle_time_s(groups[g].tool, s, m, !s.retract_to_r || last || clear));
      if (i == 0) spend(split.moves_s, rapid_time_s(s.initial_z_mm - s.r_plane_mm, m.rapid_z_mm_min, m.accel_mm_s2));
      at = p;
    }
    spend(split.moves_s, rapid_time_s(100.0, m.rapid_z_mm_min, m.accel_mm_s2));
    st.tool_time_s.push_back(st.time_s - before);
  }
  if (options.return_at_end) {
    const aco::Point2 finish = options.finish.value_or(m.start);
    st.travel_mm += aco::euclidean(at, finish);
    spend(split.moves_s, xy_move_time(at, finish, m));
  }
  return st;
}

namespace {

// A tool group's holes as the solver sees them: one point per stop, where a
// stop is a single hole or a whole chain. Without chains, stop i is hole i.
struct RouteUnits {
  std::vector<aco::Point2> points;
  std::vector<std::size_t> begin;  // stop k drills members[begin[k] .. begin[k+1])
  aco::Order members;              // hole indices grouped by stop, chains in their own order

  aco::Order expand(const aco::Order& stops) const {
    aco::Order out;
    out.reserve(members.size());
    for (aco::HoleIndex k : stops) out.insert(out.end(), members.begin() + static_cast<long>(begin[k]),
                                              members.begin() + static_cast<long>(begin[k + 1]));
    return out;
  }
};

RouteUnits route_units(const aco::HoleSet& holes, const aco::Order& input_order) {
  RouteUnits u;
  u.points.reserve(input_order.size());
  u.begin.reserve(input_order.size() + 1);
  const bool chains = std::any_of(input_order.begin(), input_order.end(), [&](aco::HoleIndex h) { return holes[h].chain != 0; });
  if (!chains) {
    for (aco::HoleIndex h : input_order) u.points.push_back(holes[h].center);
    u.members = input_order;
    for (std::size_t i = 0; i <= input_order.size(); ++i) u.begin.push_back(i);
    return u;
  }
  // Stops in the order of their first hole; a chain's holes keep their order.
  std::map<std::uint32_t, std::size_t> stop_of_chain;
  std::vector<aco::Order> stops;
  for (aco::HoleIndex h : input_order) {
    const std::uint32_t c = holes[h].chain;
    if (c == 0) {
      stops.push_back({h});
      continue;
    }
    auto [it, fresh] = stop_of_chain.emplace(c, stops.size());
    if (fresh) stops.emplace_back();
    stops[it->second].push_back(h);
  }
  for (const aco::Order& stop : stops) {
    u.begin.push_back(u.members.size());
    aco::Point2 centroid{0, 0};
    for (aco::HoleIndex h : stop) {
      centroid.x += holes[h].center.x;
      centroid.y += holes[h].center.y;
      u.members.push_back(h);
    }
    u.points.push_back({centroid.x / static_cast<double>(stop.size()), centroid.y / static_cast<double>(stop.size())});
  }
  u.begin.push_back(u.members.size());
  return u;
}

}  // namespace

int default_max_hits(double d) {
  // Carbide micro drills in FR-4, one 1.6 mm board a stack: makers give
  // 1000-3000 hits for 0.2-0.3 mm drills, more for larger ones.
  if (d <= 0.3) return 1500;
  if (d <= 0.6) return 2000;
  if (d <= 1.2) return 3000;
  return 4000;
}

void split_worn_drills(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options) {
  const bool any = std::any_of(result.groups.begin(), result.groups.end(), [](const ToolGroup& g) {
    return g.tool.max_hits > 0 && g.optimized.size() > static_cast<std::size_t>(g.tool.max_hits);
  });
  if (!any) return;
  int next_number = 0;
  for (const ToolGroup& g : result.groups) next_number = std::max(next_number, g.tool.number);
  std::vector<ToolGroup> split;
  for (ToolGroup& g : result.groups) {
    const std::size_t life = g.tool.max_hits > 0 ? static_cast<std::size_t>(g.tool.max_hits) : g.optimized.size();
    if (g.optimized.size() <= life) {
      split.push_back(std::move(g));
      continue;
    }
    // The same cut in every variant, so that each is timed with the same changes.
    auto chunk = [&](const aco::Order& order, std::size_t k) {
      const std::size_t from = std::min(order.size(), k * life), to = std::min(order.size(), (k + 1) * life);
      return aco::Order(order.begin() + static_cast<long>(from), order.begin() + static_cast<long>(to));
    };
    const std::size_t runs = (g.optimized.size() + life - 1) / life;
    for (std::size_t k = 0; k < runs; ++k) {
      ToolGroup part;
      part.tool = g.tool;
      if (k > 0) {
        part.tool.number = ++next_number;
        part.tool.name = gcode::tool_name(g.tool) + " SISTER OF T" + std::to_string(g.tool.number);
      }
      part.input_order = chunk(g.input_order, k);
      part.nearest_neighbor = chunk(g.nearest_neighbor, k);
      part.optimized = chunk(g.optimized, k);
      part.solution = g.solution;
      split.push_back(std::move(part));
    }
  }
  if (next_number > 200) {
    throw UserError("the drills' lives (max_hits) need tool numbers up to T" + std::to_string(next_number) +
                    "; a control has T1..T200: give longer lives or split the job");
  }
  result.groups = std::move(split);
  std::vector<const aco::Order*> in, nn, opt;
  for (const ToolGroup& g : result.groups) {
    in.push_back(&g.input_order);
    nn.push_back(&g.nearest_neighbor);
    opt.push_back(&g.optimized);
  }
  result.input_order = route_stats(holes, result.groups, in, options);
  result.nearest_neighbor = route_stats(holes, result.groups, nn, options);
  result.optimized = route_stats(holes, result.groups, opt, options);
}

void order_groups(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options) {
  const Machine& m = options.machine;
  const aco::Point2 finish = options.finish.value_or(m.start);
  // Each tool's holes as an open path from where the previous tool ended; the
  // last one ends at the start position, so the return home is optimised too.
  const aco::Metric metric = options.objective == Objective::Time && !m.linear_rapids ? aco::Metric::Chebyshev
                                                                                      : aco::Metric::Euclidean;
  aco::Point2 at = m.start, at_nn = m.start;
  result.solver = aco::resolve(options.solver, holes.size());
  for (std::size_t g = 0; g < result.groups.size(); ++g) {
    ToolGroup& group = result.groups[g];
    const bool last = g + 1 == result.groups.size();
    aco::Problem p;
    p.metric = metric;
    p.shape = aco::Shape::OpenPath;
    p.start = at;
    if (last && options.return_at_end) p.end = finish;
    // The route's stops: a hole, or a chain (a drilled slot's holes) drilled
    // together in its own order, stopping at the chain's centroid.
    const RouteUnits units = route_units(holes, group.input_order);
    p.points = units.points;
    // --time-limit bounds the whole run: each tool gets its share by hole count.
    aco::Params params = options.solver;
    if (params.time_limit_s > 0) {
      params.time_limit_s = std::max(0.01, options.solver.time_limit_s * static_cast<double>(group.input_order.size()) /
                                               static_cast<double>(holes.size()));
    }
    group.solution = aco::solve(p, params);
    group.optimized = units.expand(group.solution.order);
    aco::Problem pnn = p;
    pnn.start = at_nn;
    group.nearest_neighbor = units.expand(aco::nearest_neighbor(pnn));
    at = holes[group.optimized.back()].center;
    at_nn = holes[group.nearest_neighbor.back()].center;
    result.iterations += group.solution.iterations;
    result.solver_wall_s += group.solution.wall_s;
    if (result.thread_busy_s.size() < group.solution.thread_busy_s.size()) {
      result.thread_busy_s.resize(group.solution.thread_busy_s.size(), 0.0);
    }
    for (std::size_t k = 0; k < group.solution.thread_busy_s.size(); ++k) {
      result.thread_busy_s[k] += group.solution.thread_busy_s[k];
    }
  }
  std::vector<const aco::Order*> in, nn, opt;
  for (const ToolGroup& g : result.groups) {
    in.push_back(&g.input_order);
    nn.push_back(&g.nearest_neighbor);
    opt.push_back(&g.optimized);
  }
  result.input_order = route_stats(holes, result.groups, in, options);
  result.nearest_neighbor = route_stats(holes, result.groups, nn, options);
  result.optimized = route_stats(holes, result.groups, opt, options);
}

PlanResult plan_job(const aco::HoleSet& holes, const PlanOptions& options, const std::string& source) {
  const Machine& m = options.machine;
  // A hole without a diameter would become a "0.000 MM DRILL": the user says
  // which drill (--default-diameter), or a tool table has a tool that takes it.
  const bool table_takes_zero =
      options.tools && std::any_of(options.tools->entries.begin(), options.tools->entries.end(),
                                   [](const ToolTableEntry& e) { return e.min_hole_mm <= 1e-9; });
  for (const aco::Hole& h : holes) {
    if (!(h.diameter > 0) && !table_takes_zero) {
      throw UserError(source, h.source_line,
                      "hole without a diameter; give one with --default-diameter MM, or a --tools table "
                      "with a tool whose min_hole_mm is 0");
    }
  }
  check_travel(holes, m, source);
  for (const aco::Hole& h : holes) {
    for (const Machine::Rect& r : m.clamps) {
      if (h.center.x >= r.x_min && h.center.x <= r.x_max && h.center.y >= r.y_min && h.center.y <= r.y_max) {
        throw UserError(source, h.source_line, "hole at (" + fmt3(h.center.x) + ", " + fmt3(h.center.y) +
                                                   ") lies under a clamp of the machine profile");
      }
    }
  }

  ToolTable table;
  const bool apart = options.keep_sources_apart && !options.hole_source.empty();
  if (apart) {
    if (options.tools) throw UserError(source, 0, "keeping inputs apart generates each input's tools; drop --tools");
    // Each input's tools, numbered on from the previous input's.
    const std::uint32_t sources = *std::max_element(options.hole_source.begin(), options.hole_source.end()) + 1;
    for (std::uint32_t k = 0; k < sources; ++k) {
      aco::HoleSet mine;
      for (std::size_t i = 0; i < holes.size(); ++i) {
        if (options.hole_source[i] == k) mine.push_back(holes[i]);
      }
      if (mine.empty()) continue;
      ToolTable part = generate_tool_table(mine, options.material, options.thickness_mm, m);
      for (ToolTableEntry& e : part.entries) {
        e.tool.number = static_cast<int>(table.entries.size()) + 1;
        e.source = static_cast<int>(k);
        table.entries.push_back(e);
      }
    }
    table.generated = true;
  } else {
    table = options.tools ? *options.tools : generate_tool_table(holes, options.material, options.thickness_mm, m);
  }
  PlanResult result;
  result.groups.resize(table.entries.size());
  std::vector<std::string> unfit;
  std::size_t unfit_count = 0;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const double d = holes[i].diameter;
    std::size_t chosen = table.entries.size();
    for (std::size_t t = 0; t < table.entries.size(); ++t) {
      if (table.entries[t].source >= 0 && static_cast<std::uint32_t>(table.entries[t].source) != options.hole_source[i]) continue;
      if (d >= table.entries[t].min_hole_mm - 1e-9 && d <= table.entries[t].max_hole_mm + 1e-9) {
        chosen = t;
        break;
      }
    }
    if (chosen == table.entries.size()) {
      ++unfit_count;
      if (unfit.size() < 5) {
        unfit.push_back("D" + fmt3(d) + " at (" + fmt3(holes[i].center.x) + ", " + fmt3(holes[i].center.y) + ")" +
                        (holes[i].source_line ? " line " + std::to_string(holes[i].source_line) : ""));
      }
      continue;
    }
    result.groups[chosen].input_order.push_back(static_cast<aco::HoleIndex>(i));
  }
  if (unfit_count > 0) {
    std::string list;
    for (const auto& u : unfit) list += (list.empty() ? "" : "; ") + u;
    if (unfit_count > unfit.size()) list += "; ...";
    throw UserError(source, 0, std::to_string(unfit_count) + " hole(s) fit no tool in the tool table: " + list);
  }
  for (std::size_t t = 0; t < table.entries.size(); ++t) result.groups[t].tool = table.entries[t].tool;
  result.groups.erase(std::remove_if(result.groups.begin(), result.groups.end(),
                                     [](const ToolGroup& g) { return g.input_order.empty(); }),
                      result.groups.end());

  order_groups(holes, result, options);
  split_worn_drills(holes, result, options);
  return result;
}

std::vector<gcode::ToolPass> to_passes(const aco::HoleSet& holes, const PlanResult& plan, const Machine& machine) {
  std::vector<gcode::ToolPass> passes;
  std::size_t index = 0;
  for (const ToolGroup& g : plan.groups) {
    gcode::ToolPass pass;
    pass.tool = g.tool;
    for (aco::HoleIndex h : g.optimized) {
      pass.holes.push_back(holes[h].center);
      pass.index.push_back(++index);
    }
    if (!machine.clamps.empty()) {
      pass.clear_after.assign(pass.holes.size(), false);
      for (std::size_t i = 0; i + 1 < pass.holes.size(); ++i) {
        pass.clear_after[i] = crosses_clamp(pass.holes[i], pass.holes[i + 1], machine);
      }
    }
    passes.push_back(std::move(pass));
  }
  return passes;
}

}  // namespace app
