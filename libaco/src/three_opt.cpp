// Sequential 3-opt with deeper steps, the search from a hole below
// kFiveOptFrom holes and above kAlphaLimit (--local-search 3opt): the best
// 3-opt step from t1 by Lin and Kernighan's gain criterion, made when it
// closes with a gain; when none does, deepen() chains whole 3-opt steps from
// the kDeepen most promising, as LKH chains its basis moves. 2-opt, Or-opt
// and the route's flips are local_search.cpp's; LKH's 5-opt step is
// five_opt.cpp's. docs/colony.md has the measurements.
#include <algorithm>

#include "local_search.h"

namespace aco::detail {

bool LocalSearcher::try_three_opt(HoleIndex t1) {
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  // The search goes deeper from the kDeepen best steps, one after the other
  // (LKH's breadth at its first levels). Measured from nearest-neighbour
  // routes on 7 TSPLIB drilling instances, summed gap and time of one
  // improve(), when the deeper steps were 2-opt steps: 1 step, depth 8:
  // 30.4 %, 0.16 s; 3 steps, depth 6: 26.5 %, 0.17 s; 3 steps, depth 20:
  // 26.4 %, 0.43 s.
  constexpr int kDeepen = 3;
  Step best[kDeepen];
  for (int dir = 0; dir < 2; ++dir) {
    const HoleIndex t2 = next(t1, dir);
    if (t2 == v || restricted(t1, t2)) continue;
    ArrayTour tour{*this};
    if (three_opt_step(tour, t1, dir, space_.d(t1, t2), best, kDeepen, cand_.k)) return true;
  }
  for (int q = 0; q < kDeepen; ++q) {
    if (best[q].gain <= kMinGain) return false;
    if (deepen(t1, best[q])) return true;
  }
  return false;
}

template <class Tour>
bool LocalSearcher::three_opt_step(Tour& tour, HoleIndex t1, int dir, double gain, Step* best, int keep, int breadth) {
  // Names follow Lin & Kernighan: x1 = (t1,t2) out, y1 = (t2,t3) in,
  // x2 = (t3,t4) out, y2 = (t4,t5) in, x3 = (t5,t6) out, y3 = (t6,t1) in.
  // Gains are partial sums that must stay positive (the gain criterion);
  // `gain` is the first, x1's length, or deeper down what the steps before
  // gained with x1 taken out.
  // V, an open path's start and end, is never t1..t6: its edges cost
  // differently each way and are left to 2-opt and Or-opt, which read them in
  // array order.
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  const HoleIndex t2 = tour.next(t1, dir);
  const HoleIndex* n2 = cand_.of(t2);
  const double* n2_length = cand_.lengths_of(t2);
  for (int r3 = 0; r3 < breadth; ++r3) {
    const HoleIndex t3 = n2[r3];
    const double g1 = gain - n2_length[r3];
    if (g1 <= kMinGain) break;
    if (t3 == t1 || t3 == tour.next(t2, dir)) continue;
    for (int stretch = 0; stretch < 2; ++stretch) {
      // stretch 0: t4 before t3, so closing up would be a 2-opt move, and a
      //   second flip follows; stretch 1: t4 after t3, so t2..t3 is cut out
      //   whole and must be put back between t5 and t6 inside it.
      const HoleIndex t4 = tour.next(t3, stretch == 0 ? 1 - dir : dir);
      if (t4 == v || t4 == t1 || t4 == t2) continue;
      const double g1x = g1 + space_.d(t3, t4);
      const HoleIndex* n4 = cand_.of(t4);
      const double* n4_length = cand_.lengths_of(t4);
      for (int r5 = 0; r5 < breadth; ++r5) {
        const HoleIndex t5 = n4[r5];
        const double g2 = g1x - n4_length[r5];
        if (g2 <= kMinGain) break;
        if (t5 == t3 || t5 == t1) continue;
        if (stretch == 0) {
          // After the first flip the route reads t1 t4 ... t2 t3 ...; t6
          // must precede t5 in that reading: t5's old successor inside the
          // turned stretch t2..t4, its old predecessor outside it.
          const bool inside = tour.between(t2, t5, t4, dir);
          if (t5 == tour.next(t4, 1 - dir) && inside) continue;  // t5 is t4's new neighbour
          const HoleIndex t6 = tour.next(t5, inside ? dir : 1 - dir);
          if (t6 == v) continue;
          const double g3 = g2 + space_.d(t5, t6);
          if (g3 - space_.d(t6, t1) > kMinGain) {
            gain_ += g3 - space_.d(t6, t1);
            tour.flip(t1, t2, t4, t3);
            tour.flip(t1, t4, t6, t5);
            for (HoleIndex t : {t1, t2, t3, t4, t5, t6}) push(t);
            return true;
          }
          if (g3 > best[keep - 1].gain) {
            int q = keep - 1;
            while (q > 0 && best[q - 1].gain < g3) {
              best[q] = best[q - 1];
              --q;
            }
            best[q] = {g3, {t2, t3, t4, t5, t6}};
          }
        } else {
          if (!tour.between(t2, t5, t3, dir)) continue;
          for (int side = 0; side < 2; ++side) {
            // side 0: t6 after t5, the stretch goes back as it was (in two
            // pieces swapped); side 1: t6 before t5, both pieces turned.
            if (side == 0 && t5 == t3) continue;
            if (side == 1 && t5 == t2) continue;
            const HoleIndex t6 = tour.next(t5, side == 0 ? dir : 1 - dir);
            if (t6 == v) continue;
            const double total = g2 + space_.d(t5, t6) - space_.d(t6, t1);
            if (total <= kMinGain) continue;
            gain_ += total;
            if (side == 0) {
              tour.flip(t1, t2, t5, t6);
              tour.flip(t1, t5, t3, t4);
              tour.flip(t1, t3, t6, t2);
            } else {
              tour.flip(t1, t2, t6, t5);
              tour.flip(t2, t5, t3, t4);
            }
            for (HoleIndex t : {t1, t2, t3, t4, t5, t6}) push(t);
            return true;
          }
        }
      }
    }
  }
  return false;
}

bool LocalSearcher::deepen(HoleIndex t1, Step step) {
  // Lin-Kernighan's deeper steps, each a whole sequential 3-opt step as LKH
  // chains its basis moves (Helsgaun 2000): the step is made, then edge
  // (t1, t6) is taken out again and the best 3-opt step from t6 searched,
  // closing with (t_last, t1), until one closes with a gain or kDeepSteps
  // were searched in vain; then every flip is undone. A trial flip is made
  // on the array while it is short; from the first long one on (more than
  // kArrayFlip positions), the chain goes on in trial_, over the array as it
  // then is, and only a chain that closes with a gain is made on the array,
  // flip by flip in the same order: the same route as making and undoing
  // every flip on the array gives, but a long flip in vain costs nothing.
  flips_.clear();
  bool overlaid = false;
  auto length = [&](HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) {
    return overlaid ? trial_.flip_length(a, b, c, d) : flip_length(a, b, c, d);
  };
  auto make = [&](HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d, std::size_t positions) {
    if (!overlaid && positions > array_flip_) {
      trial_.reset(route_.data(), pos_.data(), m_, !space_.open() && !windowed_);
      overlaid = true;
    }
    if (overlaid) {
      trial_.flip(a, b, c, d);
    } else {
      flip(a, b, c, d);
      flips_.push_back({a, b, c, d});
    }
  };
  for (int searched = 0; searched < kDeepSteps; ++searched) {
    const HoleIndex(&t)[5] = step.t;  // t2..t6
    const std::size_t first = length(t1, t[0], t[2], t[1]);
    if (first > deepen_reach()) break;
    make(t1, t[0], t[2], t[1], first);
    const std::size_t second = length(t1, t[2], t[4], t[3]);
    if (second > deepen_reach()) break;
    make(t1, t[2], t[4], t[3], second);
    const int dir = (overlaid ? trial_.next(t1, 0) : next(t1, 0)) == t[4] ? 0 : 1;  // t6 is now t1's neighbour
    const int trial_flips = overlaid ? trial_.flips() : 0;
    Step deeper;
    const int breadth = std::min(kDeepBreadth, cand_.k);
    ArrayTour tour{*this};
    if (overlaid ? three_opt_step(trial_, t1, dir, step.gain, &deeper, 1, breadth)
                 : three_opt_step(tour, t1, dir, step.gain, &deeper, 1, breadth)) {
      if (overlaid) make_trial_flips();
      for (const auto& f : flips_) {
        for (HoleIndex x : f) push(x);
      }
      for (int f = 0; f < trial_flips; ++f) {
        for (HoleIndex x : trial_.flip_at(f)) push(x);
      }
      return true;
    }
    if (deeper.gain <= kMinGain) break;
    step = deeper;
  }
  // Nothing closed with a gain: trial_ is dropped, the array's flips undone.
  undo_array_flips();
  return false;
}

}  // namespace aco::detail
