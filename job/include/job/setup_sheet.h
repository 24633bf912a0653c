#pragma once
// The setup sheet (--setup-sheet): one self-contained printable HTML page for
// the operator — where to set program zero, which tools to load, how long the
// job takes. Inline CSS and SVG only: no scripts, no network, no date, so the
// same plan gives the same page.
#include <string>

#include "planning/plan.h"
#include "job/report.h"

namespace job {

// `route_svg`: the route picture (job::route_svg) when it is already made
// (drawing it again took 1.3 s at 10^6 holes); empty: drawn here.
std::string setup_sheet_html(const aco::HoleSet& holes, const planning::PlanResult& plan, const planning::PlanOptions& options,
                             const ReportContext& context, std::string route_svg = {});

}  // namespace job
