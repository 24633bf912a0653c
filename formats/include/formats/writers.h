#pragma once
// Drill files written back in the planned order, for machines that take them.
#include <string>
#include <vector>

#include "gcode/program.h"

namespace formats {

// The passes as an Excellon drill file in drilling order (explicit decimals,
// tools numbered as in the passes).
std::string write_excellon(const std::vector<gcode::ToolPass>& passes, bool metric, const std::string& source);

}  // namespace formats
