#pragma once
// A hole milled by an end mill, as the moves both program writers render
// (the canned-cycle dialects' and GRBL's and Marlin's): once over the helix's
// start at or above R, a rapid to R, a feed to the top of the part, equal
// clockwise turns down to the depth (G2, conventional milling, which a light
// machine holds best), a full circle at the depth to cut the helix's last
// ramp away, a feed to the centre and a rapid out of the hole up the middle,
// never along the wall. The centre is written as I J from the start point,
// both rounded as printed, so the arc's centre is the hole's to the printed
// precision.
#include <cmath>
#include <optional>
#include <vector>

#include "aco/geometry.h"
#include "gcode/program.h"

namespace gcode {

struct PathMove {
  enum Kind { Rapid, Feed, ArcCw } kind = Rapid;
  std::optional<double> x, y, z;  // mm, work coordinates; nullopt: the axis does not move
  aco::Point2 centre;             // ArcCw: its centre
  double feed_mm_min = 0.0;       // Feed, ArcCw
};

// Where the helix starts (east of the centre on its path circle) and the
// moves from there; `retract_z_mm`: where the spindle goes when done (R for
// the next hole, the initial plane after the last).
aco::Point2 milled_hole_start(aco::Point2 centre, double hole_diameter_mm, const Tool& end_mill);
std::vector<PathMove> milled_hole_moves(aco::Point2 centre, double hole_diameter_mm, const Tool& end_mill,
                                        double r_plane_mm, double retract_z_mm);

// A slot `width_mm` wide from `a` to `b` milled along its length: a
// racetrack about the segment (clockwise, like the helix: round a, along one
// side, round b, back along the other), ramped down lap after lap by at most
// the tool's pitch, a lap at the depth, a feed to the middle of the segment
// and out. It starts on the right side at `a` (milled_slot_start); the slot
// must be wider than the end mill.
aco::Point2 milled_slot_start(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& end_mill);
std::vector<PathMove> milled_slot_moves(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& end_mill,
                                        double r_plane_mm, double retract_z_mm);

// Hole i of an end mill's pass as the writers mill it: a helix, or with the
// next hole the slot the two end (ToolPass::slot_to_next); `span` holes are
// made, `retract_z_mm` as G99/G98 would (R between holes, the initial plane
// after the pass's last and before a move over a clamp).
struct MilledStop {
  aco::Point2 start;
  std::vector<PathMove> moves;
  std::size_t span = 1;
  double diameter_mm = 0.0;  // the hole's, or the slot's width
};
MilledStop milled_stop(const ToolPass& pass, std::size_t i, const ProgramSettings& settings);

// The decimals of a length in program units and a value rounded to them, so
// that I and J are computed from the numbers as printed.
inline double rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

}  // namespace gcode
