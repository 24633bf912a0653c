#pragma once
// An array route as a few flips would leave it, without making them: the
// route is read through a list of pieces of the array, each read forwards or
// backwards, and a flip only cuts and turns pieces. deepen()'s trial flips
// go here from the first that would rewrite many positions on (kArrayFlip in
// local_search.h); only a chain that closes with a gain is made on the
// array. On an array a flip costs up to half the route: at 100 000 holes
// the trial flips, made and undone, were half of every position the search
// rewrote (counted at 265117f), though there deepen() tries only those of up
// to 1000 positions.
//
// A flip here costs the pieces it touches (at most 2 + 2 per flip before
// it); a look-up scans the pieces, so it is for a handful of flips, not a
// route's worth.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "aco/problem.h"

namespace aco::detail {

// Whether position pb lies on the way from pa forward to pc, around a cycle.
inline bool on_the_way(std::size_t pa, std::size_t pb, std::size_t pc) {
  return pa <= pc ? (pa <= pb && pb <= pc) : (pb >= pa || pb <= pc);
}

class FlipOverlay {
 public:
  static constexpr int kMaxFlips = 20;

  // Reads `route` (m holes) and `pos` (each hole's place in it) as they are
  // now; they must not change while this is in use. `shortest_side`: a
  // flip's length counts the shorter side (a closed tour searched whole, as
  // LocalSearcher::flip_length counts it).
  void reset(const HoleIndex* route, const std::uint32_t* pos, std::size_t m, bool shortest_side) {
    route_ = route;
    pos_ = pos;
    m_ = m;
    shortest_side_ = shortest_side;
    piece_[0] = {0, static_cast<std::uint32_t>(m - 1), 0, false};
    pieces_ = 1;
    flips_ = 0;
  }

  // Where x stands in the route as flipped (position 0 never moves).
  std::size_t position(HoleIndex x) const {
    const std::uint32_t p = pos_[x];
    const Piece& s = piece_[piece_of(p)];
    return s.at + (s.reversed ? s.last - p : p - s.first);
  }
  // As LocalSearcher::next: x's successor (dir 0) or predecessor.
  HoleIndex next(HoleIndex x, int dir) const {
    const std::uint32_t p = pos_[x];
    const int i = piece_of(p);
    const Piece& s = piece_[static_cast<std::size_t>(i)];
    const bool up = (dir == 0) != s.reversed;  // which way along the array
    if (up ? p < s.last : p > s.first) return route_[up ? p + 1 : p - 1];
    const int j = dir == 0 ? (i + 1 == pieces_ ? 0 : i + 1) : (i == 0 ? pieces_ - 1 : i - 1);
    const Piece& t = piece_[static_cast<std::size_t>(j)];
    return route_[(dir == 0) != t.reversed ? t.first : t.last];  // t's first hole that way
  }
  // As LocalSearcher::between: whether b lies on the way from a to c.
  bool between(HoleIndex a, HoleIndex b, HoleIndex c, int dir) const {
    if (dir == 1) std::swap(a, c);
    return on_the_way(position(a), position(b), position(c));
  }
  // As LocalSearcher::flip: removes {a, b} and {c, d} (b after a, d after c,
  // the same way round), adds {a, c} and {b, d}; and keeps it in flips().
  void flip(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) {
    if (flips_ == kMaxFlips) throw std::logic_error("FlipOverlay: more flips than it holds");
    log_[static_cast<std::size_t>(flips_++)] = {a, b, c, d};
    const auto [p, q] = edges_at(a, b, c, d);
    reverse(std::min(p, q) + 1, std::max(p, q));
  }
  // As LocalSearcher::flip_length.
  std::size_t flip_length(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) const {
    const auto [p, q] = edges_at(a, b, c, d);
    const std::size_t inner = p < q ? q - p : p - q;
    return shortest_side_ ? std::min(inner, m_ - inner) : inner;
  }
  int flips() const { return flips_; }
  std::size_t size() const { return m_; }
  const std::array<HoleIndex, 4>& flip_at(int i) const { return log_[static_cast<std::size_t>(i)]; }

 private:
  // Array positions first..last, read from route position `at` on,
  // backwards if reversed; piece_ holds them in route order. (Found from a
  // hole's array position by a scan: a branch-free count over them sorted
  // by array position measured no faster, pla7397 over 20 000 iterations.)
  struct Piece {
    std::uint32_t first, last, at;
    bool reversed;
  };
  std::size_t succ(std::size_t v) const { return v + 1 == m_ ? 0 : v + 1; }
  // Where flip(a, b, c, d)'s two edges start, read forwards: the positions
  // of a and c, or of b and d if b comes first.
  std::pair<std::size_t, std::size_t> edges_at(HoleIndex a, HoleIndex b, HoleIndex c, HoleIndex d) const {
    const std::size_t pa = position(a);
    if (position(b) == succ(pa)) return {pa, position(c)};
    return {position(b), position(d)};
  }
  int piece_of(std::uint32_t p) const {
    int i = 0;
    while (p < piece_[static_cast<std::size_t>(i)].first || p > piece_[static_cast<std::size_t>(i)].last) ++i;
    return i;
  }
  // Makes a piece start at route position v (0 < v < m); returns its index.
  int cut(std::size_t v) {
    int i = pieces_ - 1;
    while (piece_[i].at > v) --i;
    const Piece s = piece_[i];
    if (s.at == v) return i;
    const auto k = static_cast<std::uint32_t>(v - s.at);
    const auto vv = static_cast<std::uint32_t>(v);
    std::copy_backward(piece_.begin() + i + 1, piece_.begin() + pieces_, piece_.begin() + pieces_ + 1);
    ++pieces_;
    if (!s.reversed) {
      piece_[i] = {s.first, s.first + k - 1, s.at, false};
      piece_[i + 1] = {s.first + k, s.last, vv, false};
    } else {
      piece_[i] = {s.last - k + 1, s.last, s.at, true};
      piece_[i + 1] = {s.first, s.last - k, vv, true};
    }
    return i + 1;
  }
  // Turns route positions l..r around (0 < l <= r < m).
  void reverse(std::size_t l, std::size_t r) {
    const int i = cut(l);
    const int j = r + 1 < m_ ? cut(r + 1) : pieces_;  // pieces i..j-1 hold l..r
    std::reverse(piece_.begin() + i, piece_.begin() + j);
    auto at = static_cast<std::uint32_t>(l);
    for (int q = i; q < j; ++q) {
      piece_[q].reversed = !piece_[q].reversed;
      piece_[q].at = at;
      at += piece_[q].last - piece_[q].first + 1;
    }
  }

  const HoleIndex* route_ = nullptr;
  const std::uint32_t* pos_ = nullptr;
  std::size_t m_ = 0;
  bool shortest_side_ = false;
  std::array<Piece, 2 * kMaxFlips + 1> piece_{};  // a flip cuts at most two
  int pieces_ = 0;
  std::array<std::array<HoleIndex, 4>, kMaxFlips> log_{};
  int flips_ = 0;
};

}  // namespace aco::detail
