#include "milling.h"

#include <algorithm>
#include <cmath>

namespace gcode {

double Helix::length_mm() const {
  const double circumference = 2.0 * M_PI * path_radius_mm;
  const double one_turn = std::hypot(circumference, depth_per_turn_mm);
  return turns * one_turn + circumference + path_radius_mm;
}

Helix helix_for(double hole_diameter_mm, const Tool& t) {
  Helix h;
  h.path_radius_mm = std::max(0.0, (hole_diameter_mm - t.diameter_mm) / 2.0);
  if (h.path_radius_mm < kPlungeRadiusMm) {
    h.path_radius_mm = 0.0;
    return h;
  }
  const double depth = -t.depth_mm;  // from the top of the part (Z 0)
  const double pitch = t.helix_pitch_mm > 0 ? t.helix_pitch_mm : depth;
  h.turns = std::max(1, static_cast<int>(std::ceil(depth / pitch - 1e-9)));
  h.depth_per_turn_mm = depth / h.turns;
  return h;
}

aco::Point2 milled_hole_start(aco::Point2 centre, double hole_diameter_mm, const Tool& t) {
  return {centre.x + helix_for(hole_diameter_mm, t).path_radius_mm, centre.y};
}

std::vector<PathMove> milled_hole_moves(aco::Point2 centre, double hole_diameter_mm, const Tool& t, double r_plane_mm,
                                        double retract_z_mm) {
  const Helix h = helix_for(hole_diameter_mm, t);
  const double feed = t.feed_mm_min;
  std::vector<PathMove> m;
  m.push_back({PathMove::Rapid, std::nullopt, std::nullopt, r_plane_mm, {}, 0.0});
  if (h.path_radius_mm == 0.0) {
    // The hole is the end mill's size: plunged like a drill.
    m.push_back({PathMove::Feed, std::nullopt, std::nullopt, t.depth_mm, {}, feed});
    m.push_back({PathMove::Rapid, std::nullopt, std::nullopt, retract_z_mm, {}, 0.0});
    return m;
  }
  const aco::Point2 start{centre.x + h.path_radius_mm, centre.y};
  m.push_back({PathMove::Feed, std::nullopt, std::nullopt, 0.0, {}, feed});
  for (int k = 1; k <= h.turns; ++k) {
    const double z = k == h.turns ? t.depth_mm : -k * h.depth_per_turn_mm;
    m.push_back({PathMove::ArcCw, start.x, start.y, z, centre, feed});
  }
  m.push_back({PathMove::ArcCw, start.x, start.y, std::nullopt, centre, feed});
  m.push_back({PathMove::Feed, centre.x, centre.y, std::nullopt, {}, feed});
  m.push_back({PathMove::Rapid, std::nullopt, std::nullopt, retract_z_mm, {}, 0.0});
  return m;
}

}  // namespace gcode
