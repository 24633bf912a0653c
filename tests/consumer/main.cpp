// Solves a 10-hole problem through the installed library and prints its length.
#include <cstdio>

#include "aco/solve.h"

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
  return s.order.size() == 10 ? 0 : 1;
}
