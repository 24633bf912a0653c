#pragma once
/**
 * DXF → holes. A layered reader after ezdxf: bytes → group-code tags →
 * sections → entities → holes. Every CIRCLE in model space becomes a hole
 * (and, when asked, every closed contour that is round: contours.h),
 * including those reached through INSERT/MINSERT (nested, scaled, rotated,
 * mirrored, arrayed), placed in world coordinates (OCS applied) and converted
 * to millimetres from $INSUNITS.
 *
 * Structural failures throw dxf::ReadError carrying the 1-based line;
 * sloppiness that can be read safely becomes a Diagnostic warning.
 *
 * **Example**:
 *   dxf::ReadResult r = dxf::read_holes(file_text, dxf::ReadOptions{});
 *   for (const aco::Hole& h : r.holes) use(h.center, h.diameter);
 */
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"

namespace dxf {

enum class Severity { Warning, Error };

struct Diagnostic {
  Severity severity = Severity::Warning;
  std::uint32_t line = 0;  // 0 = the file as a whole
  std::string message;
};

// An input the reader cannot turn into holes. line() is 0 when no single line is to blame.
class ReadError : public std::runtime_error {
 public:
  ReadError(std::uint32_t line, const std::string& message)
      : std::runtime_error(message), line_(line) {}
  std::uint32_t line() const { return line_; }

 private:
  std::uint32_t line_;
};

struct ReadOptions {
  // Millimetres per drawing unit when $INSUNITS is absent or 0 ("unitless").
  double default_unit_mm = 1.0;
  // Layer name patterns with * and ? wildcards, case-insensitive; empty = every layer.
  std::vector<std::string> layers;
  double min_diameter_mm = 0.0;
  double max_diameter_mm = std::numeric_limits<double>::infinity();
  // Caps that keep a hostile file from eating the machine: holes produced, and
  // block references followed (an INSERT array of empty blocks makes no holes but costs time).
  std::size_t max_holes = 5'000'000;
  // What the limit is called in messages ("more than N holes (...)"): the
  // page names its own, with no --max-holes to give (issue 84).
  std::string max_holes_named = "the hole limit, --max-holes";
  std::size_t max_block_references = 10'000'000;
  int max_block_depth = 200;
  // Issue 71: closed contours that are circles within `round_tolerance` (the
  // largest deviation of the contour from its fitted circle, a fraction of
  // the radius) are holes too: SPLINE loops, polygons of LINEs or closed
  // polylines, arc pairs, loops of LINEs and ARCs, full-circle ARCs, circular
  // ELLIPSEs. Off, they are counted and named in a warning, not read.
  bool round_contours = false;
  double round_tolerance = 0.025;
  // Millimetres per drawing unit whatever $INSUNITS says (0: as the drawing says).
  double units_override_mm = 0.0;
};

// An ARC placed in the world (mm): what a tapped hole's thread is drawn with
// (ISO 6410-1: about three quarters of a circle at the thread's major
// diameter, around the tap drill's full circle).
struct DrawnArc {
  aco::Point2 center;
  double diameter = 0.0;  // mm
  double span_deg = 0.0;  // (0, 360]
  std::string layer;
  std::uint32_t line = 0;
};

// Text placed in the world (mm): TEXT, MTEXT, a MULTILEADER's text, the
// MTEXT a LEADER points from, a DIMENSION's own text; what a hole callout is
// written with. `text` is as written (MTEXT's formatting codes kept: the
// callout reader reads them); `anchors` are its insertion point first, then
// where its leader or dimension points.
struct DrawnText {
  std::string text;
  std::vector<aco::Point2> anchors;
  std::string layer;
  std::uint32_t line = 0;
  // Its text style's font is a GD&T font (gdt.shx, AIGDT), where letters
  // stand for symbols: n is the diameter sign, v the counterbore, w the
  // countersink, x the depth.
  bool gdt_font = false;
};

struct ReadResult {
  aco::HoleSet holes;                   // file order, duplicates removed, mm
  std::vector<Diagnostic> diagnostics;  // warnings and notes, in file order
  std::size_t duplicates_removed = 0;
  std::size_t skipped_by_filter = 0;    // dropped by --layer / --min/--max-diameter
  // Round closed contours drawn without a CIRCLE: read as holes (round_contours), or only counted.
  std::size_t round_contours = 0;
  std::size_t round_contour_holes = 0;   // of them, read as holes (not on a CIRCLE, selected)
  std::string round_contour_kinds;       // "12 SPLINE, 40 LINE, 2 ARC+LWPOLYLINE"
  std::string version;                  // $ACADVER, e.g. "AC1024"; empty for R10/R12 files without it
  double unit_mm = 1.0;                 // millimetres per drawing unit that was applied
  // What the drawing says of its holes besides the circles (issue 82): arcs
  // (layer filter applied) and texts, in model space and in its blocks.
  std::vector<DrawnArc> arcs;
  std::vector<DrawnText> texts;
  bool binary = false;
};

// Reads a whole DXF file held in memory (ASCII or binary).
ReadResult read_holes(std::string_view data, const ReadOptions& options = {});

// True when the first bytes look like a DXF (ASCII "0 / SECTION" or the binary sentinel).
bool looks_like_dxf(std::string_view head);

// The selection every reader applies: --layer patterns and the diameter range
// (mm, 1e-6 mm tolerance).
bool selected(const aco::Hole& hole, const ReadOptions& options);

// Case-insensitive match with * (any run) and ? (one character).
bool wildcard_match(std::string_view pattern, std::string_view text);

// Millimetres per unit for a $INSUNITS code; 0 for "unitless" or an unknown code.
double insunits_to_mm(int code);

}  // namespace dxf
