#pragma once
// Everything `acodrill plan` takes, as one value (issue 64): the command
// line fills it from its options, the page from its form. Text fields take
// the words the options take ("grbl", "lower-left", "3x2"); a file an option
// names comes as its content (NamedText), read by the front end. Each field
// is checked, and turned into the stages' own options, when a job starts:
// a bad one is the job's one-line error.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "aco/params.h"
#include "formats/holes.h"
#include "planning/placement.h"
#include "planning/plan.h"

namespace job {

// A file given by its content: its name for messages, and its text.
struct NamedText {
  std::string name;
  std::string text;
};

// The colony (--threads, --seed, --time-limit, --iterations, --algorithm, ...).
struct SolverSettings {
  int threads = 0;  // 0: all cores
  std::uint64_t seed = 1;
  double time_limit_s = 0.0;  // the whole job's, reading the inputs included; 0: none
  // The time limit holds for the outputs too (the page's, issue 84): the
  // colony ends early enough for the program, its check and the files to
  // be made within it, or does not begin when there is no time for it.
  bool time_limit_covers_outputs = false;
  int iterations = 0;         // 0: until the time limit, else the size's default
  std::string algorithm = "focused";
  int ants = 0;
  double alpha = 1.0;
  std::optional<double> beta, rho;
  std::string local_search = "auto";
  int focus_edges = 0;
};

// How inputs are read (--layer, --min-diameter, --slots, --excellon-format, ...).
struct InputSettings {
  std::vector<std::string> layers;
  std::optional<double> min_diameter_mm, max_diameter_mm;
  std::string input_units;  // mm | inch; empty: each format's own default
  std::size_t max_holes = 5'000'000;
  std::string max_holes_named = "the hole limit, --max-holes";  // in messages; the page says its own
  std::size_t max_expansion = 10'000'000;
  std::string slots = "drill";  // drill | skip | mill
  double slot_pitch_mm = 0.0;
  std::optional<NamedText> apertures;  // an RS-274D Gerber's aperture list
  std::string excellon_format;         // UNITS,I:D,lz|tz
  bool round_contours = false;
  double round_tolerance_pct = 2.5;
  std::string dxf_units;  // mm | cm | m | inch | feet; empty: the DXF's header
  std::string concentric = "features";  // features | separate (issue 82)
  std::string step;                      // an ODB++ or IPC-2581 job's step (issue 86); empty: its panel, else its only step
  std::optional<NamedText> processes;    // a process table (JSON, issue 82)
  bool keep_milling = false;             // a program's milling kept as written (--keep-milling, issue 83)
};

// The tools on the bench and the side of the board (--drills, --end-mill, --side, ...).
struct BenchSettings {
  std::string drills;  // "0.8,1.0:-0.05:+0.1"; empty: the machine profile's
  std::optional<double> end_mill_mm;
  std::string side = "front";  // front | back
  std::string mirror_axis;     // x=V | y=V; empty: through the holes' centre
  std::optional<double> alignment_pins_mm;
};

// Which of the outputs to make besides the program (each costs time on large jobs).
struct Wanted {
  bool report = false, route_svg = false, compare_svg = false, setup_sheet = false;
  bool excellon = false, gerber = false, convergence = false;
  static Wanted all() { return {true, true, true, true, true, true, true}; }
};

struct PlanSettings {
  InputSettings input;
  SolverSettings solver;
  BenchSettings bench;
  std::string machine = "";  // a built-in class; empty: vf2, or router for grbl/marlin
  std::optional<NamedText> machine_profile;  // a profile file (wins over `machine`)
  std::string dialect;  // haas | fanuc | linuxcnc | grbl | marlin; empty: the machine's
  std::string units;    // mm | inch; empty: mm (a program input keeps its own)
  std::optional<NamedText> tools;  // a tool table (JSON)
  std::string material;            // steel | aluminium | pcb; empty: steel, pcb for drill files
  std::optional<double> thickness_mm, default_diameter_mm;
  std::string objective = "distance";  // distance | time
  std::string origin;                  // lower-left (default) | center | upper-left | drawing | X,Y
  std::string panel;                   // COLSxROWS, with `pitch`
  std::string pitch;                   // DX,DY
  std::optional<NamedText> panel_file;  // a panel file (instead of `panel`)
  std::size_t batch = 1;
  bool keep_files_apart = false;
  bool keep_style = false;  // a program input: its own lines and style
  double min_spacing_mm = 0.0;
  std::size_t resume_from = 1;
  int program_number = 1001;
  std::optional<double> probe_plate_mm;
  // Issue 82: spot every drilled hole first (or the machine profile's "spot").
  bool spot = false;
  // The program's name as the report gives it ("-": standard output).
  std::string program_name = "-";
  Wanted wanted;
  // A test hook, and only that: drops the last hole of the program before
  // plan's own check, so a test can see a faulty program refused.
  bool break_writer_for_test = false;
};

// The settings as the stages take them; each throws formats::InputError
// (exit 2) naming the option for a bad value.
aco::Params solver_params(const SolverSettings& s);
formats::InputOptions input_options(const InputSettings& s);
formats::InputOptions::ExcellonFormat parse_excellon_format(const std::string& text);
planning::Origin parse_origin(const std::string& text);
planning::MirrorAxis parse_mirror_axis(const BenchSettings& s);
// --machine: a built-in class by name, or the profile given.
planning::Machine machine_of(const std::string& name, const std::optional<NamedText>& profile);
// --panel: COLSxROWS with --pitch, or a panel file's copies.
std::vector<planning::PanelCopy> panel_copies(const std::string& panel, const std::string& pitch,
                                              const std::optional<NamedText>& panel_file);
// The owned tools: the settings, else the machine profile's.
planning::Tooling tooling_of(const BenchSettings& s, const planning::Machine& machine);

// The board as the program drills it (plan) or should (verify): mirrored
// for --side back, then program zero, then the alignment pins (not part of
// the extent that places zero) at the end, in program coordinates. Returns
// the pins' indices; `notes` get the header's lines saying so.
std::vector<aco::HoleIndex> turn_and_place(aco::HoleSet& holes, const BenchSettings& bench, const planning::Origin* origin,
                                           planning::Placement* placement, std::vector<std::string>* notes);

}  // namespace job
