// LKH's basis move (Helsgaun 2000, "An effective implementation of the
// Lin-Kernighan traveling salesman heuristic", section 4.3; LKH's
// Best5OptMove): a sequential 5-opt step. From t1 and each of its route
// neighbours t2, five nested levels over the candidates of the last hole
// reached, each new edge paid from the partial gain, which must stay
// positive; a removed edge either way round from the hole a candidate leads
// to. Any closing (t_2i, t1) at level 2 to 5 that gives one cycle and gains is
// made at once. When none does, the best 5-opt step that gives one cycle, by
// partial gain, is made on trial and the search goes on from t1 and the new
// end t10 (Lin-Kernighan's chain), up to kFiveOptSteps steps; a chain that
// never closes with a gain is undone. Edges a step added are not removed
// later in its chain, nor removed ones added back. Gains are paid in the
// ascent's penalised costs where the candidates carry them (candidates.h; up
// to kPenalisedTo holes, colony.h);
// what the route loses is summed in lengths.
//
// `--local-search 5opt` (and auto from kFiveOptFrom holes) runs it after
// 2-opt and Or-opt, in place of the 3-opt step and its deeper steps
// (three_opt.cpp). docs/colony.md has its measurements.
#include <algorithm>

#include "kopt_move.h"
#include "local_search.h"

namespace aco::detail {

namespace {

bool holds(const std::vector<std::array<HoleIndex, 2>>& edges, HoleIndex a, HoleIndex b) {
  for (const auto& e : edges) {
    if (same_edge(a, b, e[0], e[1])) return true;
  }
  return false;
}

// One search from a removed edge (t1, t2): the first gaining move, or the best
// 5-opt step that gives one cycle. `Tour`: the array route or the trial flips over it.
template <class Tour>
class KOptSearch {
 public:
  KOptSearch(const Space& space, const Candidates& cand, const Tour& tour, HoleIndex v, int breadth,
             const std::vector<std::array<HoleIndex, 2>>& added_before,
             const std::vector<std::array<HoleIndex, 2>>& removed_before)
      : space_(space), cand_(cand), tour_(tour), v_(v), breadth_(breadth), added_before_(added_before),
        removed_before_(removed_before) {}

  double c(HoleIndex a, HoleIndex b) const { return penalised(space_, cand_, a, b); }
  // `gain`: c(t1, t2) plus what the chain's steps before gained.
  bool from(HoleIndex t1, HoleIndex t2, double gain) {
    t_[0] = t1;
    t_[1] = t2;
    dir_ = tour_.next(t1, 0) == t2 ? 0 : 1;
    return extend(1, gain);
  }

  KOptMove found;  // the first move that closes with a gain
  KOptMove best;
  double best_gain = 0.0;  // the best step's partial gain, (t10, t1) not paid

 private:
  bool neighbours(HoleIndex a, HoleIndex b) const { return tour_.next(a, 0) == b || tour_.next(a, 1) == b; }
  bool removed_here(int i, HoleIndex a, HoleIndex b) const {
    for (int j = 0; j < i; ++j) {
      if (same_edge(a, b, t_[2 * j], t_[2 * j + 1])) return true;
    }
    return false;
  }
  KOptMove move(int k) const {
    KOptMove m;
    m.k = k;
    std::copy(t_, t_ + 2 * k, m.t);
    return m;
  }

  // t_[0..2i-1] chosen: i edges removed, i - 1 added; g the partial gain.
  bool extend(int i, double g) {
    const HoleIndex last = t_[2 * i - 1];
    if (i >= 2) {
      const double closed = g - c(last, t_[0]);
      if (closed > kMinGain && !neighbours(last, t_[0]) && !holds(removed_before_, last, t_[0])) {
        const KOptMove m = move(i);
        if (kopt_feasible(tour_, m, nullptr)) {
          found = m;
          return true;
        }
      }
    }
    if (i == kMaxMoveK) {
      if (g > best_gain + kMinGain && !neighbours(last, t_[0]) && !holds(removed_before_, last, t_[0])) {
        const KOptMove m = move(i);
        if (kopt_feasible(tour_, m, nullptr)) {
          best = m;
          best_gain = g;
        }
      }
      return false;
    }
    const HoleIndex* nbr = cand_.search_row(last);
    const double* nbr_length = cand_.search_costs(last);
    for (int r = 0; r < breadth_; ++r) {
      const HoleIndex a = nbr[r];
      const double g1 = g - nbr_length[r];
      if (g1 <= kMinGain) break;  // rows are sorted by cost: no later one passes
      if (a == v_ || a == t_[0] || neighbours(last, a) || holds(removed_before_, last, a)) continue;
      for (int side = 0; side < 2; ++side) {
        const HoleIndex b = tour_.next(a, side ^ dir_);  // read from t1 to t2: the same either way the route is stored
        if (b == v_ || removed_here(i, a, b) || holds(added_before_, a, b)) continue;
        t_[2 * i] = a;
        t_[2 * i + 1] = b;
        if (extend(i + 1, g1 + c(a, b))) return true;
      }
    }
    return false;
  }

  const Space& space_;
  const Candidates& cand_;
  const Tour& tour_;
  HoleIndex v_;
  int breadth_;
  const std::vector<std::array<HoleIndex, 2>>& added_before_;
  const std::vector<std::array<HoleIndex, 2>>& removed_before_;
  HoleIndex t_[2 * kMaxMoveK] = {};
  int dir_ = 0;
};

// What `move` shortens the route by, in lengths (the search's gains are in
// costs with penalties: the same sum, but for rounding).
double length_gain(const Space& space, const KOptMove& move) {
  double g = 0.0;
  for (int i = 0; i < move.k; ++i) {
    g += space.d(move.t[2 * i], move.t[2 * i + 1]) - space.d(move.t[2 * i + 1], move.t[(2 * i + 2) % (2 * move.k)]);
  }
  return g;
}

}  // namespace

bool LocalSearcher::try_five_opt(HoleIndex t1) {
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  const int breadth = std::min(kDeepBreadth, cand_.k);
  chain_added_.clear();
  chain_removed_.clear();
  ArrayTour tour{*this};
  KOptSearch<ArrayTour> first(space_, cand_, tour, v, breadth, chain_added_, chain_removed_);
  for (int dir = 0; dir < 2; ++dir) {
    const HoleIndex t2 = next(t1, dir);
    if (t2 == v || restricted(t1, t2)) continue;
    if (first.from(t1, t2, penalised(space_, cand_, t1, t2))) {
      KOptFlips flips;
      kopt_feasible(tour, first.found, &flips);
      make_flips(flips);
      gain_ += length_gain(space_, first.found);
      for (int i = 0; i < 2 * first.found.k; ++i) push(first.found.t[i]);
      return true;
    }
  }
  if (first.best_gain <= kMinGain) return false;
  return five_opt_chain(t1, first.best, first.best_gain);
}

bool LocalSearcher::five_opt_chain(HoleIndex t1, KOptMove step, double gain) {
  // As deepen(): trial flips on the array while short, from the first long
  // one on in trial_; only a chain that closes with a gain reaches the array.
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  const int breadth = std::min(kDeepBreadth, cand_.k);
  flips_.clear();
  bool overlaid = false;
  ArrayTour tour{*this};
  auto flips_of = [&](const KOptMove& move, KOptFlips& out) {
    return overlaid ? kopt_feasible(trial_, move, &out) : kopt_feasible(tour, move, &out);
  };
  auto make = [&](const KOptFlips& flips) {
    // false: a flip longer than deepen_reach(); the flips before it stay made, to be undone.
    for (int f = 0; f < flips.count; ++f) {
      const FlipNodes& x = flips.flip[static_cast<std::size_t>(f)];
      const std::size_t positions = overlaid ? trial_.flip_length(x[0], x[1], x[2], x[3]) : flip_length(x[0], x[1], x[2], x[3]);
      if (positions > deepen_reach()) return false;
      if (!overlaid && positions > array_flip_) {
        trial_.reset(route_.data(), pos_.data(), m_, !space_.open() && !windowed_);
        overlaid = true;
      }
      if (overlaid) {
        if (trial_.flips() == FlipOverlay::kMaxFlips) return false;
        trial_.flip(x[0], x[1], x[2], x[3]);
      } else {
        flip(x[0], x[1], x[2], x[3]);
        flips_.push_back(x);
      }
    }
    return true;
  };
  double made = 0.0;  // what the chain's steps made so far gained, in lengths
  KOptMove steps[kFiveOptSteps];
  for (int searched = 0; searched < kFiveOptSteps; ++searched) {
    KOptFlips flips;
    if (!flips_of(step, flips) || !make(flips)) break;
    made += length_gain(space_, step);
    steps[searched] = step;
    for (int i = 0; i < step.k; ++i) {
      chain_removed_.push_back({step.t[2 * i], step.t[2 * i + 1]});
      if (i + 1 < step.k) chain_added_.push_back({step.t[2 * i + 1], step.t[2 * i + 2]});
    }
    const HoleIndex t2 = step.t[2 * step.k - 1];  // now t1's neighbour
    bool closed = false;
    KOptMove found, deeper;
    double deeper_gain = 0.0;
    if (overlaid) {
      KOptSearch<FlipOverlay> s(space_, cand_, trial_, v, breadth, chain_added_, chain_removed_);
      closed = s.from(t1, t2, gain);
      found = s.found, deeper = s.best, deeper_gain = s.best_gain;
    } else {
      KOptSearch<ArrayTour> s(space_, cand_, tour, v, breadth, chain_added_, chain_removed_);
      closed = s.from(t1, t2, gain);
      found = s.found, deeper = s.best, deeper_gain = s.best_gain;
    }
    if (closed) {
      KOptFlips last;
      flips_of(found, last);
      // The chain's trial flips, then the closing move, made on the array.
      if (overlaid) make_trial_flips();
      make_flips(last);
      // The holes of every step, in order: the queue, and so the search
      // after, must not depend on where the trial flips were made.
      for (int s = 0; s <= searched; ++s) {
        for (int i = 0; i < 2 * steps[s].k; ++i) push(steps[s].t[i]);
      }
      for (int i = 0; i < 2 * found.k; ++i) push(found.t[i]);
      gain_ += made + length_gain(space_, found);
      return true;
    }
    if (deeper_gain <= kMinGain) break;
    step = deeper;
    gain = deeper_gain;
  }
  undo_array_flips();
  return false;
}

}  // namespace aco::detail
