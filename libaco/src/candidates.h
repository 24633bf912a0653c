#pragma once
// Nearest-neighbour candidate lists: for each hole its k nearest other holes,
// nearest first. Built with a k-d tree (nanoflann) in O(n k log n), never an
// n² scan, so 100 000 holes take well under a second.
#include <vector>

#include "space.h"

namespace aco::detail {

struct Candidates {
  int k = 0;
  std::vector<HoleIndex> list;  // n * k, row i = the k nearest holes of i

  const HoleIndex* of(HoleIndex i) const { return list.data() + static_cast<std::size_t>(i) * k; }
};

Candidates build_candidates(const Space& space, int k);

}  // namespace aco::detail
