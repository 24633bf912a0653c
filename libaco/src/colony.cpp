// The colony's set-up: candidate lists by the problem's size and search
// (every other hole up to kFullListLimit: the exact Ant System; alpha-nearest
// with local search up to kAlphaLimit; else the nearest), the heuristic
// weights eta^beta, and the tables of full-list mode.
#include "colony.h"

namespace aco::detail {

// Rows a piece between two looks at the clock: tens of milliseconds in the
// browser's single thread.
constexpr std::size_t kRowsAPiece = 16384;

Colony::Colony(const Problem& problem, const Params& params, Team& team, const Clock& started)
  : clock_(started), problem_(problem), p_(params), team_(&team), space_(problem), n_(space_.holes()) {}

bool Colony::set_up(Team& team, double until_s) {
  team_ = &team;
  const auto slice_over = [&] { return this->slice_over(until_s); };
  if (set_up_ == SetUp::Lists) {
    if (slice_over()) return false;
    if (n_ <= kFullListLimit) {
      cand_ = detail::build_candidates(space_, static_cast<int>(n_) - 1, team);
    } else if (uses_alpha_lists(n_, p_.local_search)) {
      // joined_nearest() and alpha_candidates(), in pieces.
      if (!alpha_) {
        Candidates nearest;
        if (!nearest_rows(team, kAlphaFrom, until_s, nearest)) return false;
        // (No look at the clock here: a slice that came back to it would fill no row.)
        nearest = detail::joined(space_, std::move(nearest));
        std::vector<double>().swap(nearest.length);  // not read by alpha_candidates: 13 MB less at 100 000 holes
        alpha_ = std::make_unique<AlphaLists>(space_, std::move(nearest), p_.candidates,
                                              ascent_iterations(n_, p_.time_limit_s),
                                              uses_penalised_costs(n_, p_.local_search));
        worked_ = true;
      }
      for (bool made = false; !made; worked_ = true) {
        if (slice_over()) return false;
        made = alpha_->step(team, kRowsAPiece);
      }
      cand_ = alpha_->take();
      alpha_.reset();
    } else if (!nearest_rows(team, p_.candidates, until_s, cand_)) {
      return false;
    }
    k_ = cand_.k;
    // Grown a piece at a time, as the lists are.
    eta_beta_.reserve(static_cast<std::size_t>(n_) * k_);
    set_up_ = SetUp::Weights;
    worked_ = true;
  }
  if (set_up_ == SetUp::Weights) {
    while (weighted_ < n_) {
      if (slice_over()) return false;
      const HoleIndex to = static_cast<HoleIndex>(std::min<std::size_t>(n_, weighted_ + kRowsAPiece));
      eta_beta_.resize(static_cast<std::size_t>(to) * k_);
      for (HoleIndex i = weighted_; i < to; ++i) {
        const double* length = cand_.lengths_of(i);
        for (int r = 0; r < k_; ++r) eta_beta_[idx(i, r)] = std::pow(eta(length[r]), p_.beta);
      }
      weighted_ = to;
      worked_ = true;
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
    set_up_ = SetUp::Trail;
  }
  if (set_up_ == SetUp::Trail) {
    // Zeroed here, set by start_rounds(): 0.1 s of a slice at 10^6 holes, a piece of its own.
    if (slice_over()) return false;
    const std::size_t slots = static_cast<std::size_t>(n_) * k_;
    tau_ = detail::Trail(slots, 0.0, p_.rho);
    // Focused ants weigh their few rows as they go and never read choice_.
    if (p_.algorithm != Algorithm::FocusedAcs) choice_.assign(slots, 0.0);
    set_up_ = SetUp::Done;
    worked_ = true;
  }
  return true;
}

bool Colony::nearest_rows(Team& team, int k, double until_s, Candidates& out) {
  if (!rows_) {
    rows_ = std::make_unique<NearestRows>(space_, k);  // the k-d tree: a piece of its own
    worked_ = true;
  }
  for (bool filled = false; !filled; worked_ = true) {
    if (slice_over(until_s)) return false;
    filled = rows_->fill(team, kRowsAPiece);
  }
  out = rows_->take();
  rows_.reset();
  return true;
}

Order Colony::to_order(const std::vector<HoleIndex>& route) const {
  Order o;
  o.reserve(n_);
  for (HoleIndex h : route) {
    if (h < n_) o.push_back(h);
  }
  return o;
}

}  // namespace aco::detail
