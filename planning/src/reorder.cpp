#include "planning/reorder.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "formats/holes.h"

namespace planning {

namespace {

// Groups of mutually overlapping holes (centres closer than `spacing`, or at
// the same place) among `members`, by a grid of that size; returns a group
// number per member (0: alone).
std::vector<std::uint32_t> overlap_groups(const aco::HoleSet& holes, const std::vector<aco::HoleIndex>& members,
                                          double spacing, std::uint32_t& next_group) {
  const std::size_t n = members.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  const double cell = std::max(spacing, 1e-6);
  std::map<std::pair<long long, long long>, std::vector<std::size_t>> grid;
  auto key = [&](aco::Point2 p) { return std::make_pair(std::llround(std::floor(p.x / cell)), std::llround(std::floor(p.y / cell))); };
  for (std::size_t i = 0; i < n; ++i) {
    const aco::Point2 p = holes[members[i]].center;
    const auto [cx, cy] = key(p);
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = grid.find({cx + dx, cy + dy});
        if (it == grid.end()) continue;
        for (std::size_t j : it->second) {
          const double d = aco::euclidean(p, holes[members[j]].center);
          if (d < spacing - 1e-9 || d <= 1e-9) parent[find(i)] = find(j);
        }
      }
    }
    grid[{cx, cy}].push_back(i);
  }
  std::map<std::size_t, std::size_t> size;
  for (std::size_t i = 0; i < n; ++i) ++size[find(i)];
  std::map<std::size_t, std::uint32_t> number;
  std::vector<std::uint32_t> out(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t root = find(i);
    if (size[root] < 2) continue;
    auto [it, fresh] = number.emplace(root, next_group);
    if (fresh) ++next_group;
    out[i] = it->second;
  }
  return out;
}

// The tool a run's time is estimated with: its first hole's cycle.
gcode::Tool estimate_tool(const gcode::ToolRun& run) {
  gcode::Tool t;
  t.number = std::max(run.tool, 0);
  t.diameter_mm = run.diameter_mm.value_or(0.0);
  t.spindle_rpm = static_cast<int>(run.spindle_rpm);
  const gcode::HoleCycle& c = run.holes.front().cycle;
  t.depth_mm = c.bottom_mm();
  t.feed_mm_min = c.feed_mm_min;
  if (c.code == 0) {
    for (const gcode::ZMove& m : c.moves) {
      if (m.kind == gcode::ZMove::Feed) {
        t.feed_mm_min = m.feed_mm_min;
        break;
      }
    }
  }
  if (!(t.feed_mm_min > 0)) t.feed_mm_min = 250.0;  // a program without F: the control's default, unknown here
  if ((c.code == 83 || c.code == 73) && c.q_mm && *c.q_mm > 0) {
    t.cycle = c.code == 83 ? gcode::Cycle::G83 : gcode::Cycle::G73;
    t.peck_mm = *c.q_mm;
  }
  return t;
}

}  // namespace

ReorderResult reorder_program(const gcode::DrillingProgram& input, const PlanOptions& options, const ReorderOptions& reorder) {
  ReorderResult r;
  r.program = input;
  r.holes = formats::program_holes(input);
  std::uint32_t next_group = 1;
  aco::HoleIndex next = 0;  // the runs' holes follow each other in r.holes
  for (const gcode::ToolRun& run : input.runs) {
    if (run.holes.empty()) continue;
    ToolGroup g;
    g.tool = estimate_tool(run);
    for (std::size_t i = 0; i < run.holes.size(); ++i) g.input_order.push_back(next++);
    const double spacing = std::max(reorder.min_spacing_mm, run.diameter_mm.value_or(0.0));
    const std::vector<std::uint32_t> groups = overlap_groups(r.holes, g.input_order, spacing, next_group);
    for (std::size_t i = 0; i < groups.size(); ++i) {
      r.holes[g.input_order[i]].chain = groups[i];
      if (groups[i]) ++r.overlapping_holes;
    }
    r.plan.groups.push_back(std::move(g));
  }
  r.overlap_groups = next_group - 1;
  PlanOptions o = options;
  // The program ends where the input ended: over its last hole, or at its park position.
  o.return_at_end = input.end.has_value();
  o.finish = input.end;
  order_groups(r.holes, r.plan, o);
  // Never longer than the input: where the colony's order is (tiny runs, a
  // start the input chose well), the input's own order stands.
  if (r.plan.optimized.travel_mm > r.plan.input_order.travel_mm) {
    for (ToolGroup& g : r.plan.groups) g.optimized = g.input_order;
    r.plan.optimized = r.plan.input_order;
  }
  // The runs in their new order; runs without holes stay as they were.
  std::size_t group = 0;
  for (std::size_t k = 0; k < input.runs.size(); ++k) {
    if (input.runs[k].holes.empty()) continue;
    const ToolGroup& g = r.plan.groups[group++];
    const aco::HoleIndex base = g.input_order.front();
    std::vector<gcode::ProgramHole> ordered;
    ordered.reserve(g.optimized.size());
    for (aco::HoleIndex h : g.optimized) ordered.push_back(input.runs[k].holes[h - base]);
    r.program.runs[k].holes = std::move(ordered);
  }
  return r;
}

}  // namespace planning
