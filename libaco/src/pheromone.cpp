// The trail: tau on candidate edges only (n x k, trail.h), read through
// tau^alpha * eta^beta by the classic colonies' ants (refresh_choice), and
// updated after each round on one thread: the Ant System's evaporation and
// deposit of every ant (1/C_k), MAX-MIN's best-only deposit within its
// limits (Stützle & Hoos 2000), and ACS's local wear and global update on
// the best route's edges, which the focused colony shares.
#include <limits>

#include "colony.h"

namespace aco::detail {

void Colony::refresh_choice() {
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

void Colony::route_slots(const std::vector<HoleIndex>& route, std::vector<std::size_t>& slots) {
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

void Colony::mmas_limits(double best) {
  run_.tau_max = 1.0 / (p_.rho * best);
  // With local search ACOTSP uses tau_min = tau_max / (2n); without, the
  // p_best = 0.05 formula of Stützle & Hoos 2000, eq. 11.
  if (run_.use_ls) {
    run_.tau_min = run_.tau_max / (2.0 * n_);
  } else {
    const double p_root = std::pow(0.05, 1.0 / n_);
    const double avg = std::max(2.0, n_ / 2.0);
    run_.tau_min = std::min(run_.tau_max, run_.tau_max * (1.0 - p_root) / ((avg - 1.0) * p_root));
  }
}

void Colony::update_pheromone(const std::vector<HoleIndex>& ib_route, double ib_len) {
  // Pheromone update, on one thread, after the barrier.
  switch (p_.algorithm) {
    case Algorithm::AntSystem:
      evaporate(1.0 - p_.rho);
      for (const AntRoute& w : run_.work) deposit(w.route, 1.0 / std::max(w.length, 1e-9));
      break;
    case Algorithm::MaxMinAntSystem: {
      evaporate(1.0 - p_.rho);
      // u_gb schedule (Stützle & Hoos 2000, with local search): the best
      // since the last restart deposits ever more often as the run goes on.
      const int u_gb = run_.since_restart < 25 ? 25 : run_.since_restart < 75 ? 5 : run_.since_restart < 125 ? 3 : run_.since_restart < 250 ? 2 : 1;
      const bool use_gb = (run_.it % u_gb) == 0;
      const auto& route = use_gb ? run_.restart_best : ib_route;
      const double len = use_gb ? run_.restart_best_len : ib_len;
      mmas_limits(run_.best_len);
      deposit(route, 1.0 / std::max(len, 1e-9));
      tau_.update_all([&](double t) { return std::clamp(t, run_.tau_min, run_.tau_max); });
      // Stagnation: reinitialise the trails (the best-so-far is kept).
      if (run_.since_restart >= std::max(50, p_.stall_iterations / 2)) {
        set_all_tau(run_.tau_max);
        run_.since_restart = 0;
        run_.restart_best_len = std::numeric_limits<double>::infinity();
      }
      break;
    }
    case Algorithm::AntColonySystem:
    case Algorithm::FocusedAcs: {
      // Local update, deferred to the barrier and applied in ant order so the
      // result does not depend on thread timing.
      for (const AntRoute& w : run_.work) {
        const std::vector<std::size_t>& worn = run_.workers[static_cast<std::size_t>(w.worker)].worn;
        for (std::size_t i = w.worn_from; i < w.worn_to; ++i) tau_.update(worn[i], [this](double t) { return wear(t); });
      }
      // Global update on the best route's edges only (applied lazily, see
      // Trail): the best so far, or for the focused colony its best since
      // its last restart. Their slots are found again when that route
      // changes, which it does only with another length, and on a route of
      // more than kReinforceHoles holes, whose best changes nearly every
      // iteration, at most every n / kReinforceHoles iterations: finding
      // every slot again was 15 % of a run on 100 000 holes, all of it serial.
      const auto& gbest = run_.focused ? run_.restart_best : run_.best_route;
      const double gbest_len = run_.focused ? run_.restart_best_len : run_.best_len;
      const int reinforce_every = static_cast<int>(std::max<std::size_t>(1, n_ / kReinforceHoles));
      if (run_.reinforced_for != gbest_len && (run_.reinforced_for < 0.0 || run_.it - run_.reinforced_at >= reinforce_every)) {
        run_.reinforced_at = run_.it;
        route_slots(gbest, run_.reinforce_slots);
        tau_.reinforce(run_.reinforce_slots, gbest_len);
        run_.reinforced_for = gbest_len;
      }
      tau_.global_update();
      break;
    }
  }
  if (!run_.focused) refresh_choice();
  for (AntWork& w : run_.workers) w.worn.clear();
}

}  // namespace aco::detail
