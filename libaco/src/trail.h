#pragma once
// Pheromone on candidate edges, with ACS's global update applied lazily.
//
// ACS reinforces the best route's edges every iteration:
//   tau <- (1 - rho) tau + rho / L.
// Done eagerly that is 2n writes per iteration, and in the focused colony,
// whose ants change a few dozen edges each, the pheromone update was the
// largest serial part of an iteration: 30 us of 300 on pcb1173 with 2
// threads, where every write also takes the cache line from the core whose
// ants read it. Here the reinforced slots are only marked, with the count of
// updates they have seen; g updates later their trail is
//   1/L + (1 - rho)^g (tau - 1/L),
// computed when read and written back only when the slot is touched otherwise
// or the best route changes. Everything depends only on counts, never on
// timing, so results stay the same for any thread count.
#include <cmath>
#include <cstdint>
#include <vector>

namespace aco::detail {

class Trail {
 public:
  Trail() = default;
  Trail(std::size_t slots, double initial, double rho) : tau_(slots, initial), since_(slots, kEager), rho_(rho) {
    // (1 - rho)^g for the g that matter: past the table it is computed, or 0
    // if the table has already reached 0.
    decay_.resize(4096);
    double f = 1.0;
    for (double& d : decay_) {
      d = f;
      f *= 1.0 - rho;
    }
  }

  double operator[](std::size_t e) const {
    const std::uint32_t since = since_[e];
    if (since == kEager) return tau_[e];
    const std::uint32_t g = updates_ - since;
    const double f = g < decay_.size() ? decay_[g] : (decay_.back() > 0.0 ? std::pow(1.0 - rho_, g) : 0.0);
    return target_ + f * (tau_[e] - target_);
  }
  // Sets slot e from its current trail (the best route's reinforcement goes on).
  template <class Change>
  void update(std::size_t e, Change&& change) {
    const double next = change((*this)[e]);
    if (since_[e] != kEager) {
      tau_[e] = next;
      since_[e] = updates_;
    } else if (next != tau_[e]) {
      // Most of ACS's local updates find tau0 and leave it: not writing
      // keeps the line shared with the core whose ants read it.
      tau_[e] = next;
    }
  }
  // From now on `slots` (the best route's, of length `length`) are reinforced.
  void reinforce(const std::vector<std::size_t>& slots, double length) {
    for (const std::size_t e : reinforced_) {
      tau_[e] = (*this)[e];
      since_[e] = kEager;
    }
    reinforced_ = slots;
    target_ = 1.0 / length;
    for (const std::size_t e : reinforced_) since_[e] = updates_;
  }
  // One global update of every reinforced slot.
  void global_update() { ++updates_; }
  // Sets every slot from its current trail.
  template <class Change>
  void update_all(Change&& change) {
    for (std::size_t e = 0; e < tau_.size(); ++e) update(e, change);
  }
  std::size_t size() const { return tau_.size(); }

 private:
  static constexpr std::uint32_t kEager = UINT32_MAX;
  std::vector<double> tau_;
  std::vector<std::uint32_t> since_;  // updates_ when tau_[e] was last exact, or kEager
  std::vector<double> decay_;         // (1 - rho)^g
  std::vector<std::size_t> reinforced_;
  double rho_ = 0.0;
  double target_ = 0.0;
  std::uint32_t updates_ = 0;
};

}  // namespace aco::detail
