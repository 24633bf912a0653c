#pragma once
// 2-opt, Or-opt and 3-opt with Lin-Kernighan's deeper steps on an array route
// with neighbour lists and don't-look bits (Bentley 1992; Johnson & McGeoch
// 1997, "The TSP: a case study in local optimization"), or LKH's 5-opt step
// in place of the 3-opt: local_search.cpp (the queue, 2-opt, Or-opt and the
// route's flips), three_opt.cpp and five_opt.cpp. The route is a cycle over Space::route_size() nodes whose
// position 0 never moves, so an open path's virtual node V keeps its place and
// its direction-dependent edges stay right.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "candidates.h"
#include "flip_overlay.h"
#include "kopt_move.h"
#include "space.h"

namespace aco::detail {

// A move must gain more than this to be taken: rounding noise must not make
// two equal-length routes swap forever.
inline constexpr double kMinGain = 1e-9;

inline bool same_edge(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) { return (a == c && b == d) || (a == d && b == c); }

// What edge (a, b) costs the 5-opt step and the non-sequential moves: its
// length, plus the ascent's penalties of its ends where the candidates carry them.
inline double penalised(const Space& space, const Candidates& cand, HoleIndex a, HoleIndex b) {
  return cand.has_pi() ? space.d(a, b) + cand.pi[a] + cand.pi[b] : space.d(a, b);
}

// Which moves a search tries at each hole, each set adding to the one before.
enum class Moves {
  TwoOpt,
  // + moving a segment of 1 to 3 holes elsewhere, either way round (Or 1976).
  OrOpt,
  // + every sequential 3-opt move found from neighbour lists (Johnson &
  // McGeoch 1997; LK's depth-3 step): the two that are two 2-opt flips in a
  // row, and the two that move a whole stretch of the route elsewhere, turned
  // or not, which Or-opt does only for stretches of up to 3 holes.
  ThreeOpt,
  // 2-opt, Or-opt, then LKH's sequential 5-opt step in place of the 3-opt
  // step and its deeper steps (five_opt.cpp).
  FiveOpt
};

// Aligned to a cache line: one searcher per ant, and ants run on different threads.
class alignas(64) LocalSearcher {
 public:
  LocalSearcher(const Space& space, const Candidates& candidates);

  // Improves `route` in place until no move gains.
  // `moves` says which moves are tried (see Moves).
  // Routes longer than kWindow are improved in overlapping windows of
  // kWindow positions: an array 2-opt move reverses up to half the route, so
  // on a million holes whole-route search is quadratic; windows keep every
  // move's cost bounded and the pass linear.
  void improve(std::vector<HoleIndex>& route, Moves moves);
  // Ends improve() early once `due()` is true (asked every 64 holes searched):
  // the route stays whole, as improved as it got. For a stop or a time limit
  // (issue 84: the first tour's search of 10^5 holes took seconds no Stop
  // could end), never for a slice's end, which must not change the result.
  void interrupt_when(std::function<bool()> due) { due_ = std::move(due); }
  bool interrupted() const { return interrupted_; }
  // improve() in slices, for a front end that must have control back often
  // (issue 84: the page's worker every 0.1 s): begin() takes the route,
  // search() searches until no move gains (true) or until `pause()` says
  // (false; asked as interrupt_when's `due` is), end() gives the route back.
  // Paused and resumed it makes the moves improve() makes, in that order.
  void begin(std::vector<HoleIndex>& route, Moves moves);
  bool search(const std::function<bool()>& pause);
  void end(std::vector<HoleIndex>& route);
  // The route under a search in slices, between begin() and end().
  const std::vector<HoleIndex>& route() const { return route_; }
  // The same, looking only where something changed: the queue starts with
  // `seeds` (the ends of an ant's new edges) and grows only where moves are
  // made, so the search costs what the ant changed, plus O(n) to load the route.
  // That O(n) was measured against holding an ant's route as runs of the
  // reference instead (a segment list over it: nothing loaded, a flip costing
  // the runs it touches). The runs lost: 2.2 times fewer iterations on
  // 29 588 holes, 2.4 on 100 000 (30 s, 2 threads). Each neighbour look-up
  // there is four dependent loads against the array's two, and flips with
  // their splits were a fifth of the perf samples (29 588 holes, 440 an ant).
  void improve_from(std::vector<HoleIndex>& route, Moves moves, const std::vector<HoleIndex>& seeds);
  // improve_from() in slices, as begin() is improve() in slices: search()
  // and end() go on from here (issue 84: at 10^6 holes an ant's search took
  // up to 0.3 s, longer than a page's slice).
  void begin_from(std::vector<HoleIndex>& route, Moves moves, const std::vector<HoleIndex>& seeds);
  static constexpr std::size_t kWindow = 100000;
  // After an improve_from that searched (searched_all(): it had seeds, and
  // its queue never dropped its head on a long search): every hole it was
  // given or whose edges a move changed (some more than once), so an end of
  // every edge of the route that the route it was given lacked; and each
  // hole's position in the route. Valid until the next search.
  bool searched_all() const { return !forgot_; }
  const std::vector<HoleIndex>& searched() const { return queue_; }
  const std::vector<std::uint32_t>& positions() const { return pos_; }
  // How much shorter the last improve or improve_from made the route: the
  // sum of its moves' gains, so a caller need not measure the whole route.
  double gain() const { return gain_; }

  // For tests: measure the whole route before and after every search at a
  // hole, and count the searches whose move did not shorten it or that made
  // no move yet changed it (O(n) each, so never in a run). The first failure
  // ends the search.
  void audit(bool on) { audit_ = on; }
  // LKH's non-sequential moves (its Gain23, bridge_moves.cpp) from every hole
  // whose 5-opt search found nothing; on by default, off for tests.
  void non_sequential(bool on) { non_sequential_ = on; }
  // For tests: Or-opt moves by reversals from this shift on (see kFarShift).
  void far_shift(std::size_t holes) { far_shift_ = holes; }
  // For tests: deepen()'s trial flips longer than this go to its overlay (see kArrayFlip).
  void array_flip(std::size_t positions) { array_flip_ = positions; }
  // An Or-opt move that would shift at least this many holes is made by
  // reversals of the shorter side instead, where they touch fewer (closed
  // tours searched whole). Not below it: an element of a reversal costs more
  // than one of rotate's memmove, and on pcb3038 (15 s, 2 threads) reversals
  // for every move they made shorter gave a median gap of 0.061 % against
  // 0.036 % over seeds 1-11, and 4 % fewer iterations (seed 7). On 100 000
  // holes 1 move in 8 shifted more than 25 000, and those were 98 % of the
  // shifting.
  static constexpr std::size_t kFarShift = 16384;
  // LKH's restricted search: the 3-opt and 5-opt steps' first removed edge
  // must not be an edge of `route` (`positions`: each hole's place in it;
  // both held by the caller, read while searching; null: no restriction).
  // A focused ant passes the reference: its search starts only by taking out
  // edges the ant or a move made, as LKH's starts only off its best tour.
  // 2-opt, Or-opt and the non-sequential moves (as LKH's Gain23) are not
  // restricted. docs/colony.md has what it measured.
  void restrict_to(const std::vector<HoleIndex>* route, const std::vector<std::uint32_t>* positions) {
    restrict_route_ = route;
    restrict_pos_ = positions;
  }
  bool restricted(HoleIndex a, HoleIndex b) const {
    if (restrict_route_ == nullptr) return false;
    const std::vector<HoleIndex>& r = *restrict_route_;
    const std::size_t p = (*restrict_pos_)[a], mm = r.size();
    return r[p + 1 == mm ? 0 : p + 1] == b || r[p == 0 ? mm - 1 : p - 1] == b;
  }
  std::size_t failed_audits() const { return failed_audits_; }
  std::size_t audited_searches() const { return audited_searches_; }

 private:
  void load(std::vector<HoleIndex>& route);    // route_ (taken from `route`) and pos_ (m_ set)
  void unload(std::vector<HoleIndex>& route);  // gives route_ back to `route`
  // Searches the queue until it is empty (true) or `pause` says (false).
  bool run_queue(Moves moves, const std::function<bool()>* pause = nullptr);
  void open_window(std::size_t lo);
  bool in_window(std::size_t position) const { return position >= lo_ && position <= hi_; }
  bool try_two_opt(HoleIndex a);
  bool try_or_opt(HoleIndex a);
  bool try_three_opt(HoleIndex a);
  // A sequential 3-opt step that did not close with a gain: t2..t6 and its
  // partial gain, y3 = (t6, t1) not yet paid.
  struct Step {
    double gain = 0.0;
    HoleIndex t[5] = {};
  };
  // Searches the sequential 3-opt steps that take out (t1, tour.next(t1,
  // dir)), `gain` being what that and any steps before it gained, among the
  // first `breadth` neighbours of t2 and of t4. Makes the first that closes
  // with a gain on `tour` and returns true; else leaves the `keep` best steps
  // that can go deeper in best[], best first. `tour` is the array route
  // (ArrayTour) or deepen()'s trial flips over it (FlipOverlay).
  template <class Tour>
  bool three_opt_step(Tour& tour, HoleIndex t1, int dir, double gain, Step* best, int keep, int breadth);
  // The array route as three_opt_step() reads and flips it.
  struct ArrayTour {
    LocalSearcher& s;
    HoleIndex next(HoleIndex x, int dir) const { return s.next(x, dir); }
    bool between(HoleIndex a, HoleIndex b, HoleIndex c, int dir) const { return s.between(a, b, c, dir); }
    void flip(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) { s.flip(a, b, c, d); }
    std::size_t position(HoleIndex x) const { return s.pos_[x]; }
    std::size_t size() const { return s.m_; }
  };
  // From a step three_opt_step left: makes it and searches on (three_opt.cpp).
  bool deepen(HoleIndex t1, Step step);
  // LKH's sequential 5-opt step from t1, and its chain from a step that
  // did not gain (five_opt.cpp).
  bool try_five_opt(HoleIndex t1);
  bool five_opt_chain(HoleIndex t1, KOptMove step, double gain);
  // LKH's non-sequential moves from s1: makes the first that gains (bridge_moves.cpp).
  bool try_bridge(HoleIndex s1);
  void make_flips(const KOptFlips& flips);  // on the array, in order
  // A chain's trial flips (deepen(), five_opt_chain()): those made in trial_
  // made again on the array, in order, once the chain gains; or, when it
  // does not, those made on the array (flips_) undone, last first.
  void make_trial_flips();
  void undo_array_flips();
  // 5-opt steps a chain makes on trial before it gives up.
  static constexpr int kFiveOptSteps = 3;
  // A 5-opt move takes at most 5 flips (kopt_move_test); the closing one is
  // made on the array, not in the overlay.
  static_assert(kMaxMoveK * kFiveOptSteps <= FlipOverlay::kMaxFlips, "a chain's trial flips must fit the overlay");
  // How many 3-opt steps deepen() searches below the first. Before, the
  // deeper steps were 2-opt steps (six flips at most, the best of 5
  // neighbours at each). `acodrill tsp --threads 2`, median gap, that way ->
  // 3-opt steps 2, 3, 4, 5, 6 deep: pcb3038 at 15 s, seeds 1-10: 0.052 ->
  // 0.051, 0.038, 0.028, 0.094, 0.119 % (seeds 11-20 at 3 and 4: 0.055,
  // 0.045 %); brd14051 at 65 s, seeds 1-5: 0.14 -> 0.078 % at 3 (seeds 1-3
  // at 4: 0.091 %); d15112 at 64 s, seeds 1-3: 0.165 -> 0.117 % at 3;
  // pla7397 at 91 s, seeds 1-3: 0.071 -> 0.088 % at 3, 0.114 % at 4. Deeper
  // chains' trial flips cost more than they find.
  static constexpr int kDeepSteps = 3;
  // Two trial flips a step, and up to three that close the chain.
  static_assert(2 * kDeepSteps + 3 <= FlipOverlay::kMaxFlips, "deepen's flips must fit its overlay");
  // Neighbours deepen()'s steps look at, as LKH's 5 candidates. The gain
  // carried down lets nearly every neighbour pass the gain criterion, so with
  // every hole a candidate (up to 800 holes) a step looked at all of them
  // squared: d493 at 1 s, 5 seeds, 0.02 -> 0.29 %.
  static constexpr int kDeepBreadth = 5;
  // Removes edges {a, b} and {c, d}, where b follows a and d follows c in the
  // same direction, and adds {a, c} and {b, d}: one array reversal.
  void flip(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d);
  // How many positions flip(a, b, c, d) would rewrite.
  std::size_t flip_length(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) const;
  // On routes of more than kReachFrom holes, deeper steps are tried only
  // where their flips rewrite at most kDeepenReach positions. It was set when
  // every trial flip was made on the array and undone: a flip between holes
  // near in the plane but far along the route costs up to half of it, and at
  // 100 000 holes such trial flips took 43 % of the run. With the long ones
  // in the overlay (kArrayFlip) the bound keeps them out of its slower
  // look-ups: without it, 100 000 holes at 60 s (2 threads, seeds 1 and 2)
  // came out the same (226 572 019 and 226 593 282 against 226 587 504 and
  // 226 595 810), at 300 s 0.013 % shorter (seed 1); over 10 000
  // iterations d15112 0.004 % shorter in 5 % more time, brd14051 0.005 %
  // in 10 % more (one run each, beside two of the bound's). On pla7397
  // (30 s, 3 seeds) the bound measured no better than none, so smaller routes
  // have none.
  static constexpr std::size_t kDeepenReach = 1000;
  // deepen()'s trial flips of up to this many positions are made on the
  // array, and from the first longer one on in its FlipOverlay, whose
  // look-ups cost more than the array's: at 100 000 holes (3000 iterations,
  // seed 1, no reach bound; with a branch-free look-up since replaced by a
  // scan that measured no slower) 1000 took 15.2 s, 300 15.9 s, 3000 16.3 s,
  // 10 000 17.3 s; every trial flip in the overlay 17.4 s.
  static constexpr std::size_t kArrayFlip = 1000;
  static constexpr std::size_t kReachFrom = 10000;
  std::size_t deepen_reach() const { return m_ > kReachFrom ? kDeepenReach : m_; }
  // Whether b lies on the way from a to c, going forward (dir 0) or backward.
  bool between(HoleIndex a, HoleIndex b, HoleIndex c, int dir) const;
  HoleIndex next(HoleIndex x, int dir) const { return route_[dir == 0 ? succ(pos_[x]) : pred(pos_[x])]; }
  void reverse(std::size_t i, std::size_t j);  // reverse positions i+1..j
  void move_segment(std::size_t s, std::size_t len, std::size_t q, bool reversed);
  // Reverses the stretch of the route between holes a and b (both ends in it, a
  // stretch that does not hold position 0), or the rest of the cycle when that is shorter.
  void reverse_path(HoleIndex a, HoleIndex b);
  void push(HoleIndex node);
  std::size_t succ(std::size_t i) const { return i + 1 == m_ ? 0 : i + 1; }
  std::size_t pred(std::size_t i) const { return i == 0 ? m_ - 1 : i - 1; }
  double cost_at(std::size_t i) const { return space_.e(route_[i], route_[succ(i)]); }
  double two_opt_gain(std::size_t i, std::size_t j) const;
  void apply_two_opt(std::size_t x, std::size_t y);

  const Space& space_;
  const Candidates& cand_;
  std::vector<HoleIndex> route_;
  std::vector<std::uint32_t> pos_;  // 4 bytes a hole: at 10^5 holes the searcher's hot data fits the cache better
  std::vector<std::array<HoleIndex, 4>> flips_;  // deepen's flips made on the array, to undo
  // A 5-opt chain's edges: added ones are not removed again, removed ones not added.
  std::vector<std::array<HoleIndex, 2>> chain_added_, chain_removed_;
  FlipOverlay trial_;  // deepen's flips from its first long one on (kArrayFlip)
  std::vector<HoleIndex> queue_;
  std::vector<char> queued_;
  std::size_t head_ = 0;
  bool forgot_ = false;  // whether queue_ lost holes it held (see searched_all())
  std::size_t m_ = 0;
  std::size_t lo_ = 0, hi_ = 0;  // positions a move may touch
  bool windowed_ = false;
  bool audit_ = false;
  bool non_sequential_ = true;
  std::size_t far_shift_ = kFarShift;
  std::size_t array_flip_ = kArrayFlip;
  double gain_ = 0.0;
  const std::vector<HoleIndex>* restrict_route_ = nullptr;
  const std::vector<std::uint32_t>* restrict_pos_ = nullptr;
  std::size_t failed_audits_ = 0, audited_searches_ = 0;
  std::function<bool()> due_;
  bool interrupted_ = false;
  std::uint32_t since_asked_ = 0;
  // A search in slices (begin() .. end()): its moves, and whether a route is taken.
  Moves moves_ = Moves::TwoOpt;
  bool loaded_ = false;
};

}  // namespace aco::detail
