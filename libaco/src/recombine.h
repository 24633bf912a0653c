#pragma once
// Recombining the ants of one iteration. A focused ant changes the reference
// route R in one small region, and on a large route the ants of an iteration
// improve R in different places: keeping only the best of them throws the
// other improvements away (at 100 000 holes nearly every ant improves R).
// Each improving ant is written as its exchange against R (the edges of R it
// removed, the edges it added); exchanges that touch disjoint holes are
// applied together where the result is still one cycle, as partition
// crossover does with the components two parents differ in (Whitley, Hains
// and Howe 2009).
#include <cstdint>
#include <utility>
#include <vector>

#include "space.h"

namespace aco::detail {

using Edge = std::pair<HoleIndex, HoleIndex>;

// A route as an exchange of edges against a reference cycle.
struct RouteDiff {
  std::vector<Edge> removed;  // edges of the reference the route lacks
  std::vector<Edge> added;    // edges of the route the reference lacks
  bool touches(HoleIndex node) const;
};

// `route`'s exchange against `ref` (a cycle over the same nodes, positions in
// `ref_pos`), in one pass over `route`.
void route_diff(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                const std::vector<HoleIndex>& route, RouteDiff& out);
// The same exchange, the same lists in the same order, looking only at the
// route's edges at the holes of `near`, which must hold an end of every edge
// of `route` that `ref` lacks (an ant's local search: every hole it was asked
// to look at or whose edges a move changed). `route_pos`: positions in
// `route`. O(|near| log |near|): at 100 000 holes the pass over the whole
// route took 2.4 % of a run's perf samples, this 0.1 %.
void route_diff(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                const std::vector<HoleIndex>& route, const std::vector<std::uint32_t>& route_pos,
                const std::vector<HoleIndex>& near, RouteDiff& out);

class DiffMerger {
 public:
  // Applies to `ref` the exchanges of `diffs`, taken in order: one is left
  // out when it touches a hole an earlier one touched, or when with the
  // earlier ones it would split the route into several cycles. Writes the
  // route that results to `out`, read from ref[0] on (so an open path's V
  // stays first) in the direction that keeps ref[0]'s successor `first_next`,
  // and returns how many exchanges it applied.
  std::size_t merge(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                    const std::vector<const RouteDiff*>& diffs, HoleIndex first_next, std::vector<HoleIndex>& out);
  // Which of the last merge's diffs it applied (their indices, in order).
  const std::vector<std::size_t>& applied() const { return applied_; }

 private:
  // Whether R minus `removed_` plus `added_` is one cycle; if so and `build`,
  // writes it to `out` from ref[0] on.
  bool one_cycle(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos);
  void build(const std::vector<HoleIndex>& ref, HoleIndex first_next, std::vector<HoleIndex>& out);

  std::vector<Edge> removed_, added_;
  std::vector<std::size_t> applied_;
  std::vector<std::uint32_t> mark_;  // by stamp: holes an applied exchange touched
  std::uint32_t stamp_ = 0;
  // one_cycle's working state: cut positions, segment ends and their links.
  std::vector<std::uint32_t> cuts_;
  std::vector<std::pair<HoleIndex, std::uint32_t>> slots_;  // (hole, slot), sorted
  std::vector<std::uint32_t> link_;
  std::vector<std::uint32_t> order_;  // slots in the order the cycle enters them
};

}  // namespace aco::detail
