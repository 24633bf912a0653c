#pragma once
/**
 * Where the holes sit: program zero on the part (--origin), the program's
 * statement of it, and panels of several copies of a board (--panel).
 */
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aco/geometry.h"
#include "aco/hole_set.h"
#include "gcode/program.h"

namespace planning {

// Where program zero sits on the part (--origin): the drawing's own zero, a
// corner or the centre of the holes' bounding box, or a point of the drawing.
enum class OriginKind { Drawing, LowerLeft, Center, UpperLeft, Point };
struct Origin {
  OriginKind kind = OriginKind::LowerLeft;
  aco::Point2 point;  // OriginKind::Point: in input coordinates, mm
};
// "drawing", "lower-left", "center" (or "centre"), "upper-left" or "X,Y" in mm.
std::optional<Origin> origin_from_string(const std::string& text);
std::string to_string(const Origin& origin);      // as the option is written: "lower-left", "12.500,-3.000"
std::string describe(const Origin& origin);       // for the operator: "LOWER-LEFT OF HOLES"

// The bounding box of the hole centres.
struct Extent {
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
  double width() const { return x_max - x_min; }
  double height() const { return y_max - y_min; }
};
Extent extent_of(const aco::HoleSet& holes);

// Where the holes were put: program zero in the input's coordinates and the
// hole centres' extent in program coordinates.
struct Placement {
  Origin origin;
  aco::Point2 zero;  // program X0 Y0, in input coordinates (mm)
  Extent extent;     // program coordinates (mm)
};
// Moves the holes so that the origin's point becomes X0 Y0.
Placement place_holes(aco::HoleSet& holes, const Origin& origin);

// The program header comment that tells the operator where zero is and what
// the holes span, in program units:
// "ORIGIN: LOWER-LEFT OF HOLES" and "EXTENT X0.000..150.000 Y0.000..240.000 MM":
// two header lines, each short enough to stay whole on one line.
std::string origin_comment(const Placement& placement);
std::string extent_comment(const Placement& placement, gcode::Units units);

// The program header comment that records program zero in the input's
// coordinates ("PROGRAM ZERO AT DRAWING X21.100 Y25.500 MM"), and its reader:
// `verify --holes` moves the input holes by what the program states.
std::string zero_comment(const Placement& placement);
std::optional<aco::Point2> stated_zero(std::string_view program);

// One copy of a board on a panel: the board mirrored (X negated) if asked,
// turned about the drawing's zero by 0, 90, 180 or 270 degrees
// anticlockwise, then moved by `offset` (mm, drawing coordinates).
struct PanelCopy {
  aco::Point2 offset;
  int rotate_deg = 0;
  bool mirror = false;
};
// --panel COLSxROWS --pitch DX,DY: copy (c, r) moved by (c·DX, r·DY), row by row.
std::vector<PanelCopy> panel_grid(const std::string& cols_x_rows, const std::string& pitch);
// A panel file's JSON text: {"copies": [{"x_mm": 0, "y_mm": 0, "rotate_deg": 0, "mirror": false}, ...]}.
std::vector<PanelCopy> parse_panel(const std::string& json_text, const std::string& source);
// Every copy's holes, copy after copy, each copy's slot chains its own;
// `hole_source` (per hole, may be empty) is repeated to match.
aco::HoleSet panelize(const aco::HoleSet& board, const std::vector<PanelCopy>& copies,
                      std::vector<std::uint32_t>& hole_source);

// Drilling a board from its back (--side back): the holes mirrored about a
// line, the vertical line through the centre of the holes' extent unless
// --mirror-axis says x=V (the vertical line X = V) or y=V (the horizontal
// line Y = V), in input coordinates.
struct MirrorAxis {
  bool vertical = true;          // x = V: X mirrored; else y = V: Y mirrored
  std::optional<double> at;      // nullopt: the centre of the holes' extent
};
std::optional<MirrorAxis> mirror_axis_from_string(const std::string& text);
// Resolves the axis on these holes (its position, where not given).
MirrorAxis resolve_mirror_axis(const aco::HoleSet& holes, const MirrorAxis& axis);
// Mirrors the holes about the (resolved) axis.
void mirror_holes(aco::HoleSet& holes, const MirrorAxis& axis);
// Two alignment pin holes of `diameter_mm` on the (resolved) axis, each
// kAlignmentPinMarginMm beyond the outermost hole centre on that line's
// direction, so that they lie outside the board and the board turned over
// about the line lands on the same pins.
constexpr double kAlignmentPinMarginMm = 10.0;
aco::HoleSet alignment_pins(const aco::HoleSet& holes, const MirrorAxis& axis, double diameter_mm);

// Gives every hole without a diameter (0: a CSV row without one, a TSPLIB
// node) the one the user chose (--default-diameter); returns how many.
std::size_t fill_missing_diameters(aco::HoleSet& holes, double diameter_mm);

}  // namespace planning
