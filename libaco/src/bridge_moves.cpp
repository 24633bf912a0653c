// LKH's non-sequential moves (Helsgaun 2000, section 5.3; LKH's Gain23 and
// BridgeGain): the double bridges, and the like, that no sequential search
// finds, because each half alone would split the route in two.
//
// From s1 and s2 beside it, an edge (s2, s3) to one of s2's candidates and s4
// after s3 (read from s1 to s2), so that adding (s4, s1) leaves two cycles,
// s2..s3 and s4..s1 along the route: a 2-opt move that does not give one
// route, but must gain. Then, as BridgeGain, for every edge (t1, t2) of the
// smaller cycle, an edge (t2, t3) to a candidate t3 in the other cycle, t4
// either of t3's neighbours, and (t4, t1) closing: the two cycles joined by a
// 2-opt move. Or one step deeper, (t4, t5) to a candidate and t6 beside t5,
// closing with (t6, t1) where that gives one route: joined by a 3-opt move.
// The first exchange that gains is made. Gains are paid in the costs the
// 5-opt step pays (five_opt.cpp); over a whole exchange every end loses one
// edge and gains one, so the ascent's penalties cancel.
//
// LKH's Gain23 also tries first halves that are 3-opt moves giving two
// cycles; this does not. LKH runs Gain23 over the whole tour once its
// sequential search finds nothing more; here it is tried at each hole whose
// 5-opt search found nothing (LocalSearcher::run_queue), so an ant pays for it
// only where its search looked. A pass over the whole route after every
// ant's search (as LKH) lost: pcb3038 at 15 s, seeds 1-10, median 0.084 %,
// against 0.0145 % at the dead ends and 0.0475 % without (docs/colony.md).
#include <algorithm>

#include "local_search.h"

namespace aco::detail {

bool LocalSearcher::try_bridge(HoleIndex s1) {
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  if (s1 == v || m_ < 8) return false;
  const int breadth = std::min(kDeepBreadth, cand_.k);
  auto c = [&](HoleIndex a, HoleIndex b) { return penalised(space_, cand_, a, b); };
  auto neighbours = [&](HoleIndex a, HoleIndex b) { return next(a, 0) == b || next(a, 1) == b; };
  ArrayTour tour{*this};
  for (int dir = 0; dir < 2; ++dir) {
    const HoleIndex s2 = next(s1, dir);
    if (s2 == v) continue;
    const HoleIndex* s2_row = cand_.search_row(s2);
    const double* s2_cost = cand_.search_costs(s2);
    for (int r2 = 0; r2 < breadth; ++r2) {
      const HoleIndex s3 = s2_row[r2];
      if (s3 == v || neighbours(s2, s3)) continue;
      const HoleIndex s4 = next(s3, dir);
      if (s4 == v || s4 == s1 || neighbours(s4, s1)) continue;
      const double g = c(s1, s2) - s2_cost[r2] + c(s3, s4) - c(s4, s1);
      if (g <= kMinGain) continue;
      // The smaller cycle, u2..u3 read `dir`-wise: s2..s3 or s4..s1.
      const std::size_t p2 = pos_[s2], p3 = pos_[s3];
      const std::size_t a_size = (dir == 0 ? p3 + m_ - p2 : p2 + m_ - p3) % m_ + 1;
      const bool a_smaller = 2 * a_size <= m_;
      const HoleIndex u2 = a_smaller ? s2 : s4, u3 = a_smaller ? s3 : s1;
      // The exchange's ends: removed (t[2i], t[2i+1]); added (t[i], t[mate[i]]).
      HoleIndex t[10] = {s1, s2, s3, s4};
      // Makes the exchange of the first k removed edges if it gives one route.
      auto make = [&](int k, const int* mate) {
        KOptFlips flips;
        if (!exchange_feasible(tour, k, t, mate, &flips)) return false;
        double length = 0.0;  // what the route loses, in lengths
        for (int i = 0; i < 2 * k; ++i) length += i % 2 == 0 ? space_.d(t[i], t[i + 1]) : 0.0;
        for (int i = 0; i < 2 * k; ++i) length -= i < mate[i] ? space_.d(t[i], t[mate[i]]) : 0.0;
        make_flips(flips);
        gain_ += length;
        for (int i = 0; i < 2 * k; ++i) push(t[i]);
        return true;
      };
      for (HoleIndex t1 = u2; t1 != u3;) {
        const HoleIndex t2 = next(t1, dir);
        const HoleIndex here = t1;
        t1 = t2;
        if (here == v || t2 == v) continue;
        const double g0 = g + c(here, t2);
        const HoleIndex* t2_row = cand_.search_row(t2);
        const double* t2_cost = cand_.search_costs(t2);
        for (int r = 0; r < breadth; ++r) {
          const HoleIndex t3 = t2_row[r];
          if (t3 == v || neighbours(t2, t3) || between(u2, t3, u3, dir)) continue;
          const double g1 = g0 - t2_cost[r];
          for (int side = 0; side < 2; ++side) {
            const HoleIndex t4 = next(t3, dir ^ side);
            // (t3, t4) an edge of the other cycle, not one the first half removed.
            if (t4 == v || t4 == t2 || same_edge(t3, t4, s1, s2) || same_edge(t3, t4, s3, s4)) continue;
            const double g2 = g1 + c(t3, t4);
            t[4] = here, t[5] = t2, t[6] = t3, t[7] = t4;
            if (!same_edge(t4, here, s1, s2) && !same_edge(t4, here, s3, s4) && g2 - c(t4, here) > kMinGain) {
              static const int mate[8] = {3, 2, 1, 0, 7, 6, 5, 4};
              if (make(4, mate)) return true;
            }
            // One step deeper: (t4, t5), t6 beside t5, closing (t6, t1).
            const HoleIndex* t4_row = cand_.search_row(t4);
            const double* t4_cost = cand_.search_costs(t4);
            for (int r4 = 0; r4 < breadth; ++r4) {
              const HoleIndex t5 = t4_row[r4];
              const double g3 = g2 - t4_cost[r4];
              if (g3 <= kMinGain) break;
              if (t5 == v || t5 == here || t5 == t2 || neighbours(t4, t5) || same_edge(t4, t5, s4, s1) ||
                  same_edge(t4, t5, s2, s3))
                continue;
              for (int side6 = 0; side6 < 2; ++side6) {
                const HoleIndex t6 = next(t5, side6);
                if (t6 == v || t6 == here || neighbours(t6, here) || same_edge(t6, here, s2, s3) ||
                    same_edge(t6, here, s4, s1) || same_edge(t5, t6, s1, s2) ||
                    same_edge(t5, t6, s3, s4) || same_edge(t5, t6, here, t2) || same_edge(t5, t6, t3, t4))
                  continue;
                if (g3 + c(t5, t6) - c(t6, here) <= kMinGain) continue;
                t[8] = t5, t[9] = t6;
                static const int mate[10] = {3, 2, 1, 0, 9, 6, 5, 8, 7, 4};
                if (make(5, mate)) return true;
              }
            }
          }
        }
      }
    }
  }
  return false;
}

}  // namespace aco::detail
