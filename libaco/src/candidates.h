#pragma once
// Nearest-neighbour candidate lists: for each hole its k nearest other holes,
// nearest first. Built with a k-d tree (nanoflann) in O(n k log n), never an
// n² scan, so 100 000 holes take well under a second.
#include <memory>
#include <utility>
#include <vector>

#include "space.h"

namespace aco::detail {

class Team;  // parallel.h

// The stages of the lists, each in its file: nearest.cpp (k nearest, joined
// where they fall apart), spanning_forest.h and alpha_nearness.cpp (the ascent
// and alpha-nearness).

// Candidate rows a worker takes at a time: small enough that a worker that
// comes late, or is put aside, holds up little.
constexpr std::size_t kRowChunk = 64;

struct Candidates {
  int k = 0;
  std::vector<HoleIndex> list;  // n * k, row i = the k nearest holes of i
  // Beside each entry of `list`, its distance from the row's hole (Space::d,
  // the same bits). The local search reads it where it walks a row: with the
  // distance computed there each time, the same routes took 10-14 % longer
  // (brd14051, d15112, pcb3038, pla7397). Every builder below fills it.
  std::vector<double> length;
  // Filled by alpha_candidates only, when asked: the ascent's penalties, and the same rows
  // sorted by the costs they give, c(i, j) = d(i, j) + pi[i] + pi[j], with
  // those costs beside them. LKH's 5-opt step pays its gains in these
  // (five_opt.cpp): a whole tour's cost only moves by 2 sum(pi), but a
  // partial gain that stays positive says more of where a tour goes.
  std::vector<double> pi;
  std::vector<HoleIndex> pi_list;
  std::vector<double> pi_length;

  const HoleIndex* of(HoleIndex i) const { return list.data() + static_cast<std::size_t>(i) * k; }
  const double* lengths_of(HoleIndex i) const { return length.data() + static_cast<std::size_t>(i) * k; }
  bool has_pi() const { return !pi.empty(); }
  // The rows the 5-opt step and the non-sequential moves read: sorted by
  // penalised cost, those costs beside them, where kept; else `list` and `length`.
  const HoleIndex* search_row(HoleIndex i) const {
    return has_pi() ? pi_list.data() + static_cast<std::size_t>(i) * k : of(i);
  }
  const double* search_costs(HoleIndex i) const {
    return has_pi() ? pi_length.data() + static_cast<std::size_t>(i) * k : lengths_of(i);
  }
};

// threads: how many workers fill the rows (each row alone, so any count gives
// the same lists); or the solve's team. So too below.
Candidates build_candidates(const Space& space, int k, int threads = 1);
Candidates build_candidates(const Space& space, int k, Team& team);

// build_candidates in pieces, so that a slice of a large run ends on time
// (issue 84: at 10^6 holes the rows took over a second in the browser, and
// a Stop waited for them): the tree is built at construction, then `fill`
// fills up to `rows` more rows; the lists are the same however it is cut.
// `space` must outlive it.
class NearestRows {
 public:
  NearestRows(const Space& space, int k);
  ~NearestRows();
  NearestRows(NearestRows&&) noexcept;
  NearestRows& operator=(NearestRows&&) noexcept;
  // True once every row is filled.
  bool fill(Team& team, std::size_t rows);
  // The lists, once fill() has said true.
  Candidates take();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// How far (in rings of the bucket grid, about 1.4 mean hole spacings each)
// the quadrant search looks: far enough to join the clusters of fl1400 and
// brd14051, and bounded so that a hole with an empty quadrant (every hole of
// a diagonal line has two) costs at most 65² cells, not the whole grid.
constexpr int kQuadrantRings = 32;

// `nearest` (sorted by distance, k >= 4) with each row's last places given to
// the hole's nearest neighbour in each of the four quadrants around it where
// that is not already in the row. The k nearest of holes in a cluster are all
// in the cluster; the quadrant neighbours link clusters, so a minimum spanning
// tree over these rows is one tree, not a forest (Yao graph with four cones).
Candidates with_quadrant_neighbours(const Space& space, Candidates nearest);

// The k nearest of each hole, joined by with_quadrant_neighbours only where
// they fall apart into several pieces (fl1400, d1655, brd14051): where they
// are one piece, the quadrant neighbours changed the lists of pla7397 for the
// worse (30 s, 3 seeds: 0.257 0.196 0.248 % with them, 0.154 0.202 0.159 % without).
Candidates joined_nearest(const Space& space, int k, int threads = 1);
Candidates joined_nearest(const Space& space, int k, Team& team);

// Every edge between a hole and one of its candidates, once, as (a, b) with
// a < b, in that order: an edge in only one of its ends' lists counts too.
std::vector<std::pair<HoleIndex, HoleIndex>> candidate_edges(const Candidates& candidates, HoleIndex holes);

// For each hole, the k holes of `nearest`'s row with the smallest
// alpha-nearness (Helsgaun 2000, LKH's candidates): alpha(i, j) = c(i, j)
// minus the longest edge on the path from i to j in a minimum spanning tree,
// i.e. how much longer the tree must get to hold edge (i, j), with costs
// c(i, j) = d(i, j) + pi[i] + pi[j] from `ascent_iterations` steps of Held and
// Karp's subgradient ascent, which make the tree look like a tour. Ties keep
// the nearer hole first; each row is then sorted by distance, which the local
// search's pruning needs. Where the neighbour graph falls apart into several
// trees, an edge between two of them has alpha 0. Memory O(n k + n log n).
// `nearest`'s lengths are not read (the caller may drop them first).
// `threads` workers grow each step's tree (one part of the holes each, then
// joined) and fill the rows; any count gives the same lists. With
// `penalised_rows` it keeps pi and the rows sorted by penalised cost, which
// only the 5-opt step reads (6 MB at 100 000 holes).
Candidates alpha_candidates(const Space& space, const Candidates& nearest, int k, int ascent_iterations, int threads = 1,
                            bool penalised_rows = true);
Candidates alpha_candidates(const Space& space, const Candidates& nearest, int k, int ascent_iterations, Team& team,
                            bool penalised_rows);

// alpha_candidates() in pieces (issue 84: at 2 * 10^5 holes of one tool the
// lists took 2-3 s of a page's slice, which a Stop waited for): each step()
// is the graph, one step of the ascent, the tree, its lifting table, or
// `rows` rows; true once the lists are whole. Any cut gives the same lists.
class AlphaLists {
 public:
  AlphaLists(const Space& space, Candidates nearest, int k, int ascent_iterations, bool penalised_rows);
  ~AlphaLists();
  bool step(Team& team, std::size_t rows);
  Candidates take();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// joined_nearest() of the nearest lists made by NearestRows: joined by the
// quadrant neighbours where they fall apart.
Candidates joined(const Space& space, Candidates nearest);

}  // namespace aco::detail
