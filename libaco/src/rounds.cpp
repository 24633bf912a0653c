// The team's rounds. Every round the ants build and improve their routes in
// parallel — each ant taken by whichever worker is free, writing only its own
// slot — then a barrier, and on one thread a deterministic reduction by
// (length, ant index), recombination, acceptance or a kick, and the
// pheromone update: the same seed gives the same route on any thread count.
#include <numeric>

#include "colony.h"

namespace aco::detail {

bool Colony::start(double until_s) {
  RunState& s = run_;
  constexpr std::size_t kStepsAPiece = 16384;  // a few milliseconds in a browser
  if (!first_walk_) {
    if (slice_over(until_s)) return false;
    first_walk_ = std::make_unique<NearestWalk>(space_, 0);  // its grid
    worked_ = true;
  }
  for (bool walked = false; !walked; worked_ = true) {
    if (slice_over(until_s)) return false;
    walked = first_walk_->walk(kStepsAPiece);
  }
  s.sol.algorithm = p_.algorithm;
  s.sol.ants = p_.ants;
  s.sol.threads = p_.threads;
  s.sol.thread_busy_s.assign(static_cast<std::size_t>(p_.threads), 0.0);

  // Nearest neighbour, improved when local search is on, starts the best-so-far
  // and gives C_nn for the initial trail.
  s.best_route = route_from_order(space_, first_walk_->take());
  first_walk_.reset();
  c_nn_ = std::max(space_.route_cost(s.best_route), 1e-9);
  s.use_ls = p_.local_search != LocalSearch::None;
  s.moves = p_.local_search == LocalSearch::FiveOpt       ? Moves::FiveOpt
            : p_.local_search == LocalSearch::ThreeOpt    ? Moves::ThreeOpt
            : p_.local_search == LocalSearch::TwoOptOrOpt ? Moves::OrOpt
                                                          : Moves::TwoOpt;
  if (!s.use_ls) {
    start_rounds();
    return true;
  }
  first_search_ = std::make_unique<LocalSearcher>(space_, cand_);
  // A stop or the time limit ends this search too: at 10^5 holes and more
  // it is the run's longest step (issue 84).
  first_search_->interrupt_when([this] { return must_end(); });
  first_search_->begin(s.best_route, s.moves);
  return true;
}

bool Colony::first_search(double until_s) {
  if (!first_search_) return true;
  if (slice_over(until_s)) return false;
  // (The search asks after 63 holes at the least: it gets on however short the slice.)
  const std::function<bool()> pause = [&] { return until_s > 0.0 && clock_.seconds() >= until_s; };
  const bool searched = first_search_->search(pause);
  worked_ = true;
  if (!searched) return false;
  first_search_->end(run_.best_route);
  first_search_.reset();
  start_rounds();
  return true;
}

void Colony::start_rounds() {
  RunState& s = run_;
  const double c_nn = c_nn_;
  s.best_len = space_.route_cost(s.best_route);
  s.sol.trace.push_back({0, clock_.seconds(), s.best_len});

  const double m = p_.ants;
  switch (p_.algorithm) {
    case Algorithm::AntSystem: tau0_ = m / c_nn; break;  // the thesis: tau0 = m / C_nn
    case Algorithm::MaxMinAntSystem:
      mmas_limits(c_nn);
      tau0_ = s.tau_max;
      break;
    case Algorithm::AntColonySystem:
    case Algorithm::FocusedAcs: tau0_ = 1.0 / (n_ * c_nn); break;
  }
  set_all_tau(tau0_);
  s.focused = p_.algorithm == Algorithm::FocusedAcs;
  if (!s.focused) refresh_choice();  // focused ants weigh their few rows as they go
  if (s.focused) {
    set_reference(s.best_route);
    if (s.use_ls) {
      kick_searcher_ = std::make_unique<LocalSearcher>(space_, cand_);
      kick_searcher_->interrupt_when([this] { return must_end(); });
    }
  }
  ref_len_ = s.best_len;

  s.acs = p_.algorithm == Algorithm::AntColonySystem;
  s.work.resize(static_cast<std::size_t>(p_.ants));
  s.workers = std::vector<AntWork>(static_cast<std::size_t>(p_.threads));
  if (s.use_ls) {
    s.searchers.reserve(static_cast<std::size_t>(p_.threads));
    for (int t = 0; t < p_.threads; ++t) {
      s.searchers.emplace_back(space_, cand_);
      // An ant's search from a route the first search left unfinished (ended
      // by the limit) would finish it: seconds at 10^5 holes. It ends too.
      s.searchers.back().interrupt_when([this] { return must_end(); });
    }
    // A focused ant's 3-opt or 5-opt step starts off the reference, which
    // stays where it is for the run (set_reference rewrites it in place).
    if (s.focused && uses_lkh_stall_answers(n_)) {
      for (LocalSearcher& ls : s.searchers) ls.restrict_to(&ref_route_, &ref_pos_);
    }
  }
  s.restart_best = s.best_route;
  s.restart_best_len = s.best_len;
  s.sol.stop_reason = "iterations";
  s.it = 1;
  s.ant_of_slot.resize(static_cast<std::size_t>(p_.ants));
  s.scale_of_ant.resize(static_cast<std::size_t>(p_.ants));
  order_ants();
  s.ended = p_.iterations < 1;
}

bool Colony::must_end() const {
  return (p_.stop != nullptr && p_.stop->load()) || (p_.time_limit_s > 0.0 && clock_.seconds() >= p_.time_limit_s);
}

bool Colony::advance(Team& team, int max_iterations, double until_s) {
  RunState& s = run_;
  team_ = &team;
  if (!s.ended && p_.stop != nullptr && p_.stop->load()) {
    s.sol.stop_reason = "stopped";
    s.ended = true;
  }
  if (s.ended) return true;
  if (!first_search(until_s)) return false;  // the slice ended in the first route's search
  if (s.ended) return true;                  // (no iteration to run)
  s.slice_last_it = max_iterations > 0 ? s.it + max_iterations - 1 : 0;
  s.slice_until_s = until_s;
  if (team_->threads() == 1 && (until_s > 0.0 || s.next_slot > 0 || s.ant_begun)) return ants_in_turn();
  team_->rounds(p_.ants, s.sol.thread_busy_s, [this](int slot, int worker) { ant(slot, worker); },
                [this] { return after_round(); });
  return s.ended;
}

bool Colony::ants_in_turn() {
  RunState& s = run_;
  // (A search asks after 63 holes at the least: it gets on however short the slice.)
  const std::function<bool()> pause = [&] { return s.slice_until_s > 0.0 && clock_.seconds() >= s.slice_until_s; };
  for (;;) {
    for (; s.next_slot < p_.ants; ++s.next_slot) {
      const double t0 = clock_.seconds();
      if (!s.ant_begun) {
        if (slice_over(s.slice_until_s)) return false;
        begin_ant(s.next_slot, 0);
        s.ant_begun = true;
      }
      const bool searched = !s.use_ls || s.searchers[0].search(pause);
      worked_ = true;
      if (searched) {
        end_ant(s.next_slot, 0);
        s.ant_begun = false;
      }
      s.sol.thread_busy_s[0] += clock_.seconds() - t0;
      if (!searched) return false;
    }
    s.next_slot = 0;
    if (!after_round()) return s.ended;
  }
}

Solution Colony::finish() {
  RunState& s = run_;
  if (first_search_) {
    // Stopped in the first route's search: that route, as far as it got.
    first_search_->end(s.best_route);
    first_search_.reset();
    s.best_len = space_.route_cost(s.best_route);
  }
  if (!s.ended) s.sol.stop_reason = "stopped";
  s.ended = true;
  s.sol.iterations = s.completed;
  s.sol.order = to_order(s.best_route);
  s.sol.length = route_length(problem_, s.sol.order);
  s.sol.wall_s = clock_.seconds();
  return std::move(s.sol);
}

void Colony::order_ants() {
  std::iota(run_.ant_of_slot.begin(), run_.ant_of_slot.end(), 0);
  if (!run_.focused) return;
  for (int k = 0; k < p_.ants; ++k) {
    Rng rng(p_.seed, static_cast<std::uint64_t>(run_.it), static_cast<std::uint64_t>(k));
    run_.scale_of_ant[static_cast<std::size_t>(k)] = static_cast<int>(rng.below(4));
  }
  std::stable_sort(run_.ant_of_slot.begin(), run_.ant_of_slot.end(),
                   [&](int a, int b) { return run_.scale_of_ant[static_cast<std::size_t>(a)] > run_.scale_of_ant[static_cast<std::size_t>(b)]; });
}

void Colony::ant(int slot, int worker) {
  begin_ant(slot, worker);
  if (run_.use_ls) run_.searchers[static_cast<std::size_t>(worker)].search(nullptr);
  end_ant(slot, worker);
}

void Colony::begin_ant(int slot, int worker) {
  const int k = run_.ant_of_slot[static_cast<std::size_t>(slot)];
  Rng rng(p_.seed, static_cast<std::uint64_t>(run_.it), static_cast<std::uint64_t>(k));
  AntWork& w = run_.workers[static_cast<std::size_t>(worker)];
  if (run_.focused) {
    // Each ant draws its bound from focus_edges x {1/2, 1, 2, 4}: small
    // changes polish, large ones reach out of deep local optima, and no
    // single bound served every instance (measured: 8 stalls d1291, 32
    // stalls pcb1173). A fixed share of each bound per iteration, largest
    // to the first ants, measured worse (d1291 at 5 s: 0.74 % against 0.30 %).
    const int scale = static_cast<int>(rng.below(4));  // as order_ants drew it
    construct_focused(w, rng, std::max(1, (p_.focus_edges << scale) / 2));
    if (run_.use_ls) run_.searchers[static_cast<std::size_t>(worker)].begin_from(w.route, run_.moves, w.seeds);
  } else {
    construct(w, rng, run_.acs);
    if (run_.use_ls) run_.searchers[static_cast<std::size_t>(worker)].begin(w.route, run_.moves);
  }
}

void Colony::end_ant(int slot, int worker) {
  const int k = run_.ant_of_slot[static_cast<std::size_t>(slot)];
  AntWork& w = run_.workers[static_cast<std::size_t>(worker)];
  if (run_.use_ls) run_.searchers[static_cast<std::size_t>(worker)].end(w.route);
  AntRoute& out = run_.work[static_cast<std::size_t>(k)];
  // A focused ant knows its length from its walk and its search's gains;
  // the iteration's best is measured again in full (update()).
  if (run_.focused) out.length = w.length - (run_.use_ls ? run_.searchers[static_cast<std::size_t>(worker)].gain() : 0.0);
  else out.length = space_.route_cost(w.route);
  out.worker = worker;
  out.worn_from = w.worn.size();
  if (p_.algorithm == Algorithm::AntColonySystem) {
    const std::size_t mm = w.route.size();
    for (std::size_t i = 0; i < mm; ++i) add_worn_slots(w.route[i], w.route[(i + 1) % mm], w.worn);
  } else if (run_.focused) {
    // A focused ant's route is the reference but for its new edges, so only
    // those are worn (the reference's edges get the global update).
    for (std::size_t i = 0; i + 1 < w.seeds.size(); i += 2) add_worn_slots(w.seeds[i], w.seeds[i + 1], w.worn);
  }
  out.worn_to = w.worn.size();
  // Only where update() merges them (above kManyAntsFrom holes).
  out.improves = run_.focused && n_ > kManyAntsFrom && out.length < ref_len_ - 1e-9;
  if (out.improves) {
    // Only where the ant or its search changed an edge, when the search can say.
    const LocalSearcher* ls = run_.use_ls ? &run_.searchers[static_cast<std::size_t>(worker)] : nullptr;
    if (ls != nullptr && ls->searched_all()) {
      detail::route_diff(ref_route_, ref_pos_, w.route, ls->positions(), ls->searched(), out.diff);
    } else {
      detail::route_diff(ref_route_, ref_pos_, w.route, out.diff);
    }
  }
  if (!run_.focused) {
    std::swap(out.route, w.route);
  } else if (w.best_ant < 0 || out.length < w.best_length || (out.length == w.best_length && k < w.best_ant)) {
    std::swap(w.best_route, w.route);
    w.best_length = out.length;
    w.best_ant = k;
  }
}

bool Colony::after_round() {
  // Deterministic reduction: shortest, ties to the lowest ant index.
  int ib = 0;
  for (int k = 1; k < p_.ants; ++k) {
    if (run_.work[k].length < run_.work[ib].length) ib = k;
  }
  const std::vector<HoleIndex>* ib_route = &run_.work[ib].route;
  for (AntWork& w : run_.workers) {
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
  double ib_len = run_.work[ib].length;
  bool ib_measured = !run_.focused;  // whether ib_len is ib_route's length summed in full
  const bool ib_plateau = run_.focused && ib_len <= ref_len_ + 1e-6 && !is_reference(*ib_route);
  if (run_.focused && run_.work[ib].improves) merge_improvements(ib, ib_route, ib_len);
  ++run_.since_improvement;
  ++run_.since_restart;
  if (run_.focused) accept_or_kick(ib_route, ib_len, ib_measured, ib_plateau);
  // Not the reference, yet better (an ant that gave back R, its length a
  // last bit short): rare.
  if (!ib_measured && (ib_len < run_.best_len - 1e-9 || ib_len < run_.restart_best_len - 1e-9)) {
    ib_len = space_.route_cost(*ib_route);
  }
  if (ib_len < run_.best_len - 1e-9) {
    run_.best_len = ib_len;
    run_.best_route = *ib_route;
    run_.since_improvement = 0;
    run_.sol.trace.push_back({run_.it, clock_.seconds(), run_.best_len});
  }
  // On a restart's round this comes after the restart, so this round's best
  // (from the epoch that just ended, about as good as the best so far)
  // becomes the new epoch's best and its kicks go from there: a restart
  // resets the trail and sends the reference off from the shaken route for
  // kKickAfter rounds or more, then the colony is back near the best so far.
  // Restarts as whole epochs of their own measured worse (docs/colony.md).
  if (ib_len < run_.restart_best_len - 1e-9) {
    run_.restart_best_len = ib_len;
    run_.restart_best = *ib_route;
    run_.since_restart = 0;
  }

  // Pheromone update, on one thread, after the barrier.
  update_pheromone(*ib_route, ib_len);

  run_.completed = run_.it;
  const double now = clock_.seconds();
  if (p_.on_iteration) p_.on_iteration(Progress{run_.it, now, run_.best_len});
  run_.ended = true;
  if (p_.stop != nullptr && p_.stop->load()) {
    run_.sol.stop_reason = "stopped";
    return false;
  }
  if (p_.time_limit_s > 0.0 && now >= p_.time_limit_s) {
    run_.sol.stop_reason = "time limit";
    return false;
  }
  if (p_.stall_iterations > 0 && run_.since_improvement >= p_.stall_iterations) {
    run_.sol.stop_reason = "stalled";
    return false;
  }
  if (run_.it == p_.iterations) return false;
  run_.ended = false;
  ++run_.it;
  order_ants();
  // The slice ends here, between iterations: the next advance() goes on
  // with the iteration whose ants were just drawn, as one run would.
  if (run_.slice_last_it > 0 && run_.it > run_.slice_last_it) return false;
  if (run_.slice_until_s > 0.0 && now >= run_.slice_until_s) return false;
  return true;
}

}  // namespace aco::detail
