#pragma once
// Operations on a HoleSet that every reader shares (header-only, part of aco::geometry).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "aco/geometry.h"

namespace aco {

// Issue 82: how many holes of the set are a hole feature's other operations
// (a tap, a counterbore, ...), which the program's header, the summary, the
// report and the setup sheet count apart from the holes drilled.
inline std::size_t count_operations(const HoleSet& holes) {
  return static_cast<std::size_t>(std::count_if(holes.begin(), holes.end(), [](const Hole& h) { return h.operation != 0; }));
}

// Drops exact duplicates — same centre and diameter within `tolerance_mm` —
// keeping the first occurrence and the file order; returns how many went.
// A hash of tolerance-sized cells, probing the 3 x 3 neighbouring cells, finds
// them in linear time (a sort would lose the order, a pairwise scan is n²).
inline std::size_t remove_duplicate_holes(HoleSet& holes, double tolerance_mm = 1e-6) {
  auto key = [](long long qx, long long qy) {
    std::uint64_t h = static_cast<std::uint64_t>(qx) * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(qy) + 0x7F4A7C159E3779B9ULL + (h << 6) + (h >> 2);
    return h;
  };
  std::unordered_map<std::uint64_t, std::uint32_t> first_in_cell;
  first_in_cell.reserve(holes.size() * 2);
  std::vector<std::uint32_t> next_in_cell;
  next_in_cell.reserve(holes.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const Hole& h = holes[i];
    // Clamped: a coordinate of 1e300 mm has a cell too (the neighbours' ±1 must not overflow).
    const long long qx = std::llround(std::clamp(h.center.x / tolerance_mm, -4e18, 4e18));
    const long long qy = std::llround(std::clamp(h.center.y / tolerance_mm, -4e18, 4e18));
    bool duplicate = false;
    for (long long dx = -1; dx <= 1 && !duplicate; ++dx) {
      for (long long dy = -1; dy <= 1 && !duplicate; ++dy) {
        auto it = first_in_cell.find(key(qx + dx, qy + dy));
        if (it == first_in_cell.end()) continue;
        for (std::uint32_t j = it->second; j != UINT32_MAX; j = next_in_cell[j]) {
          const Hole& o = holes[j];
          if (std::fabs(o.center.x - h.center.x) <= tolerance_mm && std::fabs(o.center.y - h.center.y) <= tolerance_mm &&
              std::fabs(o.diameter - h.diameter) <= tolerance_mm && o.operation == h.operation) {
            duplicate = true;
            break;
          }
        }
      }
    }
    if (duplicate) continue;
    const auto index = static_cast<std::uint32_t>(kept);
    if (kept != i) holes[kept] = std::move(holes[i]);
    auto [it, inserted] = first_in_cell.emplace(key(qx, qy), index);
    next_in_cell.push_back(inserted ? UINT32_MAX : it->second);
    it->second = index;
    ++kept;
  }
  const std::size_t removed = holes.size() - kept;
  holes.resize(kept);
  return removed;
}

}  // namespace aco
