// Solves a 10-hole problem through the installed library and prints its
// length; then plans the same holes as a job through the installed planning
// model (tools generated, each group ordered, timed) and prints its time;
// then plans a whole job from a CSV file's bytes in one call (aco::job) and
// prints the program's first lines and what it drills.
#include <cstdio>
#include <string>

#include "aco/solve.h"
#include "job/plan.h"
#include "planning/plan.h"

int main() {
  aco::Problem problem;
  problem.shape = aco::Shape::ClosedTour;
  // Ten holes on a 3 x 4 grid less two corners: the shortest closed tour is 10 units.
  const double xy[10][2] = {{1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {3, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}};
  for (const auto& p : xy) problem.points.push_back({p[0], p[1]});
  aco::Params params;
  params.seed = 1;
  params.iterations = 50;
  const aco::Solution s = aco::solve(problem, params);
  std::printf("holes %zu length %.3f\n", s.order.size(), s.length);

  aco::HoleSet holes;
  for (const auto& p : xy) holes.push_back({{p[0] * 10, p[1] * 10}, 3.0, "", 0});
  planning::PlanOptions options;
  options.solver.iterations = 20;
  options.machine = *planning::builtin_machine("router");
  const planning::PlanResult plan = planning::plan_job(holes, options, "consumer");
  std::printf("tools %zu time %.1f s\n", plan.groups.size(), plan.optimized.time_s);

  std::string csv = "x,y,diameter\n";
  for (const auto& p : xy) csv += std::to_string(p[0] * 10) + "," + std::to_string(p[1] * 10) + ",3.0\n";
  job::PlanSettings settings;
  settings.dialect = "linuxcnc";
  settings.solver.iterations = 20;
  settings.wanted.report = true;
  const job::Result r = job::plan({{"grid.csv", csv, ""}}, settings);
  if (r.exit_code != 0) {
    std::printf("job error: %s\n", r.error.c_str());
    return 1;
  }
  std::printf("job holes %zu tools %zu program %zu bytes report %zu bytes\n", r.holes.size(), r.plan.groups.size(),
              r.files.program.size(), r.files.report.size());
  const bool job_ok = r.holes.size() == 10 && r.files.program.find("G81") != std::string::npos &&
                      r.files.report.find("\"holes\"") != std::string::npos;
  return s.order.size() == 10 && plan.groups.size() == 1 && plan.optimized.time_s > 0 && job_ok ? 0 : 1;
}
