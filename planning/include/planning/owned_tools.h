#pragma once
/**
 * The tools on the bench: the drills a user owns (--drills, profile
 * "drills_owned") and an end mill for what none of them fits (--end-mill,
 * "end_mill_mm"). Each designed hole diameter goes to an owned drill that
 * fits it, choosing the fewest drills that cover every diameter (the fewest
 * tool changes: on a desktop router each one is the operator's minute), then
 * the closest fit; what no drill fits is milled by a helix when the end mill
 * is smaller than the hole.
 *
 * **Example**:
 *   Tooling t{parse_owned_drills("0.6,0.8,1.0,1.2", "--drills"), 1.0};
 *   std::vector<DiameterChoice> c = choose_drills({{0.75, 12}, {3.2, 4}}, t, "board.drl");
 *   // 0.75 -> the 0.8 drill (+0.05); 3.2 -> milled with the 1.0 end mill
 */
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace planning {

// Default fit of an owned drill: it may be 0.05 mm smaller and 0.10 mm larger
// than the hole. Larger is the safe side: a component lead needs clearance
// (IPC-2222 puts a hole 0.15-0.25 mm over the lead), and a board drilled at
// home is not plated, so nothing shrinks the hole afterwards; a drill smaller
// than the hole soon leaves no room for the lead.
constexpr double kDrillMinusMm = 0.05;
constexpr double kDrillPlusMm = 0.10;

struct OwnedDrill {
  double diameter_mm = 0.0;
  double minus_mm = kDrillMinusMm;  // how much smaller than the hole it may be
  double plus_mm = kDrillPlusMm;    // how much larger
  bool fits(double hole_mm) const {
    return diameter_mm >= hole_mm - minus_mm - 1e-9 && diameter_mm <= hole_mm + plus_mm + 1e-9;
  }
};

// "0.6,0.8:-0.05:+0.1,1.0": DIA[:-MINUS:+PLUS] in mm, comma-separated, each
// drill once. Throws formats::InputError naming `where`.
std::vector<OwnedDrill> parse_owned_drills(const std::string& list, const std::string& where);

struct Tooling {
  std::vector<OwnedDrill> drills;   // empty: one generated drill per designed diameter
  std::optional<double> end_mill_mm;
  bool owned() const { return !drills.empty() || end_mill_mm.has_value(); }
};

// What one designed diameter is made with.
struct DiameterChoice {
  double designed_mm = 0.0;
  std::size_t holes = 0;
  std::optional<std::size_t> drill;  // index into Tooling::drills; nullopt: milled with the end mill
};

// For each designed diameter (with its hole count), the drill or the end
// mill: the fewest owned drills that together fit every diameter a drill can
// fit (a drill fits an interval of hole sizes, so this is interval stabbing:
// greedy by the furthest reach is optimal), among those the set with the
// least total misfit (summed over holes), and each diameter to the closest
// drill of the set that fits it (the larger on a tie). A diameter no drill
// fits is milled when the end mill is smaller than it (or plunged when the
// same size); otherwise the error names each such diameter and its count.
std::vector<DiameterChoice> choose_drills(const std::vector<std::pair<double, std::size_t>>& diameters,
                                          const Tooling& tooling, const std::string& source);

}  // namespace planning
