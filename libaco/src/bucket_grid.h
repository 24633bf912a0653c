#pragma once
// Nearest remaining hole in expected O(1) per query: holes bucketed on a grid
// of about two holes per cell, searched ring by ring around the query. Holes
// are removed as a tour visits them, and reset() brings them all back in O(n)
// without allocating, so one grid serves an ant for the whole run. When a
// ring would cost more than scanning what is left, the rest is scanned.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "space.h"

namespace aco::detail {

class BucketGrid {
 public:
  explicit BucketGrid(const Space& s) : s_(s) {
    const HoleIndex n = s.holes();
    const auto [lo, hi] = s.bounds();
    x0_ = lo.x;
    y0_ = lo.y;
    const double w = std::max(hi.x - lo.x, 1e-9), h = std::max(hi.y - lo.y, 1e-9);
    cell_ = std::max(std::sqrt(w * h / std::max<double>(n, 1) * 2.0), std::max(w, h) / 4096.0);
    nx_ = static_cast<int>(std::min(4096.0, std::floor(w / cell_) + 1));
    ny_ = static_cast<int>(std::min(4096.0, std::floor(h / cell_) + 1));
    const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
    // Compressed rows: cell c holds items_[start_[c] .. start_[c] + count_[c]).
    start_.assign(cells + 1, 0);
    for (HoleIndex i = 0; i < n; ++i) ++start_[cell_of(s.point(i)) + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    full_items_.resize(n);
    std::vector<HoleIndex> fill(start_.begin(), start_.end() - 1);
    for (HoleIndex i = 0; i < n; ++i) full_items_[fill[cell_of(s.point(i))]++] = i;
    full_count_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) full_count_[c] = start_[c + 1] - start_[c];
    full_slot_.resize(n);
    for (HoleIndex k = 0; k < n; ++k) full_slot_[full_items_[k]] = k;
    reset();
  }

  void reset() {
    items_ = full_items_;
    count_ = full_count_;
    slot_ = full_slot_;
    alive_.resize(s_.holes());
    std::iota(alive_.begin(), alive_.end(), 0);
    alive_at_.resize(s_.holes());
    std::iota(alive_at_.begin(), alive_at_.end(), 0);
  }

  void remove(HoleIndex i) {
    const std::size_t c = cell_of(s_.point(i));
    const HoleIndex last_slot = start_[c] + count_[c] - 1;
    const HoleIndex at = slot_[i];
    const HoleIndex moved = items_[last_slot];
    items_[at] = moved;
    slot_[moved] = at;
    --count_[c];
    const HoleIndex a = alive_at_[i];
    alive_[a] = alive_.back();
    alive_at_[alive_[a]] = a;
    alive_.pop_back();
  }

  bool empty() const { return alive_.empty(); }
  std::size_t size() const { return alive_.size(); }

  // Nearest remaining hole to `from` by dist(h), ties to the lower index.
  template <class Dist>
  HoleIndex nearest(Point2 from, Dist&& dist) const {
    const int cx = clampx(from.x), cy = clampy(from.y);
    HoleIndex best = UINT32_MAX;
    double best_d = std::numeric_limits<double>::infinity();
    auto consider = [&](HoleIndex h) {
      const double d = dist(h);
      if (d < best_d || (d == best_d && h < best)) {
        best_d = d;
        best = h;
      }
    };
    std::size_t scanned = 0;
    for (int r = 0;; ++r) {
      if (r > 1 && scanned + 8 * static_cast<std::size_t>(r) > alive_.size() * 4) {
        for (HoleIndex h : alive_) consider(h);
        return best;
      }
      scanned += for_each_in_ring(cx, cy, r, consider);
      // Every hole outside ring r is at least r cells away, in any of our metrics.
      if (best != UINT32_MAX && best_d <= r * cell_) return best;
      if (r > nx_ + ny_) return best;
    }
  }

  // The nearest remaining hole to hole `i` by dist(h) in each quadrant
  // around it: [0°, 90°), [90°, 180°), [180°, 270°), [270°, 360°), so every
  // other hole falls in exactly one unless it coincides with `i`. UINT32_MAX
  // where a quadrant holds none within `max_rings` rings of cells. Their union
  // over all holes (the Yao graph with four cones) is connected where the
  // 16 nearest fall apart into clusters.
  template <class Dist>
  std::array<HoleIndex, 4> nearest_by_quadrant(HoleIndex i, Dist&& dist, int max_rings) const {
    const Point2 from = s_.point(i);
    const int cx = clampx(from.x), cy = clampy(from.y);
    std::array<HoleIndex, 4> best;
    best.fill(UINT32_MAX);
    std::array<double, 4> best_d;
    best_d.fill(std::numeric_limits<double>::infinity());
    auto quadrant = [&](Point2 p) {
      const double dx = p.x - from.x, dy = p.y - from.y;
      if (dx > 0 && dy >= 0) return 0;
      if (dx <= 0 && dy > 0) return 1;
      if (dx < 0 && dy <= 0) return 2;
      if (dx >= 0 && dy < 0) return 3;
      return -1;  // the same point
    };
    // Grid cells a quadrant can reach: (x sign, y sign) of its cells from (cx, cy).
    const int reach_x[4] = {nx_ - 1 - cx, cx, cx, nx_ - 1 - cx};
    const int reach_y[4] = {ny_ - 1 - cy, ny_ - 1 - cy, cy, cy};
    for (int r = 0; r <= max_rings; ++r) {
      bool open = false;
      for (int q = 0; q < 4; ++q) {
        // Done when its best is nearer than anything outside ring r - 1, or
        // when the rings have covered all the grid on its side.
        const bool done = (best[q] != UINT32_MAX && best_d[q] <= (r - 1) * cell_) ||
                          (r > std::max(reach_x[q], reach_y[q]));
        open = open || !done;
      }
      if (!open) break;
      for_each_in_ring(cx, cy, r, [&](HoleIndex h) {
        const int q = quadrant(s_.point(h));
        if (q < 0 || h == i) return;
        const double d = dist(h);
        if (d < best_d[q] || (d == best_d[q] && h < best[q])) {
          best_d[q] = d;
          best[q] = h;
        }
      });
    }
    return best;
  }

 private:
  // Calls visit(h) for every remaining hole in the cells at Chebyshev
  // distance r from cell (cx, cy); returns how many cells that was.
  template <class Visit>
  std::size_t for_each_in_ring(int cx, int cy, int r, Visit&& visit) const {
    std::size_t cells = 0;
    for (int y = cy - r; y <= cy + r; ++y) {
      if (y < 0 || y >= ny_) continue;
      const bool edge_row = (y == cy - r || y == cy + r);
      const int step = edge_row || r == 0 ? 1 : 2 * r;
      for (int x = cx - r; x <= cx + r; x += step) {
        if (x < 0 || x >= nx_) continue;
        const std::size_t c = static_cast<std::size_t>(y) * nx_ + x;
        for (HoleIndex k = start_[c], e = start_[c] + count_[c]; k < e; ++k) visit(items_[k]);
        ++cells;
      }
    }
    return cells;
  }

  int clampx(double x) const { return std::clamp(static_cast<int>((x - x0_) / cell_), 0, nx_ - 1); }
  int clampy(double y) const { return std::clamp(static_cast<int>((y - y0_) / cell_), 0, ny_ - 1); }
  std::size_t cell_of(Point2 p) const { return static_cast<std::size_t>(clampy(p.y)) * nx_ + clampx(p.x); }

  const Space& s_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<HoleIndex> start_, full_items_, full_count_, full_slot_;
  std::vector<HoleIndex> items_, count_, slot_, alive_, alive_at_;
};

// The nearest-neighbour route (nearest_neighbor_order()) walked in pieces,
// for the colony's first route: at 10^6 holes the whole walk took 0.4 s of a
// page's slice (issue 84).
class NearestWalk {
 public:
  // From hole `first` (a closed tour; an open path starts nearest its start point).
  NearestWalk(const Space& space, HoleIndex first) : space_(space), grid_(space) {
    const HoleIndex n = space.holes();
    order_.reserve(n);
    if (n == 0) return;
    HoleIndex cur = first < n ? first : 0;
    if (space.open()) cur = grid_.nearest(space.start(), [&](HoleIndex h) { return space.e(space.virtual_node(), h); });
    grid_.remove(cur);
    order_.push_back(cur);
  }

  // Walks on to up to `steps` more holes; true once every hole is in the order.
  bool walk(std::size_t steps) {
    for (; steps > 0 && !grid_.empty(); --steps) {
      const HoleIndex from = order_.back();
      const HoleIndex next = grid_.nearest(space_.point(from), [&](HoleIndex h) { return space_.d(from, h); });
      grid_.remove(next);
      order_.push_back(next);
    }
    return grid_.empty();
  }

  std::vector<HoleIndex> take() { return std::move(order_); }

 private:
  const Space& space_;
  BucketGrid grid_;
  std::vector<HoleIndex> order_;
};

}  // namespace aco::detail
