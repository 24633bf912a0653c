#include "planning/plan.h"

#include <algorithm>
#include <optional>
#include <numeric>
#include <set>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "aco/baselines.h"
#include "json.h"

namespace planning {

namespace {

std::string fmt3(double v) { return gcode::format_number(v, 3); }

}  // namespace

RouteStats route_stats(const aco::HoleSet& holes, const std::vector<ToolGroup>& groups,
                       const std::vector<const aco::Order*>& orders, const PlanOptions& options) {
  RouteStats st;
  const Machine& m = options.machine;
  // The travel: start -> every hole of every tool -> the finish, as the crow flies.
  aco::Point2 at = m.start;
  std::size_t drilled = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (aco::HoleIndex h : *orders[g]) {
      st.travel_mm += aco::euclidean(at, holes[h].center);
      at = holes[h].center;
      if (!groups[g].tool.end_mill) ++drilled;
    }
  }
  if (options.return_at_end) st.travel_mm += aco::euclidean(at, options.finish.value_or(m.start));
  // The time: the program these orders make, as the control runs it.
  gcode::ProgramSettings ps = options.program;
  ps.header_comments.clear();
  ps.home = options.finish.value_or(m.start);
  ps.resume_from = 1;
  std::ostringstream program;
  gcode::write_program(program, passes_of(holes, groups, orders, m), ps);
  const gcode::ProgramTime t = gcode::time_program(program.str(), kinematics_of(m, ps.dialect));
  TimeSplit& split = st.split;
  split.moves_s = t.moves_s;
  // A machine with a fixed hit time (a PCB drilling machine's own cycle) drills each hole in it.
  split.drilling_s = m.hit_s > 0 ? static_cast<double>(drilled) * m.hit_s : t.drilling_s;
  split.tool_changes_s = static_cast<double>(t.tool_changes) * m.tool_change_s + t.probe_s;
  split.pauses_s = t.spindle_wait_s;
  st.time_s = split.total();
  // Each tool's share: its change and what follows it up to the next (the return home in the last).
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const double after = g + 1 < t.per_tool_s.size() ? t.per_tool_s[g + 1] : 0.0;
    st.tool_time_s.push_back(orders[g]->empty() ? 0.0 : m.tool_change_s + after);
  }
  return st;
}

namespace {

// A tool group's holes as the solver sees them: one point per stop, where a
// stop is a single hole or a whole chain. Without chains, stop i is hole i.
struct RouteUnits {
  std::vector<aco::Point2> points;
  std::vector<std::size_t> begin;  // stop k drills members[begin[k] .. begin[k+1])
  aco::Order members;              // hole indices grouped by stop, chains in their own order

  aco::Order expand(const aco::Order& stops) const {
    aco::Order out;
    out.reserve(members.size());
    for (aco::HoleIndex k : stops) out.insert(out.end(), members.begin() + static_cast<long>(begin[k]),
                                              members.begin() + static_cast<long>(begin[k + 1]));
    return out;
  }
};

RouteUnits route_units(const aco::HoleSet& holes, const aco::Order& input_order) {
  RouteUnits u;
  u.points.reserve(input_order.size());
  u.begin.reserve(input_order.size() + 1);
  const bool chains = std::any_of(input_order.begin(), input_order.end(), [&](aco::HoleIndex h) { return holes[h].chain != 0; });
  if (!chains) {
    for (aco::HoleIndex h : input_order) u.points.push_back(holes[h].center);
    u.members = input_order;
    for (std::size_t i = 0; i <= input_order.size(); ++i) u.begin.push_back(i);
    return u;
  }
  // Stops in the order of their first hole; a chain's holes keep their order.
  std::map<std::uint32_t, std::size_t> stop_of_chain;
  std::vector<aco::Order> stops;
  for (aco::HoleIndex h : input_order) {
    const std::uint32_t c = holes[h].chain;
    if (c == 0) {
      stops.push_back({h});
      continue;
    }
    auto [it, fresh] = stop_of_chain.emplace(c, stops.size());
    if (fresh) stops.emplace_back();
    stops[it->second].push_back(h);
  }
  for (const aco::Order& stop : stops) {
    u.begin.push_back(u.members.size());
    aco::Point2 centroid{0, 0};
    for (aco::HoleIndex h : stop) {
      centroid.x += holes[h].center.x;
      centroid.y += holes[h].center.y;
      u.members.push_back(h);
    }
    u.points.push_back({centroid.x / static_cast<double>(stop.size()), centroid.y / static_cast<double>(stop.size())});
  }
  u.begin.push_back(u.members.size());
  return u;
}

}  // namespace

namespace {

// The travel and time of each variant (input order, nearest neighbour,
// optimized) of the groups as they are; `input_order`: false when it is
// counted already.
void count_variants(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options, bool input_order = true) {
  std::vector<const aco::Order*> in, nn, opt;
  for (const ToolGroup& g : result.groups) {
    in.push_back(&g.input_order);
    nn.push_back(&g.nearest_neighbor);
    opt.push_back(&g.optimized);
  }
  if (input_order) result.input_order = route_stats(holes, result.groups, in, options);
  result.nearest_neighbor = route_stats(holes, result.groups, nn, options);
  // The same orders are the same program: not written and timed twice (the
  // first routes alone, when the page's time limit leaves the colony out).
  const bool same = std::all_of(result.groups.begin(), result.groups.end(),
                                [](const ToolGroup& g) { return g.optimized == g.nearest_neighbor; });
  result.optimized = same ? result.nearest_neighbor : route_stats(holes, result.groups, opt, options);
}

}  // namespace

void split_worn_drills(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options) {
  const bool any = std::any_of(result.groups.begin(), result.groups.end(), [](const ToolGroup& g) {
    return g.tool.max_hits > 0 && g.optimized.size() > static_cast<std::size_t>(g.tool.max_hits);
  });
  if (!any) return;
  int next_number = 0;
  for (const ToolGroup& g : result.groups) next_number = std::max(next_number, g.tool.number);
  std::vector<ToolGroup> split;
  for (ToolGroup& g : result.groups) {
    const std::size_t life = g.tool.max_hits > 0 ? static_cast<std::size_t>(g.tool.max_hits) : g.optimized.size();
    if (g.optimized.size() <= life) {
      split.push_back(std::move(g));
      continue;
    }
    // The same cut in every variant, so that each is timed with the same changes.
    auto chunk = [&](const aco::Order& order, std::size_t k) {
      const std::size_t from = std::min(order.size(), k * life), to = std::min(order.size(), (k + 1) * life);
      return aco::Order(order.begin() + static_cast<long>(from), order.begin() + static_cast<long>(to));
    };
    const std::size_t runs = (g.optimized.size() + life - 1) / life;
    for (std::size_t k = 0; k < runs; ++k) {
      ToolGroup part;
      part.tool = g.tool;
      if (k > 0) {
        part.tool.number = ++next_number;
        part.tool.name = gcode::tool_name(g.tool) + " SISTER OF T" + std::to_string(g.tool.number);
      }
      part.input_order = chunk(g.input_order, k);
      part.nearest_neighbor = chunk(g.nearest_neighbor, k);
      part.optimized = chunk(g.optimized, k);
      part.solution = g.solution;
      split.push_back(std::move(part));
    }
  }
  if (next_number > 200) {
    throw UserError("the drills' lives (max_hits) need tool numbers up to T" + std::to_string(next_number) +
                    "; a control has T1..T200: give longer lives or split the job");
  }
  result.groups = std::move(split);
  count_variants(holes, result, options);
}

struct GroupRouter::Group {
  aco::Problem problem;
  RouteUnits units;
  aco::Order prefix;
  aco::ColonyRun run;
};

GroupRouter::GroupRouter(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options)
  : holes_(holes), result_(result), options_(options), at_(options.machine.start), at_nn_(options.machine.start) {
  result_.solver = aco::resolve(options.solver, holes.size());
}

GroupRouter::~GroupRouter() = default;

void GroupRouter::begin_group() {
  const Machine& m = options_.machine;
  ToolGroup& group = result_.groups[next_];
  const bool last = next_ + 1 == result_.groups.size();
  // Each tool's holes as an open path from where the previous tool ended; the
  // last one ends at the start position, so the return home is optimised too.
  aco::Problem p;
  p.metric = options_.objective == Objective::Time && !m.linear_rapids ? aco::Metric::Chebyshev : aco::Metric::Euclidean;
  p.shape = aco::Shape::OpenPath;
  p.start = at_;
  if (last && options_.return_at_end) p.end = options_.finish.value_or(m.start);
  // The route's stops: a hole, or a chain (a drilled slot's holes) drilled
  // together in its own order, stopping at the chain's centroid.
  // Holes drilled first as they are (alignment pins); the colony routes the rest from the last of them.
  aco::Order prefix(group.input_order.begin(), group.input_order.begin() + static_cast<long>(group.fixed_prefix));
  if (!prefix.empty()) p.start = holes_[prefix.back()].center;
  RouteUnits units = route_units(holes_, aco::Order(group.input_order.begin() + static_cast<long>(group.fixed_prefix),
                                                    group.input_order.end()));
  p.points = units.points;
  // --time-limit bounds the whole run: each tool gets its share by hole count.
  aco::Params params = options_.solver;
  if (params.time_limit_s > 0) {
    params.time_limit_s = std::max(0.01, options_.solver.time_limit_s * static_cast<double>(group.input_order.size()) /
                                             static_cast<double>(holes_.size()));
  }
  aco::ColonyRun run(p, params);
  current_ = std::make_unique<Group>(Group{std::move(p), std::move(units), std::move(prefix), std::move(run)});
}

void GroupRouter::end_group() {
  ToolGroup& group = result_.groups[next_];
  Group& c = *current_;
  auto with_prefix = [&](aco::Order rest) {
    rest.insert(rest.begin(), c.prefix.begin(), c.prefix.end());
    return rest;
  };
  if (c.problem.points.empty()) {
    group.optimized = group.nearest_neighbor = c.prefix;
  } else {
    aco::Problem pnn = c.problem;
    if (c.prefix.empty()) pnn.start = at_nn_;
    const bool same_start = pnn.start.x == c.problem.start.x && pnn.start.y == c.problem.start.y;
    std::optional<aco::Order> nn;
    if (stopped_ && !c.run.begun() && !c.run.ended()) {
      // Stopped before this tool began: its nearest-neighbour route, without
      // the colony's set-up (candidate lists and a first search: seconds at
      // 10^5 holes, which a Stop must not wait for; issue 84).
      group.solution.order = aco::nearest_neighbor(c.problem);
      group.solution.length = aco::route_length(c.problem, group.solution.order);
      group.solution.algorithm = options_.solver.algorithm;
      group.solution.stop_reason = stop_reason_;
      // The baseline from the same start is the same route: 0.6 s at 10^6 holes.
      if (same_start) nn = group.solution.order;
    } else {
      group.solution = c.run.finish();
    }
    group.optimized = with_prefix(c.units.expand(group.solution.order));
    if (!nn) nn = aco::nearest_neighbor(pnn);
    group.nearest_neighbor = with_prefix(c.units.expand(*nn));
  }
  at_ = holes_[group.optimized.back()].center;
  at_nn_ = holes_[group.nearest_neighbor.back()].center;
  result_.iterations += group.solution.iterations;
  result_.solver_wall_s += group.solution.wall_s;
  if (result_.thread_busy_s.size() < group.solution.thread_busy_s.size()) {
    result_.thread_busy_s.resize(group.solution.thread_busy_s.size(), 0.0);
  }
  for (std::size_t k = 0; k < group.solution.thread_busy_s.size(); ++k) {
    result_.thread_busy_s[k] += group.solution.thread_busy_s[k];
  }
  current_.reset();
  ++next_;
}

bool GroupRouter::advance(int max_iterations, double max_seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  int left = max_iterations;
  while (next_ < result_.groups.size()) {
    if (!current_) begin_group();
    aco::ColonyRun& run = current_->run;
    if (!current_->problem.points.empty()) {
      const int before = run.iterations();
      const double time_left = max_seconds > 0.0 ? std::max(1e-9, max_seconds - seconds()) : 0.0;
      if (!run.advance(max_iterations > 0 ? left : 0, time_left)) return false;
      left -= run.iterations() - before;
    }
    end_group();
    if (max_iterations > 0 && left <= 0 && next_ < result_.groups.size()) return false;
    if (max_seconds > 0.0 && seconds() >= max_seconds && next_ < result_.groups.size()) return false;
  }
  if (!counted_) {
    count_variants(holes_, result_, options_, !input_counted_);
    counted_ = true;
  }
  return true;
}

void GroupRouter::count_input_order() {
  std::vector<const aco::Order*> in;
  for (const ToolGroup& g : result_.groups) in.push_back(&g.input_order);
  result_.input_order = route_stats(holes_, result_.groups, in, options_);
  input_counted_ = true;
}

void GroupRouter::stop(const std::string& reason) {
  if (stopped_) return;
  stopped_ = true;
  stop_reason_ = reason;
  // The group under way keeps its best so far; those after it, their first route.
  while (next_ < result_.groups.size()) {
    if (!current_) begin_group();
    end_group();
  }
  advance(0, 0.0);
}

std::vector<aco::Order> GroupRouter::orders_so_far() const {
  std::vector<aco::Order> out;
  for (std::size_t g = 0; g < result_.groups.size(); ++g) {
    const ToolGroup& group = result_.groups[g];
    if (g < next_) {
      out.push_back(group.optimized);
    } else if (g == next_ && current_ && !current_->problem.points.empty() && current_->run.iterations() > 0) {
      aco::Order o = current_->units.expand(current_->run.best_order());
      o.insert(o.begin(), current_->prefix.begin(), current_->prefix.end());
      out.push_back(std::move(o));
    } else {
      out.push_back(group.input_order);
    }
  }
  return out;
}

int GroupRouter::group_iterations() const { return current_ ? current_->run.params().iterations : 0; }

std::size_t GroupRouter::group() const { return std::min(next_, result_.groups.size()); }
void order_groups(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options) {
  GroupRouter(holes, result, options).advance();
}

PlanResult plan_job(const aco::HoleSet& holes, const PlanOptions& options, const std::string& source) {
  PlanResult result = group_holes(holes, options, source);
  order_groups(holes, result, options);
  settle_plan(holes, result, options);
  return result;
}

namespace {

// Issue 82: a tool for each operation the holes name, in the order a hole's
// operations come (the kinds' order, then the diameter): spot drills before
// the table's own tools, the others after. `renumber`: the table is
// generated, so its tools are numbered 1.. in that order; else (the user's
// table) the new tools are numbered on from its largest number. Returns how
// many tools went before the table's own.
int add_operation_tools(ToolTable& table, std::vector<std::uint32_t> operations, const PlanOptions& options, bool renumber) {
  std::sort(operations.begin(), operations.end());
  operations.erase(std::unique(operations.begin(), operations.end()), operations.end());
  if (operations.empty()) return 0;
  std::stable_sort(operations.begin(), operations.end(), [&](std::uint32_t a, std::uint32_t b) {
    const OperationSpec& x = options.operations.at(a - 1);
    const OperationSpec& y = options.operations.at(b - 1);
    return std::tie(x.kind, x.diameter_mm) < std::tie(y.kind, y.diameter_mm);
  });
  int number = 0;
  for (const ToolTableEntry& e : table.entries) number = std::max(number, e.tool.number);
  std::vector<ToolTableEntry> before, after;
  for (std::uint32_t k : operations) {
    ToolTableEntry e;
    e.tool = operation_tool(options.operations.at(k - 1), options.material, options.machine);
    e.tool.number = ++number;
    e.operation = k;
    e.min_hole_mm = e.max_hole_mm = e.tool.diameter_mm;
    (e.tool.operation < gcode::Operation::Drill ? before : after).push_back(e);
  }
  table.entries.insert(table.entries.begin(), before.begin(), before.end());
  table.entries.insert(table.entries.end(), after.begin(), after.end());
  if (renumber) {
    for (std::size_t t = 0; t < table.entries.size(); ++t) table.entries[t].tool.number = static_cast<int>(t) + 1;
  }
  return static_cast<int>(before.size());
}

}  // namespace

PlanResult group_holes(const aco::HoleSet& holes, const PlanOptions& options, const std::string& source) {
  const Machine& m = options.machine;
  // A hole without a diameter would become a "0.000 MM DRILL": the user says
  // which drill (--default-diameter), or a tool table has a tool that takes it.
  const bool table_takes_zero =
      options.tools && std::any_of(options.tools->entries.begin(), options.tools->entries.end(),
                                   [](const ToolTableEntry& e) { return e.min_hole_mm <= 1e-9; });
  for (const aco::Hole& h : holes) {
    if (!(h.diameter > 0) && !table_takes_zero) {
      throw UserError(source, h.source_line,
                      "hole without a diameter; give one with --default-diameter MM, or a --tools table "
                      "with a tool whose min_hole_mm is 0");
    }
  }
  check_travel(holes, m, source);
  for (const aco::Hole& h : holes) {
    for (const Machine::Rect& r : m.clamps) {
      if (h.center.x >= r.x_min && h.center.x <= r.x_max && h.center.y >= r.y_min && h.center.y <= r.y_max) {
        throw UserError(source, h.source_line, "hole at (" + fmt3(h.center.x) + ", " + fmt3(h.center.y) +
                                                   ") lies under a clamp of the machine profile");
      }
    }
  }

  ToolTable table;
  PlanResult result;
  std::map<std::uint32_t, std::size_t> op_entry;  // operation k -> the table entry that makes it (not apart)
  const bool apart = options.keep_sources_apart && !options.hole_source.empty();
  if (options.tooling.owned() && options.tools) {
    throw UserError(source, 0, "--drills and --end-mill plan the tools you own; a --tools table names its own, drop one of them");
  }
  // The tools of some holes: the owned ones that make the drilled holes, or
  // one generated drill per diameter; then a tool for each operation
  // (issue 82), in the order a hole's operations come.
  auto tools_for = [&](const aco::HoleSet& some) {
    aco::HoleSet drilled;
    std::vector<std::uint32_t> operations;
    for (const aco::Hole& h : some) {
      if (h.operation == 0) drilled.push_back(h);
      else operations.push_back(h.operation);
    }
    ToolTable t;
    std::vector<DrillMapping> mapping;
    if (!options.tooling.owned()) {
      t = generate_tool_table(drilled, options.material, options.thickness_mm, m);
    } else {
      t = owned_tool_table(drilled, options.tooling, options.material, options.thickness_mm, m, source, mapping);
    }
    // Spot drills first: the drills' numbers move on by as many.
    const int spots = add_operation_tools(t, operations, options, true);
    for (DrillMapping& d : mapping) d.tool += spots;
    result.drill_map.insert(result.drill_map.end(), mapping.begin(), mapping.end());
    return t;
  };
  if (apart) {
    if (options.tools) throw UserError(source, 0, "keeping inputs apart generates each input's tools; drop --tools");
    // Each input's tools, numbered on from the previous input's.
    const std::uint32_t sources = *std::max_element(options.hole_source.begin(), options.hole_source.end()) + 1;
    for (std::uint32_t k = 0; k < sources; ++k) {
      aco::HoleSet mine;
      for (std::size_t i = 0; i < holes.size(); ++i) {
        if (options.hole_source[i] == k) mine.push_back(holes[i]);
      }
      if (mine.empty()) continue;
      const std::size_t mapped = result.drill_map.size();
      ToolTable part = tools_for(mine);
      // This input's tools 1..n become first + 1..first + n.
      const int first = static_cast<int>(table.entries.size());
      for (std::size_t q = mapped; q < result.drill_map.size(); ++q) result.drill_map[q].tool += first;
      for (ToolTableEntry& e : part.entries) {
        e.tool.number = static_cast<int>(table.entries.size()) + 1;
        e.source = static_cast<int>(k);
        table.entries.push_back(e);
      }
    }
    table.generated = true;
  } else if (options.tools) {
    table = *options.tools;
    complete_tool_table(table, options.material, options.thickness_mm, m);
    // Issue 82: an operation is made by the table's tool of its kind and
    // diameter (a tap of its pitch, where the entry gives one), completed
    // from the operation's defaults; one the table has no tool for gets a
    // generated one, numbered on from the table's.
    std::set<std::uint32_t> used;
    for (const aco::Hole& h : holes) {
      if (h.operation != 0) used.insert(h.operation);
    }
    std::vector<std::uint32_t> generated;
    std::map<std::size_t, std::uint32_t> completed_for;  // table entry -> the operation it was completed from
    for (std::uint32_t k : used) {
      const OperationSpec& spec = options.operations.at(k - 1);
      std::size_t found = table.entries.size();
      for (std::size_t t = 0; t < table.entries.size() && found == table.entries.size(); ++t) {
        const ToolTableEntry& e = table.entries[t];
        if (e.tool.operation != spec.kind || e.operation != 0 || !e.takes(spec.diameter_mm)) continue;
        if (spec.kind == gcode::Operation::Tap && e.tool.pitch_mm > 0 && std::fabs(e.tool.pitch_mm - spec.pitch_mm) > 1e-6) continue;
        if (spec.kind == gcode::Operation::Tap && e.has_cycle && (e.tool.cycle == gcode::Cycle::G74) != spec.left_hand) continue;
        found = t;
      }
      if (found == table.entries.size()) {
        generated.push_back(k);
        continue;
      }
      ToolTableEntry& e = table.entries[found];
      const gcode::Tool d = operation_tool(spec, options.material, m);
      auto [first, fresh] = completed_for.emplace(found, k);
      if (!fresh && !e.has_depth && std::fabs(options.operations.at(first->second - 1).depth_mm - spec.depth_mm) > 1e-9) {
        throw UserError(source, 0, "tool T" + std::to_string(e.tool.number) + " (" + gcode::to_string(spec.kind) +
                                       ") would make holes of two depths: give it \"depth_mm\", or each depth a tool of its own");
      }
      if (fresh) {
        if (!e.has_rpm) e.tool.spindle_rpm = d.spindle_rpm;
        if (!e.has_feed || spec.kind == gcode::Operation::Tap) e.tool.feed_mm_min = spec.pitch_mm > 0 ? spec.pitch_mm * e.tool.spindle_rpm : d.feed_mm_min;
        if (!e.has_depth) e.tool.depth_mm = d.depth_mm;
        if (!e.has_cycle) e.tool.cycle = d.cycle, e.tool.dwell_s = d.dwell_s;
        if (e.tool.pitch_mm == 0) e.tool.pitch_mm = spec.pitch_mm;
        if (e.tool.angle_deg == 0) e.tool.angle_deg = spec.angle_deg;
        if (e.tool.thread.empty()) e.tool.thread = spec.thread;
        e.tool.spindle_synchronized = d.spindle_synchronized;
      }
      op_entry[k] = found;
    }
    add_operation_tools(table, generated, options, false);
    for (std::size_t t = 0; t < table.entries.size(); ++t) {
      if (table.entries[t].operation != 0) op_entry[table.entries[t].operation] = t;
    }
    // Made in the order a hole's operations come, whatever order the table lists them in.
    std::vector<std::size_t> order(table.entries.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return table.entries[a].tool.operation < table.entries[b].tool.operation;
    });
    std::vector<std::size_t> moved_to(order.size());
    ToolTable sorted = table;
    for (std::size_t q = 0; q < order.size(); ++q) sorted.entries[q] = table.entries[order[q]], moved_to[order[q]] = q;
    table = std::move(sorted);
    for (auto& [k, t] : op_entry) t = moved_to[t];
  } else {
    table = tools_for(holes);
  }
  if (op_entry.empty()) {
    for (std::size_t t = 0; t < table.entries.size(); ++t) {
      if (table.entries[t].operation != 0) op_entry[table.entries[t].operation] = t;
    }
  }
  result.groups.resize(table.entries.size());
  std::vector<std::string> unfit;
  std::size_t unfit_count = 0;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const double d = holes[i].diameter;
    std::size_t chosen = table.entries.size();
    if (holes[i].slot_end) {
      // A slot milled along its length: the end mill's, whatever else fits its width.
      for (std::size_t t = 0; t < table.entries.size() && chosen == table.entries.size(); ++t) {
        if (table.entries[t].tool.end_mill) chosen = t;
      }
      if (chosen == table.entries.size()) {
        throw UserError(source, holes[i].source_line, "--slots mill mills slots with the end mill: give --end-mill DIA");
      }
      result.groups[chosen].input_order.push_back(static_cast<aco::HoleIndex>(i));
      continue;
    }
    if (holes[i].operation != 0 && !apart) {
      auto it = op_entry.find(holes[i].operation);
      if (it != op_entry.end()) chosen = it->second;
    }
    for (std::size_t t = 0; t < table.entries.size() && chosen == table.entries.size(); ++t) {
      if (table.entries[t].source >= 0 && static_cast<std::uint32_t>(table.entries[t].source) != options.hole_source[i]) continue;
      if (table.entries[t].operation != holes[i].operation) continue;
      if (table.entries[t].operation != 0 || (table.entries[t].tool.operation == gcode::Operation::Drill && table.entries[t].takes(d))) {
        chosen = t;
        break;
      }
    }
    if (chosen == table.entries.size()) {
      ++unfit_count;
      if (unfit.size() < 5) {
        unfit.push_back("D" + fmt3(d) + " at (" + fmt3(holes[i].center.x) + ", " + fmt3(holes[i].center.y) + ")" +
                        (holes[i].source_line ? " line " + std::to_string(holes[i].source_line) : ""));
      }
      continue;
    }
    result.groups[chosen].input_order.push_back(static_cast<aco::HoleIndex>(i));
  }
  if (unfit_count > 0) {
    std::string list;
    for (const auto& u : unfit) list += (list.empty() ? "" : "; ") + u;
    if (unfit_count > unfit.size()) list += "; ...";
    throw UserError(source, 0, std::to_string(unfit_count) + " hole(s) fit no tool in the tool table: " + list);
  }
  for (std::size_t t = 0; t < table.entries.size(); ++t) result.groups[t].tool = table.entries[t].tool;
  result.groups.erase(std::remove_if(result.groups.begin(), result.groups.end(),
                                     [](const ToolGroup& g) { return g.input_order.empty(); }),
                      result.groups.end());
  if (!options.first_holes.empty()) {
    // The tool of the holes drilled first goes first, and they begin its route.
    const aco::HoleIndex pin = options.first_holes.front();
    auto holds = [&](const ToolGroup& g) { return std::find(g.input_order.begin(), g.input_order.end(), pin) != g.input_order.end(); };
    auto it = std::find_if(result.groups.begin(), result.groups.end(), holds);
    if (it == result.groups.end()) throw UserError(source, 0, "the holes drilled first are not among the holes");
    std::rotate(result.groups.begin(), it, it + 1);
    ToolGroup& g = result.groups.front();
    for (aco::HoleIndex h : options.first_holes) {
      const auto at = std::find(g.input_order.begin(), g.input_order.end(), h);
      if (at == g.input_order.end()) throw UserError(source, 0, "the holes drilled first must share one tool");
      g.input_order.erase(at);
    }
    g.input_order.insert(g.input_order.begin(), options.first_holes.begin(), options.first_holes.end());
    g.fixed_prefix = options.first_holes.size();
  }
  return result;
}

void settle_plan(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options) {
  // Each tool's path is ordered from where the previous one ended, so on a
  // small job a baseline can come out shorter overall (ending one tool where
  // the next is best begun): then the better of them stands, never a worse
  // route than one the summary shows beside it.
  auto cost = [&](const RouteStats& r) { return options.objective == Objective::Time ? r.time_s : r.travel_mm; };
  if (cost(result.nearest_neighbor) < cost(result.optimized) && cost(result.nearest_neighbor) <= cost(result.input_order)) {
    for (ToolGroup& g : result.groups) g.optimized = g.nearest_neighbor;
    result.optimized = result.nearest_neighbor;
  } else if (cost(result.input_order) < cost(result.optimized)) {
    for (ToolGroup& g : result.groups) g.optimized = g.input_order;
    result.optimized = result.input_order;
  }
  split_worn_drills(holes, result, options);
}

std::vector<gcode::ToolPass> to_passes(const aco::HoleSet& holes, const PlanResult& plan, const Machine& machine) {
  std::vector<const aco::Order*> orders;
  for (const ToolGroup& g : plan.groups) orders.push_back(&g.optimized);
  return passes_of(holes, plan.groups, orders, machine);
}

std::vector<gcode::ToolPass> passes_of(const aco::HoleSet& holes, const std::vector<ToolGroup>& groups,
                                       const std::vector<const aco::Order*>& orders, const Machine& machine) {
  std::vector<gcode::ToolPass> passes;
  std::size_t index = 0;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const ToolGroup& g = groups[k];
    const aco::Order& order = *orders[k];
    gcode::ToolPass pass;
    pass.tool = g.tool;
    for (aco::HoleIndex h : order) {
      pass.holes.push_back(holes[h].center);
      pass.index.push_back(++index);
      if (g.tool.end_mill) pass.mill_diameter.push_back(holes[h].diameter);
    }
    // A milled slot's two ends follow each other (a chain keeps its order): milled as one.
    if (g.tool.end_mill) {
      pass.slot_to_next.assign(pass.holes.size(), false);
      for (std::size_t i = 0; i + 1 < order.size();) {
        const aco::Hole& a = holes[order[i]];
        const aco::Hole& b = holes[order[i + 1]];
        const bool pair = a.slot_end && b.slot_end && a.chain == b.chain;
        if (pair) pass.slot_to_next[i] = true;
        i += pair ? 2 : 1;
      }
    }
    if (!machine.clamps.empty()) {
      pass.clear_after.assign(pass.holes.size(), false);
      for (std::size_t i = 0; i + 1 < pass.holes.size(); ++i) {
        pass.clear_after[i] = crosses_clamp(pass.holes[i], pass.holes[i + 1], machine);
      }
    }
    passes.push_back(std::move(pass));
  }
  return passes;
}

}  // namespace planning
