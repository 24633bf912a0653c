#include "local_search.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aco::detail {

LocalSearcher::LocalSearcher(const Space& space, const Candidates& candidates)
    : space_(space), cand_(candidates) {
  const std::size_t m = space.route_size();
  route_.reserve(m);
  pos_.assign(m, 0);
  queue_.reserve(m * 2);
  queued_.assign(m, 0);
  if (candidates.length.size() != candidates.list.size()) throw std::logic_error("LocalSearcher: candidate lists without their lengths");
}

void LocalSearcher::push(HoleIndex node) {
  if (node >= space_.holes() || queued_[node]) return;  // V is never a move's anchor
  queued_[node] = 1;
  queue_.push_back(node);
}

double LocalSearcher::two_opt_gain(std::size_t i, std::size_t j) const {
  // Removing edges at positions i and j and reversing i+1..j adds
  // (route[i], route[j]) and (route[i+1], route[j+1]), each read in array order.
  return cost_at(i) + cost_at(j) - space_.e(route_[i], route_[j]) - space_.e(route_[i + 1], route_[succ(j)]);
}

void LocalSearcher::reverse(std::size_t i, std::size_t j) {
  std::size_t l = i + 1, r = j;
  std::size_t inner = j - i;
  // The two holes are read once into locals: pos_ and route_ are both arrays
  // of 32-bit integers, so after a write to one the compiler read route_
  // again, twice a step.
  HoleIndex* const route = route_.data();
  std::uint32_t* const pos = pos_.data();
  auto swap_at = [route, pos](std::size_t x, std::size_t y) {
    const HoleIndex a = route[x], b = route[y];
    route[x] = b;
    route[y] = a;
    pos[b] = static_cast<std::uint32_t>(x);
    pos[a] = static_cast<std::uint32_t>(y);
  };
  // A closed tour has no fixed position: reversing the complement gives the
  // same cycle, and is cheaper when the inner part is longer than half.
  if (!space_.open() && !windowed_ && inner * 2 > m_) {
    std::size_t outer = m_ - inner;
    l = succ(j);
    r = i;
    for (std::size_t s = 0; s < outer / 2; ++s) {
      swap_at(l, r);
      l = succ(l);
      r = pred(r);
    }
    return;
  }
  while (l < r) {
    swap_at(l, r);
    ++l;
    --r;
  }
}

void LocalSearcher::apply_two_opt(std::size_t x, std::size_t y) {
  const std::size_t i = std::min(x, y), j = std::max(x, y);
  const HoleIndex a = route_[i], b = route_[i + 1], c = route_[j], d = route_[succ(j)];
  reverse(i, j);
  push(a);
  push(b);
  push(c);
  push(d);
}

bool LocalSearcher::try_two_opt(HoleIndex a) {
  const std::size_t pa = pos_[a];
  const HoleIndex* nbr = cand_.of(a);
  const double* nbr_length = cand_.lengths_of(a);
  for (int dir = 0; dir < 2; ++dir) {
    // dir 0 replaces (a, succ a); dir 1 replaces (pred a, a).
    const std::size_t edge_a = dir == 0 ? pa : pred(pa);
    const double d_a = cost_at(edge_a);
    for (int r = 0; r < cand_.k; ++r) {
      const HoleIndex c = nbr[r];
      const double g1 = d_a - nbr_length[r];
      // Sound pruning (neighbours are sorted): a gaining 2-opt move has a first
      // partial gain > 0 at one of its endpoints, where it is found instead.
      if (g1 <= kMinGain) break;
      const std::size_t pc = pos_[c];
      const std::size_t edge_c = dir == 0 ? pc : pred(pc);
      const std::size_t i = std::min(edge_a, edge_c), j = std::max(edge_a, edge_c);
      if (j <= i + 1) continue;  // adjacent or identical edges: no 2-opt move
      if (windowed_ && (!in_window(i) || !in_window(j + 1))) continue;
      const double gain = two_opt_gain(i, j);
      if (gain > kMinGain) {
        gain_ += gain;
        apply_two_opt(i, j);
        return true;
      }
    }
  }
  return false;
}

void LocalSearcher::reverse_path(HoleIndex a, HoleIndex b) {
  const std::size_t pa = pos_[a], pb = pos_[b];
  reverse(std::min(pa, pb) - 1, std::max(pa, pb));
}

void LocalSearcher::move_segment(std::size_t s, std::size_t len, std::size_t q, bool reversed) {
  // Moves route_[s..s+len-1] to sit between positions q and q+1 (q outside the segment).
  // The holes between (X) are shifted by len: O(|X|), and a hole's nearest
  // neighbours lie anywhere along a route. On a closed tour the move is also
  // three reversals, each of the shorter side: S -> S^r unless it goes in
  // reversed, then [S^r X] -> X^r S, X^r -> X; taken for far moves (kFarShift).
  const std::size_t x_len = q > s ? q + 1 - s - len : s - q - 1;
  const std::size_t whole = x_len + len;
  if (!space_.open() && !windowed_ && m_ >= 16 && whole >= far_shift_) {
    const std::size_t by_reversals = std::min(whole, m_ - whole) + std::min(x_len, m_ - x_len) + len;
    if (by_reversals < whole) {
      const HoleIndex x_first = q > s ? route_[s + len] : route_[q + 1];
      const HoleIndex x_last = q > s ? route_[q] : route_[s - 1];
      // S (at most 3 holes of 16 or more) is reversed in place; the stretch
      // S X (or X S) then starts after position 0, which try_or_opt never
      // moves, and after it X is one stretch after position 0, whichever side
      // was reversed.
      if (!reversed) reverse(s - 1, s + len - 1);
      if (q > s) {
        reverse(s - 1, q);
      } else {
        reverse(q, s + len - 1);
      }
      reverse_path(x_first, x_last);
      return;
    }
  }
  std::size_t lo, hi;
  if (q > s) {
    std::rotate(route_.begin() + s, route_.begin() + s + len, route_.begin() + q + 1);
    if (reversed) std::reverse(route_.begin() + (q + 1 - len), route_.begin() + q + 1);
    lo = s;
    hi = q;
  } else {
    std::rotate(route_.begin() + q + 1, route_.begin() + s, route_.begin() + s + len);
    if (reversed) std::reverse(route_.begin() + q + 1, route_.begin() + q + 1 + len);
    lo = q + 1;
    hi = s + len - 1;
  }
  for (std::size_t k = lo; k <= hi; ++k) pos_[route_[k]] = static_cast<std::uint32_t>(k);
}

bool LocalSearcher::try_or_opt(HoleIndex a) {
  const std::size_t pa = pos_[a];
  for (std::size_t len = 1; len <= 3; ++len) {
    for (int side = 0; side < 2; ++side) {
      // side 0: the segment starts at a; side 1: it ends at a.
      if (side == 1 && len == 1) continue;
      std::size_t s = side == 0 ? pa : pa + 1 - len;
      if (side == 1 && pa + 1 < len) continue;
      if (s == 0 || s + len > m_) continue;  // position 0 never moves; no wrap-around segments
      if (windowed_ && (!in_window(s - 1) || !in_window(s + len))) continue;
      if (len + 2 > m_) continue;
      const std::size_t last = s + len - 1;
      const HoleIndex f = route_[s], l = route_[last];
      const HoleIndex prev = route_[s - 1], next = route_[succ(last)];
      const double remove_gain = space_.e(prev, f) + space_.e(l, next) - space_.e(prev, next);
      if (remove_gain <= kMinGain) continue;
      for (int end = 0; end < 2; ++end) {
        const HoleIndex anchor = end == 0 ? f : l;
        const HoleIndex* nbr = cand_.of(anchor);
        const double* nbr_length = cand_.lengths_of(anchor);
        for (int r = 0; r < cand_.k; ++r) {
          const HoleIndex c = nbr[r];
          // Heuristic cut (sorted neighbours): an insertion next to c costs at
          // least about d(anchor, c), which must be paid from remove_gain.
          if (nbr_length[r] >= remove_gain) break;
          const std::size_t pc = pos_[c];
          if (pc >= s && pc <= last) continue;
          if (windowed_ && (!in_window(pc) || pc == 0 || pc + 1 >= hi_)) continue;
          // Two places next to c: between (c, succ c) and between (pred c, c).
          for (int place = 0; place < 2; ++place) {
            const std::size_t q = place == 0 ? pc : pred(pc);  // insert between q and q+1
            if (windowed_ && (q < lo_ || q + 1 > hi_)) continue;
            if (q + 1 == s || q == last || (q >= s && q <= last)) continue;
            const HoleIndex u = route_[q], w = route_[succ(q)];
            if (u == prev && w == f) continue;
            const double fwd = space_.e(u, f) + space_.e(l, w) - space_.e(u, w);
            const double rev = space_.e(u, l) + space_.e(f, w) - space_.e(u, w);
            const bool reversed = rev < fwd;
            const double add = reversed ? rev : fwd;
            if (remove_gain - add > kMinGain) {
              gain_ += remove_gain - add;
              move_segment(s, len, q, reversed);
              push(prev);
              push(next);
              push(f);
              push(l);
              push(u);
              push(w);
              return true;
            }
          }
        }
      }
    }
  }
  return false;
}

bool LocalSearcher::between(HoleIndex a, HoleIndex b, HoleIndex c, int dir) const {
  if (dir == 1) std::swap(a, c);
  return on_the_way(pos_[a], pos_[b], pos_[c]);
}

void LocalSearcher::flip(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) {
  // Read both edges forward: if b precedes a, the same flip is (b, a, d, c).
  if (route_[succ(pos_[a])] != b) {
    std::swap(a, b);
    std::swap(c, d);
  }
  const std::size_t p = pos_[a], q = pos_[c];
  // Edge p is (route[p], route[p+1]); reversing the positions after the
  // lower edge up to the higher one joins a to c and b to d either way.
  reverse(std::min(p, q), std::max(p, q));
}

std::size_t LocalSearcher::flip_length(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) const {
  if (route_[succ(pos_[a])] != b) {
    std::swap(a, b);
    std::swap(c, d);
  }
  const std::size_t p = pos_[a], q = pos_[c];
  const std::size_t inner = p < q ? q - p : p - q;
  return !space_.open() && !windowed_ ? std::min(inner, m_ - inner) : inner;
}

void LocalSearcher::make_flips(const KOptFlips& flips) {
  for (int f = 0; f < flips.count; ++f) {
    const FlipNodes& x = flips.flip[static_cast<std::size_t>(f)];
    flip(x[0], x[1], x[2], x[3]);
  }
}

void LocalSearcher::make_trial_flips() {
  for (int f = 0; f < trial_.flips(); ++f) {
    const auto& x = trial_.flip_at(f);
    flip(x[0], x[1], x[2], x[3]);
  }
}

void LocalSearcher::undo_array_flips() {
  // flip(a, c, b, d) undoes flip(a, b, c, d).
  for (auto f = flips_.rbegin(); f != flips_.rend(); ++f) flip((*f)[0], (*f)[2], (*f)[1], (*f)[3]);
}

void LocalSearcher::load(std::vector<HoleIndex>& route) {
  // Taken, not copied, and given back by unload(): two copies of the route
  // an ant, 0.4 MB each at 100 000 holes.
  route_.swap(route);
  for (std::size_t i = 0; i < m_; ++i) pos_[route_[i]] = static_cast<std::uint32_t>(i);
}

void LocalSearcher::improve(std::vector<HoleIndex>& route, Moves moves) {
  begin(route, moves);
  search(nullptr);
  end(route);
}

void LocalSearcher::begin(std::vector<HoleIndex>& route, Moves moves) {
  m_ = route.size();
  gain_ = 0.0;
  forgot_ = true;  // searched() tells of improve_from alone: windows here clear the queue
  interrupted_ = false;
  moves_ = moves;
  loaded_ = false;
  if (m_ < 4 || cand_.k == 0) return;
  load(route);
  loaded_ = true;
  std::fill(queued_.begin(), queued_.end(), 0);
  if (m_ <= kWindow) {
    windowed_ = false;
    lo_ = 0;
    hi_ = m_;
    queue_.clear();
    head_ = 0;
    for (std::size_t p = 0; p < m_; ++p) push(route_[p]);
  } else {
    // Windows overlap by half, so a move across one window's border lies
    // inside the next; each is searched until no move in it gains.
    windowed_ = true;
    open_window(0);
  }
}

void LocalSearcher::open_window(std::size_t lo) {
  lo_ = lo;
  hi_ = std::min(m_ - 1, lo + kWindow);
  queue_.clear();
  head_ = 0;
  for (std::size_t p = lo_; p <= hi_; ++p) push(route_[p]);
}

bool LocalSearcher::search(const std::function<bool()>& pause) {
  if (!loaded_) return true;
  const std::function<bool()>* asked = pause ? &pause : nullptr;
  while (true) {
    if (!run_queue(moves_, asked)) return false;
    if (interrupted_ || !windowed_ || hi_ == m_ - 1) return true;
    if (!(lo_ + kWindow / 2 + 2 < m_)) return true;
    open_window(lo_ + kWindow / 2);
  }
}

void LocalSearcher::end(std::vector<HoleIndex>& route) {
  if (!loaded_) return;
  unload(route);
  loaded_ = false;
}

void LocalSearcher::unload(std::vector<HoleIndex>& route) { route.swap(route_); }

void LocalSearcher::improve_from(std::vector<HoleIndex>& route, Moves moves, const std::vector<HoleIndex>& seeds) {
  begin_from(route, moves, seeds);
  search(nullptr);
  end(route);
}

void LocalSearcher::begin_from(std::vector<HoleIndex>& route, Moves moves, const std::vector<HoleIndex>& seeds) {
  m_ = route.size();
  gain_ = 0.0;
  forgot_ = true;  // searched() says nothing of a route it did not search
  interrupted_ = false;
  moves_ = moves;
  loaded_ = false;
  if (m_ < 4 || cand_.k == 0 || seeds.empty()) return;
  load(route);
  loaded_ = true;
  forgot_ = false;
  // Whole-route search: a focused ant makes few moves, so even at a million
  // holes the O(n) reversal of a few of them costs less than windows would.
  windowed_ = false;
  lo_ = 0;
  hi_ = m_;
  queue_.clear();
  head_ = 0;
  for (const HoleIndex seed : seeds) push(seed);
}

bool LocalSearcher::run_queue(Moves moves, const std::function<bool()>* pause) {
  while (head_ < queue_.size()) {
    if ((due_ || pause != nullptr) && (++since_asked_ & 63) == 0) {
      if (due_ && due_()) {
        // Stopped: the holes still queued are unqueued, unsearched.
        for (std::size_t k = head_; k < queue_.size(); ++k) queued_[queue_[k]] = 0;
        head_ = queue_.size();
        interrupted_ = true;
        forgot_ = true;
        return true;
      }
      if (pause != nullptr && (*pause)()) return false;  // the queue as it is, for the next slice
    }
    const HoleIndex a = queue_[head_++];
    queued_[a] = 0;
    if (windowed_ && !in_window(pos_[a])) continue;
    const double before = audit_ ? space_.route_cost(route_) : 0.0;
    bool moved = try_two_opt(a);
    if (!moved && moves != Moves::TwoOpt) moved = try_or_opt(a);
    if (!moved && moves == Moves::ThreeOpt && !windowed_) moved = try_three_opt(a);
    if (!moved && moves == Moves::FiveOpt && !windowed_) moved = m_ >= 8 ? try_five_opt(a) : try_three_opt(a);
    if (!moved && moves == Moves::FiveOpt && !windowed_ && non_sequential_) moved = try_bridge(a);
    if (audit_) {
      ++audited_searches_;
      const double after = space_.route_cost(route_);
      // A move must shorten the route; a search that found none must leave it as it was.
      if (moved ? !(after < before - kMinGain) : std::abs(after - before) > kMinGain) {
        ++failed_audits_;
        queue_.clear();  // a search whose moves lengthen the route may never end
        head_ = 0;
        forgot_ = true;
        return true;
      }
    }
    if (moved) push(a);
    // Keep the queue from growing without bound: compact once its dead head is large.
    if (head_ > 4096 && head_ * 2 > queue_.size()) {
      queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
      forgot_ = true;
    }
  }
  return true;
}

}  // namespace aco::detail
