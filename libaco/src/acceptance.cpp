// Acceptance and kicks, for the focused colony after each round: the
// reference route moves to the round's best when that is better or as good
// (across a plateau); when no ant has improved it for kKickAfter rounds, the
// best since the last restart is kicked by a double bridge (near a long edge,
// walk_double_bridge, where uses_lkh_stall_answers(); else within kKickSpan
// consecutive holes), repaired by local search around the bridge's new
// edges, and becomes the reference even if worse. Long stuck, the colony
// restarts instead (restarts.cpp).
#include <limits>

#include "colony.h"

namespace aco::detail {

// The restarts' shake (restarts.cpp), and the kick where the walk bridge is
// not used: within kKickSpan consecutive positions of r, blocks A B C D ->
// A C B D, three cuts, so a segment exchange (a pure 3-opt move) more than a
// double bridge; appends the ends of its three new edges to seeds.
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

// LKH's kick (its KSwapKick with K = 4, from a long edge and by walks): a
// true double bridge, four cuts, stretches S1 S2 S3 S4 of r back as
// S1 S4 S3 S2, none turned, so all four joins are new and no sequential move
// undoes it. The first cut after the worst of 10 + n / 1000 random holes
// (its route edge longest against its nearest candidate), each other after
// the last hole a 50-step random walk over the candidate lists reaches from
// the cut before: near on the plate, anywhere along the route. Appends the
// ends of the four new edges to seeds (nothing when the cuts did not come
// out four).
void walk_double_bridge(const Space& space, const Candidates& cand, std::vector<HoleIndex>& r, Rng& rng,
                        std::vector<HoleIndex>& seeds) {
  const HoleIndex n = space.holes();
  const std::size_t m = r.size();
  if (m < 16) return;
  std::vector<std::uint32_t> pos(m);
  for (std::size_t i = 0; i < m; ++i) pos[r[i]] = static_cast<std::uint32_t>(i);
  const auto succ = [&](HoleIndex h) { return r[(pos[h] + 1) % m]; };
  const auto cuttable = [&](HoleIndex h) { return h < n && succ(h) < n; };  // neither end V
  HoleIndex cut_at[4];
  cut_at[0] = n;
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t q = 0; q < 10 + n / 1000; ++q) {
    const HoleIndex h = static_cast<HoleIndex>(rng.below(n));
    if (!cuttable(h)) continue;
    const double excess = space.d(h, succ(h)) - cand.lengths_of(h)[0];
    if (excess > worst) worst = excess, cut_at[0] = h;
  }
  if (cut_at[0] == n) return;
  const int width = std::min(cand.k, 5);
  if (width < 1) return;
  for (int c = 1; c < 4; ++c) {
    HoleIndex from = cut_at[c - 1], came_from = n, reached = n;
    for (int step = 0; step < 50; ++step) {
      const HoleIndex h = cand.of(from)[rng.below(static_cast<std::uint32_t>(width))];
      if (h == came_from || std::find(cut_at, cut_at + c, h) != cut_at + c) continue;
      came_from = from;
      from = h;
      if (cuttable(h)) reached = h;
    }
    if (reached == n) return;
    cut_at[c] = reached;
  }
  std::size_t cut[4];
  for (int c = 0; c < 4; ++c) cut[c] = pos[cut_at[c]];
  std::sort(cut, cut + 4);
  const auto at = [&](std::size_t p) { return r.begin() + static_cast<long>(p); };
  std::vector<HoleIndex> out;
  out.reserve(m);
  out.insert(out.end(), at(cut[0] + 1), at(cut[1] + 1));  // S1
  out.insert(out.end(), at(cut[3] + 1), r.end());         // S4, to the array's end
  out.insert(out.end(), r.begin(), at(cut[0] + 1));       // and from its start
  out.insert(out.end(), at(cut[2] + 1), at(cut[3] + 1));  // S3
  out.insert(out.end(), at(cut[1] + 1), at(cut[2] + 1));  // S2
  // An open path's V back at position 0: the same cycle, turned round.
  if (space.open()) std::rotate(out.begin(), std::find(out.begin(), out.end(), n), out.end());
  for (const std::size_t c : cut) seeds.insert(seeds.end(), {r[c], r[(c + 1) % m]});
  r.swap(out);
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
      if (uses_lkh_stall_answers(n_)) walk_double_bridge(space_, cand_, r, krng, seeds);
      else double_bridge(r, krng, seeds);
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
