#pragma once
// File input and output the way a CAM pipeline needs it: inputs read whole
// (or from stdin for "-"), outputs written to a temporary name beside the
// target and renamed into place only when complete, so a failed run never
// leaves a truncated program behind and never touches an existing file.
#include <string>

namespace app {

// Reads a whole file, or standard input for "-". Throws UserError.
std::string read_file(const std::string& path);

// Writes `content` to `path` atomically ("-" = standard output). Throws UserError.
void write_file_atomic(const std::string& path, const std::string& content);

// True when two paths name the same existing file.
bool same_file(const std::string& a, const std::string& b);

}  // namespace app
