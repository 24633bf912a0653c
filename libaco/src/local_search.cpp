#include "local_search.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aco::detail {

namespace {
// A move must gain more than this to be taken: rounding noise must not make
// two equal-length routes swap forever.
constexpr double kEps = 1e-9;
}  // namespace

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
      if (g1 <= kEps) break;
      const std::size_t pc = pos_[c];
      const std::size_t edge_c = dir == 0 ? pc : pred(pc);
      const std::size_t i = std::min(edge_a, edge_c), j = std::max(edge_a, edge_c);
      if (j <= i + 1) continue;  // adjacent or identical edges: no 2-opt move
      if (windowed_ && (!in_window(i) || !in_window(j + 1))) continue;
      const double gain = two_opt_gain(i, j);
      if (gain > kEps) {
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
      if (remove_gain <= kEps) continue;
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
            if (remove_gain - add > kEps) {
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

bool LocalSearcher::try_three_opt(HoleIndex t1) {
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  // The search goes deeper from the kDeepen best steps, one after the other
  // (LKH's breadth at its first levels). Measured from nearest-neighbour
  // routes on 7 TSPLIB drilling instances, summed gap and time of one
  // improve(), when the deeper steps were 2-opt steps: 1 step, depth 8:
  // 30.4 %, 0.16 s; 3 steps, depth 6: 26.5 %, 0.17 s; 3 steps, depth 20:
  // 26.4 %, 0.43 s.
  constexpr int kDeepen = 3;
  Step best[kDeepen];
  for (int dir = 0; dir < 2; ++dir) {
    const HoleIndex t2 = next(t1, dir);
    if (t2 == v) continue;
    ArrayTour tour{*this};
    if (three_opt_step(tour, t1, dir, space_.d(t1, t2), best, kDeepen, cand_.k)) return true;
  }
  for (int q = 0; q < kDeepen; ++q) {
    if (best[q].gain <= kEps) return false;
    if (deepen(t1, best[q])) return true;
  }
  return false;
}

template <class Tour>
bool LocalSearcher::three_opt_step(Tour& tour, HoleIndex t1, int dir, double gain, Step* best, int keep, int breadth) {
  // Names follow Lin & Kernighan: x1 = (t1,t2) out, y1 = (t2,t3) in,
  // x2 = (t3,t4) out, y2 = (t4,t5) in, x3 = (t5,t6) out, y3 = (t6,t1) in.
  // Gains are partial sums that must stay positive (the gain criterion);
  // `gain` is the first, x1's length, or deeper down what the steps before
  // gained with x1 taken out.
  // V, an open path's start and end, is never t1..t6: its edges cost
  // differently each way and are left to 2-opt and Or-opt, which read them in
  // array order.
  const HoleIndex v = space_.open() ? space_.virtual_node() : static_cast<HoleIndex>(-1);
  const HoleIndex t2 = tour.next(t1, dir);
  const HoleIndex* n2 = cand_.of(t2);
  const double* n2_length = cand_.lengths_of(t2);
  for (int r3 = 0; r3 < breadth; ++r3) {
    const HoleIndex t3 = n2[r3];
    const double g1 = gain - n2_length[r3];
    if (g1 <= kEps) break;
    if (t3 == t1 || t3 == tour.next(t2, dir)) continue;
    for (int stretch = 0; stretch < 2; ++stretch) {
      // stretch 0: t4 before t3, so closing up would be a 2-opt move, and a
      //   second flip follows; stretch 1: t4 after t3, so t2..t3 is cut out
      //   whole and must be put back between t5 and t6 inside it.
      const HoleIndex t4 = tour.next(t3, stretch == 0 ? 1 - dir : dir);
      if (t4 == v || t4 == t1 || t4 == t2) continue;
      const double g1x = g1 + space_.d(t3, t4);
      const HoleIndex* n4 = cand_.of(t4);
      const double* n4_length = cand_.lengths_of(t4);
      for (int r5 = 0; r5 < breadth; ++r5) {
        const HoleIndex t5 = n4[r5];
        const double g2 = g1x - n4_length[r5];
        if (g2 <= kEps) break;
        if (t5 == t3 || t5 == t1) continue;
        if (stretch == 0) {
          // After the first flip the route reads t1 t4 ... t2 t3 ...; t6
          // must precede t5 in that reading: t5's old successor inside the
          // turned stretch t2..t4, its old predecessor outside it.
          const bool inside = tour.between(t2, t5, t4, dir);
          if (t5 == tour.next(t4, 1 - dir) && inside) continue;  // t5 is t4's new neighbour
          const HoleIndex t6 = tour.next(t5, inside ? dir : 1 - dir);
          if (t6 == v) continue;
          const double g3 = g2 + space_.d(t5, t6);
          if (g3 - space_.d(t6, t1) > kEps) {
            gain_ += g3 - space_.d(t6, t1);
            tour.flip(t1, t2, t4, t3);
            tour.flip(t1, t4, t6, t5);
            for (HoleIndex t : {t1, t2, t3, t4, t5, t6}) push(t);
            return true;
          }
          if (g3 > best[keep - 1].gain) {
            int q = keep - 1;
            while (q > 0 && best[q - 1].gain < g3) {
              best[q] = best[q - 1];
              --q;
            }
            best[q] = {g3, {t2, t3, t4, t5, t6}};
          }
        } else {
          if (!tour.between(t2, t5, t3, dir)) continue;
          for (int side = 0; side < 2; ++side) {
            // side 0: t6 after t5, the stretch goes back as it was (in two
            // pieces swapped); side 1: t6 before t5, both pieces turned.
            if (side == 0 && t5 == t3) continue;
            if (side == 1 && t5 == t2) continue;
            const HoleIndex t6 = tour.next(t5, side == 0 ? dir : 1 - dir);
            if (t6 == v) continue;
            const double total = g2 + space_.d(t5, t6) - space_.d(t6, t1);
            if (total <= kEps) continue;
            gain_ += total;
            if (side == 0) {
              tour.flip(t1, t2, t5, t6);
              tour.flip(t1, t5, t3, t4);
              tour.flip(t1, t3, t6, t2);
            } else {
              tour.flip(t1, t2, t6, t5);
              tour.flip(t2, t5, t3, t4);
            }
            for (HoleIndex t : {t1, t2, t3, t4, t5, t6}) push(t);
            return true;
          }
        }
      }
    }
  }
  return false;
}

bool LocalSearcher::deepen(HoleIndex t1, Step step) {
  // Lin-Kernighan's deeper steps, each a whole sequential 3-opt step as LKH
  // chains its basis moves (Helsgaun 2000): the step is made, then edge
  // (t1, t6) is taken out again and the best 3-opt step from t6 searched,
  // closing with (t_last, t1), until one closes with a gain or kDeepSteps
  // were searched in vain; then every flip is undone. A trial flip is made
  // on the array while it is short; from the first long one on (more than
  // kArrayFlip positions), the chain goes on in trial_, over the array as it
  // then is, and only a chain that closes with a gain is made on the array,
  // flip by flip in the same order: the same route as making and undoing
  // every flip on the array gives, but a long flip in vain costs nothing.
  flips_.clear();
  bool overlaid = false;
  auto length = [&](HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) {
    return overlaid ? trial_.flip_length(a, b, c, d) : flip_length(a, b, c, d);
  };
  auto make = [&](HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d, std::size_t positions) {
    if (!overlaid && positions > array_flip_) {
      trial_.reset(route_.data(), pos_.data(), m_, !space_.open() && !windowed_);
      overlaid = true;
    }
    if (overlaid) {
      trial_.flip(a, b, c, d);
    } else {
      flip(a, b, c, d);
      flips_.push_back({a, b, c, d});
    }
  };
  for (int searched = 0; searched < kDeepSteps; ++searched) {
    const HoleIndex(&t)[5] = step.t;  // t2..t6
    const std::size_t first = length(t1, t[0], t[2], t[1]);
    if (first > deepen_reach()) break;
    make(t1, t[0], t[2], t[1], first);
    const std::size_t second = length(t1, t[2], t[4], t[3]);
    if (second > deepen_reach()) break;
    make(t1, t[2], t[4], t[3], second);
    const int dir = (overlaid ? trial_.next(t1, 0) : next(t1, 0)) == t[4] ? 0 : 1;  // t6 is now t1's neighbour
    const int trial_flips = overlaid ? trial_.flips() : 0;
    Step deeper;
    const int breadth = std::min(kDeepBreadth, cand_.k);
    ArrayTour tour{*this};
    if (overlaid ? three_opt_step(trial_, t1, dir, step.gain, &deeper, 1, breadth)
                 : three_opt_step(tour, t1, dir, step.gain, &deeper, 1, breadth)) {
      if (overlaid) {
        for (int f = 0; f < trial_.flips(); ++f) {
          const auto& x = trial_.flip_at(f);
          flip(x[0], x[1], x[2], x[3]);
        }
      }
      for (const auto& f : flips_) {
        for (HoleIndex x : f) push(x);
      }
      for (int f = 0; f < trial_flips; ++f) {
        for (HoleIndex x : trial_.flip_at(f)) push(x);
      }
      return true;
    }
    if (deeper.gain <= kEps) break;
    step = deeper;
  }
  // Nothing closed with a gain: trial_ is dropped, the array's flips undone
  // (flip(a, c, b, d) undoes flip(a, b, c, d)).
  for (auto f = flips_.rbegin(); f != flips_.rend(); ++f) flip((*f)[0], (*f)[2], (*f)[1], (*f)[3]);
  return false;
}

void LocalSearcher::load(std::vector<HoleIndex>& route) {
  // Taken, not copied, and given back by unload(): two copies of the route
  // an ant, 0.4 MB each at 100 000 holes.
  route_.swap(route);
  for (std::size_t i = 0; i < m_; ++i) pos_[route_[i]] = static_cast<std::uint32_t>(i);
}

void LocalSearcher::search_whole_route_from(const HoleIndex* first, const HoleIndex* last, Moves moves) {
  windowed_ = false;
  lo_ = 0;
  hi_ = m_;
  queue_.clear();
  head_ = 0;
  for (const HoleIndex* node = first; node != last; ++node) push(*node);
  run_queue(moves);
}

void LocalSearcher::improve(std::vector<HoleIndex>& route, Moves moves) {
  m_ = route.size();
  gain_ = 0.0;
  forgot_ = true;  // searched() tells of improve_from alone: windows here clear the queue
  if (m_ < 4 || cand_.k == 0) return;
  load(route);
  std::fill(queued_.begin(), queued_.end(), 0);
  if (m_ <= kWindow) {
    search_whole_route_from(route_.data(), route_.data() + m_, moves);
  } else {
    // Windows overlap by half, so a move across one window's border lies
    // inside the next; each is searched until no move in it gains.
    windowed_ = true;
    for (std::size_t lo = 0; lo + 2 < m_; lo += kWindow / 2) {
      lo_ = lo;
      hi_ = std::min(m_ - 1, lo + kWindow);
      queue_.clear();
      head_ = 0;
      for (std::size_t p = lo_; p <= hi_; ++p) push(route_[p]);
      run_queue(moves);
      if (hi_ == m_ - 1) break;
    }
  }
  unload(route);
}

void LocalSearcher::unload(std::vector<HoleIndex>& route) { route.swap(route_); }

void LocalSearcher::improve_from(std::vector<HoleIndex>& route, Moves moves, const std::vector<HoleIndex>& seeds) {
  m_ = route.size();
  gain_ = 0.0;
  forgot_ = true;  // searched() says nothing of a route it did not search
  if (m_ < 4 || cand_.k == 0 || seeds.empty()) return;
  load(route);
  forgot_ = false;
  // Whole-route search: a focused ant makes few moves, so even at a million
  // holes the O(n) reversal of a few of them costs less than windows would.
  search_whole_route_from(seeds.data(), seeds.data() + seeds.size(), moves);
  unload(route);
}

void LocalSearcher::run_queue(Moves moves) {
  while (head_ < queue_.size()) {
    const HoleIndex a = queue_[head_++];
    queued_[a] = 0;
    if (windowed_ && !in_window(pos_[a])) continue;
    const double before = audit_ ? space_.route_cost(route_) : 0.0;
    bool moved = try_two_opt(a);
    if (!moved && moves != Moves::TwoOpt) moved = try_or_opt(a);
    if (!moved && moves == Moves::ThreeOpt && !windowed_) moved = try_three_opt(a);
    if (!moved && moves == Moves::FiveOpt && !windowed_) moved = m_ >= 8 ? try_five_opt(a) : try_three_opt(a);
    if (audit_) {
      ++audited_searches_;
      const double after = space_.route_cost(route_);
      // A move must shorten the route; a search that found none must leave it as it was.
      if (moved ? !(after < before - kEps) : std::abs(after - before) > kEps) {
        ++failed_audits_;
        queue_.clear();  // a search whose moves lengthen the route may never end
        head_ = 0;
        forgot_ = true;
        return;
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
}

}  // namespace aco::detail
