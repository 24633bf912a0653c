// Hole features into operations (planning/operations.h).
#include "planning/operations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "formats/error.h"
#include "formats/threads.h"

namespace planning {

namespace {

// Metric screws' holes (M3-M20): the ISO 273 clearance hole (medium), the
// counterbore of an ISO 4762 socket head cap screw (DIN 974-1, row 1: its
// diameter, and its depth, the head's height k = d plus the allowance), and
// the head diameter of an ISO 10642 countersunk screw (dk max).
struct ScrewHole {
  double screw_mm, clearance_mm, counterbore_mm, counterbore_depth_mm, countersink_mm;
};
constexpr ScrewHole kScrewHoles[] = {
    {3, 3.4, 6.5, 3.4, 6.72},      {4, 4.5, 8.0, 4.4, 8.96},       {5, 5.5, 10.0, 5.4, 11.2},
    {6, 6.6, 11.0, 6.4, 13.44},    {8, 9.0, 15.0, 8.6, 17.92},     {10, 11.0, 18.0, 10.6, 22.4},
    {12, 13.5, 20.0, 12.6, 26.88}, {16, 17.5, 26.0, 16.6, 33.6},   {20, 22.0, 33.0, 20.6, 40.32},
};

// The row whose `field` is within 0.15 mm of `mm`, or null.
const ScrewHole* screw_hole(double ScrewHole::*field, double mm) {
  for (const ScrewHole& h : kScrewHoles) {
    if (std::fabs(h.*field - mm) <= 0.15) return &h;
  }
  return nullptr;
}

// The features' places and drills, to find each among the holes.
using Place = std::tuple<long long, long long, long long>;
Place place_of(aco::Point2 c, double d) {
  return {std::llround(c.x * 1000.0), std::llround(c.y * 1000.0), std::llround(d * 1000.0)};
}

}  // namespace

double socket_head_counterbore_depth_mm(double counterbore_mm) {
  const ScrewHole* h = screw_hole(&ScrewHole::counterbore_mm, counterbore_mm);
  return h ? h->counterbore_depth_mm : 0.0;
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
  auto rpm_for = [&](double vc_m_min) { return spindle_rpm_for(vc_m_min, std::max(spec.diameter_mm, 0.5), machine.max_rpm, 50.0); };
  switch (spec.kind) {
    case gcode::Operation::Tap: {
      // HSS machine taps (makers' tapping speeds, the slow end): the feed is
      // the pitch a turn, as G84 needs it.
      t.spindle_rpm = std::min(rpm_for(steel ? 8.0 : 15.0), 1000);
      t.feed_mm_min = spec.pitch_mm * t.spindle_rpm;
      t.cycle = spec.left_hand ? gcode::Cycle::G74 : gcode::Cycle::G84;
      t.spindle_synchronized = machine.spindle_encoder;
      break;
    }
    case gcode::Operation::Counterbore:
      if (spec.end_mill_mm > 0) {
        // Milled by the end mill's helix to the counterbore's diameter and
        // depth (GRBL, Marlin): the end mill's own data, its depth the counterbore's.
        const gcode::Tool mill = generated_end_mill(spec.end_mill_mm, material, -spec.depth_mm, machine);
        t.diameter_mm = mill.diameter_mm;
        t.end_mill = true;
        t.spindle_rpm = mill.spindle_rpm;
        t.feed_mm_min = mill.feed_mm_min;
        t.helix_pitch_mm = mill.helix_pitch_mm;
        break;
      }
      [[fallthrough]];
    case gcode::Operation::Countersink: {
      // HSS countersinks and piloted counterbores: slower than a drill at the
      // edge, a light feed, and a dwell at the bottom for a clean face.
      t.spindle_rpm = rpm_for(steel ? 12.0 : 30.0);
      // (a counterbore about 0.01 mm a turn per mm of its diameter, makers' lower figures)
      const double per_rev = spec.kind == gcode::Operation::Countersink ? 0.05 : std::clamp(0.01 * spec.diameter_mm, 0.05, 0.2);
      t.feed_mm_min = std::max(5.0, std::round(t.spindle_rpm * per_rev));
      t.cycle = gcode::Cycle::G82;
      t.dwell_s = spec.kind == gcode::Operation::Countersink ? 0.3 : 0.5;
      break;
    }
    case gcode::Operation::Ream:
      // HSS machine reamers: about two thirds of a drill's speed at the
      // edge, two to three times its feed a turn; fed in and out (G85).
      t.spindle_rpm = rpm_for(steel ? 10.0 : 30.0);
      t.feed_mm_min = std::max(10.0, std::round(t.spindle_rpm * std::clamp(0.02 * spec.diameter_mm, 0.08, 0.4)));
      t.cycle = gcode::Cycle::G85;
      break;
    case gcode::Operation::Spot:
      // HSS spot drills: a drill's speed at the edge, 0.05 mm a turn.
      t.spindle_rpm = rpm_for(steel ? 20.0 : 60.0);
      t.feed_mm_min = std::max(10.0, std::round(t.spindle_rpm * 0.05));
      break;
    default:
      t.spindle_rpm = rpm_for(steel ? 15.0 : 40.0);
      t.feed_mm_min = std::max(5.0, std::round(t.spindle_rpm * 0.01 * spec.diameter_mm));
      break;
  }
  // A process table's cutting data: a tap's feed stays its pitch a turn.
  if (spec.rpm) {
    t.spindle_rpm = std::min(*spec.rpm, std::max(1, machine.max_rpm));
    if (spec.kind == gcode::Operation::Tap) t.feed_mm_min = spec.pitch_mm * t.spindle_rpm;
  }
  if (spec.feed_mm_min && spec.kind != gcode::Operation::Tap) t.feed_mm_min = *spec.feed_mm_min;
  if (spec.dwell_s && t.cycle == gcode::Cycle::G82) t.dwell_s = std::max(0.001, *spec.dwell_s);
  if (!spec.name.empty()) t.name = spec.name;
  return t;
}

namespace {

// A reamer's stock (Machinery's Handbook's range, its middle): what the
// drill leaves for the reamer to take, on the diameter.
double ream_allowance_mm(double reamer_mm) { return reamer_mm <= 6.0 ? 0.2 : reamer_mm <= 12.0 ? 0.3 : 0.4; }

// The Z of a through drill's tip (tools.cpp): through, its 118-degree point
// (0.3 D) and 0.5 mm; nothing that follows it goes deeper.
double drill_tip_mm(double thickness_mm, double drill_mm) { return thickness_mm + 0.3 * drill_mm + 0.5; }

void apply_cutting_data(OperationSpec& spec, const formats::ProcessStep* step) {
  if (step == nullptr) return;
  spec.rpm = step->rpm;
  spec.feed_mm_min = step->feed_mm_min;
  spec.dwell_s = step->dwell_s;
  spec.name = step->name;
}

}  // namespace

Operations add_operations(aco::HoleSet& holes, std::vector<std::uint32_t>& hole_source,
                          const std::vector<formats::HoleFeature>& drawn, const OperationSettings& s,
                          const std::string& source) {
  Operations out;
  // Inputs that know no features (Excellon, CSV, ...): each hole a plain one,
  // for a process table to select.
  std::vector<formats::HoleFeature> plain;
  if (drawn.empty() && s.processes != nullptr) {
    for (const aco::Hole& h : holes) {
      if (h.operation != 0 || h.chain != 0 || h.slot_end) continue;
      formats::HoleFeature f;
      f.center = h.center;
      f.diameter_mm = f.drill_mm = h.diameter;
      f.layer = h.layer;
      f.line = h.source_line;
      f.rule = formats::matching_rule(*s.processes, f, "plain");
      if (f.rule != 0) plain.push_back(std::move(f));
    }
  }
  const std::vector<formats::HoleFeature>& features = drawn.empty() ? plain : drawn;
  if (features.empty() && !s.spot) return out;
  std::map<Place, std::size_t> hole_at;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    if (holes[i].operation == 0) hole_at.emplace(place_of(holes[i].center, holes[i].diameter), i);
  }
  std::map<std::string, std::uint32_t> spec_index;
  auto add = [&](std::size_t hole, const OperationSpec& spec) {
    char key[400];
    std::snprintf(key, sizeof key, "%d %.4f %.4f %.4f %.4f %d %d %.4f %.4f %.4f ", static_cast<int>(spec.kind), spec.diameter_mm,
                  spec.depth_mm, spec.pitch_mm, spec.angle_deg, spec.left_hand ? 1 : 0, spec.rpm.value_or(0),
                  spec.feed_mm_min.value_or(0), spec.dwell_s.value_or(-1), spec.end_mill_mm);
    auto [it, fresh] = spec_index.emplace(std::string(key) + spec.thread + "|" + spec.name, static_cast<std::uint32_t>(out.specs.size() + 1));
    if (fresh) out.specs.push_back(spec);
    aco::Hole h = holes[hole];
    h.diameter = spec.diameter_mm;
    h.operation = it->second;
    h.chain = 0;
    h.slot_end = false;
    holes.push_back(std::move(h));
    if (!hole_source.empty()) hole_source.push_back(hole_source[hole]);
  };
  std::map<std::string, std::size_t> by_hand_count, no_depth;
  std::uint32_t no_depth_line = 0;
  std::vector<std::size_t> spotted;  // holes spotted by the one spot drill (--spot, a rule's "spot")
  std::vector<char> is_spotted(holes.size(), 0), featured(holes.size(), 0);
  auto spot = [&](std::size_t hole) {
    if (!is_spotted[hole]) is_spotted[hole] = 1, spotted.push_back(hole);
  };
  for (const formats::HoleFeature& f : features) {
    const formats::ProcessRule* rule = s.processes != nullptr && f.rule != 0 && f.rule <= s.processes->rules.size()
                                           ? &s.processes->rules[f.rule - 1]
                                           : nullptr;
    if (rule == nullptr && (f.kind == formats::FeatureKind::Plain || f.kind == formats::FeatureKind::Undecided)) continue;
    auto found = hole_at.find(place_of(f.center, f.drill_mm));
    if (found == hole_at.end()) continue;  // filtered out: nothing of it is made
    const std::size_t hole = found->second;
    if (featured[hole]) continue;  // a feature given twice (a duplicate row) is made once
    featured[hole] = 1;
    const std::string at = " at X" + gcode::format_number(f.center.x, 3) + " Y" + gcode::format_number(f.center.y, 3);
    auto step = [&](gcode::Operation k) { return rule ? formats::step_of(*rule, k) : nullptr; };
    const formats::ProcessStep* spot_step = step(gcode::Operation::Spot);
    const formats::ProcessStep* drill_step = step(gcode::Operation::Drill);
    const formats::ProcessStep* ream_step = step(gcode::Operation::Ream);
    const formats::ProcessStep* sink_step = step(gcode::Operation::Countersink);
    const formats::ProcessStep* bore_step = step(gcode::Operation::Counterbore);
    const formats::ProcessStep* tap_step = step(gcode::Operation::Tap);
    const std::string by = rule ? " (" + s.processes->path + ", " + rule->where + ")" : "";
    auto refuse = [&](const std::string& what) { throw formats::InputError(source, f.line, what + by); };
    // What makes the feature: the rule's steps, else what the drawing shows.
    bool bore = rule ? bore_step != nullptr : f.kind == formats::FeatureKind::Counterbore;
    bool sink = rule ? sink_step != nullptr : f.kind == formats::FeatureKind::Countersink;
    const bool tap = rule ? tap_step != nullptr : f.kind == formats::FeatureKind::Tapped;
    // The thread a tap makes: the step's, the rule's, the drawing's.
    const formats::Thread* thread = nullptr;
    if (tap) {
      const std::string name = tap_step && !tap_step->thread.empty() ? tap_step->thread : !f.thread.empty() ? f.thread : rule ? rule->thread : "";
      thread = formats::find_thread(name);
      if (thread == nullptr) {
        refuse("tap at X" + gcode::format_number(f.center.x, 3) + " Y" + gcode::format_number(f.center.y, 3) +
               ": no thread (the drawing shows none; give the tap's \"thread\")");
      }
    }
    // The drill: the step's, else under the reamer by its stock, else the thread's tap drill, else as drawn.
    double drill = f.drill_mm;
    const double reamer = ream_step && ream_step->diameter_mm ? *ream_step->diameter_mm : f.diameter_mm;
    if (drill_step && drill_step->diameter_mm) drill = *drill_step->diameter_mm;
    else if (ream_step) drill = reamer - ream_allowance_mm(reamer);
    else if (thread != nullptr && rule != nullptr) drill = thread->tap_drill_mm;
    const std::string named_hole = "hole D" + gcode::format_short(f.diameter_mm) + at;
    if (ream_step && !(drill < reamer)) {
      refuse(named_hole + ": the drill D" + gcode::format_short(drill) + " is not smaller than the reamer D" + gcode::format_short(reamer));
    }
    if (thread != nullptr && !(drill < thread->major_mm)) {
      refuse(named_hole + ": the tap drill D" + gcode::format_short(drill) + " is not smaller than " + thread->name + "'s major diameter");
    }
    if (std::fabs(drill - holes[hole].diameter) > 1e-9) holes[hole].diameter = drill;
    const double tip = drill_tip_mm(s.thickness_mm, drill);
    if (s.spot || spot_step) {
      if (spot_step && (spot_step->diameter_mm || spot_step->depth_mm || spot_step->angle_deg || spot_step->rpm ||
                        spot_step->feed_mm_min || !spot_step->name.empty())) {
        // A spot drill of the rule's own.
        OperationSpec spec;
        spec.kind = gcode::Operation::Spot;
        spec.diameter_mm = spot_step->diameter_mm.value_or(drill > 6.0 ? 10.0 : 6.0);
        spec.angle_deg = spot_step->angle_deg.value_or(90.0);
        spec.depth_mm = -spot_step->depth_mm.value_or(0.5 * std::min(drill, spec.diameter_mm) / std::tan(0.5 * spec.angle_deg * M_PI / 180.0));
        apply_cutting_data(spec, spot_step);
        add(hole, spec);
        is_spotted[hole] = 1;
      } else {
        spot(hole);
      }
    }
    if (ream_step) {
      OperationSpec spec;
      spec.kind = gcode::Operation::Ream;
      spec.diameter_mm = reamer;
      // Through, and the reamer's lead (about 1 mm) beyond, never below the drill's tip.
      spec.depth_mm = -std::min(ream_step->depth_mm.value_or(s.thickness_mm + 1.0), tip);
      apply_cutting_data(spec, ream_step);
      add(hole, spec);
    }
    if (bore || sink) {
      const formats::ProcessStep* st = bore ? bore_step : sink_step;
      OperationSpec spec;
      spec.kind = bore ? gcode::Operation::Counterbore : gcode::Operation::Countersink;
      const bool drawn_ring = f.kind == formats::FeatureKind::Counterbore || f.kind == formats::FeatureKind::Countersink;
      const ScrewHole* screw = screw_hole(&ScrewHole::clearance_mm, f.diameter_mm);
      spec.diameter_mm = st && st->diameter_mm ? *st->diameter_mm
                         : drawn_ring          ? f.outer_diameter_mm
                         : screw               ? (bore ? screw->counterbore_mm : screw->countersink_mm)
                                               : 0.0;
      const std::string what = std::string(bore ? "counterbore" : "countersink");
      if (!(spec.diameter_mm > 0)) {
        refuse(what + at + ": the drawing shows no larger circle and D" + gcode::format_short(f.diameter_mm) +
               " is no ISO 273 clearance hole: give its \"diameter_mm\"");
      }
      const std::string named = what + " D" + gcode::format_short(spec.diameter_mm) + at;
      double depth = 0.0;
      if (bore) {
        depth = st && st->depth_mm ? *st->depth_mm : f.depth_mm > 0 ? f.depth_mm : socket_head_counterbore_depth_mm(spec.diameter_mm);
        if (!s.can_counterbore) {
          // GRBL and Marlin: the end mill's helix mills it, or nothing can.
          if (!s.end_mill_mm || !(*s.end_mill_mm < spec.diameter_mm - 1e-9)) {
            refuse(named + ": GRBL and Marlin programs mill counterbores with the end mill: give --end-mill DIA, smaller than D" +
                   gcode::format_short(spec.diameter_mm) + " (or plan for a control with canned cycles)");
          }
          spec.end_mill_mm = *s.end_mill_mm;
        }
        if (!(depth > 0)) {
          ++no_depth["D" + gcode::format_short(spec.diameter_mm)];
          if (no_depth_line == 0) no_depth_line = f.line;
          out.not_made.push_back({f.line, "counterbore D" + gcode::format_short(spec.diameter_mm) + at + ": no depth given"});
          bore = false;
        }
      } else {
        spec.angle_deg = st && st->angle_deg ? *st->angle_deg : f.angle_deg > 0 ? f.angle_deg : f.inch ? 82.0 : 90.0;
        depth = st && st->depth_mm ? *st->depth_mm : 0.5 * spec.diameter_mm / std::tan(0.5 * spec.angle_deg * M_PI / 180.0);
      }
      if (bore || sink) {
        if (depth >= s.thickness_mm - 1e-9) {
          refuse(named + " is " + gcode::format_short(depth) + " mm deep, as deep as the part or deeper (" +
                 gcode::format_short(s.thickness_mm) + " mm, --thickness)");
        }
        if (!(spec.diameter_mm > f.diameter_mm)) refuse(named + " is no larger than its hole D" + gcode::format_short(f.diameter_mm));
        spec.depth_mm = -depth;
        apply_cutting_data(spec, st);
        add(hole, spec);
      }
    }
    if (tap) {
      if (!s.can_tap) {
        ++by_hand_count[thread->name];
        out.by_hand.push_back("TAP " + thread->name + (tap_step && tap_step->left_hand ? " LH" : "") + at);
        out.not_made.push_back({f.line, "tap " + thread->name + at + ", by hand"});
        continue;
      }
      OperationSpec spec;
      spec.kind = gcode::Operation::Tap;
      spec.diameter_mm = thread->major_mm;
      spec.pitch_mm = thread->pitch_mm;
      spec.thread = thread->name;
      spec.left_hand = tap_step && tap_step->left_hand;
      // Through the part and a plug tap's lead (about 3 pitches) beyond, so the
      // thread is whole to the bottom face, but never below the drill's tip,
      // where the tap would cut what the part lies on. A blind depth (the
      // step's) stays 3 pitches above the drill's tip.
      const double through = std::min(s.thickness_mm + 3.0 * thread->pitch_mm, tip);
      if (tap_step && tap_step->depth_mm) {
        if (*tap_step->depth_mm > tip - 3.0 * thread->pitch_mm + 1e-9) {
          refuse("tap " + thread->name + at + " is " + gcode::format_short(*tap_step->depth_mm) + " mm deep: a tap stops 3 pitches above its drill's tip (" +
                 gcode::format_short(tip) + " mm)");
        }
        spec.depth_mm = -*tap_step->depth_mm;
      } else {
        spec.depth_mm = -through;
      }
      apply_cutting_data(spec, tap_step);
      add(hole, spec);
    }
  }
  if (s.spot) {
    for (std::size_t i = 0; i < is_spotted.size(); ++i) {
      const aco::Hole& h = holes[i];
      if (h.operation == 0 && h.chain == 0 && !h.slot_end && h.diameter > 0) spot(i);
    }
  }
  if (!spotted.empty()) {
    // One spot drill for all: a 6 mm one, or 10 mm where a hole is larger
    // than 6 mm; the cone as wide as the smallest hole (no wider than any of
    // its holes: it centres the drill and leaves no chamfer), at most the
    // spot drill's own diameter.
    double smallest = holes[spotted.front()].diameter, largest = 0.0;
    for (std::size_t i : spotted) smallest = std::min(smallest, holes[i].diameter), largest = std::max(largest, holes[i].diameter);
    OperationSpec spec;
    spec.kind = gcode::Operation::Spot;
    spec.diameter_mm = largest > 6.0 ? 10.0 : 6.0;
    spec.angle_deg = 90.0;
    spec.depth_mm = -0.5 * std::min(smallest, spec.diameter_mm);  // a 90-degree cone's depth is its radius
    std::sort(spotted.begin(), spotted.end());
    for (std::size_t i : spotted) add(i, spec);
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
  if (!no_depth.empty()) {
    const auto [n, l] = listing(no_depth);
    out.warnings.push_back({no_depth_line, std::to_string(n) + " counterbore(s) (" + l + ") not made: no depth (a callout's "
                                           "depth, a process table's, or a socket head screw's counterbore diameter, gives one)"});
  }
  return out;
}

}  // namespace planning
