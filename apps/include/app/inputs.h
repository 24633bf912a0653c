#pragma once
// The input stage of the command line: files read whole and handed to
// job/inputs.h, which parses their bytes.
#include <cstdint>
#include <string>
#include <vector>

#include "formats/holes.h"
#include "job/inputs.h"

namespace app {

using formats::InputFormat;
using formats::InputOptions;
using formats::LoadedHoles;
using formats::Note;

// Reads `path` ("-" = standard input) and parses it with formats::parse_holes.
LoadedHoles load_holes(const std::string& path, const InputOptions& options);

// Several inputs, one job: each file read whole (with an nc_param.txt
// beside it) and given to job::read_inputs.
using Job = job::Inputs;
job::InputFile read_input_file(const std::string& path);

// The inputs with each file once, in the order given: a path given again, or
// another name of the same file, is left out and listed in `repeated` (the
// caller warns), so a file given twice is read, drilled and named once.
std::vector<std::string> distinct_inputs(const std::vector<std::string>& paths, std::vector<std::string>& repeated);

// Throws UserError for a drilling program among other inputs: a program is reordered alone.
Job load_job(const std::vector<std::string>& paths, const InputOptions& options);

using job::time_left;

}  // namespace app
