#pragma once
// The route as a picture (SVG): holes to scale and coloured by tool, the path
// with its direction, the start, and a legend with lengths and minutes saved.
#include <string>

#include "planning/plan.h"

namespace job {

// The optimized route, in program coordinates, with program zero marked.
std::string route_svg(const aco::HoleSet& holes, const planning::PlanResult& plan, const planning::PlanOptions& options,
                      const planning::Placement& placement, const std::string& title);
// Input order and optimized order side by side.
std::string compare_svg(const aco::HoleSet& holes, const planning::PlanResult& plan, const planning::PlanOptions& options,
                        const planning::Placement& placement, const std::string& title);

}  // namespace job
