#pragma once
// acodrill's commands, each given its parsed arguments: acodrill_main.cpp
// holds the argument tables, plan_command.cpp the plan command (files read,
// the job called, files written, the summary printed), commands.cpp the others.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/inputs.h"
#include "job/settings.h"

namespace cli {

// Seconds since the process started: --time-limit bounds the whole run.
double seconds_since_start();

// How inputs are read, with the file an option names (--apertures).
struct InputArgs {
  job::InputSettings settings;
  std::string apertures;  // path of an aperture list
  std::string processes;  // path of a process table (issue 82)
};
// The settings with the aperture list read.
job::InputSettings read_input_settings(const InputArgs& a);

struct PlanArgs {
  std::vector<std::string> inputs;  // one job
  std::string output, report, svg, svg_compare, convergence, excellon, gerber, setup_sheet;
  std::string tools, machine, panel;  // a file, or (machine, panel) a name or grid
  job::PlanSettings settings;         // the rest, bound to the options directly
  bool quiet = false;
  bool filter_progress = false;
};

int cmd_plan(PlanArgs& a, const InputArgs& in);
// `features`: one row a hole feature (--features) instead of one a hole.
int cmd_holes(const std::string& input, const InputArgs& in, const std::string& format, bool features, bool quiet);
int cmd_tsp(const std::string& input, const std::string& tour, const job::SolverSettings& s, bool quiet);
struct VerifyArgs {
  std::string program, origin, panel, pitch;
  std::vector<std::string> holes;
  job::BenchSettings bench;
  bool spot = false;  // plan was given --spot (issue 82)
};
int cmd_verify(const VerifyArgs& a, const InputArgs& in, bool quiet);
int cmd_machines(const std::string& show);

// The inputs with each file once; a file given again is named in a warning.
std::vector<std::string> read_once(const std::vector<std::string>& paths, bool quiet);

// The line `acodrill: FILE: N holes from FORMAT, ...` on stderr (nothing when quiet).
// `skipped_label` says what became of what the input holds but the holes leave out;
// `holes`: how many holes to say the input gave (default: those it holds).
void print_warnings(const formats::LoadedHoles& loaded, const std::string& path, bool quiet,
                    const char* skipped_label = "NOT MADE", std::optional<std::size_t> holes = std::nullopt);

// --machine NAME_OR_FILE: a built-in class by name, unless a file of that name
// is here, or a profile file (read into `profile`).
void resolve_machine(const std::string& name_or_path, std::string& name, std::optional<job::NamedText>& profile);
// --panel COLSxROWS or a panel file (read into `file`).
void resolve_panel(const std::string& panel, std::string& grid, std::optional<job::NamedText>& file);

}  // namespace cli
