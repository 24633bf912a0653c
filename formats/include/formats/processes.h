#pragma once
/**
 * A process table (`--processes FILE.json`, issue 82): which hole features
 * get which operations, as a shop writes it down once for its parts.
 *
 *   {"processes": [
 *     {"layer": "HOLES-M6", "operations": ["spot", "drill", {"operation": "tap", "thread": "M6"}]},
 *     {"kind": "undecided", "diameter_mm": [6.4, 6.8],
 *      "operations": ["drill", {"operation": "counterbore", "depth_mm": 6.4}]},
 *     {"diameter_mm": 6, "operations": [{"operation": "drill", "diameter_mm": 5.8}, "ream"]}
 *   ]}
 *
 * A rule selects features by what it names, all of it: `layer` (the hole's,
 * any case), `kind` (as the drawing shows it: plain, tapped, counterbore,
 * countersink, undecided), `diameter_mm` (the hole as drawn: a number, within
 * 0.01 mm, or [min, max]) and `thread` ("M6", "1/4-20 UNC"). The first rule
 * that selects a feature gives its operations, in the order a hole's
 * operations come (spot, drill, ream, countersink or counterbore, tap); each
 * step leaves out what the drawing and the standards give (planning/operations.h).
 * The table decides before the layer and the callout: a rule with a
 * counterbore or a countersink makes an undecided circle one.
 * Parsed by planning::parse_process_table.
 */
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gcode/program.h"

namespace formats {

struct HoleFeature;

struct ProcessStep {
  gcode::Operation kind = gcode::Operation::Drill;
  std::optional<double> diameter_mm;  // the tool's (drill, reamer, counterbore, countersink's top, spot drill)
  std::optional<double> depth_mm;     // below the top, positive (counterbore, spot, a blind tap)
  std::optional<double> angle_deg;    // countersink, spot drill
  std::string thread;                 // tap: "M6"; empty: the drawing's
  bool left_hand = false;             // tap: G74
  // Cutting data; left out, the defaults of the operation's tool.
  std::optional<int> rpm;
  std::optional<double> feed_mm_min, dwell_s;
  std::string name;  // the tool's name in the program
};

struct ProcessRule {
  std::string layer;                                   // empty: any
  std::string kind;                                    // empty: any
  std::optional<std::pair<double, double>> diameter_mm;  // inclusive
  std::string thread;                                  // empty: any
  std::vector<ProcessStep> steps;                      // in their order, a drill among them
  std::string where;                                   // "FILE (process 2)", for messages
};

struct ProcessTable {
  std::string path;
  std::vector<ProcessRule> rules;
};

// The 1-based number of the first rule that selects `feature` with the kind
// it is drawn as (`drawn_kind`), or 0.
std::uint32_t matching_rule(const ProcessTable& table, const HoleFeature& feature, const std::string& drawn_kind);

// The rule's step of that kind, or null.
const ProcessStep* step_of(const ProcessRule& rule, gcode::Operation kind);

}  // namespace formats
