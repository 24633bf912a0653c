#include "local_search.h"

#include <algorithm>

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
  // A closed tour has no fixed position: reversing the complement gives the
  // same cycle, and is cheaper when the inner part is longer than half.
  if (!space_.open() && !windowed_ && inner * 2 > m_) {
    std::size_t outer = m_ - inner;
    l = succ(j);
    r = i;
    for (std::size_t s = 0; s < outer / 2; ++s) {
      std::swap(route_[l], route_[r]);
      pos_[route_[l]] = l;
      pos_[route_[r]] = r;
      l = succ(l);
      r = pred(r);
    }
    return;
  }
  while (l < r) {
    std::swap(route_[l], route_[r]);
    pos_[route_[l]] = l;
    pos_[route_[r]] = r;
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
  for (int dir = 0; dir < 2; ++dir) {
    // dir 0 replaces (a, succ a); dir 1 replaces (pred a, a).
    const std::size_t edge_a = dir == 0 ? pa : pred(pa);
    const double d_a = cost_at(edge_a);
    for (int r = 0; r < cand_.k; ++r) {
      const HoleIndex c = nbr[r];
      const double g1 = d_a - space_.d(a, c);
      // Sound pruning (neighbours are sorted): a gaining 2-opt move has a first
      // partial gain > 0 at one of its endpoints, where it is found instead.
      if (g1 <= kEps) break;
      const std::size_t pc = pos_[c];
      const std::size_t edge_c = dir == 0 ? pc : pred(pc);
      const std::size_t i = std::min(edge_a, edge_c), j = std::max(edge_a, edge_c);
      if (j <= i + 1) continue;  // adjacent or identical edges: no 2-opt move
      if (windowed_ && (!in_window(i) || !in_window(j + 1))) continue;
      if (two_opt_gain(i, j) > kEps) {
        apply_two_opt(i, j);
        return true;
      }
    }
  }
  return false;
}

void LocalSearcher::move_segment(std::size_t s, std::size_t len, std::size_t q, bool reversed) {
  // Moves route_[s..s+len-1] to sit between positions q and q+1 (q outside the segment).
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
  for (std::size_t k = lo; k <= hi; ++k) pos_[route_[k]] = k;
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
        for (int r = 0; r < cand_.k; ++r) {
          const HoleIndex c = nbr[r];
          // Heuristic cut (sorted neighbours): an insertion next to c costs at
          // least about d(anchor, c), which must be paid from remove_gain.
          if (space_.d(anchor, c) >= remove_gain) break;
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

void LocalSearcher::load(const std::vector<HoleIndex>& route) {
  route_.assign(route.begin(), route.end());
  for (std::size_t i = 0; i < m_; ++i) pos_[route_[i]] = i;
}

void LocalSearcher::search_whole_route_from(const HoleIndex* first, const HoleIndex* last, bool or_opt) {
  windowed_ = false;
  lo_ = 0;
  hi_ = m_;
  queue_.clear();
  head_ = 0;
  for (const HoleIndex* node = first; node != last; ++node) push(*node);
  run_queue(or_opt);
}

void LocalSearcher::improve(std::vector<HoleIndex>& route, bool or_opt) {
  m_ = route.size();
  if (m_ < 4 || cand_.k == 0) return;
  load(route);
  std::fill(queued_.begin(), queued_.end(), 0);
  if (m_ <= kWindow) {
    search_whole_route_from(route_.data(), route_.data() + m_, or_opt);
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
      run_queue(or_opt);
      if (hi_ == m_ - 1) break;
    }
  }
  route.assign(route_.begin(), route_.end());
}

void LocalSearcher::improve_from(std::vector<HoleIndex>& route, bool or_opt, const std::vector<HoleIndex>& seeds) {
  m_ = route.size();
  if (m_ < 4 || cand_.k == 0 || seeds.empty()) return;
  load(route);
  // Whole-route search: a focused ant makes few moves, so even at a million
  // holes the O(n) reversal of a few of them costs less than windows would.
  search_whole_route_from(seeds.data(), seeds.data() + seeds.size(), or_opt);
  route.assign(route_.begin(), route_.end());
}

void LocalSearcher::run_queue(bool or_opt) {
  while (head_ < queue_.size()) {
    const HoleIndex a = queue_[head_++];
    queued_[a] = 0;
    if (windowed_ && !in_window(pos_[a])) continue;
    bool moved = try_two_opt(a);
    if (!moved && or_opt) moved = try_or_opt(a);
    if (moved) push(a);
    // Keep the queue from growing without bound: compact once its dead head is large.
    if (head_ > 4096 && head_ * 2 > queue_.size()) {
      queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
    }
  }
}

}  // namespace aco::detail
