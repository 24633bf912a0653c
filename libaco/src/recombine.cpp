#include "recombine.h"

#include <algorithm>
#include <iterator>

#include "colony.h"

namespace aco::detail {

namespace {
Edge ordered(HoleIndex a, HoleIndex b) { return a < b ? Edge{a, b} : Edge{b, a}; }
}  // namespace

bool RouteDiff::touches(HoleIndex node) const {
  for (const Edge& e : removed) {
    if (e.first == node || e.second == node) return true;
  }
  return false;
}

namespace {
// Whether (a, b) is an edge of the cycle whose positions are `pos`.
bool adjacent(const std::vector<std::uint32_t>& pos, HoleIndex a, HoleIndex b) {
  const std::uint32_t pa = pos[a], pb = pos[b];
  const std::size_t d = pa > pb ? pa - pb : pb - pa;
  return d == 1 || d == pos.size() - 1;
}

// The exchange, given the positions in `route` (ascending) of its edges that
// `ref` lacks: edge i runs from route[i] to route[i + 1].
void diff_from_added(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                     const std::vector<HoleIndex>& route, const std::vector<std::size_t>& added_at, RouteDiff& out) {
  out.removed.clear();
  out.added.clear();
  const std::size_t m = route.size();
  if (m < 4) return;
  // The holes at a new edge, with their two neighbours on the route: an edge
  // of R at such a hole is removed unless it is one of those two.
  struct Touched {
    HoleIndex hole, prev, next;
  };
  std::vector<Touched> touched;
  for (const std::size_t i : added_at) {
    const HoleIndex a = route[i], b = route[i + 1 == m ? 0 : i + 1];
    out.added.push_back(ordered(a, b));
    touched.push_back({a, route[(i + m - 1) % m], b});
    touched.push_back({b, a, route[(i + 2) % m]});
  }
  std::sort(touched.begin(), touched.end(), [](const Touched& x, const Touched& y) { return x.hole < y.hole; });
  touched.erase(std::unique(touched.begin(), touched.end(),
                            [](const Touched& x, const Touched& y) { return x.hole == y.hole; }),
                touched.end());
  for (const Touched& t : touched) {
    const std::uint32_t p = ref_pos[t.hole];
    for (const HoleIndex y : {ref[(p + 1) % m], ref[(p + m - 1) % m]}) {
      if (y != t.prev && y != t.next) out.removed.push_back(ordered(t.hole, y));
    }
  }
  std::sort(out.removed.begin(), out.removed.end());
  out.removed.erase(std::unique(out.removed.begin(), out.removed.end()), out.removed.end());
}
}  // namespace

void route_diff(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                const std::vector<HoleIndex>& route, RouteDiff& out) {
  const std::size_t m = route.size();
  std::vector<std::size_t> added_at;
  for (std::size_t i = 0; i < m; ++i) {
    if (!adjacent(ref_pos, route[i], route[i + 1 == m ? 0 : i + 1])) added_at.push_back(i);
  }
  diff_from_added(ref, ref_pos, route, added_at, out);
}

void route_diff(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                const std::vector<HoleIndex>& route, const std::vector<std::uint32_t>& route_pos,
                const std::vector<HoleIndex>& near, RouteDiff& out) {
  const std::size_t m = route.size();
  // A new edge has an end in `near`: it is one of the two edges at that end.
  std::vector<std::size_t> added_at;
  for (const HoleIndex h : near) {
    const std::size_t p = route_pos[h];
    for (const std::size_t i : {p, (p + m - 1) % m}) {
      if (!adjacent(ref_pos, route[i], route[i + 1 == m ? 0 : i + 1])) added_at.push_back(i);
    }
  }
  std::sort(added_at.begin(), added_at.end());
  added_at.erase(std::unique(added_at.begin(), added_at.end()), added_at.end());
  diff_from_added(ref, ref_pos, route, added_at, out);
}

std::size_t DiffMerger::merge(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos,
                              const std::vector<const RouteDiff*>& diffs, HoleIndex first_next,
                              std::vector<HoleIndex>& out) {
  const std::size_t m = ref.size();
  if (mark_.size() != m) {
    mark_.assign(m, 0);
    stamp_ = 0;
  }
  if (++stamp_ == 0) {
    std::fill(mark_.begin(), mark_.end(), 0);
    stamp_ = 1;
  }
  removed_.clear();
  added_.clear();
  applied_.clear();
  bool current = true;  // whether one_cycle's state (order_) is that of the exchanges applied
  for (std::size_t i = 0; i < diffs.size(); ++i) {
    const RouteDiff* d = diffs[i];
    if (d->removed.empty() || d->removed.size() != d->added.size()) continue;
    bool disjoint = true;
    for (const auto* edges : {&d->removed, &d->added}) {
      for (const Edge& e : *edges) disjoint = disjoint && mark_[e.first] != stamp_ && mark_[e.second] != stamp_;
    }
    if (!disjoint) continue;
    const std::size_t removed_before = removed_.size(), added_before = added_.size();
    removed_.insert(removed_.end(), d->removed.begin(), d->removed.end());
    added_.insert(added_.end(), d->added.begin(), d->added.end());
    current = one_cycle(ref, ref_pos);
    if (!current) {
      removed_.resize(removed_before);
      added_.resize(added_before);
      continue;
    }
    for (const Edge& e : d->removed) mark_[e.first] = mark_[e.second] = stamp_;
    applied_.push_back(i);
  }
  if (!applied_.empty()) {
    if (!current) one_cycle(ref, ref_pos);  // the last one tried was left out
    build(ref, first_next, out);
  }
  return applied_.size();
}

bool DiffMerger::one_cycle(const std::vector<HoleIndex>& ref, const std::vector<std::uint32_t>& ref_pos) {
  const std::uint32_t m = static_cast<std::uint32_t>(ref.size());
  // Each removed edge (ref[c], ref[c + 1]) is a cut after position c; the
  // cuts split R into segments, segment j running from after cut j to cut j + 1.
  cuts_.clear();
  for (const auto& [u, v] : removed_) {
    const std::uint32_t pu = ref_pos[u], pv = ref_pos[v];
    if ((pu + 1) % m == pv) cuts_.push_back(pu);
    else if ((pv + 1) % m == pu) cuts_.push_back(pv);
    else return false;  // not an edge of R
  }
  std::sort(cuts_.begin(), cuts_.end());
  if (std::adjacent_find(cuts_.begin(), cuts_.end()) != cuts_.end()) return false;
  const std::uint32_t r = static_cast<std::uint32_t>(cuts_.size());
  if (r < 2 || added_.size() != r) return false;
  // Slot 2j is segment j's head, 2j + 1 its tail (the same hole when it has one).
  slots_.clear();
  for (std::uint32_t j = 0; j < r; ++j) {
    slots_.push_back({ref[(cuts_[j] + 1) % m], 2 * j});
    slots_.push_back({ref[cuts_[(j + 1) % r]], 2 * j + 1});
  }
  std::sort(slots_.begin(), slots_.end());
  link_.assign(2 * r, UINT32_MAX);
  auto take = [&](HoleIndex hole) {
    auto it = std::lower_bound(slots_.begin(), slots_.end(), std::pair<HoleIndex, std::uint32_t>{hole, 0});
    for (; it != slots_.end() && it->first == hole; ++it) {
      if (link_[it->second] == UINT32_MAX) return it->second;
    }
    return UINT32_MAX;
  };
  for (const auto& [a, b] : added_) {
    const std::uint32_t sa = take(a);
    if (sa == UINT32_MAX) return false;
    link_[sa] = sa;  // held, so b cannot take the same slot
    const std::uint32_t sb = take(b);
    if (sb == UINT32_MAX) return false;
    link_[sa] = sb;
    link_[sb] = sa;
  }
  // Walk: enter a segment at one end, leave at the other, follow the new edge.
  order_.clear();
  std::uint32_t s = 0;
  do {
    order_.push_back(s);
    s = link_[s ^ 1];
    if (s == UINT32_MAX || order_.size() > r) return false;
  } while (s != 0);
  return order_.size() == r;
}

void DiffMerger::build(const std::vector<HoleIndex>& ref, HoleIndex first_next, std::vector<HoleIndex>& out) {
  const std::uint32_t m = static_cast<std::uint32_t>(ref.size());
  const std::uint32_t r = static_cast<std::uint32_t>(cuts_.size());
  out.clear();
  out.reserve(m);
  for (const std::uint32_t s : order_) {
    const std::uint32_t j = s / 2, from = (cuts_[j] + 1) % m, to = cuts_[(j + 1) % r];
    // Positions from..to, cyclically: one run, or two where it wraps.
    const auto at = [&](std::uint32_t p) { return ref.begin() + static_cast<long>(p); };
    if (s % 2 == 0) {
      if (from <= to) {
        out.insert(out.end(), at(from), at(to + 1));
      } else {
        out.insert(out.end(), at(from), ref.end());
        out.insert(out.end(), ref.begin(), at(to + 1));
      }
    } else {
      if (from <= to) {
        out.insert(out.end(), std::make_reverse_iterator(at(to + 1)), std::make_reverse_iterator(at(from)));
      } else {
        out.insert(out.end(), std::make_reverse_iterator(at(to + 1)), ref.rend());
        out.insert(out.end(), ref.rbegin(), std::make_reverse_iterator(at(from)));
      }
    }
  }
  // From ref[0] on, with first_next after it where that is its neighbour.
  std::rotate(out.begin(), std::find(out.begin(), out.end(), ref[0]), out.end());
  if (m > 2 && out[1] != first_next && out[m - 1] == first_next) std::reverse(out.begin() + 1, out.end());
}

// The focused colony's round: every ant that improved the reference left its
// route as an exchange of edges against it (route_diff); the best ant's
// exchange and the others' that touch other holes are applied together
// (DiffMerger), their gains added, when that beats the best ant alone.
void Colony::merge_improvements(int ib, const std::vector<HoleIndex>*& ib_route, double& ib_len) {
  // The other ants' improvements elsewhere on the route, added to the best's.
  run_.improving.clear();
  for (int k = 0; k < p_.ants; ++k) {
    if (run_.work[k].improves) run_.improving.push_back(k);
  }
  std::sort(run_.improving.begin(), run_.improving.end(), [&](int a, int b) {
    return run_.work[a].length < run_.work[b].length || (run_.work[a].length == run_.work[b].length && a < b);
  });
  // An open path's V keeps the successor it has in R, or in the best ant's
  // route if that ant changed it; no other ant may change it.
  const HoleIndex v = ref_route_[0];
  const bool best_moves_v = space_.open() && run_.work[ib].diff.touches(v);
  run_.diffs.clear();
  run_.diff_ants.clear();
  for (int k : run_.improving) {
    if (k == ib || !space_.open() || !run_.work[k].diff.touches(v)) {
      run_.diffs.push_back(&run_.work[k].diff);
      run_.diff_ants.push_back(k);
    }
  }
  if (run_.diffs.size() >= 2 &&
      run_.merger.merge(ref_route_, ref_pos_, run_.diffs, best_moves_v ? (*ib_route)[1] : ref_route_[1], run_.merged) >= 2) {
    // The exchanges touch disjoint holes, so their gains add up.
    double merged_len = ref_len_;
    for (std::size_t d : run_.merger.applied()) merged_len += run_.work[run_.diff_ants[d]].length - ref_len_;
    if (merged_len < ib_len - 1e-9) {
      ib_route = &run_.merged;
      ib_len = merged_len;
    }
  }
}

}  // namespace aco::detail
