#pragma once
#include <string>
#include <vector>

#include "aco/geometry.h"
#include "aco/params.h"

namespace aco {

struct TracePoint {
  int iteration = 0;       // 0 = the nearest-neighbour start
  double wall_s = 0.0;
  double best_length = 0.0;
};

struct Solution {
  Order order;                 // visiting order of Problem::points
  double length = 0.0;         // route_length(problem, order)
  int iterations = 0;          // colony iterations run
  double wall_s = 0.0;
  std::vector<TracePoint> trace;       // best length each time it improved
  std::vector<double> thread_busy_s;   // time each worker spent building and improving tours
  Algorithm algorithm = Algorithm::AntColonySystem;
  int ants = 0;
  int threads = 0;
  std::string stop_reason;     // "iterations", "time limit", "stalled", "trivial"
};

}  // namespace aco
