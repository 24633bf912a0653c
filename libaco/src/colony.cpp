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
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

#include "aco/baselines.h"
#include "aco/error.h"
#include "aco/solve.h"
#include "bucket_grid.h"
#include "candidates.h"
#include "hilbert.h"
#include "local_search.h"
#include "parallel.h"
#include "recombine.h"
#include "rng.h"
#include "space.h"
#include "trail.h"

namespace aco {

namespace detail {
Order nearest_neighbor_order(const Space& space, const Candidates& cand);
}

namespace {

using detail::Candidates;
using detail::LocalSearcher;
using detail::Rng;
using detail::Space;

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
bool uses_alpha_lists(std::size_t holes, LocalSearch local_search) {
  return local_search != LocalSearch::None && holes > kFullListLimit && holes <= kAlphaLimit;
}
// Subgradient steps before alpha is measured: 100 took 0.1 s on pcb3038 and
// 1.5 s on d15112, so fewer on larger inputs (66 on d15112, 20 from 50 000),
// and under a time limit no more than about 5 % of it at the 1.5 us per hole
// and step measured on 100 000 holes (2 steps for d15112 in 1 s). Counted, not
// timed, so the same options give the same candidates on any machine.
int ascent_iterations(std::size_t holes, double time_limit_s) {
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
// route is kicked by a double bridge within kKickSpan consecutive holes.
constexpr int kKickAfter = 30;
// ACS's local update: tau = (1 - xi) tau + xi tau0 on every edge an ant used.
constexpr double kWear = 0.1;
constexpr std::size_t kKickSpan = 50;
// After this many iterations in which the colony's best since its last
// restart did not improve (some ten kicks in vain), the colony restarts: the
// best route so far, shaken by max(kRestartKicks, n / 50) such double bridges
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
constexpr double kJumpyOrder = 4.0;
constexpr int kRestartAfter = 300;
constexpr int kRestartKicks = 200;

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
  std::unique_ptr<detail::BucketGrid> grid;  // candidate-list mode: nearest unvisited hole
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

class Colony {
 public:
  Colony(const Problem& problem, const Params& params, detail::Team& team, const Clock& started)
      : clock_(started), problem_(problem), p_(params), team_(team), space_(problem), n_(space_.holes()) {
    if (n_ <= kFullListLimit) {
      cand_ = detail::build_candidates(space_, static_cast<int>(n_) - 1, team_);
    } else if (uses_alpha_lists(n_, p_.local_search)) {
      Candidates nearest = detail::joined_nearest(space_, kAlphaFrom, team_);
      std::vector<double>().swap(nearest.length);  // not read by alpha_candidates: 13 MB less at 100 000 holes
      cand_ = detail::alpha_candidates(space_, nearest, p_.candidates, ascent_iterations(n_, p_.time_limit_s), team_);
    } else {
      cand_ = detail::build_candidates(space_, p_.candidates, team_);
    }
    k_ = cand_.k;
    const std::size_t slots = static_cast<std::size_t>(n_) * k_;
    tau_ = detail::Trail(slots, 0.0, p_.rho);
    // Focused ants weigh their few rows as they go and never read choice_.
    if (p_.algorithm != Algorithm::FocusedAcs) choice_.assign(slots, 0.0);
    eta_beta_.assign(slots, 0.0);
    for (HoleIndex i = 0; i < n_; ++i) {
      const double* length = cand_.lengths_of(i);
      for (int r = 0; r < k_; ++r) eta_beta_[idx(i, r)] = std::pow(eta(length[r]), p_.beta);
    }
    if (space_.open()) {
      // Weights of the first step, from the start (V) to each hole: fixed for the whole run.
      start_weight_.resize(n_);
      for (HoleIndex h = 0; h < n_; ++h) start_weight_[h] = std::pow(eta(space_.e(n_, h)), p_.beta);
    }
    if (k_ == static_cast<int>(n_) - 1 && n_ > 1) {
      rank_.assign(static_cast<std::size_t>(n_) * n_, -1);
      // Focused ants weigh their candidate rows directly and never read it.
      if (p_.algorithm != Algorithm::FocusedAcs) dense_choice_.assign(static_cast<std::size_t>(n_) * n_, 0.0);
      for (HoleIndex i = 0; i < n_; ++i) {
        for (int r = 0; r < k_; ++r) rank_[static_cast<std::size_t>(i) * n_ + cand_.of(i)[r]] = r;
      }
    }
  }

  Solution run();

 private:
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
  void refresh_choice() {
    const double a = p_.alpha;
    const detail::Trail& tau = tau_;
    if (a == 1.0) {  // the common case: skip n*k calls to pow
      for (std::size_t e = 0; e < choice_.size(); ++e) choice_[e] = tau[e] * eta_beta_[e];
    } else {
      for (std::size_t e = 0; e < choice_.size(); ++e) choice_[e] = std::pow(tau[e], a) * eta_beta_[e];
    }
    if (!dense_choice_.empty()) {
      for (HoleIndex i = 0; i < n_; ++i) {
        const HoleIndex* c = cand_.of(i);
        double* row = dense_choice_.data() + static_cast<std::size_t>(i) * n_;
        for (int r = 0; r < k_; ++r) row[c[r]] = choice_[idx(i, r)];
      }
    }
  }
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
  void route_slots(const std::vector<HoleIndex>& route, std::vector<std::size_t>& slots) {
    const std::size_t mm = route.size();
    if (!rank_.empty()) {  // rows of every hole: rank_ finds a slot at once
      slots.clear();
      for (std::size_t i = 0; i < mm; ++i) add_slots(route[i], route[(i + 1) % mm], slots);
      return;
    }
    route_neighbours_.resize(2 * static_cast<std::size_t>(n_));
    for (std::size_t i = 0; i < mm; ++i) {
      const HoleIndex a = route[i], b = route[(i + 1) % mm];
      if (a < n_) route_neighbours_[2 * static_cast<std::size_t>(a) + 1] = b;
      if (b < n_) route_neighbours_[2 * static_cast<std::size_t>(b)] = a;
    }
    // Every slot written below is counted or overwritten, so only a first
    // call's growth is zeroed, not the whole buffer each time.
    slots.resize(2 * static_cast<std::size_t>(n_) + static_cast<std::size_t>(k_));
    std::size_t count = 0;
    for (HoleIndex h = 0; h < n_; ++h) {
      const HoleIndex* c = cand_.of(h);
      const HoleIndex before = route_neighbours_[2 * static_cast<std::size_t>(h)];
      const HoleIndex after = route_neighbours_[2 * static_cast<std::size_t>(h) + 1];
      for (int r = 0; r < k_; ++r) {
        slots[count] = idx(h, r);
        count += static_cast<std::size_t>((c[r] == before) | (c[r] == after));
      }
    }
    slots.resize(count);
  }
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
  detail::Team& team_;
  Space space_;
  HoleIndex n_;
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
};

double Colony::set_reference(const std::vector<HoleIndex>& route) {
  const std::size_t m = route.size();
  std::size_t changed = 0;  // R's first position that changed
  if (ref_route_.size() != m) {
    ref_route_ = route;
    ref_pos_.resize(m);
    ref_points_.resize(m);
    ref_prefix_.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
      ref_pos_[route[i]] = static_cast<std::uint32_t>(i);
      ref_points_[i] = point_of(route[i]);
    }
  } else {
    changed = rewrite_reference(route);
  }
  if (m == 0) return 0.0;
  // The sums before position `changed` stand, and summed on from there, in
  // the same order, they are the same bits as summed from position 0. (At
  // 100 000 holes the first change lies a third of the way along on average.)
  const std::size_t from = changed == 0 ? 0 : std::min(changed, m) - 1;
  double sum = ref_prefix_[from];  // 0 at position 0
  for (std::size_t i = from; i < m; ++i) {
    ref_prefix_[i] = sum;
    if (i + 1 == m) break;
    // space_.e(), from the points: V (first, if anywhere) leaves from the start.
    sum += ref_route_[i + 1] < n_ ? space_.d(ref_points_[i], ref_points_[i + 1]) : space_.e(ref_route_[i], ref_route_[i + 1]);
  }
  return m > 1 ? sum + space_.e(ref_route_[m - 1], ref_route_[0]) : 0.0;
}

bool Colony::is_reference(const std::vector<HoleIndex>& route) const {
  const std::size_t m = route.size();
  if (m != ref_route_.size()) return false;
  if (m < 3) return true;
  const std::size_t p0 = ref_pos_[route[0]];
  if (ref_route_[(p0 + 1) % m] == route[1]) {
    // route = R[p0..m) R[0..p0)
    return std::equal(route.begin(), route.begin() + static_cast<long>(m - p0), ref_route_.begin() + static_cast<long>(p0)) &&
           std::equal(route.begin() + static_cast<long>(m - p0), route.end(), ref_route_.begin());
  }
  if (space_.open() || ref_route_[(p0 + m - 1) % m] != route[1]) return false;
  // The other way round: route = R[p0] R[p0 - 1] ... R[0] R[m - 1] ... R[p0 + 1]
  return std::equal(route.begin(), route.begin() + static_cast<long>(p0 + 1), ref_route_.rbegin() + static_cast<long>(m - 1 - p0)) &&
         std::equal(route.begin() + static_cast<long>(p0 + 1), route.end(), ref_route_.rbegin());
}

std::size_t Colony::rewrite_reference(const std::vector<HoleIndex>& route) {
  const std::size_t m = route.size();
  // The new reference is mostly the old one: read it from the old one's first
  // node, in the old one's direction, and write only the positions that
  // changed. The lines left alone stay in the cache of the core whose ants
  // read them (an open path has V first and one direction already).
  std::size_t from = 0;
  bool backward = false;
  // A merged route (recombine.h) starts where R does, the same way round.
  if (!space_.open() && !(route[0] == ref_route_[0] && route[1] == ref_route_[1])) {
    from = static_cast<std::size_t>(std::find(route.begin(), route.end(), ref_route_[0]) - route.begin());
    // Which way the old route runs: look where some node's old successor is.
    // (Rarely past the first probe: an ant changes a short stretch.)
    for (const std::size_t probe : {std::size_t{0}, m / 2, m / 4, 3 * m / 4}) {
      const HoleIndex x = ref_route_[probe], next = ref_route_[(probe + 1) % m];
      const std::size_t px = probe == 0 ? from : static_cast<std::size_t>(std::find(route.begin(), route.end(), x) - route.begin());
      if (route[(px + 1) % m] == next) break;
      if (route[(px + m - 1) % m] == next) {
        backward = true;
        break;
      }
    }
  }
  std::size_t changed = m;
  auto put = [&](std::size_t i, HoleIndex h) {
    if (ref_route_[i] == h) return;
    ref_route_[i] = h;
    ref_pos_[h] = static_cast<std::uint32_t>(i);
    ref_points_[i] = point_of(h);
    changed = std::min(changed, i);
  };
  // Positions [at, at + len) from src[0, len): a block of 16 that stands is
  // passed over on one test. An iteration changes some 15 % of the positions
  // of 100 000 holes; hole by hole the rewrite took 0.41 ms a time, so 0.12.
  auto put_run = [&](const HoleIndex* src, std::size_t at, std::size_t len) {
    constexpr std::size_t kBlock = 16;
    const HoleIndex* old = ref_route_.data() + at;
    std::size_t i = 0;
    for (; i + kBlock <= len; i += kBlock) {
      HoleIndex differ = 0;
      for (std::size_t j = i; j < i + kBlock; ++j) differ |= src[j] ^ old[j];
      if (differ == 0) continue;
      for (std::size_t j = i; j < i + kBlock; ++j) put(at + j, src[j]);
    }
    for (; i < len; ++i) put(at + i, src[i]);
  };
  if (!backward) {
    put_run(route.data() + from, 0, m - from);
    put_run(route.data(), m - from, from);
  } else {
    for (std::size_t i = 0; i < m; ++i) put(i, route[(from + m - i) % m]);
  }
  return changed;
}

HoleIndex Colony::choose_focused(HoleIndex cur, const AntWork& w, Rng& rng, HoleIndex exclude) const {
  // ACS's pseudo-random proportional rule over the unvisited candidates, with
  // tau^alpha * eta^beta computed here: a focused ant looks at few rows, so
  // refreshing all n*k of them every iteration would cost more than it saves.
  const HoleIndex* c = cand_.of(cur);
  const std::size_t row = idx(cur, 0);
  const detail::Trail& tau = tau_;
  const double* eb = eta_beta_.data() + idx(cur, 0);
  double weight[64];
  const int k = std::min(k_, 64);
  double total = 0.0;
  int best_r = -1;
  for (int r = 0; r < k; ++r) {
    const bool free = w.mark[c[r]] != w.stamp && c[r] != exclude;
    const double t = free ? tau[row + r] : 0.0;
    const double v = free ? (p_.alpha == 1.0 ? t : std::pow(t, p_.alpha)) * eb[r] : 0.0;
    weight[r] = v;
    total += v;
    if (free && (best_r < 0 || v > weight[best_r])) best_r = r;
  }
  if (best_r < 0) return n_ + 1;  // every candidate visited
  if (rng.uniform() < p_.q0 || !(total > 0.0)) return c[best_r];
  double x = rng.uniform() * total;
  for (int r = 0; r < k; ++r) {
    x -= weight[r];
    if (x < 0.0 && weight[r] > 0.0) return c[r];
  }
  return c[best_r];
}

void Colony::construct_focused(AntWork& w, Rng& rng, int bound) const {
  // Walk from a random node of the reference route R. While the ant has made
  // fewer than `bound` new edges it chooses by the ACS rule; after that it
  // copies R, skipping what it has visited. Every edge that is not R's is new,
  // and its two ends seed the local search. The copy is made run by run of R
  // between the few visited positions, its length read from R's prefix sums,
  // so an ant costs a memcpy of the route plus what it changes, not a step
  // per hole (100 000 holes: 1.8 ms an ant before).
  const std::size_t m = ref_route_.size();  // nodes, V included for an open path
  if (w.mark.size() != m) {
    w.mark.assign(m, 0);
    w.stamp = 0;
  }
  if (++w.stamp == 0) {
    std::fill(w.mark.begin(), w.mark.end(), 0);
    w.stamp = 1;
  }
  const std::uint32_t last_pos = static_cast<std::uint32_t>(m - 1);
  auto after = [&](std::uint32_t p) { return p == last_pos ? 0u : p + 1; };
  w.route.clear();
  w.seeds.clear();
  w.visited_pos.clear();
  w.length = 0.0;
  auto visit = [&](HoleIndex h) {
    w.mark[h] = w.stamp;
    w.visited_pos.push_back(ref_pos_[h]);
    w.route.push_back(h);
  };
  HoleIndex cur = ref_route_[rng.below(static_cast<std::uint32_t>(m))];
  const HoleIndex first = cur;
  visit(cur);
  int changes = 0;
  while (w.route.size() < m && changes < bound) {
    const std::uint32_t pc = ref_pos_[cur];
    const HoleIndex follow = ref_route_[after(pc)];
    const bool follow_free = w.mark[follow] != w.stamp;
    HoleIndex next = n_ + 1;
    if (cur < n_) {
      // Deviate from R here with probability p_dev (the choice then excludes
      // R's own edge); where R's next hole is already visited a new edge must
      // be made anyway, and the same rule picks it.
      if (!follow_free || rng.uniform() < kDeviate) next = choose_focused(cur, w, rng, follow);
      else next = follow;
    }
    if (next > n_) {
      // The next unvisited position of R: few are visited, so a scan is short.
      std::uint32_t p = after(pc);
      while (w.mark[ref_route_[p]] == w.stamp) p = after(p);
      next = ref_route_[p];
    }
    if (next != follow) {  // a new edge: its ends, in pairs (V among them is skipped later)
      ++changes;
      w.seeds.push_back(cur);
      w.seeds.push_back(next);
    }
    w.length += space_.e(cur, next);
    visit(next);
    cur = next;
  }
  if (w.route.size() < m) {
    // The rest is R from after cur, cyclically, without the visited positions.
    std::vector<std::uint32_t>& gaps = w.visited_pos;
    std::sort(gaps.begin(), gaps.end());
    auto copy_run = [&](std::uint32_t a, std::uint32_t b) {  // positions a..b-1 of R, a < b
      const HoleIndex head = ref_route_[a];
      if (ref_route_[after(ref_pos_[cur])] != head) {
        w.seeds.push_back(cur);
        w.seeds.push_back(head);
      }
      w.length += space_.e(cur, head) + (ref_prefix_[b - 1] - ref_prefix_[a]);
      w.route.insert(w.route.end(), ref_route_.begin() + a, ref_route_.begin() + b);
      cur = ref_route_[b - 1];
    };
    auto copy_range = [&](std::uint32_t lo, std::uint32_t hi) {  // unvisited positions in [lo, hi)
      auto g = std::lower_bound(gaps.begin(), gaps.end(), lo);
      std::uint32_t p = lo;
      for (; g != gaps.end() && *g < hi; ++g) {
        if (*g > p) copy_run(p, *g);
        p = *g + 1;
      }
      if (p < hi) copy_run(p, hi);
    };
    const std::uint32_t start = after(ref_pos_[cur]);
    copy_range(start, static_cast<std::uint32_t>(m));
    if (start > 0) copy_range(0, start);
  }
  if (ref_route_[after(ref_pos_[cur])] != first) {
    w.seeds.push_back(cur);
    w.seeds.push_back(first);
  }
  w.length += space_.e(cur, first);
  // An open path keeps V at position 0.
  if (space_.open()) {
    const auto v = std::find(w.route.begin(), w.route.end(), n_);
    std::rotate(w.route.begin(), v, w.route.end());
  }
}

HoleIndex Colony::nearest_unvisited(HoleIndex cur, const AntWork& w) const {
  // Every candidate is visited: take the nearest unvisited hole, which is the
  // argmax of tau^alpha * eta^beta when all non-candidate edges share one tau.
  // The grid finds it without scanning every unvisited hole (that scan made
  // tour construction quadratic on large panels). Only candidate-list mode
  // gets here, and it always has a grid.
  return w.grid->nearest(space_.point(cur), [&](HoleIndex h) { return space_.d(cur, h); });
}

HoleIndex Colony::choose_next(HoleIndex cur, AntWork& w, Rng& rng, bool acs) {
  if (cur == n_) {
    // Leaving the open path's start: no pheromone is kept on V's edges, so
    // choose by eta^beta alone over all unvisited holes.
    double total = 0.0;
    w.weight.resize(w.unvisited.size());
    for (std::size_t u = 0; u < w.unvisited.size(); ++u) {
      w.weight[u] = start_weight_[w.unvisited[u]];
      total += w.weight[u];
    }
    double r = rng.uniform() * total;
    for (std::size_t u = 0; u < w.unvisited.size(); ++u) {
      r -= w.weight[u];
      if (r < 0.0) return w.unvisited[u];
    }
    return w.unvisited.back();
  }
  if (!dense_choice_.empty()) {
    const double* row = dense_choice_.data() + static_cast<std::size_t>(cur) * n_;
    const std::size_t m = w.unvisited.size();
    w.weight.resize(m);
    double total = 0.0;
    for (std::size_t u = 0; u < m; ++u) {
      const double v = row[w.unvisited[u]];
      w.weight[u] = v;
      total += v;
    }
    auto argmax = [&] {
      // Ties go to the lower hole index, so the choice does not depend on list order.
      std::size_t best = 0;
      for (std::size_t u = 1; u < m; ++u) {
        if (w.weight[u] > w.weight[best] || (w.weight[u] == w.weight[best] && w.unvisited[u] < w.unvisited[best])) best = u;
      }
      return w.unvisited[best];
    };
    if ((acs && rng.uniform() < p_.q0) || !(total > 0.0)) return argmax();
    double r = rng.uniform() * total;
    for (std::size_t u = 0; u < m; ++u) {
      r -= w.weight[u];
      if (r < 0.0 && w.weight[u] > 0.0) return w.unvisited[u];
    }
    return argmax();
  }
  const HoleIndex* c = cand_.of(cur);
  const double* ch = choice_.data() + idx(cur, 0);
  w.weight.resize(static_cast<std::size_t>(k_));
  double total = 0.0;
  int best_r = -1;
  for (int r = 0; r < k_; ++r) {
    const bool free = w.where[c[r]] != UINT32_MAX;
    const double v = free ? ch[r] : 0.0;
    w.weight[r] = v;
    total += v;
    if (free && (best_r < 0 || v > w.weight[best_r])) best_r = r;
  }
  if (best_r < 0) return nearest_unvisited(cur, w);
  if (acs && rng.uniform() < p_.q0) return c[best_r];
  if (!(total > 0.0)) return c[best_r];  // underflow of tiny weights: fall back to the best
  double r = rng.uniform() * total;
  for (int q = 0; q < k_; ++q) {
    r -= w.weight[q];
    if (r < 0.0 && w.weight[q] > 0.0) return c[q];
  }
  return c[best_r];
}

void Colony::construct(AntWork& w, Rng& rng, bool acs) {
  w.route.clear();
  w.unvisited.resize(n_);
  w.where.resize(n_);
  std::iota(w.unvisited.begin(), w.unvisited.end(), 0);
  std::iota(w.where.begin(), w.where.end(), 0);
  const bool use_grid = dense_choice_.empty();  // candidate-list mode
  if (use_grid) {
    if (!w.grid) w.grid = std::make_unique<detail::BucketGrid>(space_);
    else w.grid->reset();
  }
  auto visit = [&w, use_grid](HoleIndex h) {
    if (use_grid) w.grid->remove(h);
    const HoleIndex at = w.where[h];
    const HoleIndex last = w.unvisited.back();
    w.unvisited[at] = last;
    w.where[last] = at;
    w.unvisited.pop_back();
    w.where[h] = UINT32_MAX;
    w.route.push_back(h);
  };
  HoleIndex cur;
  if (space_.open()) {
    w.route.push_back(n_);
    cur = n_;
  } else {
    cur = static_cast<HoleIndex>(rng.below(n_));  // the thesis: ants start at random holes
    visit(cur);
  }
  while (!w.unvisited.empty()) {
    const HoleIndex next = choose_next(cur, w, rng, acs);
    visit(next);
    cur = next;
  }
}

void Colony::deposit_edge(HoleIndex a, HoleIndex b, double amount) {
  if (a >= n_ || b >= n_) return;  // V's edges carry no pheromone
  int r = rank_of(a, b);
  const auto add = [amount](double t) { return t + amount; };
  if (r >= 0) tau_.update(idx(a, r), add);
  r = rank_of(b, a);
  if (r >= 0) tau_.update(idx(b, r), add);
}

void Colony::deposit(const std::vector<HoleIndex>& route, double amount) {
  const std::size_t m = route.size();
  for (std::size_t i = 0; i + 1 < m; ++i) deposit_edge(route[i], route[i + 1], amount);
  if (!space_.open() && m > 2) deposit_edge(route[m - 1], route[0], amount);
}

Order Colony::to_order(const std::vector<HoleIndex>& route) const {
  Order o;
  o.reserve(n_);
  for (HoleIndex h : route) {
    if (h < n_) o.push_back(h);
  }
  return o;
}

Solution Colony::run() {
  const Clock& clock = clock_;
  Solution sol;
  sol.algorithm = p_.algorithm;
  sol.ants = p_.ants;
  sol.threads = p_.threads;
  sol.thread_busy_s.assign(static_cast<std::size_t>(p_.threads), 0.0);

  // Nearest neighbour, improved when local search is on, starts the best-so-far
  // and gives C_nn for the initial trail.
  Order nn = detail::nearest_neighbor_order(space_, cand_);
  std::vector<HoleIndex> best_route;
  if (space_.open()) best_route.push_back(n_);
  best_route.insert(best_route.end(), nn.begin(), nn.end());
  const double c_nn = std::max(space_.route_cost(best_route), 1e-9);
  const bool use_ls = p_.local_search != LocalSearch::None;
  const detail::Moves moves = p_.local_search == LocalSearch::ThreeOpt      ? detail::Moves::ThreeOpt
                              : p_.local_search == LocalSearch::TwoOptOrOpt ? detail::Moves::OrOpt
                                                                            : detail::Moves::TwoOpt;
  if (use_ls) {
    LocalSearcher ls(space_, cand_);
    ls.improve(best_route, moves);
  }
  double best_len = space_.route_cost(best_route);
  sol.trace.push_back({0, clock.seconds(), best_len});

  const double rho = p_.rho;
  const double m = p_.ants;
  double tau_max = 0.0, tau_min = 0.0;
  auto mmas_limits = [&](double best) {
    tau_max = 1.0 / (rho * best);
    // With local search ACOTSP uses tau_min = tau_max / (2n); without, the
    // p_best = 0.05 formula of Stützle & Hoos 2000, eq. 11.
    if (use_ls) {
      tau_min = tau_max / (2.0 * n_);
    } else {
      const double p_root = std::pow(0.05, 1.0 / n_);
      const double avg = std::max(2.0, n_ / 2.0);
      tau_min = std::min(tau_max, tau_max * (1.0 - p_root) / ((avg - 1.0) * p_root));
    }
  };
  switch (p_.algorithm) {
    case Algorithm::AntSystem: tau0_ = m / c_nn; break;  // the thesis: tau0 = m / C_nn
    case Algorithm::MaxMinAntSystem:
      mmas_limits(c_nn);
      tau0_ = tau_max;
      break;
    case Algorithm::AntColonySystem:
    case Algorithm::FocusedAcs: tau0_ = 1.0 / (n_ * c_nn); break;
  }
  set_all_tau(tau0_);
  const bool focused = p_.algorithm == Algorithm::FocusedAcs;
  if (!focused) refresh_choice();  // focused ants weigh their few rows as they go
  if (focused) {
    set_reference(best_route);
    if (use_ls) kick_searcher_ = std::make_unique<LocalSearcher>(space_, cand_);
  }
  ref_len_ = best_len;

  const bool acs = p_.algorithm == Algorithm::AntColonySystem;
  std::vector<AntRoute> work(static_cast<std::size_t>(p_.ants));
  std::vector<AntWork> workers(static_cast<std::size_t>(p_.threads));
  std::vector<LocalSearcher> searchers;
  if (use_ls) {
    searchers.reserve(static_cast<std::size_t>(p_.threads));
    for (int t = 0; t < p_.threads; ++t) searchers.emplace_back(space_, cand_);
  }

  double reinforced_for = -1.0;  // the best length whose route's edges the trail reinforces
  int reinforced_at = 0;         // since this iteration
  int since_improvement = 0;
  int since_restart = 0;
  std::vector<HoleIndex> restart_best = best_route;
  double restart_best_len = best_len;
  sol.stop_reason = "iterations";
  int it = 1;  // the iteration under way
  // Focused ants draw how many edges they may change, first thing; they are
  // handed out largest first, so a round ends on short ones and the workers
  // finish it together.
  std::vector<int> ant_of_slot(static_cast<std::size_t>(p_.ants));
  std::vector<int> scale_of_ant(static_cast<std::size_t>(p_.ants));
  auto order_ants = [&] {
    std::iota(ant_of_slot.begin(), ant_of_slot.end(), 0);
    if (!focused) return;
    for (int k = 0; k < p_.ants; ++k) {
      Rng rng(p_.seed, static_cast<std::uint64_t>(it), static_cast<std::uint64_t>(k));
      scale_of_ant[static_cast<std::size_t>(k)] = static_cast<int>(rng.below(4));
    }
    std::stable_sort(ant_of_slot.begin(), ant_of_slot.end(),
                     [&](int a, int b) { return scale_of_ant[static_cast<std::size_t>(a)] > scale_of_ant[static_cast<std::size_t>(b)]; });
  };
  auto ant = [&](int slot, int worker) {
    const int k = ant_of_slot[static_cast<std::size_t>(slot)];
    Rng rng(p_.seed, static_cast<std::uint64_t>(it), static_cast<std::uint64_t>(k));
    AntWork& w = workers[static_cast<std::size_t>(worker)];
    if (focused) {
      // Each ant draws its bound from focus_edges x {1/2, 1, 2, 4}: small
      // changes polish, large ones reach out of deep local optima, and no
      // single bound served every instance (measured: 8 stalls d1291, 32
      // stalls pcb1173). A fixed share of each bound per iteration, largest
      // to the first ants, measured worse (d1291 at 5 s: 0.74 % against 0.30 %).
      const int scale = static_cast<int>(rng.below(4));  // as order_ants drew it
      construct_focused(w, rng, std::max(1, (p_.focus_edges << scale) / 2));
      if (use_ls) searchers[static_cast<std::size_t>(worker)].improve_from(w.route, moves, w.seeds);
    } else {
      construct(w, rng, acs);
      if (use_ls) searchers[static_cast<std::size_t>(worker)].improve(w.route, moves);
    }
    AntRoute& out = work[static_cast<std::size_t>(k)];
    // A focused ant knows its length from its walk and its search's gains;
    // the iteration's best is measured again in full (update()).
    if (focused) out.length = w.length - (use_ls ? searchers[static_cast<std::size_t>(worker)].gain() : 0.0);
    else out.length = space_.route_cost(w.route);
    out.worker = worker;
    out.worn_from = w.worn.size();
    if (p_.algorithm == Algorithm::AntColonySystem) {
      const std::size_t mm = w.route.size();
      for (std::size_t i = 0; i < mm; ++i) add_worn_slots(w.route[i], w.route[(i + 1) % mm], w.worn);
    } else if (focused) {
      // A focused ant's route is the reference but for its new edges, so only
      // those are worn (the reference's edges get the global update).
      for (std::size_t i = 0; i + 1 < w.seeds.size(); i += 2) add_worn_slots(w.seeds[i], w.seeds[i + 1], w.worn);
    }
    out.worn_to = w.worn.size();
    // Only where update() merges them (above kManyAntsFrom holes).
    out.improves = focused && n_ > kManyAntsFrom && out.length < ref_len_ - 1e-9;
    if (out.improves) {
      // Only where the ant or its search changed an edge, when the search can say.
      const LocalSearcher* ls = use_ls ? &searchers[static_cast<std::size_t>(worker)] : nullptr;
      if (ls != nullptr && ls->searched_all()) {
        detail::route_diff(ref_route_, ref_pos_, w.route, ls->positions(), ls->searched(), out.diff);
      } else {
        detail::route_diff(ref_route_, ref_pos_, w.route, out.diff);
      }
    }
    if (!focused) {
      std::swap(out.route, w.route);
    } else if (w.best_ant < 0 || out.length < w.best_length || (out.length == w.best_length && k < w.best_ant)) {
      std::swap(w.best_route, w.route);
      w.best_length = out.length;
      w.best_ant = k;
    }
  };
  // A double bridge within kKickSpan consecutive positions of r: blocks
  // A B C D -> A C B D; appends the ends of its three new edges to seeds.
  auto double_bridge = [&](std::vector<HoleIndex>& r, Rng& krng, std::vector<HoleIndex>& seeds) {
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
  };
  detail::DiffMerger merger;
  std::vector<int> improving;
  std::vector<const detail::RouteDiff*> diffs;
  std::vector<int> diff_ants;  // whose diffs[i] is
  std::vector<std::size_t> reinforce_slots;
  std::vector<HoleIndex> merged;
  // After the barrier, on one thread: says whether to run another iteration.
  auto update = [&]() -> bool {
    // Deterministic reduction: shortest, ties to the lowest ant index.
    int ib = 0;
    for (int k = 1; k < p_.ants; ++k) {
      if (work[k].length < work[ib].length) ib = k;
    }
    const std::vector<HoleIndex>* ib_route = &work[ib].route;
    for (AntWork& w : workers) {
      if (w.best_ant == ib) ib_route = &w.best_route;
      w.best_ant = -1;
    }
    // A focused ant sums its length from the reference's and its search's
    // gains: with whole-number distances (TSPLIB's) that is its route's length
    // exactly, with real ones it may differ in the last bits. The decisions
    // below take it as it is; best lengths must be exact, and a route that
    // becomes the reference is measured in full by set_reference(), which sums
    // its edges anyway. Measuring it besides, as before, cost as much as an
    // ant at 100 000 holes: 1.2 ms of the 2.6 ms serial part of an iteration.
    double ib_len = work[ib].length;
    bool ib_measured = !focused;  // whether ib_len is ib_route's length summed in full
    const bool ib_plateau = focused && ib_len <= ref_len_ + 1e-6 && !is_reference(*ib_route);
    if (focused && work[ib].improves) {
      // The other ants' improvements elsewhere on the route, added to the best's.
      improving.clear();
      for (int k = 0; k < p_.ants; ++k) {
        if (work[k].improves) improving.push_back(k);
      }
      std::sort(improving.begin(), improving.end(), [&](int a, int b) {
        return work[a].length < work[b].length || (work[a].length == work[b].length && a < b);
      });
      // An open path's V keeps the successor it has in R, or in the best ant's
      // route if that ant changed it; no other ant may change it.
      const HoleIndex v = ref_route_[0];
      const bool best_moves_v = space_.open() && work[ib].diff.touches(v);
      diffs.clear();
      diff_ants.clear();
      for (int k : improving) {
        if (k == ib || !space_.open() || !work[k].diff.touches(v)) {
          diffs.push_back(&work[k].diff);
          diff_ants.push_back(k);
        }
      }
      if (diffs.size() >= 2 &&
          merger.merge(ref_route_, ref_pos_, diffs, best_moves_v ? (*ib_route)[1] : ref_route_[1], merged) >= 2) {
        // The exchanges touch disjoint holes, so their gains add up.
        double merged_len = ref_len_;
        for (std::size_t d : merger.applied()) merged_len += work[diff_ants[d]].length - ref_len_;
        if (merged_len < ib_len - 1e-9) {
          ib_route = &merged;
          ib_len = merged_len;
        }
      }
    }
    ++since_improvement;
    ++since_restart;
    if (focused) {
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
        Rng krng(p_.seed ^ 0x9E3779B97F4A7C15ULL, static_cast<std::uint64_t>(it), 0xFFFF);
        const bool restart = since_restart >= kRestartAfter;
        std::vector<HoleIndex> r = restart ? best_route : restart_best;  // not a wandering reference
        std::vector<HoleIndex> seeds;
        const int kicks = restart ? std::max<int>(kRestartKicks, static_cast<int>(n_ / 50)) : 1;
        for (int q = 0; q < kicks; ++q) double_bridge(r, krng, seeds);
        if (!seeds.empty()) {
          if (restart) {
            kick_searcher_->improve(r, moves);
            set_all_tau(tau0_);
            reinforced_for = -1.0;
            restart_best_len = std::numeric_limits<double>::infinity();
            since_restart = 0;
          } else {
            kick_searcher_->improve_from(r, moves, seeds);
          }
          ref_len_ = set_reference(r);
          if (ref_len_ < restart_best_len - 1e-9) {
            restart_best_len = ref_len_;
            restart_best = r;
            since_restart = 0;
          }
          if (ref_len_ < best_len - 1e-9) {
            best_len = ref_len_;
            best_route = r;
            since_improvement = 0;
            sol.trace.push_back({it, clock.seconds(), best_len});
          }
        }
        ref_stall_ = 0;
      }
    }
    // Not the reference, yet better (an ant that gave back R, its length a
    // last bit short): rare.
    if (!ib_measured && (ib_len < best_len - 1e-9 || ib_len < restart_best_len - 1e-9)) {
      ib_len = space_.route_cost(*ib_route);
    }
    if (ib_len < best_len - 1e-9) {
      best_len = ib_len;
      best_route = *ib_route;
      since_improvement = 0;
      sol.trace.push_back({it, clock.seconds(), best_len});
    }
    if (ib_len < restart_best_len - 1e-9) {
      restart_best_len = ib_len;
      restart_best = *ib_route;
      since_restart = 0;
    }

    // Pheromone update, on one thread, after the barrier.
    switch (p_.algorithm) {
      case Algorithm::AntSystem:
        evaporate(1.0 - rho);
        for (const AntRoute& w : work) deposit(w.route, 1.0 / std::max(w.length, 1e-9));
        break;
      case Algorithm::MaxMinAntSystem: {
        evaporate(1.0 - rho);
        // u_gb schedule (Stützle & Hoos 2000, with local search): the best
        // since the last restart deposits ever more often as the run goes on.
        const int u_gb = since_restart < 25 ? 25 : since_restart < 75 ? 5 : since_restart < 125 ? 3 : since_restart < 250 ? 2 : 1;
        const bool use_gb = (it % u_gb) == 0;
        const auto& route = use_gb ? restart_best : *ib_route;
        const double len = use_gb ? restart_best_len : ib_len;
        mmas_limits(best_len);
        deposit(route, 1.0 / std::max(len, 1e-9));
        tau_.update_all([&](double t) { return std::clamp(t, tau_min, tau_max); });
        // Stagnation: reinitialise the trails (the best-so-far is kept).
        if (since_restart >= std::max(50, p_.stall_iterations / 2)) {
          set_all_tau(tau_max);
          since_restart = 0;
          restart_best_len = std::numeric_limits<double>::infinity();
        }
        break;
      }
      case Algorithm::AntColonySystem:
      case Algorithm::FocusedAcs: {
        // Local update, deferred to the barrier and applied in ant order so the
        // result does not depend on thread timing.
        for (const AntRoute& w : work) {
          const std::vector<std::size_t>& worn = workers[static_cast<std::size_t>(w.worker)].worn;
          for (std::size_t i = w.worn_from; i < w.worn_to; ++i) tau_.update(worn[i], [this](double t) { return wear(t); });
        }
        // Global update on the best route's edges only (applied lazily, see
        // Trail): the best so far, or for the focused colony its best since
        // its last restart. Their slots are found again when that route
        // changes, which it does only with another length, and on a route of
        // more than kReinforceHoles holes, whose best changes nearly every
        // iteration, at most every n / kReinforceHoles iterations: finding
        // every slot again was 15 % of a run on 100 000 holes, all of it serial.
        const auto& gbest = focused ? restart_best : best_route;
        const double gbest_len = focused ? restart_best_len : best_len;
        const int reinforce_every = static_cast<int>(std::max<std::size_t>(1, n_ / kReinforceHoles));
        if (reinforced_for != gbest_len && (reinforced_for < 0.0 || it - reinforced_at >= reinforce_every)) {
          reinforced_at = it;
          route_slots(gbest, reinforce_slots);
          tau_.reinforce(reinforce_slots, gbest_len);
          reinforced_for = gbest_len;
        }
        tau_.global_update();
        break;
      }
    }
    if (!focused) refresh_choice();
    for (AntWork& w : workers) w.worn.clear();

    const double now = clock.seconds();
    if (p_.on_iteration) p_.on_iteration(Progress{it, now, best_len});
    if (p_.time_limit_s > 0.0 && now >= p_.time_limit_s) {
      sol.stop_reason = "time limit";
      return false;
    }
    if (p_.stall_iterations > 0 && since_improvement >= p_.stall_iterations) {
      sol.stop_reason = "stalled";
      return false;
    }
    if (it == p_.iterations) return false;
    ++it;
    order_ants();
    return true;
  };
  order_ants();
  if (p_.iterations >= 1) team_.rounds(p_.ants, sol.thread_busy_s, ant, update);
  sol.iterations = std::min(it, p_.iterations);
  sol.order = to_order(best_route);
  sol.length = route_length(problem_, sol.order);
  sol.wall_s = clock.seconds();
  return sol;
}

}  // namespace

Params resolve(const Params& in, std::size_t n) {
  Params p = in;
  // (Measured: ACS with local search beats this MMAS at every TSPLIB size we
  // benchmark, so ACS is the default algorithm; see Params.)
  const bool ls = p.local_search != LocalSearch::None;
  switch (p.algorithm) {
    case Algorithm::AntSystem:
      if (p.beta < 0) p.beta = 4.0;  // the thesis's sets use 4 and 4.5
      if (p.rho < 0) p.rho = 0.5;
      if (p.ants <= 0) p.ants = static_cast<int>(std::clamp<std::size_t>(n, 1, 100));
      break;
    case Algorithm::MaxMinAntSystem:
      if (p.beta < 0) p.beta = 2.0;
      if (p.rho < 0) p.rho = ls ? 0.2 : 0.02;
      if (p.ants <= 0) p.ants = ls ? 10 : static_cast<int>(std::clamp<std::size_t>(n, 1, 100));
      break;
    case Algorithm::AntColonySystem:
    case Algorithm::FocusedAcs:
      if (p.beta < 0) p.beta = 2.0;
      if (p.rho < 0) p.rho = 0.1;
      // Focused ants above kManyAntsFrom holes: 20, since the improvements of
      // an iteration's ants are merged and an iteration's serial part grows
      // with n. Measured at 2 threads, seeds 1-3: brd14051 at 65 s 0.138 0.140
      // 0.166 % with 10, 0.126 0.111 0.116 % with 20, 0.161 0.134 0.162 %
      // with 40; d15112 at 64 s 0.174 0.170 0.176 % with 10, 0.160 0.127
      // 0.176 % with 20; E100k at 60 s (seed 1) 226.72e6 and 226.69e6. On
      // pcb3038 (15 s, 5 seeds) 10, 20 and 40 were alike: 0.110, 0.118, 0.102 %.
      if (p.ants <= 0) p.ants = p.algorithm == Algorithm::FocusedAcs && n > kManyAntsFrom ? 20 : 10;
      break;
  }
  if (p.focus_edges <= 0) p.focus_edges = 16;
  // 5 alpha-nearest measured better than the 12 nearest (see kAlphaFrom);
  // where the lists are the nearest (beyond kAlphaLimit) they keep their 12.
  if (p.candidates <= 0) p.candidates = uses_alpha_lists(n, p.local_search) ? 5 : ls ? 12 : 20;
  // Without a budget, the work grows with n: 300 iterations up to a few
  // thousand holes, fewer beyond (2e6 / n: 20 at 100 000, 3 at a million). A
  // focused iteration costs a small part of a whole-route one, so it gets ten
  // times as many, and a longer patience (kicks come every kKickAfter).
  const bool focused = p.algorithm == Algorithm::FocusedAcs;
  if (p.iterations <= 0) {
    const double work = focused ? 2e7 : 2e6;
    p.iterations = p.time_limit_s > 0 ? std::numeric_limits<int>::max()
                                      : static_cast<int>(std::clamp<double>(work / std::max<std::size_t>(n, 1), focused ? 20 : 3,
                                                                            focused ? 3000 : 300));
  }
  // Stop early on stagnation only when the user set no budget of their own:
  // --iterations N means N iterations (the thesis's runs count on it).
  if (p.stall_iterations == 0) {
    p.stall_iterations = (p.time_limit_s > 0 || in.iterations > 0) ? -1 : (focused ? 600 : 100);
  }
  if (p.threads <= 0) p.threads = std::max(1, omp_get_num_procs());
  return p;
}

Solution solve(const Problem& problem, const Params& params) {
  params.validate();
  const std::size_t n = problem.points.size();
  for (const Point2& pt : problem.points) {
    if (!std::isfinite(pt.x) || !std::isfinite(pt.y)) throw InputError("a point has a non-finite coordinate");
  }
  Params p = resolve(params, n);
  if (n <= 3) {
    // Nothing to search: try every order of up to 3 points.
    Solution s;
    s.algorithm = p.algorithm;
    s.threads = p.threads;
    s.ants = p.ants;
    s.thread_busy_s.assign(static_cast<std::size_t>(p.threads), 0.0);
    s.stop_reason = "trivial";
    Order o(n);
    std::iota(o.begin(), o.end(), 0);
    s.order = o;
    s.length = route_length(problem, o);
    while (std::next_permutation(o.begin(), o.end())) {
      const double len = route_length(problem, o);
      if (len < s.length - 1e-12) {
        s.length = len;
        s.order = o;
      }
    }
    s.trace.push_back({0, 0.0, s.length});
    return s;
  }
  const Clock started;
  Problem numbered;
  std::vector<HoleIndex> input_index;  // by the colony's hole number: the hole's index in problem.points
  if (n >= kCurveOrderFrom) input_index = detail::hilbert_order(problem.points);
  if (!input_index.empty() && detail::order_stretch(problem.points, input_index) <= kJumpyOrder) input_index.clear();
  if (!input_index.empty()) {
    numbered = problem;
    for (std::size_t i = 0; i < n; ++i) numbered.points[i] = problem.points[input_index[i]];
  }
  // One team for the whole solve: the candidate lists' rows and ascent and
  // the iterations all run on it, and a worker that starts late is never waited for.
  Solution solution;
  detail::Team::run(p.threads, [&](detail::Team& team) {
    Colony colony(input_index.empty() ? problem : numbered, p, team, started);
    solution = colony.run();
  });
  // The same route through the same points: its length is unchanged.
  if (!input_index.empty()) {
    for (HoleIndex& h : solution.order) h = input_index[h];
  }
  return solution;
}

}  // namespace aco
