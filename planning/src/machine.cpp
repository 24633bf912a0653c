#include "planning/machine.h"

#include <algorithm>
#include <cmath>

#include "json.h"
#include "planning/owned_tools.h"
#include "planning/placement.h"

namespace planning {

namespace {

std::string fmt3(double v) { return gcode::format_number(v, 3); }

}  // namespace

std::optional<Machine> builtin_machine(const std::string& name) {
  for (const MachineClass& c : machine_classes()) {
    if (c.name == name) return parse_machine(c.profile_json, "machine class " + c.name);
  }
  return std::nullopt;
}

std::string machine_class_names() {
  std::string names;
  for (const MachineClass& c : machine_classes()) names += (names.empty() ? "" : ", ") + c.name;
  return names;
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
  if (j.contains("r_plane_mm")) {
    const double r = json_number(j, "r_plane_mm", 0, path);
    if (!(r > 0 && r <= 50)) throw UserError(path, 0, "r_plane_mm (height above the part where feeds begin) must be in (0, 50] mm");
    m.r_plane_mm = r;
  }
  if (!(m.hit_s >= 0 && m.hit_s <= 600)) throw UserError(path, 0, "hit_s must be 0..600");
  if (!(m.spindle_start_s >= 0 && m.spindle_start_s <= 600)) throw UserError(path, 0, "spindle_start_s must be 0..600");
  m.rapid_xy_mm_min = json_number(j, "rapid_xy_mm_min", m.rapid_xy_mm_min, path);
  m.rapid_z_mm_min = json_number(j, "rapid_z_mm_min", m.rapid_z_mm_min, path);
  m.accel_mm_s2 = json_number(j, "accel_mm_s2", m.accel_mm_s2, path);
  m.tool_change_s = json_number(j, "tool_change_s", m.tool_change_s, path);
  m.junction_deviation_mm = json_number(j, "junction_deviation_mm", m.junction_deviation_mm, path);
  m.arc_tolerance_mm = json_number(j, "arc_tolerance_mm", m.arc_tolerance_mm, path);
  if (!(m.junction_deviation_mm >= 0 && m.junction_deviation_mm <= 10)) throw UserError(path, 0, "junction_deviation_mm must be 0..10");
  if (!(m.arc_tolerance_mm > 0 && m.arc_tolerance_mm <= 1)) throw UserError(path, 0, "arc_tolerance_mm must be in (0, 1]");
  m.max_rpm = static_cast<int>(json_number(j, "max_rpm", m.max_rpm, path));
  if (m.max_rpm < 1) throw UserError(path, 0, "max_rpm must be >= 1");
  if (j.contains("linear_rapids")) {
    if (!j["linear_rapids"].is_boolean()) throw UserError(path, 0, "\"linear_rapids\" must be true or false");
    m.linear_rapids = j["linear_rapids"].get<bool>();
  }
  if (j.contains("spot")) {
    if (!j["spot"].is_boolean()) throw UserError(path, 0, "\"spot\" must be true or false");
    m.spot = j["spot"].get<bool>();
  }
  if (j.contains("spindle_encoder")) {
    if (!j["spindle_encoder"].is_boolean()) throw UserError(path, 0, "\"spindle_encoder\" must be true or false");
    m.spindle_encoder = j["spindle_encoder"].get<bool>();
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
  if (j.contains("drills_owned")) {
    // "0.6,0.8,1.0", or a list of numbers and "DIA:-MINUS:+PLUS" strings.
    const json& d = j["drills_owned"];
    if (d.is_string()) {
      m.drills_owned = d.get<std::string>();
    } else if (d.is_array()) {
      for (const json& e : d) {
        if (!e.is_number() && !e.is_string()) throw UserError(path, 0, "\"drills_owned\" lists diameters in mm: [0.6, 0.8, \"1.0:-0.05:+0.1\"]");
        m.drills_owned += (m.drills_owned.empty() ? "" : ",") + (e.is_string() ? e.get<std::string>() : gcode::format_number(e.get<double>(), 4));
      }
    } else {
      throw UserError(path, 0, "\"drills_owned\" lists diameters in mm: [0.6, 0.8, \"1.0:-0.05:+0.1\"] or \"0.6,0.8,1.0\"");
    }
    parse_owned_drills(m.drills_owned, path + " drills_owned");  // refused here, naming the profile
  }
  auto positive = [&](const char* key, double high) -> std::optional<double> {
    if (!j.contains(key)) return std::nullopt;
    const double v = json_number(j, key, 0, path);
    if (!(v > 0 && v <= high)) throw UserError(path, 0, std::string(key) + " must be in (0, " + fmt3(high) + "]");
    return v;
  };
  m.end_mill_mm = positive("end_mill_mm", 100);
  m.probe_plate_mm = positive("probe_plate_mm", 50);
  m.probe_feed_mm_min = positive("probe_feed_mm_min", 5000).value_or(m.probe_feed_mm_min);
  m.probe_travel_mm = positive("probe_travel_mm", 500).value_or(m.probe_travel_mm);
  return m;
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

gcode::Kinematics kinematics_of(const Machine& m, gcode::Dialect dialect) {
  gcode::Kinematics k;
  k.rate_mm_min[0] = k.rate_mm_min[1] = m.rapid_xy_mm_min;
  k.rate_mm_min[2] = m.rapid_z_mm_min;
  k.accel_mm_s2[0] = k.accel_mm_s2[1] = k.accel_mm_s2[2] = m.accel_mm_s2;
  k.junction_deviation_mm = m.junction_deviation_mm;
  k.arc_tolerance_mm = m.arc_tolerance_mm;
  k.linear_rapids = m.linear_rapids;
  k.dwell_p_in_ms = dialect == gcode::Dialect::Marlin;
  k.cycle_p_integer_ms = dialect == gcode::Dialect::Haas || dialect == gcode::Dialect::Fanuc;
  return k;
}

}  // namespace planning
