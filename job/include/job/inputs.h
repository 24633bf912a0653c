#pragma once
// The job's inputs as bytes with their names (no file is opened here): each
// parsed by the reader formats/ chooses by content; several files, one job.
#include <cstdint>
#include <string>
#include <vector>

#include "formats/holes.h"

namespace job {

struct InputFile {
  std::string name;   // as messages name it: a path, or "-" for standard input
  std::string bytes;  // the file's content
  // Allegro writes its drill files' number format only in an nc_param.txt
  // beside them: its content, where the front end found one.
  std::string nc_param;
};

formats::LoadedHoles read_input(const InputFile& file, const formats::InputOptions& options);

// Several inputs, one job (`plan a.drl b.drl c.gbr`, `verify --holes a b`):
// each read as read_input reads it, in any mix of formats, and their holes
// put together in the order given. A hole in two files (same centre and
// diameter) is drilled once and counted in `holes.duplicates_removed`.
struct Inputs {
  formats::LoadedHoles holes;  // every file's holes, slots, notes and warnings; name: the stems joined by '+'
  struct Source {
    std::string file;
    std::size_t holes = 0;  // after filters and duplicates
  };
  std::vector<Source> sources;
  std::vector<std::uint32_t> hole_source;  // per hole of `holes`: its index in `sources`
  std::vector<formats::LoadedHoles> parts;  // each file as read (holes left out), for its summary line
};

// Throws formats::InputError for a drilling program among other inputs: a program is reordered alone.
Inputs read_inputs(const std::vector<InputFile>& files, const formats::InputOptions& options);

// What a --time-limit of `limit_s` for the whole run leaves the solver once
// `spent_s` went on reading the inputs: 0 (no limit) stays 0, and a limit
// already used up leaves 0.01 s, one iteration's worth at most.
double time_left(double limit_s, double spent_s);

}  // namespace job
