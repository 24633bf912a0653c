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

MilledStop milled_stop(const ToolPass& p, std::size_t i, const ProgramSettings& s) {
  MilledStop stop;
  const Tool& t = p.tool;
  stop.diameter_mm = i < p.mill_diameter.size() ? p.mill_diameter[i] : t.diameter_mm;
  stop.span = i + 1 < p.slot_to_next.size() && p.slot_to_next[i] ? 2 : 1;
  const std::size_t last = i + stop.span - 1;
  const bool clear = last < p.clear_after.size() && p.clear_after[last];
  const double retract = !s.retract_to_r || last + 1 == p.holes.size() || clear ? s.initial_z_mm : s.r_plane_mm;
  if (stop.span == 2) {
    const aco::Point2 a = p.holes[i], b = p.holes[i + 1];
    stop.start = milled_slot_start(a, b, stop.diameter_mm, t);
    stop.moves = milled_slot_moves(a, b, stop.diameter_mm, t, s.r_plane_mm, retract);
  } else {
    stop.start = milled_hole_start(p.holes[i], stop.diameter_mm, t);
    stop.moves = milled_hole_moves(p.holes[i], stop.diameter_mm, t, s.r_plane_mm, retract);
  }
  return stop;
}

namespace {

// The racetrack's geometry: offset r from the segment a-b, unit direction u
// and left normal n; the four corners where the arcs meet the sides.
struct Track {
  double r = 0.0, side = 0.0;  // offset and side length
  aco::Point2 u{1, 0}, n{0, 1};
  aco::Point2 at(aco::Point2 p, double along_n) const { return {p.x + along_n * n.x, p.y + along_n * n.y}; }
};

Track track_of(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& t) {
  Track k;
  k.r = std::max(0.0, (width_mm - t.diameter_mm) / 2.0);
  k.side = aco::euclidean(a, b);
  if (k.side > 0) k.u = {(b.x - a.x) / k.side, (b.y - a.y) / k.side};
  k.n = {-k.u.y, k.u.x};
  return k;
}

}  // namespace

aco::Point2 milled_slot_start(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& t) {
  const Track k = track_of(a, b, width_mm, t);
  return k.at(a, -k.r);  // on the right side at a: the first arc goes round a to the left side
}

double milled_slot_length_mm(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& t) {
  const Track k = track_of(a, b, width_mm, t);
  const double lap = 2.0 * M_PI * k.r + 2.0 * k.side;
  const double depth = -t.depth_mm;
  const int laps = std::max(1, static_cast<int>(std::ceil(depth / (t.helix_pitch_mm > 0 ? t.helix_pitch_mm : depth) - 1e-9)));
  return laps * std::hypot(lap, depth / laps) + lap + std::hypot(k.r, k.side / 2.0);
}

std::vector<PathMove> milled_slot_moves(aco::Point2 a, aco::Point2 b, double width_mm, const Tool& t, double r_plane_mm,
                                        double retract_z_mm) {
  const Track k = track_of(a, b, width_mm, t);
  const double feed = t.feed_mm_min;
  const double depth = -t.depth_mm;
  const double pitch = t.helix_pitch_mm > 0 ? t.helix_pitch_mm : depth;
  const int laps = std::max(1, static_cast<int>(std::ceil(depth / pitch - 1e-9)));
  // Z goes down in proportion to the way along each lap: the arcs take their
  // share, the sides theirs.
  const double lap = 2.0 * M_PI * k.r + 2.0 * k.side;
  const double per_mm = depth / laps / lap;
  std::vector<PathMove> m;
  m.push_back({PathMove::Rapid, std::nullopt, std::nullopt, r_plane_mm, {}, 0.0});
  m.push_back({PathMove::Feed, std::nullopt, std::nullopt, 0.0, {}, feed});
  double z = 0.0;
  auto step = [&](double length, bool ramp) { return ramp ? (z -= length * per_mm, std::max(z, t.depth_mm)) : t.depth_mm; };
  for (int lapno = 0; lapno <= laps; ++lapno) {
    const bool ramp = lapno < laps;  // the last lap is at the depth
    const double z1 = step(M_PI * k.r, ramp);
    const aco::Point2 left_a = k.at(a, k.r), left_b = k.at(b, k.r), right_b = k.at(b, -k.r), right_a = k.at(a, -k.r);
    m.push_back({PathMove::ArcCw, left_a.x, left_a.y, z1, a, feed});
    const double z2 = step(k.side, ramp);
    m.push_back({PathMove::Feed, left_b.x, left_b.y, z2, {}, feed});
    const double z3 = step(M_PI * k.r, ramp);
    m.push_back({PathMove::ArcCw, right_b.x, right_b.y, z3, b, feed});
    double z4 = step(k.side, ramp);
    if (lapno + 1 == laps) z4 = t.depth_mm;  // exactly at the depth where the ramp ends
    m.push_back({PathMove::Feed, right_a.x, right_a.y, z4, {}, feed});
  }
  const aco::Point2 middle{(a.x + b.x) / 2, (a.y + b.y) / 2};
  m.push_back({PathMove::Feed, middle.x, middle.y, std::nullopt, {}, feed});
  m.push_back({PathMove::Rapid, std::nullopt, std::nullopt, retract_z_mm, {}, 0.0});
  return m;
}

}  // namespace gcode
