// The candidate lists' first stage: each hole's k nearest other holes by a
// k-d tree (nanoflann) in O(n k log n), rows filled by the team's workers,
// and where the lists fall apart into clusters, each hole's nearest
// neighbour in each quadrant to join them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <nanoflann.hpp>
#include <numeric>
#include <utility>

#include "bucket_grid.h"
#include "candidates.h"
#include "parallel.h"

namespace aco::detail {

namespace {

struct PointCloud {
  const Space* space;
  std::size_t kdtree_get_point_count() const { return space->holes(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return dim == 0 ? space->point(static_cast<HoleIndex>(i)).x : space->point(static_cast<HoleIndex>(i)).y;
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};

static_assert(NANOFLANN_VERSION >= 0x140, "NearestRows counts on the tree's constructor building it (nanoflann 1.4)");

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2,
                                                 std::size_t>;

}  // namespace

struct NearestRows::Impl {
  const Space* space;
  Candidates c;
  PointCloud cloud;
  std::unique_ptr<Tree> tree;
  std::size_t want = 0, next = 0;  // neighbours asked of the tree; the first row not filled
  // Rows are independent: each worker fills chunks of them with its own scratch.
  struct Scratch {
    std::vector<std::size_t> idx;
    std::vector<double> dist2;
    std::vector<std::pair<double, HoleIndex>> row;
  };
  std::vector<Scratch> scratch;

  void fill_row(HoleIndex i, Scratch& sc) {
    const HoleIndex n = space->holes();
    const double q[2] = {space->point(i).x, space->point(i).y};
    std::size_t found = tree->knnSearch(q, want, sc.idx.data(), sc.dist2.data());
    std::vector<std::pair<double, HoleIndex>>& row = sc.row;
    row.clear();
    for (std::size_t r = 0; r < found; ++r) {
      auto j = static_cast<HoleIndex>(sc.idx[r]);
      if (j != i) row.emplace_back(space->d(i, j), j);
    }
    std::sort(row.begin(), row.end());
    if (row.size() < static_cast<std::size_t>(c.k)) {
      // Many coincident points crowd the k-d result; fall back to a full scan for this row.
      row.clear();
      for (HoleIndex j = 0; j < n; ++j) {
        if (j != i) row.emplace_back(space->d(i, j), j);
      }
      std::partial_sort(row.begin(), row.begin() + c.k, row.end());
    }
    HoleIndex* out = c.list.data() + static_cast<std::size_t>(i) * c.k;
    double* out_length = c.length.data() + static_cast<std::size_t>(i) * c.k;
    for (int r = 0; r < c.k; ++r) {
      out[r] = row[r].second;
      out_length[r] = row[r].first;
    }
  }
};

NearestRows::NearestRows(const Space& space, int k) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  const HoleIndex n = space.holes();
  m.space = &space;
  m.c.k = std::max(0, std::min<int>(k, static_cast<int>(n) - 1));
  // Reserved, and grown as the rows are filled: zeroed here at once, the
  // lists of 10^6 holes (144 MB) took 0.4 s of a page's slice (issue 84).
  m.c.list.reserve(static_cast<std::size_t>(n) * m.c.k);
  m.c.length.reserve(m.c.list.capacity());
  if (m.c.k == 0) {
    m.next = n;
    return;
  }
  m.cloud = PointCloud{&space};
  // The constructor builds the tree (nanoflann 1.4); a buildIndex() after it
  // built it again: 0.3 s of a page's slice at 10^6 holes (issue 84).
  m.tree = std::make_unique<Tree>(2, m.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  // Ask for a few more than k: coincident holes and metric ties are then
  // resolved by our own sort (distance in the problem's metric, then index),
  // which keeps the lists identical on every machine and thread count.
  m.want = std::min<std::size_t>(n, static_cast<std::size_t>(m.c.k) + 1 + 4);
}

NearestRows::~NearestRows() = default;
NearestRows::NearestRows(NearestRows&&) noexcept = default;
NearestRows& NearestRows::operator=(NearestRows&&) noexcept = default;

bool NearestRows::fill(Team& team, std::size_t rows) {
  Impl& m = *impl_;
  const std::size_t n = m.space->holes();
  if (m.scratch.size() < static_cast<std::size_t>(team.threads())) {
    m.scratch.resize(static_cast<std::size_t>(team.threads()));
    for (Impl::Scratch& sc : m.scratch) {
      sc.idx.resize(m.want);
      sc.dist2.resize(m.want);
    }
  }
  const std::size_t from = m.next, to = std::min(n, m.next + rows);
  m.c.list.resize(to * static_cast<std::size_t>(m.c.k));
  m.c.length.resize(m.c.list.size());
  team.chunks(to - from, kRowChunk, [&](std::size_t begin, std::size_t end, int me) {
    for (std::size_t i = from + begin; i < from + end; ++i) m.fill_row(static_cast<HoleIndex>(i), m.scratch[static_cast<std::size_t>(me)]);
  });
  m.next = to;
  return m.next == n;
}

Candidates NearestRows::take() { return std::move(impl_->c); }

Candidates build_candidates(const Space& space, int k, Team& team) {
  NearestRows rows(space, k);
  rows.fill(team, space.holes());
  return rows.take();
}

Candidates with_quadrant_neighbours(const Space& space, Candidates nearest) {
  const HoleIndex n = space.holes();
  const int k = nearest.k;
  if (k < 4) return nearest;
  BucketGrid grid(space);
  std::vector<HoleIndex> quadrant, row;
  for (HoleIndex i = 0; i < n; ++i) {
    HoleIndex* out = nearest.list.data() + static_cast<std::size_t>(i) * k;
    quadrant.clear();
    for (HoleIndex q : grid.nearest_by_quadrant(i, [&](HoleIndex h) { return space.d(i, h); }, kQuadrantRings)) {
      if (q != UINT32_MAX && std::find(quadrant.begin(), quadrant.end(), q) == quadrant.end()) quadrant.push_back(q);
    }
    // The quadrant neighbours, and the nearest of the rest to fill the row,
    // sorted by distance (a quadrant neighbour outside the k nearest is no
    // nearer than any of them, so this is the row with its last places given up).
    row = quadrant;
    for (int r = 0; r < k && row.size() < static_cast<std::size_t>(k); ++r) {
      if (std::find(quadrant.begin(), quadrant.end(), out[r]) == quadrant.end()) row.push_back(out[r]);
    }
    std::sort(row.begin(), row.end(), [&](HoleIndex a, HoleIndex b) {
      const double da = space.d(i, a), db = space.d(i, b);
      return da < db || (da == db && a < b);
    });
    std::copy(row.begin(), row.end(), out);
    double* out_length = nearest.length.data() + static_cast<std::size_t>(i) * k;
    for (int r = 0; r < k; ++r) out_length[r] = space.d(i, out[r]);
  }
  return nearest;
}

Candidates joined_nearest(const Space& space, int k, Team& team) { return joined(space, build_candidates(space, k, team)); }

Candidates joined(const Space& space, Candidates nearest) {
  const HoleIndex n = space.holes();
  std::vector<HoleIndex> root(n);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](HoleIndex x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  // Straight from the rows: a union of two joined holes does nothing, so the
  // sorted edge list that alpha_candidates builds anyway is not needed here.
  HoleIndex pieces = n;
  for (HoleIndex a = 0; a < n; ++a) {
    for (int r = 0; r < nearest.k; ++r) {
      const HoleIndex ra = find(a), rb = find(nearest.of(a)[r]);
      if (ra == rb) continue;
      root[ra] = rb;
      --pieces;
    }
  }
  return pieces > 1 ? with_quadrant_neighbours(space, std::move(nearest)) : nearest;
}

std::vector<std::pair<HoleIndex, HoleIndex>> candidate_edges(const Candidates& candidates, HoleIndex holes) {
  // Each edge's larger end, bucketed by its smaller end (a counting sort);
  // each bucket then sorted and without repeats. The same list as sorting all
  // n k pairs, at O(n k log k): 16 nearest of uniform holes, 0.5-0.9 ms
  // against 1.3-1.8 ms on 1173 of them, 73 ms against 185 ms on 100 000.
  std::vector<std::uint32_t> first(static_cast<std::size_t>(holes) + 1, 0);
  for (HoleIndex i = 0; i < holes; ++i) {
    for (int r = 0; r < candidates.k; ++r) ++first[std::min(i, candidates.of(i)[r]) + 1];
  }
  for (HoleIndex i = 0; i < holes; ++i) first[i + 1] += first[i];
  std::vector<HoleIndex> larger(first[holes]);
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (HoleIndex i = 0; i < holes; ++i) {
    for (int r = 0; r < candidates.k; ++r) {
      const HoleIndex j = candidates.of(i)[r];
      larger[fill[std::min(i, j)]++] = std::max(i, j);
    }
  }
  std::vector<std::pair<HoleIndex, HoleIndex>> edges;
  edges.reserve(larger.size());
  for (HoleIndex a = 0; a < holes; ++a) {
    HoleIndex* const from = larger.data() + first[a];
    HoleIndex* const to = larger.data() + first[a + 1];
    std::sort(from, to);
    for (HoleIndex* b = from; b != to; ++b) {
      if (b == from || *b != b[-1]) edges.emplace_back(a, *b);
    }
  }
  return edges;
}

Candidates build_candidates(const Space& space, int k, int threads) {
  Candidates c;
  Team::run(threads, [&](Team& team) { c = build_candidates(space, k, team); });
  return c;
}

Candidates joined_nearest(const Space& space, int k, int threads) {
  Candidates c;
  Team::run(threads, [&](Team& team) { c = joined_nearest(space, k, team); });
  return c;
}

}  // namespace aco::detail
