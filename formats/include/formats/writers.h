#pragma once
// Drill files written back in the planned order, for machines that take them.
#include <string>
#include <vector>

#include "gcode/program.h"

namespace formats {

// The passes as an Excellon drill file in drilling order (explicit decimals,
// tools numbered as in the passes).
std::string write_excellon(const std::vector<gcode::ToolPass>& passes, bool metric, const std::string& source);

// The passes as an RS-274X drill file: one round aperture per tool, a flash per
// hole in drilling order, mm in 4.6 format. `file_function` (a Gerber X2
// %TF.FileFunction value such as "Plated,1,2,PTH,Drill") is written when known.
std::string write_gerber(const std::vector<gcode::ToolPass>& passes, const std::string& source,
                         const std::string& file_function);

}  // namespace formats
