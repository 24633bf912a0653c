// Restarts: after kRestartAfter rounds in which the colony's best since its
// last restart did not improve (some ten kicks in vain), the best route so far
// is shaken by max(kRestartKicks, n / 50) double bridges (or, every
// kFreshEvery-th restart where uses_fresh_restarts(), a new nearest-neighbour
// route from a random hole takes its place), improved by a whole local
// search, and becomes the reference on a fresh trail (colony.h tells what
// that measured).
#include <limits>

#include "colony.h"

namespace aco::detail {

bool Colony::restart_due() const { return run_.since_restart >= kRestartAfter; }

bool Colony::restart(Rng& krng, std::vector<HoleIndex>& r) {
  ++run_.restarts;
  if (uses_fresh_restarts(n_) && run_.restarts % kFreshEvery == 0) {
    r = route_from_order(space_, nearest_neighbor_order(space_, cand_, static_cast<HoleIndex>(krng.below(n_))));
  } else {
    r = run_.best_route;  // not a wandering reference
    std::vector<HoleIndex> seeds;
    const int kicks = std::max<int>(kRestartKicks, static_cast<int>(n_ / 50));
    for (int q = 0; q < kicks; ++q) double_bridge(r, krng, seeds);
    if (seeds.empty()) return false;
  }
  kick_searcher_->improve(r, run_.moves);
  set_all_tau(tau0_);
  run_.reinforced_for = -1.0;
  run_.restart_best_len = std::numeric_limits<double>::infinity();
  run_.since_restart = 0;
  return true;
}

}  // namespace aco::detail
