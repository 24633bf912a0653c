#include "candidates.h"

#include <algorithm>
#include <nanoflann.hpp>
#include <numeric>
#include <utility>

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

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2,
                                                 std::size_t>;

}  // namespace

Candidates build_candidates(const Space& space, int k) {
  const HoleIndex n = space.holes();
  Candidates c;
  c.k = std::max(0, std::min<int>(k, static_cast<int>(n) - 1));
  c.list.assign(static_cast<std::size_t>(n) * c.k, 0);
  if (c.k == 0) return c;
  PointCloud cloud{&space};
  Tree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  // Ask for a few more than k: coincident holes and metric ties are then
  // resolved by our own sort (distance in the problem's metric, then index),
  // which keeps the lists identical on every machine and thread count.
  const std::size_t want = std::min<std::size_t>(n, static_cast<std::size_t>(c.k) + 1 + 4);
  std::vector<std::size_t> idx(want);
  std::vector<double> dist2(want);
  std::vector<std::pair<double, HoleIndex>> row;
  for (HoleIndex i = 0; i < n; ++i) {
    const double q[2] = {space.point(i).x, space.point(i).y};
    std::size_t found = tree.knnSearch(q, want, idx.data(), dist2.data());
    row.clear();
    for (std::size_t r = 0; r < found; ++r) {
      auto j = static_cast<HoleIndex>(idx[r]);
      if (j != i) row.emplace_back(space.d(i, j), j);
    }
    std::sort(row.begin(), row.end());
    if (row.size() < static_cast<std::size_t>(c.k)) {
      // Many coincident points crowd the k-d result; fall back to a full scan for this row.
      row.clear();
      for (HoleIndex j = 0; j < n; ++j) {
        if (j != i) row.emplace_back(space.d(i, j), j);
      }
      std::partial_sort(row.begin(), row.begin() + c.k, row.end());
    }
    HoleIndex* out = c.list.data() + static_cast<std::size_t>(i) * c.k;
    for (int r = 0; r < c.k; ++r) out[r] = row[r].second;
  }
  return c;
}

}  // namespace aco::detail
