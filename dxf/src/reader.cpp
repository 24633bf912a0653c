// Layers 2-4 of the DXF reader: sections → entities → holes.
//
// Only what makes a hole is interpreted: the HEADER's $INSUNITS and $ACADVER,
// BLOCK_RECORD handles (to recognise paper space), text STYLEs' fonts, BLOCK
// definitions, and CIRCLE / INSERT entities; besides, what a hole feature is
// drawn with (issue 82): ARCs, and the texts of TEXT, MTEXT, MULTILEADER,
// LEADER and DIMENSION. Everything else is skipped tag by tag, so an entity
// type we have never seen cannot break the read.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "aco/hole_set.h"
#include "contours.h"
#include "dxf/reader.h"
#include "tag_reader.h"

namespace dxf {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// Affine map x' = L x + t, as a 3x4 matrix.
struct Affine {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  Vec3 apply(const Vec3& p) const {
    Vec3 r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    return r;
  }
  Vec3 apply_linear(const Vec3& v) const {
    Vec3 r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return r;
  }
  // (this ∘ o)(x) = this(o(x))
  Affine then_after(const Affine& o) const {
    Affine r;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 4; ++j) {
        double v = (j == 3) ? m[i][3] : 0.0;
        for (int k = 0; k < 3; ++k) v += m[i][k] * o.m[k][j];
        r.m[i][j] = v;
      }
    }
    return r;
  }
};

// DXF's arbitrary-axis algorithm: the OCS axes of an extrusion direction N.
// (Reference: AutoCAD DXF Reference, "Arbitrary Axis Algorithm".) It is applied
// for any N, because real files carry normals like (2.6e-24, 1.7e-20, -1).
struct Ocs {
  Vec3 ax{1, 0, 0}, ay{0, 1, 0}, az{0, 0, 1};
};

Ocs make_ocs(Vec3 n, std::uint32_t line) {
  double len = norm(n);
  if (!(len > 1e-12)) throw ReadError(line, "extrusion direction (210/220/230) is a zero vector");
  for (double& c : n) c /= len;
  Ocs o;
  o.az = n;
  constexpr double kLimit = 1.0 / 64.0;
  Vec3 ax = (std::fabs(n[0]) < kLimit && std::fabs(n[1]) < kLimit) ? cross({0, 1, 0}, n) : cross({0, 0, 1}, n);
  double l = norm(ax);
  for (double& c : ax) c /= l;
  o.ax = ax;
  o.ay = cross(n, ax);
  return o;
}

Affine ocs_to_wcs(const Ocs& o) {
  Affine a;
  for (int i = 0; i < 3; ++i) {
    a.m[i][0] = o.ax[i];
    a.m[i][1] = o.ay[i];
    a.m[i][2] = o.az[i];
    a.m[i][3] = 0.0;
  }
  return a;
}

std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

struct Circle {
  Vec3 center{0, 0, 0};  // OCS
  double radius = 0.0;
  Vec3 extrusion{0, 0, 1};
  std::string_view layer;
  std::uint32_t line = 0;
};

struct Insert {
  std::string_view block;
  Vec3 point{0, 0, 0};  // OCS
  Vec3 scale{1, 1, 1};
  double rotation_deg = 0.0;
  int columns = 1, rows = 1;
  double column_spacing = 0.0, row_spacing = 0.0;
  Vec3 extrusion{0, 0, 1};
  std::string_view layer;
  std::uint32_t line = 0;
};

// A text entity as read (issue 82: hole callouts): its points in its space
// (OCS ignored: annotations lie in the drawing's plane).
struct TextEntity {
  std::string text;
  std::vector<Vec3> points;  // insertion point first, then leader or dimension points
  std::string_view layer, style, handle, annotation;  // annotation: a LEADER's MTEXT (340)
  bool gdt_font = false;    // its style's font is GD&T (gdt.shx, AIGDT): letters are symbols
  bool is_leader = false;   // a LEADER: its points go to the text it annotates
  std::uint32_t line = 0;
};

struct Block {
  std::string name;
  Vec3 base{0, 0, 0};
  std::vector<Circle> circles;
  std::vector<Insert> inserts;
  std::vector<contours::Piece> pieces;  // LINE, ARC, polylines, SPLINE, ELLIPSE: maybe round contours
  std::vector<TextEntity> texts;
  std::vector<std::pair<bool, std::size_t>> order;  // (is_insert, index): file order
  std::uint32_t line = 0;
};

// The fields of one entity, gathered from its tags.
struct Fields {
  std::string_view type;
  std::uint32_t line = 0;
  std::string_view layer = "0";
  std::string_view name;    // 2: block name
  std::string_view handle;  // 5
  std::string_view owner;   // 330
  Vec3 p{0, 0, 0};          // 10/20/30
  bool has_p = false;
  double radius = 0.0;  // 40
  bool has_radius = false;
  Vec3 scale{1, 1, 1};  // 41/42/43
  double rotation = 0.0;  // 50
  int columns = 1, rows = 1;  // 70/71 on INSERT
  double column_spacing = 0.0, row_spacing = 0.0;  // 44/45
  Vec3 extrusion{0, 0, 1};  // 210/220/230
  bool paper_space = false;  // 67 = 1
};

class Parser {
 public:
  Parser(std::string_view text, const ReadOptions& options, ReadResult& result)
      : tags_(text), options_(options), result_(result) {}

  void run();

 private:
  bool advance() {
    have_ = tags_.next(tag_);
    return have_;
  }
  bool at0(std::string_view v) const { return have_ && tag_.code == 0 && trim(tag_.value) == v; }
  void skip_to_next_0() {
    while (advance() && tag_.code != 0) {
    }
  }
  Fields read_fields(bool is_insert);
  void read_header();
  void read_tables();
  void read_blocks();
  void read_entities();
  void expand();
  void emit_circle(const Circle& c, const Affine& to_world);
  // A piece of a possible contour, when the entity at tag_ is one (nullopt: skip it).
  std::optional<contours::Piece> read_piece(std::string_view type);
  std::vector<Tag> read_tags();
  // A TEXT, MTEXT, MULTILEADER, LEADER or DIMENSION at tag_ (nullopt: in paper space, or no text).
  std::optional<TextEntity> read_text(std::string_view type);
  void place_text(const TextEntity& t, const Affine& to_world);
  void place_piece(const contours::Piece& p, const Affine& to_world);
  void add_round_contours(double unit);
  void check_units();
  void expand_insert(const Insert& ins, const Affine& parent, int depth);
  bool is_paper(const Fields& f) const { return is_paper(f.paper_space, f.owner); }
  bool is_paper(bool paper_space, std::string_view owner) const {
    return paper_space || (!owner.empty() && paper_records_.count(upper(owner)) != 0);
  }

  TagReader tags_;
  Tag tag_;
  bool have_ = false;
  const ReadOptions& options_;
  ReadResult& result_;

  int insunits_ = -1;
  std::unordered_set<std::string> paper_records_;  // handles of *Paper_Space* block records
  std::vector<Block> blocks_;
  std::unordered_map<std::string, std::size_t> block_index_;  // upper-case name → blocks_
  std::vector<Circle> model_circles_;
  std::vector<Insert> model_inserts_;
  std::vector<contours::Piece> model_pieces_;
  std::vector<TextEntity> model_texts_;
  std::unordered_set<std::string> gdt_styles_;  // upper-case names of text styles whose font is GD&T
  std::vector<contours::Placed> placed_;
  std::vector<DrawnArc> arcs_;  // drawing units until expand() scales them
  // Texts as placed (result_.texts, drawing units until expand() scales them)
  // and the LEADERs' points, joined to the texts they annotate by handle.
  static constexpr std::size_t kMaxTexts = 200'000;  // a callout past them is not read
  std::size_t texts_placed_ = 0;
  std::unordered_map<std::string, std::size_t> text_by_handle_;
  std::vector<std::pair<std::string, std::vector<aco::Point2>>> leaders_;
  std::size_t placed_points_ = 0;
  bool contours_cut_ = false;
  // Model-space entities in file order: (is_insert, index into the vector above).
  std::vector<std::pair<bool, std::size_t>> model_order_;
  bool saw_entities_ = false;
  bool saw_eof_ = false;
  std::string open_section_;
  std::uint32_t open_section_line_ = 0;

  // Expansion state.
  std::vector<std::size_t> stack_;
  std::size_t references_ = 0;
  std::size_t ellipses_ = 0;
  std::size_t tilted_ = 0;
  std::uint32_t first_ellipse_line_ = 0;
  std::size_t raw_holes_ = 0;
  aco::HoleSet raw_;
};

Fields Parser::read_fields(bool is_insert) {
  Fields f;
  f.type = trim(tag_.value);
  f.line = tag_.line;
  while (advance() && tag_.code != 0) {
    switch (tag_.code) {
      case 2: f.name = trim(tag_.value); break;
      case 5: f.handle = trim(tag_.value); break;
      case 8: f.layer = trim(tag_.value); break;
      case 10: f.p[0] = parse_double(tag_); f.has_p = true; break;
      case 20: f.p[1] = parse_double(tag_); break;
      case 30: f.p[2] = parse_double(tag_); break;
      case 40: f.radius = parse_double(tag_); f.has_radius = true; break;
      case 41: f.scale[0] = parse_double(tag_); break;
      case 42: f.scale[1] = parse_double(tag_); break;
      case 43: f.scale[2] = parse_double(tag_); break;
      case 44: if (is_insert) f.column_spacing = parse_double(tag_); break;
      case 45: if (is_insert) f.row_spacing = parse_double(tag_); break;
      case 50: f.rotation = parse_double(tag_); break;
      case 67: f.paper_space = parse_int(tag_, result_.diagnostics) == 1; break;
      case 70: if (is_insert) f.columns = parse_int(tag_, result_.diagnostics); break;
      case 71: if (is_insert) f.rows = parse_int(tag_, result_.diagnostics); break;
      case 210: f.extrusion[0] = parse_double(tag_); break;
      case 220: f.extrusion[1] = parse_double(tag_); break;
      case 230: f.extrusion[2] = parse_double(tag_); break;
      case 330: if (f.owner.empty()) f.owner = trim(tag_.value); break;
      default: break;
    }
  }
  return f;
}

bool is_text_type(std::string_view type) {
  return type == "TEXT" || type == "MTEXT" || type == "MULTILEADER" || type == "MLEADER" || type == "LEADER" || type == "DIMENSION";
}

bool is_piece_type(std::string_view type) {
  return type == "LINE" || type == "ARC" || type == "LWPOLYLINE" || type == "POLYLINE" || type == "SPLINE" || type == "ELLIPSE";
}

Circle to_circle(const Fields& f) {
  if (!f.has_radius) throw ReadError(f.line, "CIRCLE has no radius (group code 40)");
  if (!(f.radius > 0.0)) {
    throw ReadError(f.line, "CIRCLE radius must be positive, found " + std::to_string(f.radius));
  }
  Circle c;
  c.center = f.p;
  c.radius = f.radius;
  c.extrusion = f.extrusion;
  c.layer = f.layer;
  c.line = f.line;
  return c;
}

Insert to_insert(const Fields& f) {
  if (f.name.empty()) throw ReadError(f.line, "INSERT names no block (group code 2)");
  if (f.columns < 1 || f.rows < 1) {
    throw ReadError(f.line, "INSERT array of " + std::to_string(f.columns) + " x " + std::to_string(f.rows) +
                                " (group codes 70/71) must be at least 1 x 1");
  }
  Insert ins;
  ins.block = f.name;
  ins.point = f.p;
  ins.scale = f.scale;
  // LibreCAD writes a Z scale of 0; a zero Z scale only flattens Z, which a
  // drill hole does not have, so read it as 1 (as ezdxf does).
  if (ins.scale[2] == 0.0) ins.scale[2] = 1.0;
  ins.rotation_deg = f.rotation;
  ins.columns = f.columns;
  ins.rows = f.rows;
  ins.column_spacing = f.column_spacing;
  ins.row_spacing = f.row_spacing;
  ins.extrusion = f.extrusion;
  ins.line = f.line;
  return ins;
}

std::vector<Tag> Parser::read_tags() {
  std::vector<Tag> tags;
  while (advance() && tag_.code != 0) tags.push_back(tag_);
  return tags;
}

std::optional<contours::Piece> Parser::read_piece(std::string_view type) {
  contours::Piece p;
  p.kind = type;
  p.line = tag_.line;
  p.layer = "0";
  std::vector<Tag> tags = read_tags();
  bool paper = false;
  std::string_view owner;
  for (const Tag& t : tags) {
    if (t.code == 8) p.layer = trim(t.value);
    if (t.code == 67) paper = parse_int(t, result_.diagnostics) == 1;
    if (t.code == 330 && owner.empty()) owner = trim(t.value);
    if (t.code == 210) p.extrusion[0] = parse_double(t);
    if (t.code == 220) p.extrusion[1] = parse_double(t);
    if (t.code == 230) p.extrusion[2] = parse_double(t);
  }
  if (is_paper(paper, owner)) {
    if (type == "POLYLINE") {
      while (at0("VERTEX")) read_tags();
      if (at0("SEQEND")) read_tags();
    }
    return std::nullopt;
  }
  auto number = [&](int code, double fallback) {
    for (const Tag& t : tags) {
      if (t.code == code) return parse_double(t);
    }
    return fallback;
  };

  if (type == "LINE") {
    p.extrusion = {0, 0, 1};  // LINE is in world coordinates
    const Vec3 a{number(10, 0), number(20, 0), number(30, 0)}, b{number(11, 0), number(21, 0), number(31, 0)};
    p.points = {a, b};
  } else if (type == "ARC") {
    contours::add_arc(p, {number(10, 0), number(20, 0), number(30, 0)}, number(40, 0), number(50, 0), number(51, 360));
    if (!(number(40, 0) > 0)) return std::nullopt;
    const double start = number(50, 0), end = number(51, 360);
    if (std::isfinite(end - start) && std::fabs(start) <= 1e9 && std::fabs(end) <= 1e9) {
      double span = std::fmod(end - start, 360.0);
      if (span <= 1e-12) span += 360.0;
      p.arc_center = {number(10, 0), number(20, 0), number(30, 0)};
      p.arc_radius = number(40, 0);
      p.arc_span_deg = span;
    }
  } else if (type == "ELLIPSE") {
    // World coordinates: centre, major axis end (relative), minor/major ratio, start and end parameters.
    const Vec3 c{number(10, 0), number(20, 0), number(30, 0)}, major{number(11, 0), number(21, 0), number(31, 0)};
    const Vec3 n = p.extrusion;
    const double ratio = number(40, 1), t0 = number(41, 0);
    const double raw_t1 = number(42, 2 * M_PI);
    if (std::fabs(t0) > 1e6 || std::fabs(raw_t1) > 1e6) return std::nullopt;
    double span = std::fmod(raw_t1 - t0, 2 * M_PI);
    if (span <= 1e-12) span += 2 * M_PI;
    const double t1 = t0 + span;
    const Vec3 minor_dir = cross(n, major);
    const double len = norm(minor_dir), major_len = norm(major);
    if (!(len > 0) || !(major_len > 0)) return std::nullopt;
    const int steps = std::max(4, static_cast<int>(std::ceil((t1 - t0) * 180.0 / M_PI / 5.0)));
    for (int i = 0; i <= steps; ++i) {
      const double t = t0 + (t1 - t0) * i / steps;
      Vec3 q{};
      for (int k = 0; k < 3; ++k) q[k] = c[k] + std::cos(t) * major[k] + std::sin(t) * ratio * major_len * minor_dir[k] / len;
      p.points.push_back(q);
    }
    p.extrusion = {0, 0, 1};
  } else if (type == "SPLINE") {
    int degree = 3;
    std::vector<double> knots, weights;
    std::vector<Vec3> control, fit;
    for (const Tag& t : tags) {
      switch (t.code) {
        case 71: degree = parse_int(t, result_.diagnostics); break;
        case 40: knots.push_back(parse_double(t)); break;
        case 41: weights.push_back(parse_double(t)); break;
        case 10: control.push_back({parse_double(t), 0, 0}); break;
        case 20: if (!control.empty()) control.back()[1] = parse_double(t); break;
        case 30: if (!control.empty()) control.back()[2] = parse_double(t); break;
        case 11: fit.push_back({parse_double(t), 0, 0}); break;
        case 21: if (!fit.empty()) fit.back()[1] = parse_double(t); break;
        case 31: if (!fit.empty()) fit.back()[2] = parse_double(t); break;
        default: break;
      }
    }
    p.points = contours::sample_spline(degree, knots, control, weights);
    if (p.points.empty()) p.points = fit;  // fit points lie on the curve
    p.extrusion = {0, 0, 1};
  } else if (type == "LWPOLYLINE" || type == "POLYLINE") {
    std::vector<Vec3> vertices;
    std::vector<double> bulges;
    int flag = 0;
    for (const Tag& t : tags) {
      if (t.code == 70) flag = parse_int(t, result_.diagnostics);
    }
    if (type == "LWPOLYLINE") {
      const double z = number(38, 0);
      for (const Tag& t : tags) {
        if (t.code == 10) vertices.push_back({parse_double(t), 0, z}), bulges.push_back(0);
        if (t.code == 20 && !vertices.empty()) vertices.back()[1] = parse_double(t);
        if (t.code == 42 && !bulges.empty()) bulges.back() = parse_double(t);
      }
    } else {
      const double z = number(30, 0);
      while (at0("VERTEX")) {
        const std::vector<Tag> v = read_tags();
        Vec3 q{0, 0, z};
        double bulge = 0;
        int vflag = 0;
        for (const Tag& t : v) {
          if (t.code == 10) q[0] = parse_double(t);
          if (t.code == 20) q[1] = parse_double(t);
          if (t.code == 30 && (flag & 8)) q[2] = parse_double(t);
          if (t.code == 42) bulge = parse_double(t);
          if (t.code == 70) vflag = parse_int(t, result_.diagnostics);
        }
        if (vflag & 16) continue;  // a spline frame's control point, not on the curve
        vertices.push_back(q);
        bulges.push_back(bulge);
      }
      if (at0("SEQEND")) read_tags();
      if (flag & (16 | 64)) return std::nullopt;  // meshes are no contours
      if (flag & 8) p.extrusion = {0, 0, 1};       // a 3D polyline is in world coordinates
    }
    if (vertices.size() < 2) return std::nullopt;
    const bool closed = (flag & 1) != 0;
    for (std::size_t i = 0; i + 1 < vertices.size(); ++i) contours::add_bulge(p, vertices[i], vertices[i + 1], bulges[i]);
    if (closed) {
      contours::add_bulge(p, vertices.back(), vertices.front(), bulges.back());
      if (p.points.size() > 1) p.points.pop_back();  // the first vertex again
      p.closed = true;
    }
  }
  if (p.points.size() < 2) return std::nullopt;
  return p;
}

void Parser::place_piece(const contours::Piece& p, const Affine& to_world) {
  const Affine m = to_world.then_after(ocs_to_wcs(make_ocs(p.extrusion, p.line)));
  if (p.arc_radius > 0 && arcs_.size() < options_.max_holes) {
    // The arc's circle seen from above, as emit_circle sees a circle: a circle
    // only under a uniform scale in a plane parallel to XY.
    const Vec3 c = m.apply(p.arc_center);
    const Vec3 u = m.apply_linear({p.arc_radius, 0, 0}), v = m.apply_linear({0, p.arc_radius, 0});
    const double lu = std::hypot(u[0], u[1]), lv = std::hypot(v[0], v[1]), tol = 1e-6 * std::max(lu, lv);
    if (std::fabs(lu - lv) <= tol && std::fabs(u[0] * v[0] + u[1] * v[1]) <= tol * lu && lu > 0 && std::isfinite(c[0]) &&
        std::isfinite(c[1])) {
      arcs_.push_back({{c[0], c[1]}, 2.0 * lu, p.arc_span_deg, std::string(p.layer), p.line});
    }
  }
  contours::Placed out;
  out.kind = p.kind;
  out.closed = p.closed;
  out.layer = p.layer;
  out.line = p.line;
  // Contours are looked for on at most this many points; a drawing past it
  // (block arrays of linework) keeps its CIRCLEs and is told the rest was not examined.
  constexpr std::size_t kMaxContourPoints = 5'000'000;
  if (placed_points_ + p.points.size() > kMaxContourPoints) {
    if (!contours_cut_) {
      contours_cut_ = true;
      result_.diagnostics.push_back({Severity::Warning, p.line,
                                     "more than 5000000 points on lines, arcs and curves: contours from here on are not "
                                     "examined for round holes"});
    }
    return;
  }
  out.points.reserve(p.points.size());
  for (const Vec3& q : p.points) {
    const Vec3 w = m.apply(q);
    if (!std::isfinite(w[0]) || !std::isfinite(w[1])) return;  // placed beyond the representable: no contour
    out.points.push_back({w[0], w[1]});
  }
  placed_points_ += out.points.size();
  placed_.push_back(std::move(out));
}

std::optional<TextEntity> Parser::read_text(std::string_view type) {
  TextEntity t;
  t.line = tag_.line;
  t.layer = "0";
  const std::vector<Tag> tags = read_tags();
  bool paper = false;
  std::string_view owner;
  std::string chunks, last;  // MTEXT: 3 (chunks of 250) then 1
  std::optional<Vec3> p11;
  std::vector<Vec3> points;  // LEADER, MULTILEADER, DIMENSION: every point given
  double measured = 0.0;
  bool has_measured = false;
  for (const Tag& g : tags) {
    switch (g.code) {
      case 1: last = std::string(g.value); break;
      case 3: if (type == "MTEXT") chunks += std::string(g.value); break;
      case 304: if (type == "MULTILEADER" || type == "MLEADER") chunks += std::string(g.value); break;
      case 5: t.handle = trim(g.value); break;
      case 7: t.style = trim(g.value); break;
      case 8: t.layer = trim(g.value); break;
      case 42: if (type == "DIMENSION") measured = parse_double(g), has_measured = true; break;
      case 67: paper = parse_int(g, result_.diagnostics) == 1; break;
      case 330: if (owner.empty()) owner = trim(g.value); break;
      case 340: if (type == "LEADER") t.annotation = trim(g.value); break;
      case 10: case 11: case 12: case 13: case 14: case 15: case 16:
        points.push_back({parse_double(g), 0, 0});
        break;
      case 20: case 21: case 22: case 23: case 24: case 25: case 26:
        if (!points.empty()) points.back()[1] = parse_double(g);
        if (g.code == 21 && !points.empty()) p11 = points.back();
        break;
      default: break;
    }
  }
  if (is_paper(paper, owner) || points.empty()) return std::nullopt;
  if (type == "LEADER") {
    t.is_leader = true;
    t.points = std::move(points);  // its vertices, the arrowhead first
    return t;
  }
  t.text = type == "MTEXT" ? chunks + last : type == "MULTILEADER" || type == "MLEADER" ? chunks : last;
  if (type == "DIMENSION") {
    // "<>" stands for the measured value; an empty text is that value alone.
    const std::string value = has_measured ? std::to_string(measured) : std::string();
    if (t.text.empty()) t.text = "<>";
    for (std::size_t at = t.text.find("<>"); at != std::string::npos; at = t.text.find("<>", at + value.size())) {
      t.text.replace(at, 2, value);
    }
  }
  if (t.text.empty()) return std::nullopt;
  // The insertion point first: a justified TEXT stands at its second point.
  if (type == "TEXT" && p11 && (std::fabs((*p11)[0]) > 0 || std::fabs((*p11)[1]) > 0)) t.points.push_back(*p11);
  else if (type == "DIMENSION" && p11) t.points.push_back(*p11);
  for (const Vec3& q : points) t.points.push_back(q);
  t.gdt_font = gdt_styles_.count(upper(t.style)) != 0;
  return t;
}

void Parser::place_text(const TextEntity& t, const Affine& to_world) {
  if (texts_placed_ >= kMaxTexts) return;
  DrawnText out;
  out.text = t.text;
  out.layer = std::string(t.layer);
  out.line = t.line;
  out.gdt_font = t.gdt_font;
  for (const Vec3& q : t.points) {
    const Vec3 w = to_world.apply(q);
    if (std::isfinite(w[0]) && std::isfinite(w[1])) out.anchors.push_back({w[0], w[1]});
  }
  if (out.anchors.empty()) return;
  ++texts_placed_;
  if (t.is_leader) {
    leaders_.push_back({std::string(t.annotation), std::move(out.anchors)});
    return;
  }
  if (!t.handle.empty()) text_by_handle_.emplace(upper(t.handle), result_.texts.size());
  result_.texts.push_back(std::move(out));
}

void Parser::read_header() {
  // Header variables: (9, $NAME) followed by its value tags, up to the next code 0.
  std::string_view variable;
  while (have_ && tag_.code != 0) {
    if (tag_.code == 9) {
      variable = trim(tag_.value);
    } else if (variable == "$INSUNITS" && tag_.code == 70) {
      insunits_ = parse_int(tag_, result_.diagnostics);
    } else if (variable == "$ACADVER" && tag_.code == 1) {
      result_.version = std::string(trim(tag_.value));
    }
    advance();
  }
}

void Parser::read_tables() {
  // Only BLOCK_RECORD entries matter: their handles tell which owner is paper space.
  while (have_ && !at0("ENDSEC") && !at0("EOF") && !at0("SECTION")) {
    if (tag_.code == 0 && trim(tag_.value) == "BLOCK_RECORD") {
      Fields f = read_fields(false);
      if (!f.handle.empty() && upper(f.name).rfind("*PAPER_SPACE", 0) == 0) {
        paper_records_.insert(upper(f.handle));
      }
    } else if (tag_.code == 0 && trim(tag_.value) == "STYLE") {
      // A text style whose font is a GD&T font (gdt.shx, AIGDT.ttf): its letters are symbols.
      std::string name, font;
      for (const Tag& g : read_tags()) {
        if (g.code == 2) name = upper(trim(g.value));
        if (g.code == 3 || g.code == 4) font += upper(trim(g.value)) + " ";
      }
      if (!name.empty() && font.find("GDT") != std::string::npos) gdt_styles_.insert(name);
    } else {
      skip_to_next_0();
    }
  }
}

void Parser::read_blocks() {
  Block* current = nullptr;
  bool current_is_paper = false;
  while (have_ && !at0("ENDSEC") && !at0("EOF") && !at0("SECTION")) {
    if (tag_.code != 0) {
      advance();
      continue;
    }
    std::string_view type = trim(tag_.value);
    if (type == "BLOCK") {
      Fields f = read_fields(false);
      std::string key = upper(f.name);
      if (key.empty()) throw ReadError(f.line, "BLOCK has no name (group code 2)");
      Block b;
      b.name = std::string(f.name);
      b.base = f.p;
      b.line = f.line;
      current_is_paper = key.rfind("*PAPER_SPACE", 0) == 0;
      auto [it, inserted] = block_index_.emplace(key, blocks_.size());
      if (!inserted) {
        result_.diagnostics.push_back({Severity::Warning, f.line,
                                       "block \"" + b.name + "\" is defined twice; the later definition is used"});
        blocks_[it->second] = std::move(b);
        current = &blocks_[it->second];
      } else {
        blocks_.push_back(std::move(b));
        current = &blocks_.back();
      }
    } else if (type == "ENDBLK") {
      current = nullptr;
      skip_to_next_0();
    } else if (type == "CIRCLE" && current != nullptr && !current_is_paper) {
      Fields f = read_fields(false);
      current->order.emplace_back(false, current->circles.size());
      current->circles.push_back(to_circle(f));
    } else if (type == "INSERT" && current != nullptr && !current_is_paper) {
      Fields f = read_fields(true);
      current->order.emplace_back(true, current->inserts.size());
      current->inserts.push_back(to_insert(f));
    } else if (current != nullptr && !current_is_paper && is_piece_type(type)) {
      if (auto piece = read_piece(type)) current->pieces.push_back(std::move(*piece));
    } else if (current != nullptr && !current_is_paper && is_text_type(type)) {
      if (auto text = read_text(type)) current->texts.push_back(std::move(*text));
    } else {
      skip_to_next_0();
    }
  }
}

void Parser::read_entities() {
  saw_entities_ = true;
  while (have_ && !at0("ENDSEC") && !at0("EOF") && !at0("SECTION")) {
    if (tag_.code != 0) {
      advance();
      continue;
    }
    std::string_view type = trim(tag_.value);
    if (type == "CIRCLE") {
      Fields f = read_fields(false);
      Circle c = to_circle(f);
      if (!is_paper(f)) {
        model_order_.emplace_back(false, model_circles_.size());
        model_circles_.push_back(c);
      }
    } else if (type == "INSERT") {
      Fields f = read_fields(true);
      Insert ins = to_insert(f);
      if (!is_paper(f)) {
        model_order_.emplace_back(true, model_inserts_.size());
        model_inserts_.push_back(ins);
      }
    } else if (is_piece_type(type)) {
      if (auto piece = read_piece(type)) model_pieces_.push_back(std::move(*piece));
    } else if (is_text_type(type)) {
      if (auto text = read_text(type)) model_texts_.push_back(std::move(*text));
    } else {
      skip_to_next_0();
    }
  }
}

void Parser::run() {
  if (!advance()) throw ReadError(0, "empty file: no DXF group codes");
  while (have_) {
    if (tag_.code != 0) {
      advance();
      continue;
    }
    std::string_view v = trim(tag_.value);
    if (v == "EOF") {
      saw_eof_ = true;
      break;
    }
    if (v == "ENDSEC") {
      open_section_.clear();
      advance();
      continue;
    }
    if (v != "SECTION") {
      if (open_section_.empty()) {
        throw ReadError(tag_.line, "expected SECTION or EOF, found \"" + std::string(v.substr(0, 40)) + "\"");
      }
      skip_to_next_0();
      continue;
    }
    const std::uint32_t section_line = tag_.line;
    if (!advance() || tag_.code != 2) {
      throw ReadError(section_line, "SECTION without a name (group code 2)");
    }
    std::string name = upper(trim(tag_.value));
    open_section_ = name;
    open_section_line_ = section_line;
    advance();
    if (name == "HEADER") {
      read_header();
    } else if (name == "TABLES") {
      read_tables();
    } else if (name == "BLOCKS") {
      read_blocks();
    } else if (name == "ENTITIES") {
      read_entities();
    } else {
      while (have_ && !at0("ENDSEC") && !at0("EOF") && !at0("SECTION")) skip_to_next_0();
    }
  }
  if (!saw_eof_) {
    if (!open_section_.empty()) {
      throw ReadError(open_section_line_, "file ends inside the " + open_section_ +
                                              " section with no ENDSEC (truncated file?)");
    }
    result_.diagnostics.push_back({Severity::Warning, 0, "no EOF marker at the end of the file"});
  }
  if (!saw_entities_ && blocks_.empty()) {
    throw ReadError(0, "no ENTITIES section: not a DXF drawing");
  }
  expand();
}

void Parser::emit_circle(const Circle& c, const Affine& to_world) {
  Ocs o = make_ocs(c.extrusion, c.line);
  Affine m = to_world.then_after(ocs_to_wcs(o));
  Vec3 center = m.apply(c.center);
  Vec3 u = m.apply_linear({c.radius, 0, 0});
  Vec3 v = m.apply_linear({0, c.radius, 0});
  // The hole is what the drill sees from above: the circle projected on XY.
  // It is a circle only if the two projected radius vectors are orthogonal and
  // equally long; otherwise a non-uniform scale or a tilted plane made it an ellipse.
  double lu = std::hypot(u[0], u[1]);
  double lv = std::hypot(v[0], v[1]);
  double dot = u[0] * v[0] + u[1] * v[1];
  double tol = 1e-6 * std::max(lu, lv);
  if (std::fabs(lu - lv) > tol || std::fabs(dot) > tol * std::max(lu, lv) || !(lu > 0.0)) {
    bool tilted = std::fabs(u[2]) > tol || std::fabs(v[2]) > tol;
    (tilted ? tilted_ : ellipses_)++;
    if (first_ellipse_line_ == 0) first_ellipse_line_ = c.line;
    return;
  }
  if (++raw_holes_ > options_.max_holes) {
    throw ReadError(c.line, "more than " + std::to_string(options_.max_holes) + " holes (" + options_.max_holes_named +
                                "); block arrays expand too far");
  }
  aco::Hole h;
  h.center = {center[0], center[1]};
  h.diameter = 2.0 * lu;
  // The circle's own layer, as ezdxf reports it. (AutoCAD draws layer-"0"
  // block content on the INSERT's layer, but that is display, and the
  // reference reader keeps the entity's layer.)
  h.layer = std::string(c.layer);
  h.source_line = c.line;
  raw_.push_back(std::move(h));
}

Affine insert_transform(const Insert& ins, const Vec3& base, int column, int row) {
  const double a = ins.rotation_deg * M_PI / 180.0;
  const double ca = std::cos(a), sa = std::sin(a);
  // MINSERT: the array offset is laid out along the rotated block axes, unscaled.
  const double ox = column * ins.column_spacing, oy = row * ins.row_spacing;
  Vec3 p{ins.point[0] + ca * ox - sa * oy, ins.point[1] + sa * ox + ca * oy, ins.point[2]};
  // block → OCS of the insert: scale about the base point, rotate about Z, move to p.
  Affine local;
  const double sx = ins.scale[0], sy = ins.scale[1], sz = ins.scale[2];
  local.m[0][0] = ca * sx; local.m[0][1] = -sa * sy; local.m[0][2] = 0;
  local.m[1][0] = sa * sx; local.m[1][1] = ca * sy;  local.m[1][2] = 0;
  local.m[2][0] = 0;       local.m[2][1] = 0;        local.m[2][2] = sz;
  for (int i = 0; i < 3; ++i) {
    local.m[i][3] = p[i] - (local.m[i][0] * base[0] + local.m[i][1] * base[1] + local.m[i][2] * base[2]);
  }
  return local;
}

void Parser::expand_insert(const Insert& ins, const Affine& parent, int depth) {
  auto it = block_index_.find(upper(ins.block));
  if (it == block_index_.end()) {
    throw ReadError(ins.line, "INSERT of undefined block \"" + std::string(ins.block) + "\"");
  }
  const std::size_t index = it->second;
  if (std::find(stack_.begin(), stack_.end(), index) != stack_.end()) {
    throw ReadError(ins.line, "block \"" + blocks_[index].name + "\" inserts itself (cyclic block reference)");
  }
  if (depth >= options_.max_block_depth) {
    throw ReadError(ins.line, "blocks nested more than " + std::to_string(options_.max_block_depth) +
                                  " deep at block \"" + blocks_[index].name + "\"");
  }
  const Block& block = blocks_[index];
  if (block.order.empty() && block.pieces.empty() && block.texts.empty()) {
    // Nothing to place: count the references without composing a transform each.
    references_ += static_cast<std::size_t>(ins.rows) * static_cast<std::size_t>(ins.columns);
    if (references_ > options_.max_block_references) {
      throw ReadError(ins.line, "more than " + std::to_string(options_.max_block_references) +
                                    " block references expanded (the expansion limit)");
    }
    return;
  }
  const Affine to_parent_ocs = ocs_to_wcs(make_ocs(ins.extrusion, ins.line));
  stack_.push_back(index);
  for (int r = 0; r < ins.rows; ++r) {
    for (int c = 0; c < ins.columns; ++c) {
      if (++references_ > options_.max_block_references) {
        throw ReadError(ins.line, "more than " + std::to_string(options_.max_block_references) +
                                      " block references expanded (the expansion limit)");
      }
      Affine m = parent.then_after(to_parent_ocs).then_after(insert_transform(ins, block.base, c, r));
      for (auto [is_insert, i] : block.order) {
        if (is_insert) expand_insert(block.inserts[i], m, depth + 1);
        else emit_circle(block.circles[i], m);
      }
      for (const contours::Piece& p : block.pieces) place_piece(p, m);
      for (const TextEntity& t : block.texts) place_text(t, m);
    }
  }
  stack_.pop_back();
}

void Parser::expand() {
  // File order, with each INSERT's holes where the INSERT stands (as ezdxf lists them).
  Affine identity;
  for (auto [is_insert, i] : model_order_) {
    if (is_insert) expand_insert(model_inserts_[i], identity, 0);
    else emit_circle(model_circles_[i], identity);
  }
  for (const contours::Piece& p : model_pieces_) place_piece(p, identity);
  for (const TextEntity& t : model_texts_) place_text(t, identity);
  // A LEADER's points belong to the MTEXT it annotates: where the callout points.
  for (auto& [annotation, points] : leaders_) {
    auto it = text_by_handle_.find(upper(annotation));
    if (it == text_by_handle_.end()) continue;
    std::vector<aco::Point2>& anchors = result_.texts[it->second].anchors;
    anchors.insert(anchors.end(), points.begin(), points.end());
  }
  leaders_.clear();
  if (ellipses_ > 0) {
    result_.diagnostics.push_back(
        {Severity::Warning, first_ellipse_line_,
         std::to_string(ellipses_) + " block circle(s) under a non-uniform scale are ellipses, not holes; skipped"});
  }
  if (tilted_ > 0) {
    result_.diagnostics.push_back({Severity::Warning, first_ellipse_line_,
                                   std::to_string(tilted_) +
                                       " circle(s) not parallel to the XY plane are not drillable from above; skipped"});
  }

  // Units.
  double unit = options_.default_unit_mm;
  if (insunits_ > 0) {
    unit = insunits_to_mm(insunits_);
    if (unit == 0.0) {
      result_.diagnostics.push_back({Severity::Warning, 0,
                                     "unknown $INSUNITS " + std::to_string(insunits_) + "; millimetres assumed"});
      unit = options_.default_unit_mm;
    }
  }
  if (options_.units_override_mm > 0) unit = options_.units_override_mm;
  result_.unit_mm = unit;

  // Scale and filter, then drop exact duplicates (same centre and diameter within 1e-6 mm).
  constexpr double kTol = 1e-6;
  aco::HoleSet& out = result_.holes;
  out.reserve(raw_.size());
  for (aco::Hole& h : raw_) {
    h.center.x *= unit;
    h.center.y *= unit;
    h.diameter *= unit;
    if (!std::isfinite(h.center.x) || !std::isfinite(h.center.y) || !std::isfinite(h.diameter)) {
      throw ReadError(h.source_line, "circle lies outside the representable range");
    }
    if (!selected(h, options_)) {
      ++result_.skipped_by_filter;
      continue;
    }
    out.push_back(std::move(h));
  }
  result_.duplicates_removed = aco::remove_duplicate_holes(out, kTol);
  raw_.clear();
  for (DrawnArc& a : arcs_) {
    a.center.x *= unit, a.center.y *= unit, a.diameter *= unit;
    // The layer filter holds for arcs too (a part chosen by its layers); the diameter range does not.
    const bool on_layer = options_.layers.empty() ||
                          std::any_of(options_.layers.begin(), options_.layers.end(),
                                      [&](const std::string& pattern) { return wildcard_match(pattern, a.layer); });
    if (std::isfinite(a.center.x) && std::isfinite(a.center.y) && std::isfinite(a.diameter) && on_layer) {
      result_.arcs.push_back(std::move(a));
    }
  }
  arcs_.clear();
  for (DrawnText& t : result_.texts) {
    for (aco::Point2& q : t.anchors) q.x *= unit, q.y *= unit;
  }
  add_round_contours(unit);
  check_units();
}

void Parser::add_round_contours(double unit) {
  const std::vector<contours::Found> found = contours::round_loops(placed_, options_.round_tolerance);
  placed_.clear();
  if (found.empty()) return;
  // The CIRCLEs' holes by X, to find a contour drawn on one (one hole).
  std::vector<std::pair<double, std::size_t>> by_x;
  for (std::size_t i = 0; i < result_.holes.size(); ++i) by_x.push_back({result_.holes[i].center.x, i});
  std::sort(by_x.begin(), by_x.end());
  std::map<std::string, std::size_t> kinds;
  std::uint32_t first_line = 0;
  for (const contours::Found& f : found) {
    aco::Hole h;
    h.center = {f.center.x * unit, f.center.y * unit};
    h.diameter = f.diameter * unit;
    h.layer = f.layer;
    h.source_line = f.line;
    const double tol = options_.round_tolerance * h.diameter / 2;
    bool on_circle = false;
    for (auto it = std::lower_bound(by_x.begin(), by_x.end(), std::make_pair(h.center.x - tol, std::size_t{0}));
         it != by_x.end() && it->first <= h.center.x + tol && !on_circle; ++it) {
      const aco::Hole& c = result_.holes[it->second];
      on_circle = aco::euclidean(c.center, h.center) <= tol && std::fabs(c.diameter - h.diameter) <= 2 * tol;
    }
    if (on_circle) continue;  // drawn twice: the CIRCLE is the hole
    ++result_.round_contours;
    ++kinds[f.kinds];
    if (first_line == 0) first_line = f.line;
    if (!options_.round_contours) continue;
    if (!selected(h, options_)) {
      ++result_.skipped_by_filter;
      continue;
    }
    ++result_.round_contour_holes;
    result_.holes.push_back(std::move(h));
  }
  for (const auto& [kind, n] : kinds) {
    result_.round_contour_kinds += (result_.round_contour_kinds.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  }
  if (result_.round_contours > 0 && !options_.round_contours) {
    result_.diagnostics.push_back({Severity::Warning, first_line,
                                   std::to_string(result_.round_contours) + " round closed contour(s) drawn without a CIRCLE (" +
                                       result_.round_contour_kinds + "): not read; --round-contours reads them as holes"});
  }
  if (options_.round_contours) result_.duplicates_removed += aco::remove_duplicate_holes(result_.holes, 1e-6);
}

// A header that states its units wrongly (Onshape writes inch for a drawing
// made in mm): holes and an extent that make no sense in those units.
void Parser::check_units() {
  // Only a unit larger than the millimetre can blow a drawing up so.
  if (insunits_ <= 0 || insunits_to_mm(insunits_) <= 1.0 || options_.units_override_mm > 0 || result_.holes.empty()) return;
  std::vector<double> d;
  double x0 = result_.holes[0].center.x, x1 = x0, y0 = result_.holes[0].center.y, y1 = y0;
  for (const aco::Hole& h : result_.holes) {
    d.push_back(h.diameter);
    x0 = std::min(x0, h.center.x), x1 = std::max(x1, h.center.x);
    y0 = std::min(y0, h.center.y), y1 = std::max(y1, h.center.y);
  }
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  const double median = d[d.size() / 2], extent = std::max(x1 - x0, y1 - y0);
  if (median <= 50.0 && extent <= 2000.0) return;
  const char* name = insunits_ == 1 ? "inch" : insunits_ == 2 ? "feet" : insunits_ == 4 ? "mm" : insunits_ == 5 ? "cm" : insunits_ == 6 ? "m" : "its unit";
  char text[320];
  std::snprintf(text, sizeof text,
                "the drawing says its unit is %s ($INSUNITS %d), which makes its holes D%.1f mm (median) over %.0f mm: "
                "if it was drawn in another unit (Onshape writes inch for mm drawings), give --dxf-units mm",
                name, insunits_, median, extent);
  result_.diagnostics.push_back({Severity::Warning, 0, text});
}

void check_text_encoding(std::string_view data) {
  if (data.size() >= 2 && ((static_cast<unsigned char>(data[0]) == 0xFF && static_cast<unsigned char>(data[1]) == 0xFE) ||
                           (static_cast<unsigned char>(data[0]) == 0xFE && static_cast<unsigned char>(data[1]) == 0xFF))) {
    throw ReadError(1, "UTF-16 text is not a DXF encoding; save the drawing as ASCII DXF");
  }
  std::string_view head = data.substr(0, 4096);
  std::size_t nul = head.find('\0');
  if (nul != std::string_view::npos) {
    std::uint32_t line = 1 + static_cast<std::uint32_t>(std::count(head.begin(), head.begin() + nul, '\n'));
    bool utf16 = head.size() >= 4 && (head[1] == '\0' || head[0] == '\0');
    throw ReadError(line, utf16 ? "UTF-16 text is not a DXF encoding; save the drawing as ASCII DXF"
                                : "binary data in a text DXF (not a DXF file?)");
  }
}

constexpr std::string_view kBinarySentinel{"AutoCAD Binary DXF\r\n\x1a\0", 22};

}  // namespace

double insunits_to_mm(int code) {
  switch (code) {
    case 1: return 25.4;            // inches
    case 2: return 304.8;           // feet
    case 3: return 1609344.0;       // miles
    case 4: return 1.0;             // millimetres
    case 5: return 10.0;            // centimetres
    case 6: return 1000.0;          // metres
    case 7: return 1e6;             // kilometres
    case 8: return 25.4e-6;         // microinches
    case 9: return 25.4e-3;         // mils
    case 10: return 914.4;          // yards
    case 11: return 1e-7;           // angstroms
    case 12: return 1e-6;           // nanometres
    case 13: return 1e-3;           // microns
    case 14: return 100.0;          // decimetres
    case 15: return 10000.0;        // decametres
    case 16: return 100000.0;       // hectometres
    case 17: return 1e12;           // gigametres
    case 18: return 1.495978707e14; // astronomical units
    case 19: return 9.4607304725808e18;  // light years
    case 20: return 3.08567758149137e19; // parsecs
    case 21: return 1200.0 / 3937.0 * 1000.0;  // US survey feet
    case 22: return 1000.0 / 39.37;            // US survey inches
    case 23: return 3600.0 / 3937.0 * 1000.0;  // US survey yards
    case 24: return 1609347.218694;            // US survey miles
    default: return 0.0;
  }
}

bool selected(const aco::Hole& hole, const ReadOptions& options) {
  constexpr double kTol = 1e-6;
  if (hole.diameter < options.min_diameter_mm - kTol || hole.diameter > options.max_diameter_mm + kTol) return false;
  if (options.layers.empty()) return true;
  for (const std::string& pattern : options.layers) {
    if (wildcard_match(pattern, hole.layer)) return true;
  }
  return false;
}

bool wildcard_match(std::string_view pattern, std::string_view text) {
  // Iterative matcher with one backtrack point for the last '*': linear in practice.
  std::size_t p = 0, t = 0, star = std::string_view::npos, mark = 0;
  auto eq = [](char a, char b) {
    return std::toupper(static_cast<unsigned char>(a)) == std::toupper(static_cast<unsigned char>(b));
  };
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || (pattern[p] != '*' && eq(pattern[p], text[t])))) {
      ++p;
      ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

bool looks_like_dxf(std::string_view head) {
  if (head.substr(0, kBinarySentinel.size()) == kBinarySentinel) return true;
  // First tag "0 / SECTION", after optional 999 comments and padding.
  TagReader tags(head);
  Tag t;
  try {
    for (int i = 0; i < 50 && tags.next(t); ++i) {
      if (t.code == 0) return trim(t.value) == "SECTION";
    }
  } catch (const ReadError&) {
  }
  return false;
}

ReadResult read_holes(std::string_view data, const ReadOptions& options) {
  ReadResult result;
  std::string converted;
  if (data.substr(0, kBinarySentinel.size()) == kBinarySentinel) {
    converted = binary_to_text(data);
    data = converted;
    result.binary = true;
  } else {
    check_text_encoding(data);
  }
  Parser parser(data, options, result);
  parser.run();
  return result;
}

}  // namespace dxf
