// Hole features into operations (planning/operations.h).
#include "planning/operations.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "formats/error.h"

namespace planning {

namespace {

// ISO 4762 socket head cap screws' counterbores (DIN 974-1, row 1): the
// counterbore's diameter and its depth, the head's height k = d plus the
// allowance.
struct Counterbore {
  double screw_mm, diameter_mm, depth_mm;
};
constexpr Counterbore kSocketHead[] = {
    {3, 6.5, 3.4},   {4, 8.0, 4.4},   {5, 10.0, 5.4},  {6, 11.0, 6.4},   {8, 15.0, 8.6},
    {10, 18.0, 10.6}, {12, 20.0, 12.6}, {16, 26.0, 16.6}, {20, 33.0, 20.6},
};

// The features' places and drills, to find each among the holes.
using Place = std::tuple<long long, long long, long long>;
Place place_of(aco::Point2 c, double d) {
  return {std::llround(c.x * 1000.0), std::llround(c.y * 1000.0), std::llround(d * 1000.0)};
}

int rpm_for(double vc_m_min, double d_mm, const Machine& machine) {
  return static_cast<int>(std::clamp(std::round(1000.0 * vc_m_min / (M_PI * std::max(d_mm, 0.5))), 50.0,
                                     std::max(50.0, static_cast<double>(machine.max_rpm))));
}

}  // namespace

double socket_head_counterbore_depth_mm(double counterbore_mm) {
  for (const Counterbore& c : kSocketHead) {
    if (std::fabs(c.diameter_mm - counterbore_mm) <= 0.15) return c.depth_mm;
  }
  return 0.0;
}

gcode::Tool operation_tool(const OperationSpec& spec, Material material, const Machine& machine) {
  gcode::Tool t;
  t.operation = spec.kind;
  t.diameter_mm = spec.diameter_mm;
  t.depth_mm = spec.depth_mm;
  t.pitch_mm = spec.pitch_mm;
  t.angle_deg = spec.angle_deg;
  t.thread = spec.thread;
  const bool steel = material == Material::Steel;
  switch (spec.kind) {
    case gcode::Operation::Tap: {
      // HSS machine taps (makers' tapping speeds, the slow end): the feed is
      // the pitch a turn, as G84 needs it.
      t.spindle_rpm = std::min(rpm_for(steel ? 8.0 : 15.0, spec.diameter_mm, machine), 1000);
      t.feed_mm_min = spec.pitch_mm * t.spindle_rpm;
      t.cycle = gcode::Cycle::G84;
      break;
    }
    case gcode::Operation::Countersink:
    case gcode::Operation::Counterbore: {
      // HSS countersinks and piloted counterbores: slower than a drill at the
      // edge, a light feed, and a dwell at the bottom for a clean face.
      t.spindle_rpm = rpm_for(steel ? 12.0 : 30.0, spec.diameter_mm, machine);
      // (a counterbore about 0.01 mm a turn per mm of its diameter, makers' lower figures)
      const double per_rev = spec.kind == gcode::Operation::Countersink ? 0.05 : std::clamp(0.01 * spec.diameter_mm, 0.05, 0.2);
      t.feed_mm_min = std::max(5.0, std::round(t.spindle_rpm * per_rev));
      t.cycle = gcode::Cycle::G82;
      t.dwell_s = spec.kind == gcode::Operation::Countersink ? 0.3 : 0.5;
      break;
    }
    default:
      t.spindle_rpm = rpm_for(steel ? 15.0 : 40.0, spec.diameter_mm, machine);
      t.feed_mm_min = std::max(5.0, std::round(t.spindle_rpm * 0.01 * spec.diameter_mm));
      break;
  }
  return t;
}

Operations add_operations(aco::HoleSet& holes, std::vector<std::uint32_t>& hole_source,
                          const std::vector<formats::HoleFeature>& features, const OperationSettings& s,
                          const std::string& source) {
  Operations out;
  if (features.empty()) return out;
  std::map<Place, std::size_t> hole_at;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    if (holes[i].operation == 0) hole_at.emplace(place_of(holes[i].center, holes[i].diameter), i);
  }
  std::map<std::tuple<int, long long, long long, long long, long long, std::string>, std::uint32_t> spec_index;
  auto add = [&](std::size_t hole, const OperationSpec& spec) {
    const auto key = std::make_tuple(static_cast<int>(spec.kind), std::llround(spec.diameter_mm * 1000), std::llround(spec.depth_mm * 1000),
                                     std::llround(spec.pitch_mm * 1000), std::llround(spec.angle_deg * 1000), spec.thread);
    auto [it, fresh] = spec_index.emplace(key, static_cast<std::uint32_t>(out.specs.size() + 1));
    if (fresh) out.specs.push_back(spec);
    aco::Hole h = holes[hole];
    h.diameter = spec.diameter_mm;
    h.operation = it->second;
    h.chain = 0;
    h.slot_end = false;
    holes.push_back(std::move(h));
    if (!hole_source.empty()) hole_source.push_back(hole_source[hole]);
  };
  std::map<std::string, std::size_t> by_hand_count, no_depth, no_bore;
  std::uint32_t no_depth_line = 0;
  for (const formats::HoleFeature& f : features) {
    if (f.kind == formats::FeatureKind::Plain || f.kind == formats::FeatureKind::Undecided) continue;
    auto found = hole_at.find(place_of(f.center, f.drill_mm));
    if (found == hole_at.end()) continue;  // filtered out: nothing of it is made
    const std::size_t hole = found->second;
    const std::string at = " at X" + gcode::format_number(f.center.x, 3) + " Y" + gcode::format_number(f.center.y, 3);
    const std::string named = std::string(formats::to_string(f.kind)) + " D" + gcode::format_short(f.kind == formats::FeatureKind::Tapped ? f.drill_mm : f.outer_diameter_mm) + at;
    if (f.kind == formats::FeatureKind::Counterbore || f.kind == formats::FeatureKind::Countersink) {
      OperationSpec spec;
      spec.diameter_mm = f.outer_diameter_mm;
      double depth = 0.0;
      if (f.kind == formats::FeatureKind::Counterbore) {
        spec.kind = gcode::Operation::Counterbore;
        depth = f.depth_mm > 0 ? f.depth_mm : socket_head_counterbore_depth_mm(f.outer_diameter_mm);
        if (!s.can_counterbore) {
          ++no_bore["D" + gcode::format_short(f.outer_diameter_mm)];
          out.not_made.push_back({f.line, "counterbore D" + gcode::format_short(f.outer_diameter_mm) + at + ": this control cannot"});
          continue;
        }
        if (!(depth > 0)) {
          ++no_depth["D" + gcode::format_short(f.outer_diameter_mm)];
          if (no_depth_line == 0) no_depth_line = f.line;
          out.not_made.push_back({f.line, "counterbore D" + gcode::format_short(f.outer_diameter_mm) + at + ": no depth given"});
          continue;
        }
      } else {
        spec.kind = gcode::Operation::Countersink;
        spec.angle_deg = f.angle_deg > 0 ? f.angle_deg : f.inch ? 82.0 : 90.0;
        depth = 0.5 * f.outer_diameter_mm / std::tan(0.5 * spec.angle_deg * M_PI / 180.0);
      }
      if (depth >= s.thickness_mm - 1e-9) {
        throw formats::InputError(source, f.line, named + " is " + gcode::format_short(depth) + " mm deep, as deep as the part or deeper (" +
                                                      gcode::format_short(s.thickness_mm) + " mm, --thickness)");
      }
      if (!(f.outer_diameter_mm > f.diameter_mm)) {
        throw formats::InputError(source, f.line, named + " is no larger than its hole D" + gcode::format_short(f.diameter_mm));
      }
      spec.depth_mm = -depth;
      add(hole, spec);
    }
    if (f.kind == formats::FeatureKind::Tapped) {
      if (!(f.pitch_mm > 0) || !(f.outer_diameter_mm > f.drill_mm)) {
        throw formats::InputError(source, f.line, named + ": thread " + f.thread + " has no pitch or a tap drill as large as its major");
      }
      if (!s.can_tap) {
        ++by_hand_count[f.thread];
        out.by_hand.push_back("TAP " + f.thread + at);
        out.not_made.push_back({f.line, "tap " + f.thread + at + ": by hand, this control cannot tap"});
        continue;
      }
      OperationSpec spec;
      spec.kind = gcode::Operation::Tap;
      spec.diameter_mm = f.outer_diameter_mm;
      spec.pitch_mm = f.pitch_mm;
      spec.thread = f.thread;
      // Through the part and a plug tap's lead (about 3 pitches) beyond, so the
      // thread is whole to the bottom face, but never below the drill's tip
      // (through, its 118-degree point and 0.5 mm: tools.cpp), where the tap
      // would cut what the part lies on.
      spec.depth_mm = -std::min(s.thickness_mm + 3.0 * f.pitch_mm, s.thickness_mm + 0.3 * f.drill_mm + 0.5);
      add(hole, spec);
    }
  }
  auto listing = [](const std::map<std::string, std::size_t>& counts) {
    std::string l;
    std::size_t n = 0;
    for (const auto& [name, k] : counts) l += (l.empty() ? "" : ", ") + name + " x" + std::to_string(k), n += k;
    return std::make_pair(n, l);
  };
  if (!by_hand_count.empty()) {
    const auto [n, l] = listing(by_hand_count);
    out.warnings.push_back({0, std::to_string(n) + " tapped hole(s) (" + l + ") drilled at the tap drill; GRBL and Marlin "
                                "cannot tap: the program ends with a pause that lists them, tap them by hand"});
  }
  if (!no_bore.empty()) {
    const auto [n, l] = listing(no_bore);
    out.warnings.push_back({0, std::to_string(n) + " counterbore(s) (" + l + ") not made: GRBL and Marlin programs "
                                "do not counterbore yet; the holes are drilled"});
  }
  if (!no_depth.empty()) {
    const auto [n, l] = listing(no_depth);
    out.warnings.push_back({no_depth_line, std::to_string(n) + " counterbore(s) (" + l + ") not made: no depth (a callout's "
                                           "depth, or a socket head screw's counterbore diameter, gives one)"});
  }
  return out;
}

}  // namespace planning
