#pragma once
/**
 * The main job as pure stages: holes → tool groups → an ordered open path per
 * tool → G-code passes, with the travel and machining time (and where it
 * goes) of the optimized order and of the baselines. apps/ only reads files,
 * calls these and writes.
 */
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "aco/problem.h"
#include "aco/solve.h"
#include "gcode/program.h"
#include "planning/machine.h"
#include "planning/operations.h"
#include "planning/placement.h"
#include "planning/tools.h"

namespace planning {

enum class Objective { Distance, Time };

struct PlanOptions {
  aco::Params solver;
  Objective objective = Objective::Distance;
  Machine machine;
  std::optional<ToolTable> tools;  // nullopt: generated
  Material material = Material::Steel;
  double thickness_mm = 6.35;      // the thesis's 1/4" plate
  gcode::ProgramSettings program;
  // After the last hole the spindle returns to `finish` (default: the
  // machine's start) — or, for a program that ends over its last hole, stays.
  bool return_at_end = true;
  std::optional<aco::Point2> finish;
  // Several inputs: per hole, the input it came from (empty: one input). With
  // keep_sources_apart each input's holes get tools of their own, drilled
  // input after input (plated and non-plated holes at different steps);
  // otherwise holes of one diameter share a tool whatever file they are in.
  std::vector<std::uint32_t> hole_source;
  bool keep_sources_apart = false;
  // The drills the user owns and an end mill (empty: one generated drill per
  // diameter, or the tool table).
  Tooling tooling;
  // Holes drilled before all others, in this order (alignment pins): their
  // tool goes first and they begin its route.
  std::vector<aco::HoleIndex> first_holes;
  // Issue 82: the operations of the holes whose aco::Hole::operation is k > 0
  // (specs[k - 1]), each made by a tool of its own after the drills.
  std::vector<OperationSpec> operations;
};

struct ToolGroup {
  gcode::Tool tool;
  std::vector<aco::HoleIndex> input_order;  // indices into the hole set, in input order
  aco::Order optimized;                     // the same indices, in drilling order
  aco::Order nearest_neighbor;              // baseline
  aco::Solution solution;
  // The first `fixed_prefix` holes of every order are drilled first, as they
  // are (alignment pins); the colony routes the rest from the last of them.
  std::size_t fixed_prefix = 0;
};

// Where the machine's time goes: moving between holes (XY rapids, and Z to
// and from the clearance), drilling (each hole's cycle at its spot), changing
// tools, and waiting (spindle run-up). The parts add up to the total.
struct TimeSplit {
  double moves_s = 0.0, drilling_s = 0.0, tool_changes_s = 0.0, pauses_s = 0.0;
  double total() const { return moves_s + drilling_s + tool_changes_s + pauses_s; }
};

struct RouteStats {
  double travel_mm = 0.0;   // XY, start → every hole of every tool → start
  double time_s = 0.0;      // machining time estimate
  TimeSplit split;          // the same time by what it is spent on
  std::vector<double> tool_time_s;  // per tool group: its tool change, moves and cycles (the return home is in none)
};

struct PlanResult {
  std::vector<ToolGroup> groups;
  RouteStats input_order, nearest_neighbor, optimized;
  int iterations = 0;       // summed over tool groups
  double solver_wall_s = 0.0;
  std::vector<double> thread_busy_s;
  aco::Params solver;       // with defaults resolved
  std::vector<DrillMapping> drill_map;  // owned tools: what each designed diameter is made with
};

// Groups the holes (in program coordinates) by tool and orders every group.
// Throws formats::InputError (file `source`) for a hole without a diameter that no tool
// of the table takes, a hole no tool fits, one under a clamp
// or holes that do not fit the machine's travel (check_travel).
PlanResult plan_job(const aco::HoleSet& holes, const PlanOptions& options, const std::string& source);

// Drills that wear out: a group with more holes than its tool's max_hits is
// cut, in drilling order, into runs of at most max_hits, each run a physical
// drill of its own — a sister tool with the next free tool number — and the
// travel and time of every variant counted again with the extra changes.
void split_worn_drills(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options);

// Orders every group of `result` (its input_order set): each an open path
// from where the previous one ended, the last back to the finish; fills the
// orders, the solutions and the travel and time of each variant.
void order_groups(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options);

// order_groups in slices (issue 64), for a front end that must have control
// back between iterations: each group's colony run a slice at a time
// (aco::ColonyRun). However sliced, the result is order_groups'. `holes`,
// `result` and `options` must outlive the router.
class GroupRouter {
 public:
  GroupRouter(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options);
  ~GroupRouter();
  // Routes until every group is ordered (true) or `max_iterations` more
  // colony iterations (0: no bound) or `max_seconds` (0: none) have passed.
  bool advance(int max_iterations = 0, double max_seconds = 0.0);
  // Ends the routing now: the group under way keeps its best route so far,
  // the groups after it their first (nearest neighbour, improved); those not
  // begun say `reason` (their solution's stop_reason).
  void stop(const std::string& reason = "stopped");
  // The input order's travel and time, counted now rather than when the
  // routing ends (the page times it to budget its time limit, issue 84).
  void count_input_order();
  // The group being routed (groups().size() once all are), and its colony's iteration budget (0: none under way).
  std::size_t group() const;
  int group_iterations() const;
  // Each group's order as it stands: routed, the best so far, or (not yet
  // begun) its input order; to draw the route while it improves.
  std::vector<aco::Order> orders_so_far() const;

 private:
  struct Group;
  void begin_group();
  void end_group();
  const aco::HoleSet& holes_;
  PlanResult& result_;
  const PlanOptions& options_;
  aco::Point2 at_, at_nn_;  // where the optimized and the nearest-neighbour routes are
  std::size_t next_ = 0;    // the group being routed
  std::unique_ptr<Group> current_;
  bool counted_ = false, stopped_ = false, input_counted_ = false;
  std::string stop_reason_ = "stopped";
};

// plan_job in its three stages: the holes grouped by tool (the checks, the
// tools, the groups' input orders), then order_groups (or a GroupRouter),
// then settle_plan (the better of the baselines where one is, the worn
// drills split).
PlanResult group_holes(const aco::HoleSet& holes, const PlanOptions& options, const std::string& source);
void settle_plan(const aco::HoleSet& holes, PlanResult& result, const PlanOptions& options);

// The drilling passes of a plan, ready for gcode::write_program (with the
// G98 retracts the machine's clamps need).
std::vector<gcode::ToolPass> to_passes(const aco::HoleSet& holes, const PlanResult& plan, const Machine& machine);

// The passes of the groups drilled in the given orders.
std::vector<gcode::ToolPass> passes_of(const aco::HoleSet& holes, const std::vector<ToolGroup>& groups,
                                       const std::vector<const aco::Order*>& orders, const Machine& machine);

// XY travel and time of drilling the groups in the given orders: the time
// of the program acodrill writes for them, as the machine's control runs it
// (gcode::time_program with the machine's kinematics, issue 66), with each
// tool change at the profile's tool_change_s and each probe at its feed
// (tool changes), the spindle's run-up dwells (pauses), and on a machine
// with a fixed hit time (hit_s) each drilled hole at it.
RouteStats route_stats(const aco::HoleSet& holes, const std::vector<ToolGroup>& groups,
                       const std::vector<const aco::Order*>& orders, const PlanOptions& options);

}  // namespace planning
