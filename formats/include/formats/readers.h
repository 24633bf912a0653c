#pragma once
// The individual readers behind formats::parse_holes, for tests and fuzzers.
// Each takes the file's name (for messages) and bytes, and returns its holes
// in mm before filters and duplicate removal.
#include <string>
#include <string_view>

#include <vector>

#include "formats/archive.h"
#include "formats/holes.h"

namespace formats {

LoadedHoles parse_csv(const std::string& path, std::string_view data, const InputOptions& options);
LoadedHoles parse_tsplib(const std::string& path, std::string_view data);
LoadedHoles parse_xml_map(const std::string& path, std::string_view data, const InputOptions& options);

bool looks_like_excellon(std::string_view head);
LoadedHoles parse_excellon(const std::string& path, std::string_view data, const InputOptions& options);

bool looks_like_gerber(std::string_view head);
// A drilling program: its holes, and the program itself in LoadedHoles::program.
// keep_milling: gcode::ReadOptions::keep_milling (plan --keep-milling).
LoadedHoles parse_program(const std::string& path, std::string_view data, bool keep_milling = false);

LoadedHoles parse_gerber(const std::string& path, std::string_view data, const InputOptions& options);

// Issue 86: board jobs, a LoadedHoles per drill source (formats/src/board.h),
// before the slot policy and the filters.
bool looks_like_ipc2581(std::string_view head);
std::vector<LoadedHoles> parse_ipc2581(const std::string& path, std::string_view data, const InputOptions& options);
std::vector<LoadedHoles> parse_odb(const std::string& path, const std::vector<ArchiveEntry>& entries, const InputOptions& options);

}  // namespace formats
