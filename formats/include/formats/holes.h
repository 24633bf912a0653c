#pragma once
/**
 * Every input format acodrill reads, in one place and one shape: a file's
 * bytes → records carrying their line numbers → holes in mm (diameter, layer
 * or tool, source line), with the reader's warnings. The format is chosen by
 * content; the extension only breaks ties. Errors are formats::InputError
 * with file and line.
 *
 * **Example**:
 *   formats::LoadedHoles in = formats::parse_holes("board.drl", bytes, {});
 *   for (const aco::Hole& h : in.holes) use(h.center, h.diameter);
 */
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"
#include "aco/problem.h"
#include "dxf/reader.h"
#include "formats/features.h"
#include "formats/processes.h"
#include "gcode/drilling.h"

namespace formats {

// A path's last part, after the folders: after '/', and on Windows after '\\' too.
inline std::string file_name(const std::string& path) {
#ifdef _WIN32
  const std::size_t slash = path.find_last_of("/\\");
#else
  const std::size_t slash = path.find_last_of('/');
#endif
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

enum class InputFormat { Dxf, Excellon, Gerber, XmlMap, Csv, Tsplib, Program, Ipc2581, Odb };
const char* to_string(InputFormat f);

// A slot: an oval hole `width_mm` wide whose centre runs from `from` to `to`
// (mm): an Excellon G85 canned slot or routed oval, a Gerber obround flash.
struct Slot {
  aco::Point2 from, to;
  double width_mm = 0.0;
  std::string layer;
  std::uint32_t source_line = 0;
};

// What becomes of slots, whatever the format (--slots, --slot-pitch).
enum class SlotPolicy {
  Drill,  // a row of holes of the slot's width along it (the default)
  Skip,   // not drilled; named in the program's header, the report and the setup sheet
  Mill,   // milled by the end mill along its length: its two ends, a chain of holes marked slot_end
};
struct SlotOptions {
  SlotPolicy policy = SlotPolicy::Drill;
  double pitch_mm = 0.0;  // between the row's holes; 0: a quarter of the slot's width
};

struct InputOptions {
  dxf::ReadOptions dxf;          // layer and diameter filters, limits, default unit
  double default_unit_mm = 1.0;  // --input-units, for files that do not say
  bool input_units_given = false;
  SlotOptions slots;
  // RS-274D's aperture list (--apertures): its text and name; empty: none.
  std::string aperture_list, aperture_list_path;
  // Excellon: the number format stated outright (--excellon-format), which
  // wins over anything the file says or its numbers suggest; and Allegro's
  // nc_param.txt found beside a drill file (its text; empty: none).
  struct ExcellonFormat {
    bool metric = false;
    int int_digits = 0, dec_digits = 0;
    bool leading_zeros_kept = false;
  };
  std::optional<ExcellonFormat> excellon_format;
  std::string nc_param;
  // Issue 82: a DXF's concentric circles and thread arcs read as hole
  // features (formats/features.h); true: every circle a hole of its own, as
  // before (--concentric separate).
  bool concentric_separate = false;
  // Issue 82: --processes, shared by every input of a job (null: none).
  std::shared_ptr<const ProcessTable> processes;
  // Issue 86: the step of an ODB++ or IPC-2581 job to drill (--step; empty:
  // the panel step if there is one, else the only step).
  std::string step;
  // A G-code program that also mills: its milling kept as written, the
  // drilling around it reordered (plan --keep-milling, the FreeCAD post).
  bool keep_milling = false;
};

struct Note {
  std::uint32_t line = 0;
  std::string message;
};

struct LoadedHoles {
  aco::HoleSet holes;
  InputFormat format = InputFormat::Csv;
  std::vector<Note> warnings;
  // What a reader had to assume because the file did not say (Excellon
  // units and number format): shown in the summary and the report.
  std::vector<std::string> assumptions;
  // DXF: round closed contours drawn without a CIRCLE, how many were read as
  // holes (--round-contours), and what they are drawn with ("12 SPLINE, 40 LINE").
  std::size_t round_contours = 0, round_contour_holes = 0;
  std::string round_contour_kinds;
  std::size_t duplicates_removed = 0;
  // A drilling program: holes it drills again at the same place (kept in `holes`).
  std::size_t drilled_again = 0;
  std::size_t skipped_by_filter = 0;
  std::string name;            // TSPLIB NAME or the file's stem
  std::string edge_weight_type;  // TSPLIB: EUC_2D (the default), CEIL_2D or ATT
  std::optional<bool> metric;  // the units the file itself is written in, where it says (Excellon)
  std::vector<Slot> slots;     // as read; parse_holes drills or skips them (SlotOptions)
  std::size_t slots_drilled = 0, slot_holes = 0;  // slots made into rows of holes, and how many holes
  std::size_t slots_milled = 0;  // slots milled along their length (--slots mill): two holes each, its ends
  // What the input asks for that the program will not do (skipped slots,
  // routed paths): never only a warning on stderr — the program's header,
  // the report and the setup sheet name each one.
  std::vector<Note> skipped;
  // DXF (issue 82): one a hole of `holes`, in its order, what the drawing
  // says the hole is (plain, tapped, counterbored, ...); empty for formats
  // that draw no features, and with --concentric separate.
  std::vector<HoleFeature> features;
  // What the features ask for that plan does not do (taps, counterbores,
  // undecided circles): a line each on stderr, not folded into `warnings`.
  std::vector<Note> feature_warnings;
  // Gerber X2: the file's %TF.FileFunction ("Plated,1,4,PTH,Drill"): plating and layer span.
  // IPC-2581 and ODB++: the same words for each of its drill sources.
  std::string drill_function;
  // IPC-2581 and ODB++ (issue 86): a board job holds several drill sources
  // (plated and non-plated holes, a blind span), each read as a file of its
  // own, as PTH and NPTH drill files are: this one's ("plated",
  // "non-plated", "plated, blind 1-2"); empty for a file of one source.
  std::string source_label;
  // What such a file holds beyond its holes, for the summary: its format,
  // step, drill layers and board size.
  std::string description;
  // A drilling program (another CAM's G-code): its tool runs and how each hole
  // is made, which `plan` reorders; `holes` holds the same holes (layer "T<n>",
  // the diameter where the program's comments give it).
  std::shared_ptr<const gcode::DrillingProgram> program;
};

// The holes that drill a slot: a row of the slot's width at `pitch_mm` (0: a
// quarter of the width) from end to end, ordered ends first, then each
// midpoint of two drilled holes (bisection), so no hole is drilled beside a
// fresh overlapping one alone: the drill always cuts into two holes
// symmetrically and does not wander (pcb2gcode orders slot holes likewise).
std::vector<aco::Point2> slot_holes(const Slot& slot, double pitch_mm);

// Applies the slot policy: drilled slots become holes (one chain each, so the
// planner keeps their order); skipped ones are named in `skipped`. More than
// `limit.max_holes` holes in all is an InputError naming `path` and the slot's line.
void apply_slot_policy(LoadedHoles& loaded, const SlotOptions& options, const std::string& path, const dxf::ReadOptions& limit);

// A drilling program's holes in program order, one per hole drilled (one
// drilled twice is there twice): layer "T<n>" ("T<n> G55" in another work offset than G54), the diameter the program's
// comments give its tool, else 0, and the line that drills it.
aco::HoleSet program_holes(const gcode::DrillingProgram& program);

InputFormat detect_format(const std::string& path, std::string_view data);

// The distances a TSPLIB instance's lengths are counted in: its
// EDGE_WEIGHT_TYPE (EUC_2D rounded, CEIL_2D rounded up, ATT pseudo-Euclidean).
aco::Metric tsplib_metric(const LoadedHoles& loaded);

// Chooses the reader by content, reads, applies the layer and diameter
// filters and drops exact duplicates (a program's are counted, not dropped). `path` names the file in messages ("-": standard input).
// An IPC-2581 or ODB++ job's drill sources come back as one.
LoadedHoles parse_holes(const std::string& path, std::string_view data, const InputOptions& options);

// The same, a LoadedHoles for each drill source of the file: one for every
// format but IPC-2581 and ODB++ (an archive or a folder packed as a tar),
// whose plated and non-plated holes and blind spans are sources apart.
std::vector<LoadedHoles> parse_sources(const std::string& path, std::string_view data, const InputOptions& options);

}  // namespace formats
