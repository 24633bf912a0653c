// Baseline orders for reports and benchmarks, all O(n log n)-ish so that they
// run on a million holes: nearest neighbour walks a bucket grid instead of
// scanning every unvisited hole.
#include "aco/baselines.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <array>
#include <functional>
#include <numeric>

#include "bucket_grid.h"
#include "candidates.h"
#include "local_search.h"
#include "space.h"

namespace aco {

namespace detail {

Order nearest_neighbor_order(const Space& space, const Candidates&, HoleIndex first) {
  NearestWalk walk(space, first);
  walk.walk(space.holes());
  return walk.take();
}

}  // namespace detail

namespace {

Order from_route(const detail::Space& space, const std::vector<HoleIndex>& route) {
  Order o;
  o.reserve(route.size());
  for (HoleIndex h : route) {
    if (h < space.holes()) o.push_back(h);
  }
  return o;
}

}  // namespace

Order input_order(const Problem& problem) {
  Order o(problem.points.size());
  std::iota(o.begin(), o.end(), 0);
  return o;
}

Order nearest_neighbor(const Problem& problem) {
  detail::Space space(problem);
  return detail::nearest_neighbor_order(space, {}, 0);
}

Order improve(const Problem& problem, Order order, bool or_opt) {
  detail::Space space(problem);
  detail::Candidates cand = detail::build_candidates(space, 10);
  detail::LocalSearcher ls(space, cand);
  std::vector<HoleIndex> route = detail::route_from_order(space, order);
  ls.improve(route, or_opt ? detail::Moves::OrOpt : detail::Moves::TwoOpt);
  return from_route(space, route);
}

Order nearest_neighbor_2opt(const Problem& problem) { return improve(problem, nearest_neighbor(problem), false); }

Order greedy_edge(const Problem& problem) {
  detail::Space space(problem);
  const HoleIndex n = space.holes();
  if (n < 3) return nearest_neighbor(problem);
  detail::Candidates cand = detail::build_candidates(space, 10);
  struct Edge {
    double d;
    HoleIndex a, b;
  };
  std::vector<Edge> edges;
  for (auto [a, b] : detail::candidate_edges(cand, n)) edges.push_back({space.d(a, b), a, b});
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.d < y.d || (x.d == y.d && (x.a < y.a || (x.a == y.a && x.b < y.b)));
  });
  std::vector<HoleIndex> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](HoleIndex x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<std::array<HoleIndex, 2>> adj(n, {UINT32_MAX, UINT32_MAX});
  auto degree = [&](HoleIndex x) { return (adj[x][0] != UINT32_MAX) + (adj[x][1] != UINT32_MAX); };
  for (const Edge& e : edges) {
    if (degree(e.a) >= 2 || degree(e.b) >= 2) continue;
    const HoleIndex ra = find(e.a), rb = find(e.b);
    if (ra == rb) continue;  // would close a cycle early
    parent[ra] = rb;
    adj[e.a][degree(e.a)] = e.b;
    adj[e.b][degree(e.b)] = e.a;
  }
  // Chain the fragments: from the current end, walk to the nearest free fragment end.
  std::vector<char> used(n, 0);
  std::vector<HoleIndex> ends;
  for (HoleIndex i = 0; i < n; ++i) {
    if (degree(i) < 2) ends.push_back(i);
  }
  Order order;
  order.reserve(n);
  auto walk = [&](HoleIndex from) {
    HoleIndex prev = UINT32_MAX, cur = from;
    while (cur != UINT32_MAX && !used[cur]) {
      used[cur] = 1;
      order.push_back(cur);
      HoleIndex next = UINT32_MAX;
      for (HoleIndex x : adj[cur]) {
        if (x != UINT32_MAX && x != prev && !used[x]) next = x;
      }
      prev = cur;
      cur = next;
    }
  };
  Point2 at = space.open() ? problem.start : space.point(ends.empty() ? 0 : ends[0]);
  while (order.size() < n) {
    HoleIndex best = UINT32_MAX;
    double best_d = std::numeric_limits<double>::infinity();
    for (HoleIndex e : ends) {
      if (used[e]) continue;
      const double d = distance(problem.metric, at, space.point(e));
      if (d < best_d) {
        best_d = d;
        best = e;
      }
    }
    if (best == UINT32_MAX) break;
    walk(best);
    at = space.point(order.back());
  }
  return order;
}

Order raster(const Problem& problem, double row_height) {
  const std::size_t n = problem.points.size();
  Order o = input_order(problem);
  if (n == 0) return o;
  if (!(row_height > 0.0)) {
    double minx = 1e300, maxx = -1e300, miny = 1e300, maxy = -1e300;
    for (const Point2& p : problem.points) {
      minx = std::min(minx, p.x);
      maxx = std::max(maxx, p.x);
      miny = std::min(miny, p.y);
      maxy = std::max(maxy, p.y);
    }
    row_height = std::max(std::sqrt((maxx - minx) * (maxy - miny) / static_cast<double>(n)), 1e-6);
  }
  double miny = 1e300;
  for (const Point2& p : problem.points) miny = std::min(miny, p.y);
  auto row = [&](HoleIndex h) { return static_cast<long long>(std::floor((problem.points[h].y - miny) / row_height)); };
  std::stable_sort(o.begin(), o.end(), [&](HoleIndex a, HoleIndex b) {
    const long long ra = row(a), rb = row(b);
    if (ra != rb) return ra < rb;
    const double xa = problem.points[a].x, xb = problem.points[b].x;
    return (ra % 2 == 0) ? xa < xb : xa > xb;
  });
  return o;
}

}  // namespace aco
