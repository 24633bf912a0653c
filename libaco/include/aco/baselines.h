#pragma once
/**
 * The orders acodrill is compared against in reports and benchmarks. Each
 * respects the problem's shape (an open path starts nearest its start).
 */
#include "aco/problem.h"

namespace aco {

Order input_order(const Problem& problem);
Order nearest_neighbor(const Problem& problem);
// Greedy edge matching (shortest edges first, no vertex of degree 3, no early cycle).
Order greedy_edge(const Problem& problem);
// Boustrophedon raster: rows of `row_height` mm, alternating direction (what CAM packages do by default).
Order raster(const Problem& problem, double row_height = 0.0);
// Nearest neighbour improved by 2-opt with neighbour lists (what pcb2gcode does).
Order nearest_neighbor_2opt(const Problem& problem);
// Any order improved by 2-opt and Or-opt until no move gains.
Order improve(const Problem& problem, Order order, bool or_opt = true);

}  // namespace aco
