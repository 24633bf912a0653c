#pragma once
/**
 * What to order: points in mm, how distance is measured, and the shape of the
 * route. A drilling job is an open path from where the spindle is; a TSPLIB
 * instance is a closed tour.
 *
 * **Example**:
 *   aco::Problem p;
 *   p.points = {{0, 0}, {10, 0}, {10, 10}};
 *   p.shape = aco::Shape::OpenPath;  p.start = {0, 0};
 *   double len = aco::route_length(p, {0, 1, 2});  // start → holes
 */
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "aco/geometry.h"

namespace aco {

enum class Metric {
  Euclidean,  // straight-line moves
  Chebyshev,  // max(|dx|, |dy|): rapids that move each axis independently at the same rate
  Manhattan,  // |dx| + |dy|: one axis after the other
  TsplibEuc2d, // TSPLIB's EUC_2D: Euclidean rounded to the nearest integer
  TsplibCeil2d, // TSPLIB's CEIL_2D: Euclidean rounded up (pla7397, pla33810, pla85900)
  TsplibAtt    // TSPLIB's ATT: pseudo-Euclidean, sqrt(d²/10) rounded up where nint falls short
};

enum class Shape {
  ClosedTour,  // return to the first point
  OpenPath     // from `start` (not a hole) through every point; ends at `end` if set, else anywhere
};

struct Problem {
  std::vector<Point2> points;
  Metric metric = Metric::Euclidean;
  Shape shape = Shape::ClosedTour;
  Point2 start{};              // OpenPath only
  std::optional<Point2> end;   // OpenPath only: a fixed end, e.g. the home position
};

namespace detail {
// floor(x) for x >= 0 (or NaN), the same bits. The x86-64 baseline has no
// rounding instruction, so std::floor is a dozen bit operations; below 2^52
// a double's integer part fits an int64_t and two conversions give it. With
// std::floor, EUC_2D's rounding was the hottest lines of the 3-opt search
// (brd14051, perf); with this, the same routes took 4-8 % less time
// (brd14051, d15112, pcb3038). CEIL_2D keeps std::ceil: a branch on whether
// x is whole is a coin toss, and without one it measured no faster.
inline double floor_nonnegative(double x) {
  if (x < 4503599627370496.0) return static_cast<double>(static_cast<std::int64_t>(x));
  return std::floor(x);
}
}  // namespace detail

// Inline: it is the innermost call of tour construction and local search.
inline double distance(Metric metric, Point2 a, Point2 b) {
  const double dx = std::fabs(a.x - b.x), dy = std::fabs(a.y - b.y);
  switch (metric) {
    case Metric::Euclidean: return std::sqrt(dx * dx + dy * dy);
    case Metric::Chebyshev: return dx > dy ? dx : dy;
    case Metric::Manhattan: return dx + dy;
    case Metric::TsplibEuc2d: return detail::floor_nonnegative(std::sqrt(dx * dx + dy * dy) + 0.5);  // TSPLIB's nint()
    case Metric::TsplibCeil2d: return std::ceil(std::sqrt(dx * dx + dy * dy));
    case Metric::TsplibAtt: {
      // TSPLIB 95, section 2.5: r = sqrt((xd² + yd²) / 10), t = nint(r), d = t < r ? t + 1 : t.
      const double r = std::sqrt((dx * dx + dy * dy) / 10.0);
      const double t = detail::floor_nonnegative(r + 0.5);
      return t < r ? t + 1.0 : t;
    }
  }
  return 0.0;
}

// Length of the route that visits `order`: a closed tour returns to its first
// point; an open path starts at problem.start and ends at problem.end if set.
double route_length(const Problem& problem, const Order& order);

// True when `order` visits every point of the problem exactly once.
bool is_permutation_of(const Problem& problem, const Order& order);

const char* to_string(Metric metric);
std::optional<Metric> metric_from_string(const std::string& name);

}  // namespace aco
