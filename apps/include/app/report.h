#pragma once
// Machine-readable results: the --report JSON (keys per ../shared/interface.md,
// more may be added, none renamed) and the --convergence CSV.
#include <string>

#include "app/plan.h"

namespace app {

struct ReportContext {
  std::string source;   // input file
  std::string program;  // output program
  std::size_t holes = 0;
};

std::string report_json(const aco::HoleSet& holes, const PlanResult& plan, const ReportContext& context);
std::string convergence_csv(const PlanResult& plan);

}  // namespace app
