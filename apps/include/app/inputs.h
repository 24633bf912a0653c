#pragma once
// The input stage of the command line: a file's bytes, given to the reader
// formats/ chooses by content.
#include <string>

#include "formats/holes.h"

namespace app {

using formats::InputFormat;
using formats::InputOptions;
using formats::LoadedHoles;
using formats::Note;

// Reads `path` ("-" = standard input) and parses it with formats::parse_holes.
LoadedHoles load_holes(const std::string& path, const InputOptions& options);

}  // namespace app
