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

// Inline: it is the innermost call of tour construction and local search.
inline double distance(Metric metric, Point2 a, Point2 b) {
  const double dx = std::fabs(a.x - b.x), dy = std::fabs(a.y - b.y);
  switch (metric) {
    case Metric::Euclidean: return std::sqrt(dx * dx + dy * dy);
    case Metric::Chebyshev: return dx > dy ? dx : dy;
    case Metric::Manhattan: return dx + dy;
    case Metric::TsplibEuc2d: return std::floor(std::sqrt(dx * dx + dy * dy) + 0.5);  // TSPLIB's nint()
    case Metric::TsplibCeil2d: return std::ceil(std::sqrt(dx * dx + dy * dy));
    case Metric::TsplibAtt: {
      // TSPLIB 95, section 2.5: r = sqrt((xd² + yd²) / 10), t = nint(r), d = t < r ? t + 1 : t.
      const double r = std::sqrt((dx * dx + dy * dy) / 10.0);
      const double t = std::floor(r + 0.5);
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
