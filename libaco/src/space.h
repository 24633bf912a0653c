#pragma once
// The solver's view of a Problem: holes 0..n-1, plus, for an open path, one
// virtual node V = n standing for the start (edges leaving V) and the end
// (edges entering V). A route is then always a cycle stored as an array whose
// position 0 holds V, and every edge is read in array order, so the
// direction-dependent cost of V's two edges is always right.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "aco/problem.h"

namespace aco::detail {

// The points' bounding box: its lower-left and upper-right corners (the
// origin twice when there are none).
inline std::pair<Point2, Point2> bounding_box(const std::vector<Point2>& points) {
  if (points.empty()) return {};
  const double inf = std::numeric_limits<double>::infinity();
  Point2 lo{inf, inf}, hi{-inf, -inf};
  for (const Point2& q : points) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  }
  return {lo, hi};
}

class Space {
 public:
  explicit Space(const Problem& p)
      : pts_(p.points),
        metric_(p.metric),
        n_(static_cast<HoleIndex>(p.points.size())),
        open_(p.shape == Shape::OpenPath),
        start_(p.start),
        has_end_(p.end.has_value()),
        end_(p.end.value_or(Point2{})) {}

  HoleIndex holes() const { return n_; }
  bool open() const { return open_; }
  HoleIndex virtual_node() const { return n_; }
  // Array length of a route: the holes, plus V for an open path.
  HoleIndex route_size() const { return open_ ? n_ + 1 : n_; }
  const Point2& point(HoleIndex i) const { return pts_[i]; }
  // The holes' bounding box (bounding_box()).
  std::pair<Point2, Point2> bounds() const { return bounding_box(pts_); }
  Point2 start() const { return start_; }

  double d(HoleIndex a, HoleIndex b) const { return distance(metric_, pts_[a], pts_[b]); }
  double d(const Point2& a, const Point2& b) const { return distance(metric_, a, b); }

  // Cost of the directed edge a → b, where either may be V.
  double e(HoleIndex a, HoleIndex b) const {
    if (a == n_ && open_) return distance(metric_, start_, pts_[b]);
    if (b == n_ && open_) return has_end_ ? distance(metric_, pts_[a], end_) : 0.0;
    return d(a, b);
  }

  double route_cost(const std::vector<HoleIndex>& route) const {
    double total = 0.0;
    const std::size_t m = route.size();
    for (std::size_t i = 0; i < m; ++i) total += e(route[i], route[(i + 1) % m]);
    if (!open_ && m == 1) total = 0.0;
    return total;
  }

 private:
  const std::vector<Point2>& pts_;
  Metric metric_;
  HoleIndex n_;
  bool open_;
  Point2 start_;
  bool has_end_;
  Point2 end_;
};

// A hole order as a route: V first for an open path.
inline std::vector<HoleIndex> route_from_order(const Space& space, const Order& order) {
  std::vector<HoleIndex> route;
  route.reserve(order.size() + 1);
  if (space.open()) route.push_back(space.virtual_node());
  route.insert(route.end(), order.begin(), order.end());
  return route;
}

}  // namespace aco::detail
