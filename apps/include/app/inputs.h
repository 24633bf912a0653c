#pragma once
// The input stage of the command line: a file's bytes, given to the reader
// formats/ chooses by content; several files, one job.
#include <cstdint>
#include <string>
#include <vector>

#include "formats/holes.h"

namespace app {

using formats::InputFormat;
using formats::InputOptions;
using formats::LoadedHoles;
using formats::Note;

// Reads `path` ("-" = standard input) and parses it with formats::parse_holes.
LoadedHoles load_holes(const std::string& path, const InputOptions& options);

// Several inputs, one job (`plan a.drl b.drl c.gbr`, `verify --holes a b`):
// each file read as load_holes reads it, in any mix of formats, and their
// holes put together in the order given. A hole in two files (same centre
// and diameter) is drilled once and counted in `holes.duplicates_removed`.
struct Job {
  LoadedHoles holes;  // every file's holes, slots, notes and warnings; name: the stems joined by '+'
  struct Source {
    std::string file;
    std::size_t holes = 0;  // after filters and duplicates
  };
  std::vector<Source> sources;
  std::vector<std::uint32_t> hole_source;  // per hole of `holes`: its index in `sources`
  std::vector<LoadedHoles> parts;          // each file as read (holes left out), for its summary line
};
// The inputs with each file once, in the order given: a path given again, or
// another name of the same file, is left out and listed in `repeated` (the
// caller warns), so a file given twice is read, drilled and named once.
std::vector<std::string> distinct_inputs(const std::vector<std::string>& paths, std::vector<std::string>& repeated);

// Throws UserError for a drilling program among other inputs: a program is reordered alone.
Job load_job(const std::vector<std::string>& paths, const InputOptions& options);

// What a --time-limit of `limit_s` for the whole run leaves the solver once
// `spent_s` went on reading the inputs: 0 (no limit) stays 0, and a limit
// already used up leaves 0.01 s, one iteration's worth at most.
double time_left(double limit_s, double spent_s);

}  // namespace app
