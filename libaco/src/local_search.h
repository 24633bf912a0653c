#pragma once
// 2-opt and Or-opt on an array route with neighbour lists and don't-look bits
// (Bentley 1992; Johnson & McGeoch 1997, "The TSP: a case study in local
// optimization"). The route is a cycle over Space::route_size() nodes whose
// position 0 never moves, so an open path's virtual node V keeps its place and
// its direction-dependent edges stay right.
#include <vector>

#include "candidates.h"
#include "space.h"

namespace aco::detail {

// Aligned to a cache line: one searcher per ant, and ants run on different threads.
class alignas(64) LocalSearcher {
 public:
  LocalSearcher(const Space& space, const Candidates& candidates);

  // Improves `route` in place until no move gains.
  // `or_opt` adds segment moves of 1 to 3 holes to the 2-opt moves.
  // Routes longer than kWindow are improved in overlapping windows of
  // kWindow positions: an array 2-opt move reverses up to half the route, so
  // on a million holes whole-route search is quadratic; windows keep every
  // move's cost bounded and the pass linear.
  void improve(std::vector<HoleIndex>& route, bool or_opt);
  // The same, looking only where something changed: the queue starts with
  // `seeds` (the ends of an ant's new edges) and grows only where moves are
  // made, so the search costs what the ant changed, plus O(n) to load the route.
  void improve_from(std::vector<HoleIndex>& route, bool or_opt, const std::vector<HoleIndex>& seeds);
  static constexpr std::size_t kWindow = 100000;

 private:
  void load(const std::vector<HoleIndex>& route);  // route_ and pos_ from `route` (m_ set)
  void search_whole_route_from(const HoleIndex* first, const HoleIndex* last, bool or_opt);
  void run_queue(bool or_opt);
  bool in_window(std::size_t position) const { return position >= lo_ && position <= hi_; }
  bool try_two_opt(HoleIndex a);
  bool try_or_opt(HoleIndex a);
  void reverse(std::size_t i, std::size_t j);  // reverse positions i+1..j
  void move_segment(std::size_t s, std::size_t len, std::size_t q, bool reversed);
  void push(HoleIndex node);
  std::size_t succ(std::size_t i) const { return i + 1 == m_ ? 0 : i + 1; }
  std::size_t pred(std::size_t i) const { return i == 0 ? m_ - 1 : i - 1; }
  double cost_at(std::size_t i) const { return space_.e(route_[i], route_[succ(i)]); }
  double two_opt_gain(std::size_t i, std::size_t j) const;
  void apply_two_opt(std::size_t x, std::size_t y);

  const Space& space_;
  const Candidates& cand_;
  std::vector<HoleIndex> route_;
  std::vector<std::size_t> pos_;
  std::vector<HoleIndex> queue_;
  std::vector<char> queued_;
  std::size_t head_ = 0;
  std::size_t m_ = 0;
  std::size_t lo_ = 0, hi_ = 0;  // positions a move may touch
  bool windowed_ = false;
};

}  // namespace aco::detail
