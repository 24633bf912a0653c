#pragma once
/**
 * The one entry to the colony: pure, no I/O, no globals. The same problem,
 * params and seed give the same order whatever the thread count, unless a
 * time limit stops the run.
 *
 * **Example**:
 *   aco::Params params;  params.seed = 7;
 *   aco::Solution s = aco::solve(problem, params);
 */
#include "aco/params.h"
#include "aco/problem.h"
#include "aco/solution.h"

namespace aco {

Solution solve(const Problem& problem, const Params& params);

// Params with every default filled in for a problem of n points.
Params resolve(const Params& params, std::size_t n);

}  // namespace aco
