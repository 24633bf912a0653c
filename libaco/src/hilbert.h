#pragma once
// Holes in the order a Hilbert curve through their bounding square passes
// them. Holes near each other in that order are near each other on the
// plate, so when the solver numbers them that way, what it reads about a
// hole's neighbours (their points, rows, trail, places in the route) lies
// near in memory too.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "aco/geometry.h"
#include "space.h"

namespace aco::detail {

// The curve runs through a grid of kHilbertCells x kHilbertCells cells.
constexpr std::uint32_t kHilbertCells = 1u << 16;

// How far along the curve cell (x, y) lies (Hilbert 1891), in the usual
// iterative form: a quadrant at a time, from the largest, turning the point
// with the quadrant's curve.
inline std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = kHilbertCells / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) != 0 ? 1 : 0;
    const std::uint32_t ry = (y & s) != 0 ? 1 : 0;
    d += std::uint64_t{s} * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // the quadrant's curve is turned: turn the point with it
      if (rx == 1) {
        x = kHilbertCells - 1 - x;
        y = kHilbertCells - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

// Each point's place along the curve, with its index: hilbert_order() in
// two pieces (keys, then sort_keys) that a time slice may end between.
using CurveKeys = std::vector<std::pair<std::uint64_t, HoleIndex>>;

inline CurveKeys hilbert_keys(const std::vector<Point2>& points) {
  CurveKeys keyed(points.size());
  if (points.empty()) return keyed;
  const auto [lo, hi] = bounding_box(points);
  const double span = std::max(hi.x - lo.x, hi.y - lo.y);
  const double per_unit = span > 0.0 ? (kHilbertCells - 1) / span : 0.0;
  auto cell = [&](double v, double from) {
    return static_cast<std::uint32_t>(std::min<double>(kHilbertCells - 1, (v - from) * per_unit));
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    keyed[i] = {hilbert_index(cell(points[i].x, lo.x), cell(points[i].y, lo.y)), static_cast<HoleIndex>(i)};
  }
  return keyed;
}

// The indices in curve order; points in one cell by index, so the order
// depends on the points alone.
inline std::vector<HoleIndex> sort_keys(CurveKeys keyed) {
  std::sort(keyed.begin(), keyed.end());
  std::vector<HoleIndex> order(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

// The indices of `points` in curve order.
inline std::vector<HoleIndex> hilbert_order(const std::vector<Point2>& points) {
  return sort_keys(hilbert_keys(points));
}

// How much longer the path through `points` in their own order is than in
// `curve` order (hilbert_order()): near 1 when the input already follows the
// plate, in the hundreds for holes in random order.
inline double order_stretch(const std::vector<Point2>& points, const std::vector<HoleIndex>& curve) {
  double given = 0.0, along = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    given += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
    const Point2 &a = points[curve[i - 1]], &b = points[curve[i]];
    along += std::hypot(b.x - a.x, b.y - a.y);
  }
  return along > 0.0 ? given / along : 1.0;
}

}  // namespace aco::detail
