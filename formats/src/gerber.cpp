// Gerber drill data: RS-274X with X2 attributes (Ucamco's "Gerber Layer
// Format Specification", 2021.02 and later; KiCad, Ucamco, Proteus and others
// write drill files so), older RS-274X without attributes, and RS-274D whose
// apertures come in a separate list (--apertures).
//
// A hole is a flash (D03) of a round aperture; a flash of an obround or a
// rectangle, or of an aperture macro that draws a stadium (KiCad's oval
// holes), is a slot. Anything that draws (D01 strokes, G36 regions) is a
// copper, drawing, map or route layer — never drill data — and is refused
// whole: holes are never guessed from pads or symbols.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>

#include "aco/charconv.h"
#include "formats/readers.h"
#include "text.h"

namespace formats {

namespace {

constexpr double kInch = 25.4;

struct Aperture {
  enum class Shape { Circle, Obround, Rectangle, Polygon, Macro } shape = Shape::Circle;
  std::vector<double> params;  // file units (macro: its parameters as given), or mm when `mm`
  std::string macro;
  bool mm = false;             // sizes from an aperture list, already in mm
};

// What a flash of an aperture makes, in file units relative to the flash point.
struct Mark {
  bool slot = false;
  aco::Point2 from, to;  // slot ends, or the hole's centre in `from`
  double width = 0.0;
};

struct Flash {
  aco::Point2 at;  // file units
  int dcode = 0;
  std::uint32_t line = 0;
};

class GerberReader {
 public:
  GerberReader(const std::string& path, const InputOptions& options) : path_(path), options_(options) {}

  LoadedHoles run(std::string_view data);
  // Statements of an aperture list: RS-274X fragments (%FS, %MO, %AD) or rows
  // "D10 C 0.032", "D11,R,0.060,0.030", "12 ROUND 32 MIL" (see README).
  void aperture_list(const std::string& list_path, std::string_view text);

 private:
  [[noreturn]] void fail(std::uint32_t line, const std::string& what) const { throw InputError(path_, line, what); }
  [[noreturn]] void fail(const std::string& what) const { fail(line_, what); }
  void extended(std::string_view statement, std::string_view block);
  void word(std::string_view w);
  void define_aperture(std::string_view s);
  void file_function(std::string_view value);
  double coordinate(std::string_view digits, bool x) const;
  double number(std::string_view s) const;
  int code(std::string_view s) const;  // a G, D or M code, a count: a whole number 0..10^9
  double unit_mm() const { return metric_ ? 1.0 : kInch; }
  Mark mark_of(int dcode, const Aperture& a) const;
  Mark macro_mark(const Aperture& a) const;
  void flash(aco::Point2 at);
  void close_step_and_repeat();
  void emit(const Flash& f, aco::Point2 offset);

  std::string path_;
  const InputOptions& options_;
  std::string shown_path_;  // the file named in errors (the aperture list while reading it)
  std::uint32_t line_ = 1;
  // Coordinate format (%FS): digits after the point, leading or trailing zeros omitted.
  bool format_known_ = false, trailing_zeros_omitted_ = false, incremental_ = false;
  int x_int_ = 2, x_dec_ = 4, y_int_ = 2, y_dec_ = 4;  // RS-274D's usual 2.4 until told otherwise
  std::optional<bool> metric_set_;
  bool metric_ = false;
  std::map<int, Aperture> apertures_;
  std::map<std::string, std::string> macros_;  // name -> body statements
  int current_ = -1;
  int operation_ = 0;  // the modal D01/D02/D03 of deprecated coordinate-only words
  double x_ = 0, y_ = 0;
  bool region_ = false, clear_ = false;
  std::size_t draws_ = 0, regions_ = 0;
  std::uint32_t first_draw_line_ = 0;
  // %SR: flashes inside the block are repeated on a grid when it closes.
  bool in_sr_ = false;
  long sr_x_ = 1, sr_y_ = 1;
  double sr_i_ = 0, sr_j_ = 0;
  std::vector<Flash> sr_flashes_;
  std::string function_;  // %TF.FileFunction value
  bool ended_ = false;
  LoadedHoles out_;
};

double GerberReader::number(std::string_view s) const {
  double v = 0;
  if (!parse_number(s, v)) fail("\"" + std::string(s.substr(0, 40)) + "\" is not a number");
  return v;
}

int GerberReader::code(std::string_view s) const {
  int v = 0;
  auto r = aco::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || v < 0 || v > 1'000'000'000) {
    fail("\"" + std::string(s.substr(0, 20)) + "\" is not a code or count");
  }
  return v;
}

double GerberReader::coordinate(std::string_view text, bool x) const {
  if (text.find('.') != std::string_view::npos) return number(text);
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  const int ints = x ? x_int_ : y_int_, decs = x ? x_dec_ : y_dec_;
  if (text.empty() || text.size() > 18) fail("bad coordinate \"" + std::string(text) + "\"");
  long long digits = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) fail("bad coordinate \"" + std::string(text) + "\"");
    digits = digits * 10 + (c - '0');
  }
  double v = static_cast<double>(digits) / std::pow(10.0, decs);
  if (trailing_zeros_omitted_) v *= std::pow(10.0, ints + decs - static_cast<int>(text.size()));
  return negative ? -v : v;
}

void GerberReader::file_function(std::string_view value) {
  function_ = std::string(value);
  std::string lower(value);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.rfind("drillmap", 0) == 0) {
    fail("a drill map (%TF.FileFunction," + function_ + "): drawn symbols, not drill data; use the drill file itself");
  }
  if (lower.find("rout") != std::string::npos) {
    fail("a route file (%TF.FileFunction," + function_ + "): routing, not drilling");
  }
  if (lower.rfind("plated", 0) != 0 && lower.rfind("nonplated", 0) != 0) {
    fail("%TF.FileFunction," + function_ + ": this layer is not drill data (Plated or NonPlated ... Drill)");
  }
}

void GerberReader::define_aperture(std::string_view s) {
  // "ADD10C,0.8", "ADD16O,2.03X1.02", "ADD11R,0.024X0.080", "ADD12HorizOval,1.02X-0.15X0.48X0.15X-0.48X0"
  std::size_t i = 3;
  std::size_t j = i;
  while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
  if (j == i) fail("bad aperture definition \"" + std::string(s.substr(0, 40)) + "\"");
  const int dcode = code(s.substr(i, j - i));
  if (dcode < 10) fail("aperture numbers start at D10 (got D" + std::to_string(dcode) + ")");
  const std::size_t comma = s.find(',', j);
  const std::string name(s.substr(j, comma == std::string_view::npos ? std::string_view::npos : comma - j));
  Aperture a;
  if (name == "C") a.shape = Aperture::Shape::Circle;
  else if (name == "O") a.shape = Aperture::Shape::Obround;
  else if (name == "R") a.shape = Aperture::Shape::Rectangle;
  else if (name == "P") a.shape = Aperture::Shape::Polygon;
  else if (macros_.count(name)) {
    a.shape = Aperture::Shape::Macro;
    a.macro = name;
  } else {
    fail("aperture D" + std::to_string(dcode) + " uses \"" + name + "\", which is neither a standard aperture nor a macro defined before it");
  }
  if (comma != std::string_view::npos) {
    std::string_view rest = s.substr(comma + 1);
    std::size_t p = 0;
    while (p <= rest.size()) {
      std::size_t x = rest.find('X', p);
      const std::string_view part = rest.substr(p, x == std::string_view::npos ? std::string_view::npos : x - p);
      a.params.push_back(number(part));
      if (x == std::string_view::npos) break;
      p = x + 1;
    }
  }
  const std::size_t needed = a.shape == Aperture::Shape::Circle ? 1 : (a.shape == Aperture::Shape::Macro ? 0 : 2);
  if (a.params.size() < needed) fail("aperture D" + std::to_string(dcode) + " lacks its size");
  for (std::size_t k = 0; k < std::min<std::size_t>(a.params.size(), needed); ++k) {
    if (a.params[k] < 0) fail("aperture D" + std::to_string(dcode) + " has a negative size");
  }
  apertures_[dcode] = std::move(a);
}

void GerberReader::extended(std::string_view st, std::string_view block) {
  if (st.rfind("FS", 0) == 0) {
    // FS L|T A|I X<int><dec> Y<int><dec>
    trailing_zeros_omitted_ = st.find('T') != std::string_view::npos && st.find('T') < st.find('X');
    incremental_ = st.find('I') != std::string_view::npos && st.find('I') < st.find('X');
    const std::size_t x = st.find('X'), y = st.find('Y');
    auto digit = [&](std::size_t at) -> int {
      if (at >= st.size() || !std::isdigit(static_cast<unsigned char>(st[at]))) fail("bad format statement %" + std::string(st) + "*%");
      return st[at] - '0';
    };
    if (x == std::string_view::npos || y == std::string_view::npos) fail("bad format statement %" + std::string(st) + "*%");
    x_int_ = digit(x + 1), x_dec_ = digit(x + 2), y_int_ = digit(y + 1), y_dec_ = digit(y + 2);
    format_known_ = true;
  } else if (st == "MOMM" || st == "MOIN") {
    metric_ = st == "MOMM";
    metric_set_ = metric_;
  } else if (st.rfind("ADD", 0) == 0) {
    define_aperture(st);
  } else if (st.rfind("AM", 0) == 0) {
    const std::string name(trim(st.substr(2)));
    const std::size_t first = block.find('*');
    macros_[name] = std::string(first == std::string_view::npos ? std::string_view{} : block.substr(first + 1));
  } else if (st == "LPD" || st == "LPC") {
    clear_ = st == "LPC";
  } else if (st.rfind("SR", 0) == 0) {
    close_step_and_repeat();
    if (st.size() > 2) {
      // SRX<count>Y<count>I<step>J<step>
      auto field = [&](char letter) -> std::string_view {
        const std::size_t at = st.find(letter, 2);
        if (at == std::string_view::npos) fail("bad step and repeat %" + std::string(st) + "*%");
        std::size_t end = at + 1;
        while (end < st.size() && !std::isalpha(static_cast<unsigned char>(st[end]))) ++end;
        return st.substr(at + 1, end - at - 1);
      };
      sr_x_ = code(field('X'));
      sr_y_ = code(field('Y'));
      sr_i_ = number(field('I'));
      sr_j_ = number(field('J'));
      if (sr_x_ < 1 || sr_y_ < 1 || sr_x_ * sr_y_ > 1'000'000) fail("step and repeat counts out of range");
      in_sr_ = true;
    }
  } else if (st.rfind("TF.FileFunction,", 0) == 0) {
    file_function(st.substr(16));
  } else if (st.rfind("IPNEG", 0) == 0) {
    fail("a negative image (%IPNEG): not drill data");
  }
  // %TF/%TA/%TD/%TO attributes, %IN, %LN, %OF, %AS, %MI, %SF, %IR: no effect on where holes are.
}

void GerberReader::word(std::string_view w) {
  if (w.rfind("G04", 0) == 0 || w.rfind("G4 ", 0) == 0 || w == "G4") return;  // comment
  std::optional<double> x, y;
  std::optional<int> d;
  std::size_t i = 0;
  while (i < w.size()) {
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(w[i])));
    ++i;
    std::size_t start = i;
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    while (i < w.size() && (std::isdigit(static_cast<unsigned char>(w[i])) || w[i] == '.')) ++i;
    const std::string_view v = w.substr(start, i - start);
    if (v.empty() && letter != ' ') fail("unexpected \"" + std::string(w.substr(0, 40)) + "\"");
    switch (letter) {
      case 'G': {
        const int g = code(v);
        if (g == 4) return;  // "G04 ..." written without the leading zero
        if (g == 36) region_ = true;
        else if (g == 37) region_ = false;
        else if (g == 70) metric_ = false, metric_set_ = false;
        else if (g == 71) metric_ = true, metric_set_ = true;
        else if (g == 90) incremental_ = false;
        else if (g == 91) incremental_ = true;
        break;  // G01/G02/G03 interpolation, G74/G75 quadrants, G54/G55 before a D code: no position
      }
      case 'D': d = code(v); break;
      case 'X': x = coordinate(v, true); break;
      case 'Y': y = coordinate(v, false); break;
      case 'I': case 'J': break;  // arc centre offsets
      case 'M': {
        const int m = code(v);
        if (m == 2 || m == 0 || m == 30) ended_ = true;
        break;
      }
      case 'N': break;  // sequence numbers (RS-274D)
      case ' ': break;
      default: fail("unexpected \"" + std::string(w.substr(0, 40)) + "\"");
    }
  }
  if (d && *d >= 10) {
    if (!apertures_.count(*d)) {
      fail("aperture D" + std::to_string(*d) + " is not defined" +
           (options_.aperture_list.empty() && !format_known_ ? " (an RS-274D file needs its aperture list: --apertures FILE)" : ""));
    }
    current_ = *d;
    return;
  }
  if (d) operation_ = *d;
  if (!x && !y && !d) return;
  const double nx = x ? (incremental_ ? x_ + *x : *x) : x_;
  const double ny = y ? (incremental_ ? y_ + *y : *y) : y_;
  const int op = d ? *d : operation_;
  if (op == 1) {
    if (region_) ++regions_;
    else ++draws_;
    if (!first_draw_line_) first_draw_line_ = line_;
  } else if (op == 3) {
    flash({nx, ny});
  }
  x_ = nx;
  y_ = ny;
}

Mark GerberReader::macro_mark(const Aperture& a) const {
  // Substitute $n by the aperture's parameters; read circle (1), vector line
  // (20) and centre line (21) primitives. A single circle is a hole; a line
  // with round ends (KiCad's "HorizOval") is a slot; anything else cannot be drilled.
  const std::string& body = macros_.at(a.macro);
  auto value = [&](std::string_view t) -> double {
    t = trim(t);
    if (!t.empty() && t[0] == '$') {
      double index = 0;
      if (!parse_number(t.substr(1), index) || index < 1 || index > static_cast<double>(a.params.size())) {
        fail("aperture macro " + a.macro + " uses " + std::string(t) + ", which the aperture does not give");
      }
      return a.params[static_cast<std::size_t>(index) - 1];
    }
    double v = 0;
    if (!parse_number(t, v)) {
      fail("aperture macro " + a.macro + " computes \"" + std::string(t.substr(0, 30)) +
           "\"; acodrill reads macros of plain numbers and $n parameters only");
    }
    return v;
  };
  std::vector<std::array<double, 4>> circles;  // diameter, x, y, exposure
  std::vector<std::array<double, 6>> lines;    // width, x1, y1, x2, y2, exposure
  std::size_t other = 0;
  std::size_t p = 0;
  while (p < body.size()) {
    std::size_t star = body.find('*', p);
    if (star == std::string::npos) star = body.size();
    const std::string_view st = trim(std::string_view(body).substr(p, star - p));
    p = star + 1;
    if (st.empty() || st[0] == '0') continue;  // comment
    if (st[0] == '$') fail("aperture macro " + a.macro + " defines variables; acodrill reads plain macros only");
    std::vector<std::string_view> f;
    std::size_t q = 0;
    for (;;) {
      const std::size_t comma = st.find(',', q);
      f.push_back(st.substr(q, comma == std::string_view::npos ? std::string_view::npos : comma - q));
      if (comma == std::string_view::npos) break;
      q = comma + 1;
    }
    const int code = static_cast<int>(value(f[0]));
    auto rotate = [](double& px, double& py, double degrees) {
      if (degrees == 0) return;
      const double r = degrees * M_PI / 180.0, c = std::cos(r), s = std::sin(r);
      const double nx = px * c - py * s, ny = px * s + py * c;
      px = nx, py = ny;
    };
    if (code == 1 && f.size() >= 5) {
      double cx = value(f[3]), cy = value(f[4]);
      if (f.size() >= 6) rotate(cx, cy, value(f[5]));
      circles.push_back({value(f[2]), cx, cy, value(f[1])});
    } else if (code == 20 && f.size() >= 8) {
      double x1 = value(f[3]), y1 = value(f[4]), x2 = value(f[5]), y2 = value(f[6]);
      const double rot = value(f[7]);
      rotate(x1, y1, rot);
      rotate(x2, y2, rot);
      lines.push_back({value(f[2]), x1, y1, x2, y2, value(f[1])});
    } else if (code == 21 && f.size() >= 7) {
      // Centre line: a w x h rectangle, taken as a slot along its longer side (no round ends).
      const double w = value(f[2]), h = value(f[3]), rot = value(f[6]);
      double x1 = value(f[4]) - (w > h ? (w - h) / 2 : 0), y1 = value(f[5]) - (h > w ? (h - w) / 2 : 0);
      double x2 = value(f[4]) + (w > h ? (w - h) / 2 : 0), y2 = value(f[5]) + (h > w ? (h - w) / 2 : 0);
      rotate(x1, y1, rot);
      rotate(x2, y2, rot);
      lines.push_back({std::min(w, h), x1, y1, x2, y2, value(f[1])});
    } else {
      ++other;
    }
  }
  auto on = [](double exposure) { return exposure != 0.0; };
  Mark m;
  if (other == 0 && lines.empty() && circles.size() == 1 && on(circles[0][3])) {
    m.from = {circles[0][1], circles[0][2]};
    m.width = circles[0][0];
    return m;
  }
  if (other == 0 && lines.size() == 1 && on(lines[0][5])) {
    const auto& l = lines[0];
    bool ends_only = true;  // every circle is a round end of the line, as wide as it
    for (const auto& c : circles) {
      const bool at_end = (std::fabs(c[1] - l[1]) < 1e-9 && std::fabs(c[2] - l[2]) < 1e-9) ||
                          (std::fabs(c[1] - l[3]) < 1e-9 && std::fabs(c[2] - l[4]) < 1e-9);
      ends_only = ends_only && at_end && std::fabs(c[0] - l[0]) < 1e-9 && on(c[3]);
    }
    if (ends_only) {
      m.slot = true;
      m.width = l[0];
      m.from = {l[1], l[2]};
      m.to = {l[3], l[4]};
      return m;
    }
  }
  fail("aperture macro " + a.macro + " is flashed but draws neither a circle nor a slot; acodrill cannot drill it");
}

Mark GerberReader::mark_of(int dcode, const Aperture& a) const {
  Mark m;
  switch (a.shape) {
    case Aperture::Shape::Circle:
      m.width = a.params[0];
      return m;
    case Aperture::Shape::Obround:
    case Aperture::Shape::Rectangle: {
      // A slot along the longer side, as wide as the shorter (a square or a
      // circle-like obround: a slot of no length, one hole).
      const double w = a.params[0], h = a.params[1];
      m.slot = true;
      m.width = std::min(w, h);
      const double half = std::fabs(w - h) / 2;
      m.from = w >= h ? aco::Point2{-half, 0} : aco::Point2{0, -half};
      m.to = w >= h ? aco::Point2{half, 0} : aco::Point2{0, half};
      return m;
    }
    case Aperture::Shape::Polygon:
      fail("polygon aperture D" + std::to_string(dcode) + " is flashed: a polygon cannot be drilled");
    case Aperture::Shape::Macro:
      return macro_mark(a);
  }
  return m;
}

void GerberReader::flash(aco::Point2 at) {
  if (current_ < 0) fail("flash before any aperture is selected");
  if (clear_) fail("a flash of clear polarity (%LPC): it erases, so this is not drill data");
  Flash f{at, current_, line_};
  if (in_sr_) {
    sr_flashes_.push_back(f);
    return;
  }
  emit(f, {0, 0});
}

void GerberReader::emit(const Flash& f, aco::Point2 offset) {
  const Aperture& a = apertures_.at(f.dcode);
  const Mark m = mark_of(f.dcode, a);
  const double u = unit_mm(), au = a.mm ? 1.0 : u;
  const aco::Point2 at{(f.at.x + offset.x) * u, (f.at.y + offset.y) * u};  // mm
  const std::string layer = "D" + std::to_string(f.dcode);
  if (!m.slot) {
    if (!(m.width > 0)) fail(f.line, "aperture D" + std::to_string(f.dcode) + " has no size: not a drill");
    aco::Hole h;
    h.center = {at.x + m.from.x * au, at.y + m.from.y * au};
    h.diameter = m.width * au;
    h.layer = layer;
    h.source_line = f.line;
    out_.holes.push_back(std::move(h));
    check_limit(path_, f.line, out_.holes.size(), options_.dxf);
    return;
  }
  Slot s;
  s.from = {at.x + m.from.x * au, at.y + m.from.y * au};
  s.to = {at.x + m.to.x * au, at.y + m.to.y * au};
  s.width_mm = m.width * au;
  s.layer = layer;
  s.source_line = f.line;
  out_.slots.push_back(std::move(s));
  check_limit(path_, f.line, out_.slots.size(), options_.dxf);
}

void GerberReader::close_step_and_repeat() {
  if (!in_sr_) return;
  in_sr_ = false;
  for (long j = 0; j < sr_y_; ++j) {
    for (long i = 0; i < sr_x_; ++i) {
      for (const Flash& f : sr_flashes_) emit(f, {static_cast<double>(i) * sr_i_, static_cast<double>(j) * sr_j_});
    }
  }
  sr_flashes_.clear();
}

void GerberReader::aperture_list(const std::string& list_path, std::string_view text) {
  const std::string saved = path_;
  path_ = list_path;
  double list_unit = kInch;  // mm per size unit: inch unless a UNITS line or a suffix says
  auto unit_word = [](const std::string& t) -> double {
    if (t == "MM") return 1.0;
    if (t == "IN" || t == "INCH" || t == "\"") return kInch;
    if (t == "MIL" || t == "MILS" || t == "THOU") return kInch / 1000;
    return 0.0;
  };
  for_each_line(text, [&](std::uint32_t no, std::string_view raw) {
    line_ = no;
    std::string_view s = trim(raw);
    if (s.empty() || s[0] == '#' || s[0] == ';' || s.rfind("//", 0) == 0 || s.rfind("G04", 0) == 0) return true;
    if (s[0] == '%') {
      // RS-274X statements in the list: %FS, %MO, %AD (sizes then in the file's units).
      std::string_view st = s.substr(1);
      st = trim(st.substr(0, st.find('*')));  // the statement ends at '*'; a comment may follow '%'
      extended(st, st);
      return true;
    }
    std::string upper(s);
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    std::vector<std::string> f;
    std::string cur;
    for (char c : upper) {
      if (c == ',' || c == ' ' || c == '\t' || c == ';') {
        if (!cur.empty()) f.push_back(cur), cur.clear();
      } else {
        cur += c;
      }
    }
    if (!cur.empty()) f.push_back(cur);
    if (f[0] == "UNITS" || f[0] == "UNIT") {
      if (f.size() < 2 || unit_word(f[1]) == 0.0) fail("UNITS must be INCH, MM or MILS");
      list_unit = unit_word(f[1]);
      return true;
    }
    std::string code = f[0];
    if (code[0] == 'D') code.erase(0, 1);
    double dcode = 0;
    if (!parse_number(code, dcode) || dcode < 10 || dcode > 1e6 || f.size() < 3) {
      fail("expected \"D<code> <shape> <size> [<size>]\" (e.g. D10 C 0.032), found \"" + std::string(s.substr(0, 50)) + "\"");
    }
    const std::string& shape = f[1];
    Aperture a;
    a.mm = true;
    if (shape == "C" || shape == "CIRCLE" || shape == "ROUND" || shape == "CIRC") a.shape = Aperture::Shape::Circle;
    else if (shape == "R" || shape == "RECT" || shape == "RECTANGLE" || shape == "SQUARE" || shape == "SQ") a.shape = Aperture::Shape::Rectangle;
    else if (shape == "O" || shape == "OBLONG" || shape == "OVAL" || shape == "OBROUND") a.shape = Aperture::Shape::Obround;
    else fail("aperture shape \"" + f[1] + "\": expected C (round), R (rectangle) or O (obround)");
    std::vector<double> sizes;  // in list units until a unit says otherwise
    double unit = list_unit;
    for (std::size_t k = 2; k < f.size(); ++k) {
      std::string t = f[k];
      if (const double u = unit_word(t); u != 0.0) {
        unit = u;  // "32 MIL": the unit word follows the sizes it applies to
        continue;
      }
      for (const char* sfx : {"MILS", "MIL", "MM", "INCH", "IN", "\""}) {
        const std::string x(sfx);
        if (t.size() > x.size() && t.compare(t.size() - x.size(), x.size(), x) == 0) {
          unit = unit_word(x);
          t.resize(t.size() - x.size());
          break;
        }
      }
      double v = 0;
      if (!parse_number(t, v)) break;  // later words (comments, tool names) end the sizes
      if (v < 0) fail("negative aperture size");
      sizes.push_back(v);
    }
    if (sizes.empty()) fail("aperture D" + code + " lacks its size");
    if (a.shape != Aperture::Shape::Circle && sizes.size() < 2) sizes.push_back(sizes[0]);  // a square
    for (double v : sizes) a.params.push_back(v * unit);
    apertures_[static_cast<int>(dcode)] = a;
    return true;
  });
  path_ = saved;
  line_ = 1;
}

LoadedHoles GerberReader::run(std::string_view data) {
  out_.format = InputFormat::Gerber;
  metric_ = options_.input_units_given && options_.default_unit_mm == 1.0;
  if (!options_.aperture_list.empty()) aperture_list(options_.aperture_list_path, options_.aperture_list);
  std::size_t i = 0;
  const std::size_t n = data.size();
  while (i < n && !ended_) {
    const char c = data[i];
    if (c == '\n') {
      ++line_;
      ++i;
      continue;
    }
    if (c == '\r' || c == ' ' || c == '\t') {
      ++i;
      continue;
    }
    if (static_cast<unsigned char>(c) < 32) fail("control character in a Gerber file");
    const std::uint32_t start_line = line_;
    if (c == '%') {
      const std::size_t end = data.find('%', i + 1);
      if (end == std::string_view::npos) fail("file ends inside a %...% block");
      const std::string_view block = data.substr(i + 1, end - i - 1);
      // Statements of the block, each ending in '*'; an AM block is one macro.
      std::string compact;
      compact.reserve(block.size());
      for (char b : block) {
        if (b == '\n') ++line_;
        if (b != '\n' && b != '\r') compact += b;
      }
      const std::uint32_t block_end_line = line_;
      line_ = start_line;
      if (compact.rfind("AM", 0) == 0) {
        const std::size_t star = compact.find('*');
        extended(std::string_view(compact).substr(0, star), compact);
      } else {
        std::size_t p = 0;
        while (p < compact.size()) {
          std::size_t star = compact.find('*', p);
          if (star == std::string::npos) star = compact.size();
          const std::string_view st = trim(std::string_view(compact).substr(p, star - p));
          if (!st.empty()) extended(st, st);
          p = star + 1;
        }
      }
      line_ = block_end_line;
      i = end + 1;
      continue;
    }
    std::size_t star = data.find('*', i);
    if (star == std::string_view::npos) {
      const std::string_view rest = trim(data.substr(i));
      if (rest.empty()) break;
      star = n;
    }
    std::string w;
    for (std::size_t k = i; k < star; ++k) {
      if (data[k] == '\n') ++line_;
      else if (data[k] != '\r') w += data[k];
    }
    const std::uint32_t end_line = line_;
    line_ = start_line;
    word(trim(w));
    line_ = end_line;
    i = star + 1;
  }
  close_step_and_repeat();
  if (draws_ > 0 || regions_ > 0) {
    fail(first_draw_line_, "this Gerber draws " + std::to_string(draws_) + " stroke(s) and " + std::to_string(regions_) +
                               " region edge(s): it does not look like drill data (a copper, drawing, map or route "
                               "layer); acodrill drills flashed apertures only and never guesses holes from pads");
  }
  if (!function_.empty()) out_.drill_function = function_;
  out_.metric = metric_;
  return std::move(out_);
}

}  // namespace

bool looks_like_gerber(std::string_view head) {
  if (head.find("%FS") != std::string_view::npos || head.find("%MO") != std::string_view::npos ||
      head.find("%ADD") != std::string_view::npos || head.find("G04 ") != std::string_view::npos) {
    return true;
  }
  // RS-274D: words ending in '*' with D codes, no extended statements.
  return head.find("D03*") != std::string_view::npos || head.find("D02*") != std::string_view::npos ||
         head.find("D01*") != std::string_view::npos || head.find("G54D") != std::string_view::npos;
}

LoadedHoles parse_gerber(const std::string& path, std::string_view data, const InputOptions& options) {
  GerberReader reader(path, options);
  return reader.run(data);
}

}  // namespace formats
