#pragma once
// Excellon drill files (the PCB shop's format): reader and writer.
#include <string>
#include <string_view>

#include <vector>

#include "app/inputs.h"
#include "gcode/program.h"

namespace app {

bool looks_like_excellon(std::string_view head);
LoadedHoles parse_excellon(const std::string& path, std::string_view data, const InputOptions& options);

// The passes as an Excellon drill file in drilling order (explicit decimals,
// tools numbered as in the passes), for drilling machines that take Excellon.
std::string write_excellon(const std::vector<gcode::ToolPass>& passes, bool metric, const std::string& source);

}  // namespace app
