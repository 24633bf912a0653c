// The colony: every iteration the ants build routes in parallel (one ant per
// worker, each writing only its own slot), a barrier, then a deterministic
// reduction by (length, ant index) and the pheromone update on one thread.
//
// Pheromone lives on candidate edges only (n x k), so memory is O(n k) at
// any size; every other edge is taken to carry one shared trail, which makes
// the best of them simply the nearest unvisited hole (no value need be kept). For small problems the
// candidate list holds every other hole, which makes the thesis's Ant System
// exactly the published one: p_ij ∝ tau_ij^alpha * eta_ij^beta over all
// unvisited holes.
//
// References: Dorigo, Maniezzo & Colorni 1996 (Ant System); Stützle & Hoos 2000
// (MAX-MIN Ant System, trail limits and the u_gb schedule); Dorigo & Gambardella
// 1997 (Ant Colony System); Stützle's ACOTSP for default parameters.
//
// The colony's parts, each in its own file: colony.cpp (the colony's set-up:
// candidate lists, heuristic weights), rounds.cpp (the team's rounds: the
// ants' work and what follows each barrier), construction.cpp (an ant's
// route), reference.cpp (the focused colony's reference route),
// acceptance.cpp (acceptance of a round's best and kicks), restarts.cpp,
// recombine.cpp (merging the improvements of several ants), pheromone.cpp
// (the trail updates of AS, MMAS and ACS) and solve.cpp (parameters and the
// entry point). docs/colony.md tells the design and its measurements.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "aco/params.h"
#include "aco/problem.h"
#include "aco/solution.h"
#include "bucket_grid.h"
#include "candidates.h"
#include "local_search.h"
#include "parallel.h"
#include "recombine.h"
#include "rng.h"
#include "space.h"
#include "trail.h"

namespace aco::detail {

// Nearest neighbour from hole `first` (a closed tour; an open path starts
// nearest its start point).
Order nearest_neighbor_order(const Space& space, const Candidates& cand, HoleIndex first = 0);

// Up to this many holes the candidate list is every other hole (the exact Ant System).
constexpr std::size_t kFullListLimit = 800;

// With local search, above kFullListLimit, the candidates are the
// p.candidates (default 5) alpha-nearest among each hole's kAlphaFrom
// nearest (LKH's candidates). pcb3038, 2 threads, 3-opt: at 5 s the 12
// nearest gave 0.28 % (median of 3 seeds), 5 alpha-nearest after the ascent
// 0.19 % (median of 8); at 15 s 0.23 % and 0.13 % (5 seeds). Without the
// ascent alpha helped little (0.25 % at 5 s with 8 of them).
constexpr int kAlphaFrom = 16;
// Above this many holes the nearest are taken as they are: the ascent's
// sorts and the tree's O(n log n) ancestor table stop paying for themselves.
constexpr std::size_t kAlphaLimit = 200000;
// Whether a problem of `holes` gets alpha-nearness lists: the constructor
// builds them and resolve() sizes them by this one rule.
inline bool uses_alpha_lists(std::size_t holes, LocalSearch local_search) {
  return local_search != LocalSearch::None && holes > kFullListLimit && holes <= kAlphaLimit;
}
// Subgradient steps before alpha is measured: 100 took 0.1 s on pcb3038 and
// 1.5 s on d15112, so fewer on larger inputs (66 on d15112, 20 from 50 000),
// and under a time limit no more than about 5 % of it at the 1.5 us per hole
// and step measured on 100 000 holes (2 steps for d15112 in 1 s). Counted, not
// timed, so the same options give the same candidates on any machine.
inline int ascent_iterations(std::size_t holes, double time_limit_s) {
  const std::size_t n = std::max<std::size_t>(holes, 1);
  std::size_t steps = std::clamp<std::size_t>(1000000 / n, 20, 100);
  if (time_limit_s > 0) {
    const double affordable = 0.05 * time_limit_s / (1.5e-6 * static_cast<double>(n));
    steps = std::min(steps, static_cast<std::size_t>(affordable));
  }
  return static_cast<int>(steps);
}

// FocusedAcs, chosen by measurement on pcb442, pcb1173 and pcb3038 (median gap
// at fixed budgets, docs/benchmarks.md): at each step of its walk an ant
// leaves the reference route with this probability (until it has made
// focus_edges new edges), so its changes cluster in a stretch of some
// focus_edges / kDeviate holes instead of being strewn over the whole route,
// and local search can turn them into an improvement.
constexpr double kDeviate = 0.2;
// After this many iterations in which no ant improved the reference, the best
// route is kicked: by a double bridge near one of its long edges
// (walk_double_bridge) where uses_lkh_stall_answers(), else by three cuts
// within kKickSpan consecutive holes (Colony::double_bridge), a segment
// exchange the ants' search often undoes.
constexpr int kKickAfter = 30;
// ACS's local update: tau = (1 - xi) tau + xi tau0 on every edge an ant used.
constexpr double kWear = 0.1;
constexpr std::size_t kKickSpan = 50;
// After this many iterations in which the colony's best since its last
// restart did not improve (some ten kicks in vain), the colony restarts: the
// best route so far, shaken by max(kRestartKicks, n / 50) three-cut bridges
// within kKickSpan consecutive holes (Colony::double_bridge)
// and improved by a whole local search, becomes the reference, on a fresh
// trail. Without it a run stalled in its first tenth of a second (pcb442 at
// 1 s: optimal in 8 of 25 seeds; with it 18 of 25; d1291 at 5 s, median of 5
// seeds: 0.30 % -> 0.00 %). Restarting from the best so far rather than from
// the last restart's best, with 200 bridges rather than 100: pcb3038 at 15 s,
// seeds 1-10, median 0.103 % -> 0.052 % (0.056 % in a second run);
// fnl4461 at 20 s 0.134 -> 0.107 % (seeds 1-5). From the best with 100
// bridges pcb3038 gave 0.087 %; with 30 or 400 worse (0.147 %, 0.12 %).
constexpr std::size_t kReinforceHoles = 10000;
// Above this many holes a focused iteration has 20 ants (resolve()) and their
// improvements are merged (update()); on pla7397 (30 s, 3 seeds) merging
// measured worse (0.257 0.196 0.248 % with, 0.142 0.131 0.187 % without),
// on pcb3038 the same (0.110 % at 15 s), on 100 000 holes far better.
constexpr std::size_t kManyAntsFrom = 10000;
// From this many holes, given in an order that jumps about the plate (a path
// through them in input order more than kJumpyOrder times as long as along
// the curve), solve() numbers them along a Hilbert curve (hilbert.h) and the
// colony works on those numbers. In such an order the holes of a route, and
// a hole's neighbours, lie all over memory: 100 000 uniform holes given in
// random order (E100k, 30 s, 2 threads, seeds 1 and 2; 168 times as long)
// ran 5623 and 5450 iterations, the same holes in curve order 7795 and 6529,
// to shorter routes. d15112 (53 times) gained 4 % (8035 -> 8333 iterations
// at 20 s), and below kCurveOrderFrom the numbering stays as given, so routes
// up to it are as they were. An input that follows the plate already keeps
// its numbers: where distances tie, as on a grid, the numbers break the
// ties, and on the million-hole panel of bench/make_panel.py (1.85 times)
// curve numbers made the first route 4.9 % longer (nearest neighbour, then
// local search in windows), still 0.3 % after 40 s.
constexpr std::size_t kCurveOrderFrom = 16384;
// From kFiveOptFrom holes to kAlphaLimit (while the candidates are
// alpha-nearest) --local-search auto (the default) is LKH's 5-opt step;
// below and above, 3-opt with deeper steps (resolve() gives the
// measurements).
constexpr std::size_t kFiveOptFrom = 3000;
// The 5-opt step pays its gains in the ascent's penalised costs up to this
// many holes, in plain lengths above, where the ascent is cut short (27
// steps at 36 985 holes against 100 at pla7397's 7397) and its penalties
// misled the search: on five copies of pla7397 side by side (36 985 holes,
// 60 s, seeds 1-3) penalised 0.394 0.325 0.575 %, plain 0.172 0.296
// 0.199 % (3-opt 0.341 0.330 0.392 %); up to here the penalties won
// (d15112 at 64 s, seeds 1 and 2: 0.066 0.072 % against 0.096 0.107 %).
constexpr std::size_t kPenalisedTo = 20000;
// Whether alpha_candidates() keeps the ascent's penalties and the rows sorted
// by them: only the 5-opt step reads them, and only up to kPenalisedTo holes.
inline bool uses_penalised_costs(std::size_t holes, LocalSearch local_search) {
  return local_search == LocalSearch::FiveOpt && holes <= kPenalisedTo;
}
// Whether a stalled focused colony is kicked by the walk double bridge
// (walk_double_bridge) and a focused ant's 3-opt or 5-opt step is restricted
// to start off the reference (LocalSearcher::restrict_to), LKH's two answers
// to runs that stall (issue 67). Measured, 2 threads, seeds 1-5, medians,
// before -> with: pcb3038 at 15 s 0.048 -> 0.047 %, worst 0.084 -> 0.049 %
// (seeds 1-20: worst 0.130 -> 0.073 %, 9 -> 3 above 0.06 %); d493 at 1 s
// 0.20 -> 0.00 %, d657 at 2 s 0.072 -> 0.002 %, u724 at 2 s 0.048 -> 0.005 %.
// pla7397 at 91 s 0.038 % (the gap table had 0.05 %). Between kFullListLimit and kFiveOptFrom,
// where the ants' 3-opt searches alpha-nearest candidates, they lost: d1291
// at 5 s 0.00 -> 0.047 %, pcb1173 at 5 s 0.00 -> 0.007 %; above
// kManyAntsFrom, with 20 ants a round and their improvements merged, they
// did not help d15112 and brd14051 (0.063 -> 0.066 %, 0.044 -> 0.051 %;
// without them the same code gave 0.067 and 0.053 % later that day) and
// lost on the scale table (seeds 1-3, medians, the same day): 33 000 holes
// 0.562 -> 0.595 %, pla7397x5 0.264 -> 0.242 % but its worst 0.332 -> 0.880 %,
// 100 000 holes 0.526 -> 0.548 %.
inline bool uses_lkh_stall_answers(std::size_t holes) {
  return holes <= kFullListLimit || (holes >= kFiveOptFrom && holes <= kManyAntsFrom);
}
constexpr double kJumpyOrder = 4.0;
constexpr int kRestartAfter = 300;
constexpr int kRestartKicks = 200;
// Every kFreshEvery-th restart where uses_fresh_restarts(), the colony starts
// not from the best so far shaken but from a new route: nearest neighbour
// from a random hole, improved by the whole local search. A restart's epoch
// goes back to about the best so far at its first kick (see after_round),
// so this is a long walk of the reference from far away, on a fresh trail,
// that can come back another way. Measured, 2 threads, seeds 1-5, against
// without the same day (Intel Xeon): pla7397 at 91 s 0.151 0.007 0.019 0.052
// 0.006 % -> 0.036 0.040 0.006 0.084 0.006 % (median 0.019 -> 0.036 %, worst
// 0.151 -> 0.084 %; every second restart: seeds 1 and 4 0.124, 0.018 %);
// fnl4461 at 20 s median 0.026 -> 0.028 %, worst 0.040 -> 0.039 %; pcb3038
// at 15 s median 0.014 -> 0.020 %, worst 0.047 -> 0.060 %, so not below
// kFreshFrom. Above kManyAntsFrom not measured.
constexpr int kFreshEvery = 3;
constexpr std::size_t kFreshFrom = 4000;
inline bool uses_fresh_restarts(std::size_t holes) { return holes >= kFreshFrom && holes <= kManyAntsFrom; }

class Clock {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// A worker's scratch for building and improving one ant's route. One per
// worker, not per ant: an ant is taken by whichever worker is free, and its
// scratch would move from one core's cache to the other's every iteration
// (measured on pcb1173, see the commit). Aligned to a cache line: the vector
// headers are written at every step.
struct alignas(64) AntWork {
  std::vector<HoleIndex> route;       // array route, V at 0 for an open path
  std::vector<HoleIndex> unvisited;   // swap-remove list
  std::vector<HoleIndex> where;       // index of each hole in `unvisited`
  std::vector<double> weight;         // roulette weights over candidates
  std::unique_ptr<BucketGrid> grid;  // candidate-list mode: nearest unvisited hole
  // Focused construction: visited marks by stamp (no O(n) clear per ant), the
  // reference positions the ant walked (the gaps of its copy), and the ends
  // of the edges it made new.
  std::vector<std::uint32_t> mark;
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> visited_pos;  // positions in R of the holes walked before the copy
  double length = 0.0;                     // of `route` as built
  std::vector<HoleIndex> seeds;
  // Focused colony: the shortest route this worker built this round, so only
  // it, not every ant's, goes to the thread that updates the pheromone.
  std::vector<HoleIndex> best_route;
  double best_length = 0.0;
  int best_ant = -1;
  // The trail slots this worker's ants wore this round, ant after ant (kept
  // here, not with the ant, so the writes stay in this worker's cache).
  std::vector<std::size_t> worn;
};

// What an ant leaves for the pheromone update: its length, the trail slots of
// the edges ACS's local update wears (found by the ant, in parallel, so the
// serial part only writes them), and, for the colonies whose every ant
// deposits, its route (swapped with the worker's buffer, not copied).
struct alignas(64) AntRoute {
  std::vector<HoleIndex> route;
  int worker = 0;                      // whose `worn` list holds this ant's slots,
  std::size_t worn_from = 0, worn_to = 0;  // and where
  double length = 0.0;
  // Focused colony: whether the ant improved the reference, and then its
  // route as an exchange of edges against it (recombine.h).
  bool improves = false;
  detail::RouteDiff diff;
};

// The kick of a stalled focused colony where uses_lkh_stall_answers()
// (acceptance.cpp): a double bridge with four cuts near a long edge of route
// r, found by random walks over the candidate lists; appends the ends of the
// four edges it removes, which are those of the four it adds, to seeds.
void walk_double_bridge(const Space& space, const Candidates& cand, std::vector<HoleIndex>& r, Rng& rng,
                        std::vector<HoleIndex>& seeds);

class Colony {
 public:
  // The colony of a problem; set_up() then builds its candidate lists (every
  // other hole, alpha-nearest or nearest) and heuristic weights (colony.cpp).
  Colony(const Problem& problem, const Params& params, Team& team, const Clock& started);
  // A slice of ColonyRun::advance() begins; `worked`: its work so far has
  // made progress (see slice_over()).
  void begin_slice(bool worked) { worked_ = worked; }
  // The set-up on `team`, in pieces (issue 84): true once done, false when
  // the clock reached `until_s` first (0: no bound) and a later call goes
  // on where it stopped. The nearest lists' rows and the weights are cut at
  // any row, the alpha-nearest at any step of theirs, with the same result;
  // the full lists (up to kFullListLimit holes) are made whole.
  bool set_up(Team& team, double until_s);

  // The run (rounds.cpp), in slices: start() makes the first route and
  // trail; advance() runs rounds of ants on `team` until the run ends
  // (true) or the slice does: after `max_iterations` more iterations (0:
  // no bound) or once the clock reaches `until_s` (0: none). A slice ends
  // between two iterations, with the next one's ants drawn, so any slicing
  // runs the same iterations as one advance(). finish() gives the best
  // route; before the run has ended it ends it there ("stopped").
  // Of start(): it makes the nearest-neighbour route, in pieces, and is
  // false when the clock reached `until_s` (0: no bound) first, a later call
  // going on where it stopped; that route's local search, seconds on 10^5
  // holes, then runs in the slices' time (first_search), and the trail is
  // set up after it, so that a slice ends on time even then.
  bool start(double until_s);
  // Runs the first route's search until it is done (true; the rounds are
  // then set up) or the clock reaches `until_s` (false; 0: no bound).
  bool first_search(double until_s);
  bool advance(Team& team, int max_iterations, double until_s);
  // A stop asked, or the time limit reached: what ends the run, and the searches in it.
  bool must_end() const;
  Solution finish();
  int completed() const { return run_.completed; }
  Order best_order() const { return to_order(first_search_ ? first_search_->route() : run_.best_route); }

 private:
  // What run() keeps from round to round (rounds.cpp sets it up).
  struct RunState {
    Solution sol;
    std::vector<HoleIndex> best_route;  // the best so far, and its length
    double best_len = 0.0;
    bool use_ls = false, focused = false, acs = false;
    Moves moves = Moves::TwoOpt;
    double tau_max = 0.0, tau_min = 0.0;  // MMAS's trail limits
    std::vector<AntRoute> work;           // one an ant
    std::vector<AntWork> workers;         // one a worker
    std::vector<LocalSearcher> searchers;  // one a worker
    double reinforced_for = -1.0;  // the best length whose route's edges the trail reinforces
    int reinforced_at = 0;         // since this iteration
    int since_improvement = 0;
    int since_restart = 0;
    int restarts = 0;
    std::vector<HoleIndex> restart_best;  // the best since the last restart, and its length
    double restart_best_len = 0.0;
    int it = 1;  // the iteration under way
    int completed = 0;  // iterations run
    bool ended = false;
    int slice_last_it = 0;     // the slice's last iteration (0: none)
    double slice_until_s = 0;  // the slice ends at this clock (0: none)
    int next_slot = 0;         // ants_in_turn(): the next ant of the round under way,
    bool ant_begun = false;    // and whether its search is under way
    // Focused ants draw how many edges they may change, first thing; they are
    // handed out largest first, so a round ends on short ones and the workers
    // finish it together.
    std::vector<int> ant_of_slot, scale_of_ant;
    // Recombination's scratch (recombine.cpp).
    DiffMerger merger;
    std::vector<int> improving;
    std::vector<const RouteDiff*> diffs;
    std::vector<int> diff_ants;  // whose diffs[i] is
    std::vector<HoleIndex> merged;
    std::vector<std::size_t> reinforce_slots;  // pheromone.cpp's scratch
  };

  // The team's rounds (rounds.cpp): the ants' order, one ant's work on a
  // worker, and after the barrier, on one thread, everything else; false ends the run.
  void order_ants();
  void ant(int slot, int worker);  // begin_ant(), the ant's search, end_ant()
  void begin_ant(int slot, int worker);
  void end_ant(int slot, int worker);
  bool after_round();
  // The rounds on one thread, as Team::rounds() runs them there, but a slice
  // may also end between two ants and inside an ant's search: at 10^6 holes
  // an iteration's 20 ants took 0.2-0.7 s, one ant up to 0.3 s, longer than
  // a page's slice (issue 84). The next slice goes on where this one ended;
  // a round's ants read nothing another writes before after_round(), and a
  // search resumed makes the moves it would have made, so the run is the
  // same. Returns what advance() returns.
  bool ants_in_turn();
  // Recombination (recombine.cpp): the improvements of the round's other ants
  // added to the best's where they touch other holes; may make `ib_route`
  // the merged route, with its length.
  void merge_improvements(int ib, const std::vector<HoleIndex>*& ib_route, double& ib_len);
  // Acceptance and kicks (acceptance.cpp): the reference moves to the round's
  // best, or, stuck, the colony is kicked (or restarted, restarts.cpp).
  void accept_or_kick(const std::vector<HoleIndex>*& ib_route, double& ib_len, bool& ib_measured, bool ib_plateau);
  void double_bridge(std::vector<HoleIndex>& r, Rng& krng, std::vector<HoleIndex>& seeds) const;
  // Restarts (restarts.cpp): whether the colony is long stuck, and the restart
  // itself: `r` becomes the best so far shaken and improved; false when the
  // route is too short to shake.
  bool restart_due() const;
  bool restart(Rng& krng, std::vector<HoleIndex>& r);
  // The pheromone update of the colony's algorithm (pheromone.cpp).
  void update_pheromone(const std::vector<HoleIndex>& ib_route, double ib_len);
  void mmas_limits(double best);

  RunState run_;
  std::size_t idx(HoleIndex i, int r) const { return static_cast<std::size_t>(i) * k_ + r; }
  static double eta(double d) { return 1.0 / std::max(d, 1e-9); }
  int rank_of(HoleIndex i, HoleIndex j) const {
    if (!rank_.empty()) return rank_[static_cast<std::size_t>(i) * n_ + j];
    const HoleIndex* c = cand_.of(i);
    for (int r = 0; r < k_; ++r) {
      if (c[r] == j) return r;
    }
    return -1;
  }
  void set_all_tau(double v) {
    tau_.update_all([v](double) { return v; });
  }
  void refresh_choice();
  void construct(AntWork& w, Rng& rng, bool acs);
  void construct_focused(AntWork& w, Rng& rng, int bound) const;
  HoleIndex choose_focused(HoleIndex cur, const AntWork& w, Rng& rng, HoleIndex exclude) const;
  // Makes `route` the reference and returns its length, summed edge by edge
  // as Space::route_cost() sums it (the same bits).
  double set_reference(const std::vector<HoleIndex>& route);
  // Whether `route` is the reference's cycle, from any start, either way round.
  bool is_reference(const std::vector<HoleIndex>& route) const;
  // Writes the positions of R that `route` changes; returns the first (m if none).
  std::size_t rewrite_reference(const std::vector<HoleIndex>& route);
  // A hole's point, or for V the start (where its edges leave from).
  Point2 point_of(HoleIndex h) const { return h < n_ ? space_.point(h) : space_.start(); }
  HoleIndex choose_next(HoleIndex cur, AntWork& w, Rng& rng, bool acs);
  HoleIndex nearest_unvisited(HoleIndex cur, const AntWork& w) const;
  void deposit(const std::vector<HoleIndex>& route, double amount);
  void deposit_edge(HoleIndex a, HoleIndex b, double amount);
  // Appends the trail slots of edge (a, b), both ways, that are candidate edges.
  void add_slots(HoleIndex a, HoleIndex b, std::vector<std::size_t>& slots) const {
    if (a >= n_ || b >= n_) return;  // V's edges carry no pheromone
    int r = rank_of(a, b);
    if (r >= 0) slots.push_back(idx(a, r));
    r = rank_of(b, a);
    if (r >= 0) slots.push_back(idx(b, r));
  }
  // The trail slots of every edge of `route`, both ways: the set add_slots()
  // gives edge by edge (a row holds each hole once; the trail treats each
  // slot on its own, so their order is free). Short rows are read hole by
  // hole in memory order, against the hole's two neighbours in the route,
  // without a branch a match; the slots come out in trail order too. At
  // 100 000 holes a reinforcement took 5.0-5.2 ms edge by edge (two rows
  // somewhere else in memory an edge), now 3.0-3.2; with a branch a match,
  // mispredicted, the rows alone took 3.2 ms.
  void route_slots(const std::vector<HoleIndex>& route, std::vector<std::size_t>& slots);
  // ACS's local update: an edge an ant used loses some trail, toward tau0.
  double wear(double t) const { return (1.0 - kWear) * t + kWear * tau0_; }
  // The slots of edge (a, b) that wearing changes. Wearing is one map applied
  // once per use, so a slot it leaves unchanged (most sit at tau0) stays
  // unchanged however many ants use it, and the serial update skips it.
  void add_worn_slots(HoleIndex a, HoleIndex b, std::vector<std::size_t>& slots) const {
    const std::size_t first = slots.size();
    add_slots(a, b, slots);
    slots.erase(std::remove_if(slots.begin() + static_cast<std::ptrdiff_t>(first), slots.end(),
                               [this](std::size_t e) { return wear(tau_[e]) == tau_[e]; }),
                slots.end());
  }
  void evaporate(double factor) {
    tau_.update_all([factor](double t) { return t * factor; });
  }
  Order to_order(const std::vector<HoleIndex>& route) const;

  // Started by solve(), before anything it does: the numbering and the
  // candidate lists' ascent count against --time-limit.
  Clock clock_;
  const Problem& problem_;
  Params p_;
  detail::Team* team_;  // the team of the slice under way (advance())
  Space space_;
  HoleIndex n_;
  // Where set_up() is: the lists (rows_ while the nearest are filled), the
  // weights (rows below weighted_ done), then the trail.
  enum class SetUp { Lists, Weights, Trail, Done } set_up_ = SetUp::Lists;
  std::unique_ptr<NearestRows> rows_;
  // The k nearest of every hole into `out`, rows_ cut as set_up() cuts them.
  bool nearest_rows(Team& team, int k, double until_s, Candidates& out);
  std::unique_ptr<AlphaLists> alpha_;
  HoleIndex weighted_ = 0;
  Candidates cand_;
  int k_ = 0;
  detail::Trail tau_;
  std::vector<double> choice_, eta_beta_;
  std::vector<HoleIndex> route_neighbours_;  // route_slots()' scratch: each hole's two, 2n
  std::vector<int> rank_;  // full-list mode: rank of j in i's list
  // Full-list mode: choice by (i, j), so an ant scans only its unvisited holes
  // (n²/2 per tour instead of n²; measured 2x on the thesis's 70-hole runs).
  std::vector<double> dense_choice_;
  std::vector<double> start_weight_;  // open path: eta(start, h)^beta
  double tau0_ = 0.0;
  // FocusedAcs: the reference route the ants start from (the best so far),
  // and each node's position in it.
  std::vector<HoleIndex> ref_route_;
  std::vector<std::uint32_t> ref_pos_;
  // ref_prefix_[i]: length of R from position 0 to position i, read in array order.
  std::vector<double> ref_prefix_;
  // R's points in its order (V's: the start), written where R changes, so
  // the prefix sums read memory in order. Read through the holes, each
  // point somewhere else in memory, they took 0.72 ms a time at 100 000
  // holes, read here 0.39.
  std::vector<Point2> ref_points_;
  double ref_len_ = 0.0;
  int ref_stall_ = 0;  // iterations since the reference last improved
  std::unique_ptr<LocalSearcher> kick_searcher_;
  // The first route's search while it runs (start() to first_search()), and
  // the nearest-neighbour route's length, which sets the first trail.
  std::unique_ptr<LocalSearcher> first_search_;
  std::unique_ptr<NearestWalk> first_walk_;  // the first route while start() walks it
  // Whether a piece of work was done in the slice under way: a slice is over
  // when the clock reaches its end and it has done one, so that any slice,
  // however short, gets on, and none begins a piece once its time is up.
  bool worked_ = false;
  bool slice_over(double until_s) const { return worked_ && until_s > 0.0 && clock_.seconds() >= until_s; }
  double c_nn_ = 1.0;
  void start_rounds();
};

}  // namespace aco::detail
