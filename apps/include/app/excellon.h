#pragma once
// Excellon drill files (the PCB shop's format): reader and writer.
#include <string>
#include <string_view>

#include "app/inputs.h"

namespace app {

bool looks_like_excellon(std::string_view head);
LoadedHoles parse_excellon(const std::string& path, std::string_view data, const InputOptions& options);

}  // namespace app
