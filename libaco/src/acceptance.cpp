// Acceptance and kicks, for the focused colony after each round: the
// reference route moves to the round's best when that is better or as good
// (across a plateau); when no ant has improved it for kKickAfter rounds, the
// best since the last restart is kicked by a double bridge within kKickSpan
// consecutive holes, repaired by local search around the bridge's new edges,
// and becomes the reference even if worse. Long stuck, the colony restarts
// instead (restarts.cpp).
#include "colony.h"

namespace aco::detail {

// A double bridge within kKickSpan consecutive positions of r: blocks
// A B C D -> A C B D; appends the ends of its three new edges to seeds.
void Colony::double_bridge(std::vector<HoleIndex>& r, Rng& krng, std::vector<HoleIndex>& seeds) const {
  const std::size_t mm = r.size();
  const std::size_t span = std::min<std::size_t>(kKickSpan, mm - 2);
  if (span < 8) return;
  const std::size_t a = space_.open() ? 1 + krng.below(static_cast<std::uint32_t>(mm - span - 1)) : krng.below(static_cast<std::uint32_t>(mm - span));
  std::size_t cut[3];
  for (auto& c : cut) c = 1 + krng.below(static_cast<std::uint32_t>(span - 1));
  std::sort(cut, cut + 3);
  if (!(cut[0] < cut[1] && cut[1] < cut[2])) return;
  const std::size_t p1 = a + cut[0], p2 = a + cut[1], p3 = a + cut[2];
  std::rotate(r.begin() + static_cast<long>(p1 + 1), r.begin() + static_cast<long>(p2 + 1), r.begin() + static_cast<long>(p3 + 1));
  const std::size_t mid = p1 + (p3 - p2);  // where the swapped blocks now meet
  for (const std::size_t q : {p1, p1 + 1, mid, mid + 1, p3, (p3 + 1) % mm}) seeds.push_back(r[q]);
}

void Colony::accept_or_kick(const std::vector<HoleIndex>*& ib_route, double& ib_len, bool& ib_measured, bool ib_plateau) {
  ++ref_stall_;
  const bool better = ib_len < ref_len_ - 1e-9;
  // On routes of any length. Up to kFullListLimit holes there were no
  // kicks while the search's deeper steps were 2-opt steps: then they
  // measured worse (d493 0.02 -> 0.26 %, u574 0.00 -> 0.11 %, d657 0.07 ->
  // 0.14 %). Since those steps are whole 3-opt steps they measure better
  // (2 threads, 10 seeds, median gap without -> with, at 1 s: d493 0.11 ->
  // 0.015 % (0.017 -> 0.019 % over seeds 11-30: half the seeds stay at
  // 0.20-0.24 % either way), u574 0.00 -> 0.00 % (3 seeds above 0 -> 2);
  // at 2 s: d657 0.105 -> 0.080 %, u724 0.095 -> 0.033 %), and pcb442
  // and d198 found their optimum with all 10 seeds either way.
  const bool walk = ref_stall_ >= kKickAfter;
  if (ib_plateau && (better || ib_len <= ref_len_ + 1e-9)) {
    // The reference moves to the iteration's best when it is better or as
    // good (across a plateau), but not when that is R itself from another
    // hole: every ant was repaired back to R, which is what stalls the
    // colony and calls for a kick. (Compared as arrays, an ant's route
    // from its random first hole always differed, and for closed tours
    // the kicks never came: pcb3038 at 15 s, 5 seeds, 0.160 % -> 0.110 %.)
    ref_len_ = set_reference(*ib_route);
    ib_len = ref_len_;
    ib_measured = true;
    if (better) ref_stall_ = 0;
  } else if (walk && kick_searcher_) {
    // Stuck: every ant's changes were repaired back to the reference. Kick
    // the colony's best since its last restart with a local double bridge,
    // repair that by local search and go on from there even if it is
    // worse; long stuck, restart from the best so far (kRestartAfter).
    Rng krng(p_.seed ^ 0x9E3779B97F4A7C15ULL, static_cast<std::uint64_t>(run_.it), 0xFFFF);
    std::vector<HoleIndex> r;
    bool shaken = false;
    if (restart_due()) {
      shaken = restart(krng, r);
    } else {
      r = run_.restart_best;  // not a wandering reference
      std::vector<HoleIndex> seeds;
      double_bridge(r, krng, seeds);
      shaken = !seeds.empty();
      if (shaken) kick_searcher_->improve_from(r, run_.moves, seeds);
    }
    if (shaken) {
      ref_len_ = set_reference(r);
      if (ref_len_ < run_.restart_best_len - 1e-9) {
        run_.restart_best_len = ref_len_;
        run_.restart_best = r;
        run_.since_restart = 0;
      }
      if (ref_len_ < run_.best_len - 1e-9) {
        run_.best_len = ref_len_;
        run_.best_route = r;
        run_.since_improvement = 0;
        run_.sol.trace.push_back({run_.it, clock_.seconds(), run_.best_len});
      }
    }
    ref_stall_ = 0;
  }
}

}  // namespace aco::detail
