#include "planning/placement.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "aco/charconv.h"
#include "json.h"

namespace planning {

namespace {

std::string fmt3(double v) { return gcode::format_number(v, 3); }

}  // namespace

std::optional<Origin> origin_from_string(const std::string& text) {
  Origin o;
  if (text == "drawing") o.kind = OriginKind::Drawing;
  else if (text == "lower-left") o.kind = OriginKind::LowerLeft;
  else if (text == "center" || text == "centre") o.kind = OriginKind::Center;
  else if (text == "upper-left") o.kind = OriginKind::UpperLeft;
  else {
    const auto comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    auto number = [](const std::string& s, double& out) {
      std::size_t used = 0;
      try {
        out = std::stod(s, &used);
      } catch (const std::exception&) {
        return false;
      }
      return used == s.size() && std::isfinite(out);
    };
    o.kind = OriginKind::Point;
    if (!number(text.substr(0, comma), o.point.x) || !number(text.substr(comma + 1), o.point.y)) return std::nullopt;
  }
  return o;
}

std::string to_string(const Origin& o) {
  switch (o.kind) {
    case OriginKind::Drawing: return "drawing";
    case OriginKind::LowerLeft: return "lower-left";
    case OriginKind::Center: return "center";
    case OriginKind::UpperLeft: return "upper-left";
    case OriginKind::Point: return fmt3(o.point.x) + "," + fmt3(o.point.y);
  }
  return "?";
}

std::string describe(const Origin& o) {
  switch (o.kind) {
    case OriginKind::Drawing: return "DRAWING ZERO";
    case OriginKind::LowerLeft: return "LOWER-LEFT OF HOLES";
    case OriginKind::Center: return "CENTER OF HOLES";
    case OriginKind::UpperLeft: return "UPPER-LEFT OF HOLES";
    case OriginKind::Point: return "DRAWING POINT X" + fmt3(o.point.x) + " Y" + fmt3(o.point.y);
  }
  return "?";
}

Extent extent_of(const aco::HoleSet& holes) {
  if (holes.empty()) return {};
  Extent e{holes[0].center.x, holes[0].center.x, holes[0].center.y, holes[0].center.y};
  for (const aco::Hole& h : holes) {
    e.x_min = std::min(e.x_min, h.center.x);
    e.x_max = std::max(e.x_max, h.center.x);
    e.y_min = std::min(e.y_min, h.center.y);
    e.y_max = std::max(e.y_max, h.center.y);
  }
  return e;
}

Placement place_holes(aco::HoleSet& holes, const Origin& origin) {
  Placement p;
  p.origin = origin;
  const Extent e = extent_of(holes);
  switch (origin.kind) {
    case OriginKind::Drawing: p.zero = {0.0, 0.0}; break;
    case OriginKind::LowerLeft: p.zero = {e.x_min, e.y_min}; break;
    case OriginKind::Center: p.zero = {(e.x_min + e.x_max) / 2, (e.y_min + e.y_max) / 2}; break;
    case OriginKind::UpperLeft: p.zero = {e.x_min, e.y_max}; break;
    case OriginKind::Point: p.zero = origin.point; break;
  }
  if (p.zero.x != 0.0 || p.zero.y != 0.0) {
    for (aco::Hole& h : holes) {
      h.center.x -= p.zero.x;
      h.center.y -= p.zero.y;
    }
  }
  p.extent = extent_of(holes);
  return p;
}

std::string extent_comment(const Placement& p, gcode::Units units) {
  const bool inch = units == gcode::Units::Inch;
  auto c = [&](double mm) { return gcode::format_number(inch ? mm / 25.4 : mm, inch ? 4 : 3); };
  const Extent& e = p.extent;
  return "EXTENT X" + c(e.x_min) + ".." + c(e.x_max) + " Y" + c(e.y_min) + ".." + c(e.y_max) + (inch ? " IN" : " MM");
}

std::string origin_comment(const Placement& p) { return "ORIGIN: " + describe(p.origin); }

std::string zero_comment(const Placement& p) {
  // Six decimals: verify moves the input holes by this, and must land within
  // the program's own rounding of each position.
  return "PROGRAM ZERO AT DRAWING X" + gcode::format_number(p.zero.x, 6) + " Y" + gcode::format_number(p.zero.y, 6) + " MM";
}

std::optional<aco::Point2> stated_zero(std::string_view program) {
  // "(PROGRAM ZERO AT ...)", or "; PROGRAM ZERO AT ..." in a Marlin program.
  static constexpr std::string_view kTag = "PROGRAM ZERO AT DRAWING X";
  const auto at = program.find(kTag);
  if (at == std::string_view::npos) return std::nullopt;
  // Locale-free, as the emitter wrote it: "<x> Y<y> MM".
  std::string_view rest = program.substr(at + kTag.size(), 80);
  double x = 0, y = 0;
  auto rx = aco::from_chars(rest.data(), rest.data() + rest.size(), x);
  if (rx.ec != std::errc() || rest.substr(static_cast<std::size_t>(rx.ptr - rest.data()), 2) != " Y") return std::nullopt;
  rest.remove_prefix(static_cast<std::size_t>(rx.ptr - rest.data()) + 2);
  auto ry = aco::from_chars(rest.data(), rest.data() + rest.size(), y);
  if (ry.ec != std::errc() || rest.substr(static_cast<std::size_t>(ry.ptr - rest.data()), 3) != " MM") return std::nullopt;
  if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  return aco::Point2{x, y};
}

std::vector<PanelCopy> panel_grid(const std::string& text, const std::string& pitch) {
  int cols = 0, rows = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &cols, &x, &rows, &rest) != 3 || (x != 'x' && x != 'X') || cols < 1 || rows < 1 ||
      static_cast<long long>(cols) * rows > 10000) {
    throw UserError("--panel must be COLSxROWS (e.g. 3x2, at most 10000 copies) or a panel file (got \"" + text + "\")");
  }
  double dx = 0, dy = 0;
  if (pitch.empty() || std::sscanf(pitch.c_str(), "%lf,%lf%c", &dx, &dy, &rest) != 2 || !std::isfinite(dx) || !std::isfinite(dy)) {
    throw UserError("--panel " + text + " needs --pitch DX,DY in mm (the distance from one copy to the next)");
  }
  std::vector<PanelCopy> copies;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) copies.push_back({{c * dx, r * dy}, 0, false});
  }
  return copies;
}

std::vector<PanelCopy> parse_panel(const std::string& text, const std::string& path) {
  const json j = parse_json_text(text, path);
  if (!j.is_object() || !j.contains("copies") || !j["copies"].is_array() || j["copies"].empty()) {
    throw UserError(path, 1, "a panel file is {\"copies\": [{\"x_mm\": 0, \"y_mm\": 0, \"rotate_deg\": 0, \"mirror\": false}, ...]}");
  }
  std::vector<PanelCopy> copies;
  int k = 0;
  for (const json& c : j["copies"]) {
    const std::string where = path + " (copy " + std::to_string(++k) + ")";
    if (!c.is_object()) throw UserError(where, 0, "each copy is a JSON object");
    PanelCopy copy;
    copy.offset = {json_number(c, "x_mm", 0.0, where), json_number(c, "y_mm", 0.0, where)};
    const double turn = json_number(c, "rotate_deg", 0.0, where);
    if (turn != 0 && turn != 90 && turn != 180 && turn != 270) throw UserError(where, 0, "rotate_deg must be 0, 90, 180 or 270");
    copy.rotate_deg = static_cast<int>(turn);
    if (c.contains("mirror")) {
      if (!c["mirror"].is_boolean()) throw UserError(where, 0, "\"mirror\" must be true or false");
      copy.mirror = c["mirror"].get<bool>();
    }
    copies.push_back(copy);
  }
  return copies;
}

aco::HoleSet panelize(const aco::HoleSet& board, const std::vector<PanelCopy>& copies, std::vector<std::uint32_t>& hole_source) {
  std::uint32_t chains = 0;
  for (const aco::Hole& h : board) chains = std::max(chains, h.chain);
  aco::HoleSet out;
  out.reserve(board.size() * copies.size());
  std::vector<std::uint32_t> sources;
  for (std::size_t k = 0; k < copies.size(); ++k) {
    const PanelCopy& c = copies[k];
    for (std::size_t i = 0; i < board.size(); ++i) {
      aco::Hole h = board[i];
      double x = c.mirror ? -h.center.x : h.center.x, y = h.center.y;
      // Quarter turns exactly: no sin/cos rounding on a copy's coordinates.
      for (int q = 0; q < c.rotate_deg / 90; ++q) {
        const double t = x;
        x = -y;
        y = t;
      }
      h.center = {x + c.offset.x, y + c.offset.y};
      if (h.chain != 0) h.chain += static_cast<std::uint32_t>(k) * chains;
      out.push_back(std::move(h));
      if (!hole_source.empty()) sources.push_back(hole_source[i]);
    }
  }
  if (!hole_source.empty()) hole_source = std::move(sources);
  return out;
}

std::size_t fill_missing_diameters(aco::HoleSet& holes, double diameter_mm) {
  std::size_t filled = 0;
  for (aco::Hole& h : holes) {
    if (!(h.diameter > 0)) {
      h.diameter = diameter_mm;
      ++filled;
    }
  }
  return filled;
}

std::optional<MirrorAxis> mirror_axis_from_string(const std::string& text) {
  if (text.size() < 3 || text[1] != '=' || (text[0] != 'x' && text[0] != 'y' && text[0] != 'X' && text[0] != 'Y')) return std::nullopt;
  const std::string number = text.substr(2);
  double v = 0.0;
  auto r = aco::from_chars(number.data(), number.data() + number.size(), v);
  if (r.ec != std::errc() || r.ptr != number.data() + number.size() || !std::isfinite(v) || std::fabs(v) > 1e9) return std::nullopt;
  return MirrorAxis{text[0] == 'x' || text[0] == 'X', v};
}

MirrorAxis resolve_mirror_axis(const aco::HoleSet& holes, const MirrorAxis& axis) {
  if (axis.at) return axis;
  const Extent e = extent_of(holes);
  return MirrorAxis{axis.vertical, axis.vertical ? (e.x_min + e.x_max) / 2 : (e.y_min + e.y_max) / 2};
}

void mirror_holes(aco::HoleSet& holes, const MirrorAxis& axis) {
  const double at = axis.at.value_or(0.0);
  for (aco::Hole& h : holes) {
    if (axis.vertical) h.center.x = 2.0 * at - h.center.x;
    else h.center.y = 2.0 * at - h.center.y;
  }
}

aco::HoleSet alignment_pins(const aco::HoleSet& holes, const MirrorAxis& axis, double diameter_mm) {
  const Extent e = extent_of(holes);
  const double at = axis.at.value_or(0.0);
  aco::Hole a, b;
  a.diameter = b.diameter = diameter_mm;
  a.layer = b.layer = "ALIGNMENT PINS";
  if (axis.vertical) {
    a.center = {at, e.y_min - kAlignmentPinMarginMm};
    b.center = {at, e.y_max + kAlignmentPinMarginMm};
  } else {
    a.center = {e.x_min - kAlignmentPinMarginMm, at};
    b.center = {e.x_max + kAlignmentPinMarginMm, at};
  }
  return {a, b};
}

}  // namespace planning
