// The solver's entry points: resolve() fills in each algorithm's defaults
// for the problem's size, solve() numbers large inputs along a Hilbert curve
// when their order jumps about the plate and runs the colony on one team.
#include "omp_compat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "aco/error.h"
#include "aco/solve.h"
#include "colony.h"
#include "hilbert.h"

namespace aco {

using detail::kCurveOrderFrom;
using detail::kFiveOptFrom;
using detail::kAlphaLimit;
using detail::kJumpyOrder;
using detail::kManyAntsFrom;
using detail::uses_alpha_lists;

namespace {

// Ants an iteration of the focused colony, by the instance's size (measured
// at 2 threads, whole process, median gap over seeds 1-5 unless said):
// - up to kFullListLimit holes 10: there kicks are off and restarts (every
//   kRestartAfter iterations) carry the search, and 40 ants make them four
//   times as rare (u574 at 1 s: 0.00 % with 10, 0.08 % with 40);
// - up to kManyAntsFrom 40: a round of 10 ants whose local searches vary 3x
//   left the thread done first waiting about 5 % of the time, 40 win it back
//   (pcb1173, 9 seeds: two threads at 0.96 of what the CPUs allow over 2000
//   iterations, 0.95 over 200, against 0.89 and 0.84) and route no worse
//   (pcb3038 at 15 s 0.023 % against 0.044 %, pla7397 at 91 s 0.071 %
//   against 0.082 %, run alternately; the gap table's later run at 7ff92fe
//   gave 0.046 and 0.071 %, seeds that end near 0.1 % setting the median);
// - above, 20, since there the improvements of an iteration's ants are merged
//   and an iteration's serial part grows with n (seeds 1-3: brd14051 at 65 s
//   0.138 0.140 0.166 % with 10, 0.126 0.111 0.116 % with 20, 0.161 0.134
//   0.162 % with 40; d15112 at 64 s 0.174 0.170 0.176 % with 10, 0.160 0.127
//   0.176 % with 20; E100k at 60 s, seed 1, 226.72e6 with 10 and 226.69e6
//   with 20).
int focused_ants(std::size_t n) {
  if (n <= detail::kFullListLimit) return 10;
  return n > kManyAntsFrom ? 20 : 40;
}

}  // namespace

Params resolve(const Params& in, std::size_t n) {
  Params p = in;
  // LKH's 5-opt step (five_opt.cpp) from 3000 to 20 000 holes, 3-opt with
  // deeper steps below and above. Two threads, whole process, gap to the optimum, 3-opt ->
  // 5-opt (seeds 1-5 unless said; pcb3038 1-10, both run the same day):
  // pcb3038 at 15 s median 0.09 -> 0.07 %, fnl4461 at 20 s (seeds 1-3)
  // 0.103 -> 0.058 %, pla7397 at 91 s 0.071 -> 0.055 %, d15112 at 64 s
  // 0.114 -> 0.072 %, brd14051 at 65 s 0.078 -> 0.056 % (3-opt: the gap
  // table at bd5368f). Below, 5-opt's searches cost so much more than
  // 3-opt's (fl1400: 37 iterations in 5 s against 802) that the colony
  // lost more than the step found (seeds 1-3: d1291 at 5 s 0.00 -> 0.71 %,
  // fl1400 0.68 -> 1.01 %, pcb1173 0.00 -> 0.01 %, u724 at 2 s 0.05 ->
  // 0.09 %; d493 at 1 s 0.21 -> 0.01 %). Above 20 000 holes, paid in plain
  // lengths (kPenalisedTo), it wins every row of the scale table (60 s, 30 s
  // for 33 000; seeds 1-3, 3-opt at c455ce2 -> 5-opt at dad5d2d, medians):
  // 33 000 uniform holes 0.66 -> 0.56 %, five copies of pla7397 0.34 ->
  // 0.20 %, 100 000 uniform holes 0.65 -> 0.51 % (docs/benchmarks.md). Above kAlphaLimit the
  // candidates are the plain nearest and nothing was measured: 3-opt stays.
  if (p.local_search == LocalSearch::Auto) {
    p.local_search = n >= kFiveOptFrom && n <= kAlphaLimit ? LocalSearch::FiveOpt : LocalSearch::ThreeOpt;
  }
  const bool focused = p.algorithm == Algorithm::FocusedAcs;
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
      if (p.ants <= 0) p.ants = focused ? focused_ants(n) : 10;
      break;
  }
  if (p.focus_edges <= 0) p.focus_edges = 16;
  // 5 alpha-nearest measured better than the 12 nearest (see kAlphaFrom);
  // where the lists are the nearest (beyond kAlphaLimit) they keep their 12.
  if (p.candidates <= 0) p.candidates = uses_alpha_lists(n, p.local_search) ? 5 : ls ? 12 : 20;
  // Without a budget, the work grows with n: 300 iterations up to a few
  // thousand holes, fewer beyond (2e6 / n: 20 at 100 000, 3 at a million). A
  // focused iteration of 10 ants costs a small part of a whole-route one, so
  // it gets ten times as many, and a longer patience (kicks come every
  // kKickAfter). These counts are for the ants a focused iteration had
  // before 7ff92fe (10, 20 above kManyAntsFrom holes); scaled by those over
  // the ants it has now, a job without a budget does the same ants' work
  // whatever --ants is.
  const double iteration_scale = focused ? (n > kManyAntsFrom ? 20.0 : 10.0) / p.ants : 1.0;
  if (p.iterations <= 0) {
    const double work = focused ? 2e7 : 2e6;
    const double iterations = std::clamp<double>(work / std::max<std::size_t>(n, 1), focused ? 20 : 3, focused ? 3000 : 300);
    p.iterations = p.time_limit_s > 0 ? std::numeric_limits<int>::max()
                                      : std::max(1, static_cast<int>(iteration_scale * iterations));
  }
  // Stop early on stagnation only when the user set no budget of their own:
  // --iterations N means N iterations (the thesis's runs count on it). The
  // patience is counted in rounds, as kicks and restarts are, so a stalled
  // colony still restarts (kRestartAfter) before it stops: counted in ants,
  // 150 rounds of 40, pcb3038 stopped before any restart at 0.17-0.38 %
  // (seeds 1-3) where 10 ants a round had reached 0.05-0.22 %.
  if (p.stall_iterations == 0) {
    p.stall_iterations = (p.time_limit_s > 0 || in.iterations > 0) ? -1 : (focused ? 600 : 100);
  }
  if (p.threads <= 0) p.threads = std::max(1, omp_get_num_procs());
  return p;
}

struct ColonyRun::State {
  Params params;  // resolved
  Problem problem;  // numbered along a Hilbert curve when input_index is not empty
  std::vector<HoleIndex> input_index;  // by the colony's hole number: the hole's index in the problem given
  // The Hilbert numbering (kCurveOrderFrom holes and more), made by
  // advance() a piece at a time: the curve's keys, their sort, then the
  // check that the input jumps about and the renumbering. At 10^6 holes each
  // takes 0.1-0.2 s of a page's slice; made whole, they kept a Stop waiting
  // half a second (issue 84).
  enum class Numbering { Keys, Sort, Renumber, Done } numbering = Numbering::Done;
  detail::CurveKeys curve_keys;
  void number_piece();
  std::optional<detail::Clock> started;
  std::unique_ptr<detail::Colony> colony;
  bool begun = false;  // the colony set up and its first route made (Colony::start)
  bool ended = false;
  Solution solution;
};

ColonyRun::ColonyRun(const Problem& problem, const Params& params) : state_(std::make_unique<State>()) {
  params.validate();
  for (const Point2& pt : problem.points) {
    if (!std::isfinite(pt.x) || !std::isfinite(pt.y)) throw InputError("a point has a non-finite coordinate");
  }
  State& s = *state_;
  const std::size_t n = problem.points.size();
  s.params = resolve(params, n);
  s.problem = problem;
  if (n <= 3) {
    // Nothing to search: try every order of up to 3 points.
    Solution& sol = s.solution;
    sol.algorithm = s.params.algorithm;
    sol.threads = s.params.threads;
    sol.ants = s.params.ants;
    sol.thread_busy_s.assign(static_cast<std::size_t>(s.params.threads), 0.0);
    sol.stop_reason = "trivial";
    Order o(n);
    std::iota(o.begin(), o.end(), 0);
    sol.order = o;
    sol.length = route_length(problem, o);
    while (std::next_permutation(o.begin(), o.end())) {
      const double len = route_length(problem, o);
      if (len < sol.length - 1e-12) {
        sol.length = len;
        sol.order = o;
      }
    }
    sol.trace.push_back({0, 0.0, sol.length});
    s.ended = true;
    return;
  }
  s.started.emplace();
  if (n >= kCurveOrderFrom) s.numbering = State::Numbering::Keys;
}

void ColonyRun::State::number_piece() {
  switch (numbering) {
    case Numbering::Keys:
      curve_keys = detail::hilbert_keys(problem.points);
      numbering = Numbering::Sort;
      break;
    case Numbering::Sort:
      input_index = detail::sort_keys(std::move(curve_keys));
      curve_keys = {};
      numbering = Numbering::Renumber;
      break;
    case Numbering::Renumber:
      if (detail::order_stretch(problem.points, input_index) <= kJumpyOrder) {
        input_index.clear();
      } else {
        const std::vector<Point2> given = problem.points;
        for (std::size_t i = 0; i < input_index.size(); ++i) problem.points[i] = given[input_index[i]];
      }
      numbering = Numbering::Done;
      break;
    case Numbering::Done: break;
  }
}

ColonyRun::~ColonyRun() = default;
ColonyRun::ColonyRun(ColonyRun&&) noexcept = default;
ColonyRun& ColonyRun::operator=(ColonyRun&&) noexcept = default;

bool ColonyRun::advance(int max_iterations, double max_seconds) {
  State& s = *state_;
  if (s.ended) return true;
  // The set-up counts in the slice: at 10^6 holes it is seconds, and a
  // slice of the page's must end on time for a Stop to be heard (issue 84).
  const double until = max_seconds > 0.0 ? s.started->seconds() + max_seconds : 0.0;
  // A slice begins no piece once its time is up, but always its first.
  bool worked = false;
  const auto slice_over = [&] { return worked && until > 0.0 && s.started->seconds() >= until; };
  if (s.numbering != State::Numbering::Done) {
    for (; s.numbering != State::Numbering::Done; worked = true) {
      if (slice_over()) return false;
      s.number_piece();
    }
    // The k-d tree comes next, at 10^6 holes the longest piece of all: in a
    // slice of its own, not after a piece that used most of this one.
    if (until > 0.0) return false;
  }
  // One team a slice: the candidate lists' rows and ascent (first slice) and
  // the iterations all run on it, and a worker that starts late is never waited for.
  detail::Team::run(s.params.threads, [&](detail::Team& team) {
    if (!s.colony) s.colony = std::make_unique<detail::Colony>(s.problem, s.params, team, *s.started);
    s.colony->begin_slice(worked);
    if (!s.begun) {
      if (!s.colony->set_up(team, until) || !s.colony->start(until)) return;
      s.begun = true;
    }
    s.ended = s.colony->advance(team, max_iterations, until);
  });
  return s.ended;
}

bool ColonyRun::ended() const { return state_->ended; }

bool ColonyRun::begun() const { return state_->begun; }

int ColonyRun::iterations() const {
  const State& s = *state_;
  return s.colony ? s.colony->completed() : s.solution.iterations;
}

Order ColonyRun::best_order() const {
  const State& s = *state_;
  Order o = s.colony ? s.colony->best_order() : s.solution.order;
  if (s.colony && !s.input_index.empty()) {
    for (HoleIndex& h : o) h = s.input_index[h];
  }
  return o;
}

const Params& ColonyRun::params() const { return state_->params; }

Solution ColonyRun::finish() {
  State& s = *state_;
  if (!s.begun && !s.ended) {
    // Not begun: the first route (nearest neighbour, improved), no iteration.
    while (s.numbering != State::Numbering::Done) s.number_piece();
    detail::Team::run(s.params.threads, [&](detail::Team& team) {
      if (!s.colony) s.colony = std::make_unique<detail::Colony>(s.problem, s.params, team, *s.started);
      s.colony->set_up(team, 0.0);
      s.colony->start(0.0);
      s.begun = true;
      s.colony->first_search(0.0);
    });
  }
  if (s.colony != nullptr) {
    s.solution = s.colony->finish();
    s.colony.reset();
  }
  s.ended = true;
  // The same route through the same points: its length is unchanged.
  for (HoleIndex& h : s.solution.order) {
    if (!s.input_index.empty()) h = s.input_index[h];
  }
  s.input_index.clear();
  return std::move(s.solution);
}

Solution solve(const Problem& problem, const Params& params) {
  ColonyRun run(problem, params);
  run.advance();
  return run.finish();
}

}  // namespace aco
