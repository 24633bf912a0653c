// Excellon drill files, as EDA tools write them (IPC-NC-349 and the Excellon
// CNC-7 manual; dialect notes from gerbv's drill.c behaviour and the fixtures).
//
// Numbers without a decimal point are implicit: with LZ (leading zeros kept)
// the digits are read from the left against the integer digits of the format;
// with TZ (trailing zeros kept, the usual case) or no statement, from the right
// against its decimal digits. The format is 2:4 for inch and 3:3 for metric
// unless a header says otherwise (";FILE_FORMAT=2:4", ";FORMAT={3:3/...}",
// "METRIC,TZ,000.000"); the last statement wins.
#include "formats/readers.h"

#include <charconv>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>

#include "aco/charconv.h"
#include "aco/hole_set.h"
#include "text.h"

namespace formats {

namespace {

constexpr double kInch = 25.4;

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

struct Format {
  bool metric = false;
  // What the file (or its nc_param.txt, or --excellon-format) stated; the rest is assumed.
  bool units_stated = false, zeros_stated = false, digits_stated = false;
  enum class Zeros { Unknown, Leading, Trailing } zeros = Zeros::Unknown;  // which zeros are KEPT
  int int_digits = 0, dec_digits = 0;  // 0: the default for the units
  int ints() const { return int_digits ? int_digits : (metric ? 3 : 2); }
  int decs() const { return dec_digits ? dec_digits : (metric ? 3 : 4); }
};

class Reader {
 public:
  Reader(const std::string& path, const InputOptions& options) : path_(path), options_(options) {}

  LoadedHoles run(std::string_view data);

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }
  void header_line(std::string_view s);
  void body_line(std::string_view s);
  void define_tool(std::string_view s);
  bool units_and_zeros(std::string_view s);
  void allegro_tool_comment(std::string_view s);
  void apply_nc_param(std::string_view text);
  void detect_zeros(std::string_view data);
  void check_plausible();
  double coordinate(std::string_view digits) const;
  double unit_mm() const { return fmt_.metric ? 1.0 : kInch; }
  void hit(double x, double y);
  // Reads a word's number starting at s[i] (after its letter); advances i.
  std::string_view number_at(std::string_view s, std::size_t& i) const {
    std::size_t start = i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
    return s.substr(start, i - start);
  }
  double plain_number(std::string_view s) const {
    double v = 0;
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    auto r = aco::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) {
      fail("\"" + std::string(s) + "\" is not a number");
    }
    return v;
  }

  std::string path_;
  const InputOptions& options_;
  std::uint32_t line_ = 0;
  Format fmt_;
  bool in_header_ = false;
  bool absolute_ = true;
  bool route_mode_ = false;  // G00/G01/G02/G03: routing, not drilling
  bool ended_ = false;
  std::map<int, double> tools_;  // number → diameter in file units
  // Allegro without a header: ";T01 Holesize 1. = 8.000000 ... MILS": number → diameter in mm.
  std::map<int, double> comment_tools_mm_;
  // The zeros the numbers' shapes say are kept, where the file does not state it.
  Format::Zeros detected_zeros_ = Format::Zeros::Unknown;
  mutable bool implicit_numbers_ = false;  // a coordinate without a decimal point was read (by coordinate())
  int tool_ = -1;                // -1: none selected yet; 0: unloaded (T0)
  double x_ = 0, y_ = 0;         // file units, before the G93 offset
  double off_x_ = 0, off_y_ = 0;
  // A routed path: plunged (M15) at path_[0], then straight (G01) or arc
  // (G02/G03) moves until the retract (M16/M17). Straight moves along one line
  // make an oval slot (KiCad and Mentor write oval pads so); anything else is
  // routing, which no drill can do.
  bool plunged_ = false, path_arc_ = false;
  std::uint32_t path_line_ = 0;
  std::vector<aco::Point2> route_;  // file units, offset applied
  void end_path();
  void add_slot(aco::Point2 from, aco::Point2 to, std::uint32_t line);
  // Step and repeat (Excellon CNC-7: M25 begins a pattern, M01 ends it, each
  // M02 X Y drills it again moved by X Y from the previous copy, M08 ends):
  // the pattern's holes and slots as first drilled, and where the last copy is.
  bool recording_ = false;
  std::size_t pattern_holes_ = 0, pattern_slots_ = 0;  // where the pattern starts in out_.holes / out_.slots
  std::size_t pattern_hole_end_ = 0, pattern_slot_end_ = 0;
  double step_x_ = 0, step_y_ = 0;  // mm, the last copy's offset from the pattern
  void repeat_pattern(std::string_view s);
  LoadedHoles out_;
};

void Reader::repeat_pattern(std::string_view s) {
  // "M02X1.5Y0": one more copy, moved by X Y (file units) from the last one.
  if (s.find("M70") != std::string_view::npos || s.find("M80") != std::string_view::npos ||
      s.find("M90") != std::string_view::npos) {
    fail("a swapped or mirrored step and repeat (M70/M80/M90) is not read; export the panel without it");
  }
  if (pattern_hole_end_ == pattern_holes_ && pattern_slot_end_ == pattern_slots_) {
    fail("M02 repeats a pattern, but no M25 ... M01 pattern came before it");
  }
  double dx = 0, dy = 0;
  std::size_t i = 3;
  while (i < s.size()) {
    const char letter = s[i++];
    std::string_view v = number_at(s, i);
    if (letter == 'X') dx = v.empty() ? 0.0 : coordinate(v);
    else if (letter == 'Y') dy = v.empty() ? 0.0 : coordinate(v);
    else if (letter != ' ') fail("unexpected \"" + std::string(s.substr(0, 40)) + "\" in a step and repeat");
  }
  step_x_ += dx * unit_mm();
  step_y_ += dy * unit_mm();
  for (std::size_t k = pattern_holes_; k < pattern_hole_end_; ++k) {
    aco::Hole h = out_.holes[k];
    h.center = {h.center.x + step_x_, h.center.y + step_y_};
    h.source_line = line_;
    out_.holes.push_back(std::move(h));
    check_limit(path_, line_, out_.holes.size(), options_.dxf);
  }
  for (std::size_t k = pattern_slots_; k < pattern_slot_end_; ++k) {
    Slot slot = out_.slots[k];
    slot.from = {slot.from.x + step_x_, slot.from.y + step_y_};
    slot.to = {slot.to.x + step_x_, slot.to.y + step_y_};
    slot.source_line = line_;
    out_.slots.push_back(std::move(slot));
    check_limit(path_, line_, out_.slots.size(), options_.dxf);
  }
}

void Reader::define_tool(std::string_view s) {
  // "T01C0.028", "T1F00S00C0.028", "T1C0.028F200S100" (in the body, as old OrCAD writes)
  std::size_t i = 1;
  std::string_view num = number_at(s, i);
  int number = 0;
  auto r = aco::from_chars(num.data(), num.data() + num.size(), number);
  if (num.empty() || r.ec != std::errc() || r.ptr != num.data() + num.size() || number < 0) {
    fail("bad tool number in \"" + std::string(s) + "\"");
  }
  std::optional<double> diameter;
  while (i < s.size()) {
    char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(s[i])));
    ++i;
    std::string_view v = number_at(s, i);
    if (v.empty()) fail("bad tool definition \"" + std::string(s) + "\"");
    if (letter == 'C') diameter = plain_number(v);
    // F (feed), S (speed), B, H, Z: machine settings, not geometry.
  }
  if (diameter) {
    if (*diameter < 0) fail("tool T" + std::to_string(number) + " has a negative diameter");
    tools_[number] = *diameter;
  }
  if (!in_header_) {
    if (!diameter && number != 0 && !tools_.count(number) && !comment_tools_mm_.count(number)) {
      fail("tool T" + std::to_string(number) + " is not defined");
    }
    tool_ = number;
  }
}

void Reader::header_line(std::string_view s) {
  if (s == "%" || s == "M95") {
    in_header_ = false;
    return;
  }
  if (units_and_zeros(s)) return;
  if (s[0] == 'T' && s.size() > 1 && std::isdigit(static_cast<unsigned char>(s[1]))) {
    define_tool(s);
    return;
  }
  if (s == "G91" || s == "ICI,ON") absolute_ = false;
  if (s == "G90" || s == "ICI,OFF") absolute_ = true;
  // Settings that do not move a hit: format version, incremental input,
  // tool detection, changer, header echo, and the like.
  static const char* const known[] = {"FMAT", "ICI", "VER", "DETECT", "ATC", "OM48", "G90", "G91", "G93", "M47", "AFS",
                                      "BLKD", "CCW", "CP", "DN", "DTMDIST", "FSB", "HBCK", "HPCK", "NCSL", "OSTOP", "PCKPARAM",
                                      "PF", "PVS", "R,", "SBK", "SG", "SIXM", "TCST", "UP", "VERSION", "Z+", "Z-", "ZA", "ZC", "ZS"};
  if (std::none_of(std::begin(known), std::end(known), [&](const char* k) { return starts_with(s, k); })) {
    out_.warnings.push_back({line_, "header line \"" + std::string(s.substr(0, 40)) + "\" is not one acodrill knows; read past"});
  }
}

// "INCH,LZ", "METRIC,TZ,000.000", "M71", "M72,TZ" (Upverter): units, the
// zeros kept and the format, on one line. False when the line is none of these.
bool Reader::units_and_zeros(std::string_view s) {
  const bool inch = starts_with(s, "INCH") || starts_with(s, "M72");
  const bool metric = starts_with(s, "METRIC") || starts_with(s, "M71");
  if (!inch && !metric) return false;
  const std::size_t word = starts_with(s, "M7") ? 3 : inch ? 4 : 6;
  if (s.size() > word && s[word] != ',' && s[word] != ' ') return false;  // "M715", "INCHES"?
  if (!options_.excellon_format) {
    fmt_.metric = metric;
    fmt_.units_stated = true;
  }
  std::size_t comma = s.find(',');
  while (comma != std::string_view::npos) {
    std::size_t next = s.find(',', comma + 1);
    std::string_view part = trim(s.substr(comma + 1, next == std::string_view::npos ? next : next - comma - 1));
    if (options_.excellon_format) {
      // --excellon-format wins over what the file says.
    } else if (part == "LZ") {
      fmt_.zeros = Format::Zeros::Leading;
      fmt_.zeros_stated = true;
    } else if (part == "TZ") {
      fmt_.zeros = Format::Zeros::Trailing;
      fmt_.zeros_stated = true;
    } else if (!part.empty() && part.find('.') != std::string_view::npos) {  // "000.000"
      fmt_.int_digits = static_cast<int>(part.find('.'));
      fmt_.dec_digits = static_cast<int>(part.size() - part.find('.') - 1);
      fmt_.digits_stated = true;
    }
    comma = next;
  }
  return true;
}

// Allegro's tool list as comments, where it writes no M48 header:
// ";T01 Holesize 1. = 8.000000 Tolerance = +2.000000/-2.000000 PLATED MILS Quantity = 1873".
void Reader::allegro_tool_comment(std::string_view s) {
  if (s.size() < 4 || s[1] != 'T' || s.find("Holesize") == std::string_view::npos) return;
  int number = 0;
  auto r = aco::from_chars(s.data() + 2, s.data() + s.size(), number);
  const std::size_t eq = s.find('=');
  if (r.ec != std::errc() || eq == std::string_view::npos) return;
  std::string_view rest = trim(s.substr(eq + 1));
  double size = 0;
  auto r2 = aco::from_chars(rest.data(), rest.data() + rest.size(), size);
  if (r2.ec != std::errc() || !(size > 0)) return;
  double mm = 0;
  if (s.find(" MILS") != std::string_view::npos) mm = size * kInch / 1000.0;
  else if (s.find(" MM") != std::string_view::npos) mm = size;
  else if (s.find(" INCH") != std::string_view::npos) mm = size * kInch;
  else fail("Allegro tool T" + std::to_string(number) + " gives no unit (MILS, MM or INCH) for its size");
  comment_tools_mm_[number] = mm;
}

// Allegro's nc_param.txt: the number format its drill files do not state.
void Reader::apply_nc_param(std::string_view text) {
  for_each_line(text, [&](std::uint32_t, std::string_view raw) {
    const std::string_view l = trim(raw);
    const std::size_t space = l.find_first_of(" \t");
    if (space == std::string_view::npos) return true;
    const std::string_view key = l.substr(0, space), value = trim(l.substr(space));
    int n = 0;
    if (key == "INTEGER-PLACES" && aco::from_chars(value.data(), value.data() + value.size(), n).ec == std::errc() && n > 0 && n < 8) {
      fmt_.int_digits = n;
      fmt_.digits_stated = true;
    } else if (key == "DECIMAL-PLACES" && aco::from_chars(value.data(), value.data() + value.size(), n).ec == std::errc() && n >= 0 && n < 8) {
      fmt_.dec_digits = n;
    } else if (key == "OUTPUT-UNITS") {
      fmt_.metric = value == "METRIC";
      fmt_.units_stated = true;
    } else if (key == "SUPPRESS-LEAD-ZEROES") {
      if (value == "YES") fmt_.zeros = Format::Zeros::Trailing;
      fmt_.zeros_stated = true;
    } else if (key == "SUPPRESS-TRAIL-ZEROES") {
      if (value == "YES") fmt_.zeros = Format::Zeros::Leading;
      fmt_.zeros_stated = true;
    }
    return true;
  });
  // Neither suppressed: every number has all its digits, read from the left.
  if (fmt_.zeros == Format::Zeros::Unknown && fmt_.zeros_stated) fmt_.zeros = Format::Zeros::Leading;
}

// Numbers keep the zeros the writer did not suppress: "X015Y0165" (leading
// zeros kept, lengths varying) can only be LZ; "X5850" with no number
// starting with 0 only TZ. Both kinds seen: fixed width, either reading.
void Reader::detect_zeros(std::string_view data) {
  std::size_t leading = 0, trailing = 0;
  for_each_line(data, [&](std::uint32_t, std::string_view raw) {
    const std::string_view l = trim(raw);
    if (l.empty() || l[0] == ';' || l[0] == 'T' || l[0] == 'M' || l[0] == 'F') return true;
    for (std::size_t i = 0; i < l.size(); ++i) {
      if (l[i] != 'X' && l[i] != 'Y') continue;
      std::size_t j = i + 1;
      if (j < l.size() && (l[j] == '-' || l[j] == '+')) ++j;
      const std::size_t start = j;
      while (j < l.size() && std::isdigit(static_cast<unsigned char>(l[j]))) ++j;
      if (j < l.size() && l[j] == '.') break;  // explicit decimals: no zeros to tell
      const std::string_view digits = l.substr(start, j - start);
      if (digits.size() >= 2 && digits.find_first_not_of('0') != std::string_view::npos) {
        if (digits.front() == '0') ++leading;
        if (digits.back() == '0') ++trailing;
      }
    }
    return true;
  });
  if (leading > 0 && trailing == 0) detected_zeros_ = Format::Zeros::Leading;
  if (trailing > 0 && leading == 0) detected_zeros_ = Format::Zeros::Trailing;
}

double Reader::coordinate(std::string_view text) const {
  if (text.find('.') != std::string_view::npos) return plain_number(text);
  implicit_numbers_ = true;
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  if (text.empty() || text.size() > 12) fail("bad coordinate \"" + std::string(text) + "\"");
  long long digits = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) fail("bad coordinate \"" + std::string(text) + "\"");
    digits = digits * 10 + (c - '0');
  }
  double v;
  const Format::Zeros zeros = fmt_.zeros != Format::Zeros::Unknown ? fmt_.zeros : detected_zeros_;
  if (zeros == Format::Zeros::Leading) {
    // Leading zeros kept, trailing dropped: the first int_digits digits are the integer part.
    const int total = fmt_.ints() + fmt_.decs();
    v = static_cast<double>(digits) * std::pow(10.0, total - static_cast<int>(text.size())) / std::pow(10.0, fmt_.decs());
  } else {
    v = static_cast<double>(digits) / std::pow(10.0, fmt_.decs());
  }
  return negative ? -v : v;
}

void Reader::hit(double x, double y) {
  if (tool_ < 0) fail("drill hit before any tool is selected");
  auto t = tools_.find(tool_);
  // T0 unloads the spindle, unless the header defined a tool 0 (some EDA
  // tools number from 0; gerbv and they read those hits).
  auto c = comment_tools_mm_.find(tool_);
  if (tool_ == 0 && t == tools_.end() && c == comment_tools_mm_.end()) fail("drill hit with no tool loaded (T0)");
  if (t == tools_.end() && c == comment_tools_mm_.end()) fail("tool T" + std::to_string(tool_) + " is not defined");
  aco::Hole h;
  const double u = unit_mm();
  h.center = {(x + off_x_) * u, (y + off_y_) * u};
  h.diameter = t != tools_.end() ? t->second * u : c->second;
  h.layer = "T" + std::to_string(tool_);
  h.source_line = line_;
  out_.holes.push_back(std::move(h));
  check_limit(path_, line_, out_.holes.size(), options_.dxf);
}

void Reader::body_line(std::string_view s) {
  if (s == "M30" || s == "M00" || s == "M02") {
    ended_ = true;
    return;
  }
  if (s == "M25") {
    recording_ = true;
    pattern_holes_ = pattern_hole_end_ = out_.holes.size();
    pattern_slots_ = pattern_slot_end_ = out_.slots.size();
    step_x_ = step_y_ = 0;
    return;
  }
  if (s == "M01" && recording_) {
    recording_ = false;
    pattern_hole_end_ = out_.holes.size();
    pattern_slot_end_ = out_.slots.size();
    return;
  }
  if (starts_with(s, "M02") && s.size() > 3) {
    repeat_pattern(s);
    return;
  }
  if (s == "M08") {
    recording_ = false;
    pattern_holes_ = pattern_hole_end_ = pattern_slots_ = pattern_slot_end_ = 0;
    step_x_ = step_y_ = 0;
    return;
  }
  if (s == "M48") {
    in_header_ = true;
    return;
  }
  if (s == "%" || s == "M95") return;  // end of a header we did not see start
  if (s[0] == 'T' && s.size() > 1 && std::isdigit(static_cast<unsigned char>(s[1]))) {
    define_tool(s);
    return;
  }
  if (units_and_zeros(s)) return;
  if (starts_with(s, "M15") || starts_with(s, "M14")) {
    route_mode_ = true;  // plunge of a routing tool: a path starts here
    end_path();
    plunged_ = true;
    path_arc_ = false;
    path_line_ = line_;
    route_.assign(1, {x_ + off_x_, y_ + off_y_});
    return;
  }
  if (starts_with(s, "M16") || starts_with(s, "M17")) {
    end_path();  // retract: the path is complete
    return;
  }
  // A block of words: G codes, X/Y coordinates, a repeat R.
  std::size_t i = 0;
  std::optional<double> wx, wy, ex, ey;  // the hit (or a slot's start), and a G85 slot's end
  std::optional<long long> repeat;
  bool slot = false, g93 = false, any = false;
  int motion = -1;  // G01/G02/G03 on this line
  while (i < s.size()) {
    const char letter = s[i];  // Excellon words are upper case; "x12a4" is garbage, not an A word
    if (letter == ' ') {
      ++i;
      continue;
    }
    ++i;
    std::string_view v = number_at(s, i);
    switch (letter) {
      case 'G': {
        const double code = plain_number(v);
        const int g = std::fabs(code) < 1e6 ? static_cast<int>(code) : -1;  // G1e33 is no G code acodrill knows
        if (g == 0 || g == 1 || g == 2 || g == 3) {
          route_mode_ = true;
          motion = g;
        }
        else if (g == 5 || g == 81) route_mode_ = false;
        else if (g == 85) slot = true;
        else if (g == 90) absolute_ = true;
        else if (g == 91) absolute_ = false;
        else if (g == 93) g93 = true;
        break;
      }
      case 'X': {
        if (v.empty()) fail("X without a number");
        const double c = coordinate(v);
        if (slot) {
          ex = c;  // the slot's end point
          break;
        }
        wx = c;
        any = true;
        break;
      }
      case 'Y': {
        if (v.empty()) fail("Y without a number");
        const double c = coordinate(v);
        if (slot) {
          ey = c;
          break;
        }
        wy = c;
        any = true;
        break;
      }
      case 'R': {
        if (v.empty()) fail("R without a count");
        const double count = plain_number(v);
        if (count < 0 || count > 1000000) fail("repeat count out of range");
        repeat = static_cast<long long>(count);
        break;
      }
      case 'M': case 'F': case 'S': case 'A': case 'I': case 'J': case 'D': case 'P': case 'Z':
        break;  // feeds, speeds, arc centres, canned messages: no hit position
      case ';':
        return;
      default:
        fail("unexpected \"" + std::string(s.substr(0, 40)) + "\"");
    }
  }
  if (g93) {
    // G93 X Y: the zero point is set here; later coordinates are relative to it.
    off_x_ = wx.value_or(0.0);
    off_y_ = wy.value_or(0.0);
    return;
  }
  if (slot) {
    // "X..Y..G85X..Y..": a canned slot from the first point to the second.
    double sx = x_, sy = y_;
    if (absolute_) {
      sx = wx.value_or(x_);
      sy = wy.value_or(y_);
    } else {
      sx += wx.value_or(0.0);
      sy += wy.value_or(0.0);
    }
    const double fx = absolute_ ? ex.value_or(sx) : sx + ex.value_or(0.0);
    const double fy = absolute_ ? ey.value_or(sy) : sy + ey.value_or(0.0);
    add_slot({sx + off_x_, sy + off_y_}, {fx + off_x_, fy + off_y_}, line_);
    x_ = fx;
    y_ = fy;
    return;
  }
  if (!any) return;
  if (repeat) {
    // R n X dx Y dy: n more hits, each offset from the previous one.
    for (long long k = 0; k < *repeat; ++k) {
      x_ += wx.value_or(0.0);
      y_ += wy.value_or(0.0);
      if (route_mode_) {
        if (plunged_) route_.push_back({x_ + off_x_, y_ + off_y_});
      } else {
        hit(x_, y_);
      }
    }
    return;
  }
  if (absolute_) {
    if (wx) x_ = *wx;
    if (wy) y_ = *wy;
  } else {
    x_ += wx.value_or(0.0);
    y_ += wy.value_or(0.0);
  }
  if (route_mode_) {
    if (plunged_) {
      if (motion == 2 || motion == 3) path_arc_ = true;
      route_.push_back({x_ + off_x_, y_ + off_y_});
    }
    return;  // a rapid (G00) or a routed move: no hit
  }
  hit(x_, y_);
}

void Reader::add_slot(aco::Point2 from, aco::Point2 to, std::uint32_t line) {
  if (tool_ < 0) fail("slot before any tool is selected");
  auto t = tools_.find(tool_);
  if (t == tools_.end()) fail("tool T" + std::to_string(tool_) + " is not defined");
  const double u = unit_mm();
  Slot slot;
  slot.from = {from.x * u, from.y * u};
  slot.to = {to.x * u, to.y * u};
  slot.width_mm = t->second * u;
  slot.layer = "T" + std::to_string(tool_);
  slot.source_line = line;
  out_.slots.push_back(std::move(slot));
  check_limit(path_, line_, out_.slots.size(), options_.dxf);
}

void Reader::end_path() {
  if (!plunged_) return;
  plunged_ = false;
  if (route_.size() < 2) return;  // plunged and retracted in place: nothing cut
  // Collinear straight moves: an oval slot between the extreme points.
  const aco::Point2 a = route_.front();
  std::size_t far = 0;
  double far_d = -1;
  for (std::size_t i = 0; i < route_.size(); ++i) {
    const double d = aco::euclidean(a, route_[i]);
    if (d > far_d) far_d = d, far = i;
  }
  const aco::Point2 b = route_[far];
  bool straight = !path_arc_ && far_d > 0;
  for (const aco::Point2& p : route_) {
    // Distance from the line a-b, in file units; a thousandth of the length is drawing noise.
    const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    if (far_d > 0 && std::fabs(cross) / far_d > 1e-3 * far_d + 1e-9) straight = false;
  }
  if (straight) {
    // The extremes along the line: project every point on a-b.
    double lo = 0, hi = 0;
    for (const aco::Point2& p : route_) {
      const double t = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (far_d * far_d);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    add_slot({a.x + lo * (b.x - a.x), a.y + lo * (b.y - a.y)}, {a.x + hi * (b.x - a.x), a.y + hi * (b.y - a.y)}, path_line_);
    return;
  }
  out_.skipped.push_back({path_line_, "routed path of " + std::to_string(route_.size() - 1) + " moves" +
                                          (path_arc_ ? " with arcs" : "") + " with T" + std::to_string(tool_) +
                                          ": routing, not drilling"});
}

LoadedHoles Reader::run(std::string_view data) {
  out_.format = InputFormat::Excellon;
  if (!options_.input_units_given) {
    fmt_.metric = false;  // Excellon's default is inch
  } else {
    fmt_.metric = options_.default_unit_mm == 1.0;
  }
  // nc_param.txt beside the file speaks only for Allegro's own drill files.
  const bool allegro = data.find("Holesize") != std::string_view::npos || data.find(";LEADER:") != std::string_view::npos;
  if (!options_.nc_param.empty() && allegro) apply_nc_param(options_.nc_param);
  if (options_.excellon_format) {
    const InputOptions::ExcellonFormat& f = *options_.excellon_format;
    fmt_.metric = f.metric;
    fmt_.int_digits = f.int_digits;
    fmt_.dec_digits = f.dec_digits;
    fmt_.zeros = f.leading_zeros_kept ? Format::Zeros::Leading : Format::Zeros::Trailing;
    fmt_.units_stated = fmt_.zeros_stated = fmt_.digits_stated = true;
  }
  detect_zeros(data);
  std::size_t pos = 0;
  while (pos < data.size() && !ended_) {
    std::size_t nl = data.find('\n', pos);
    if (nl == std::string_view::npos) nl = data.size();
    std::string_view raw = data.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_;
    // Comments carry format statements from KiCad (";FORMAT={2:4/ absolute / inch / keep zeros}")
    // and Altium (";FILE_FORMAT=2:4").
    std::string_view s = trim(raw);
    if (s.empty()) continue;
    if (s[0] == ';') {
      allegro_tool_comment(s);
      if (options_.excellon_format) continue;
      std::size_t f = s.find("FILE_FORMAT=");
      std::size_t g = s.find("FORMAT={");
      if (f != std::string_view::npos || g != std::string_view::npos) {
        std::string_view spec = f != std::string_view::npos ? s.substr(f + 12) : s.substr(g + 8);
        int a = 0, b = 0;
        if (std::sscanf(std::string(spec).c_str(), "%d:%d", &a, &b) == 2 && a > 0 && b > 0 && a < 8 && b < 8) {
          fmt_.int_digits = a;
          fmt_.dec_digits = b;
          fmt_.digits_stated = true;
        }
        if (g != std::string_view::npos) {
          if (spec.find("inch") != std::string_view::npos) fmt_.metric = false, fmt_.units_stated = true;
          if (spec.find("metric") != std::string_view::npos || spec.find("mm") != std::string_view::npos) {
            fmt_.metric = true;
            fmt_.units_stated = true;
          }
          if (spec.find("suppress trailing") != std::string_view::npos) fmt_.zeros = Format::Zeros::Leading, fmt_.zeros_stated = true;
          if (spec.find("suppress leading") != std::string_view::npos) fmt_.zeros = Format::Zeros::Trailing, fmt_.zeros_stated = true;
          if (spec.find("keep zeros") != std::string_view::npos) fmt_.zeros_stated = true;
        }
      }
      continue;
    }
    for (char c : s) {
      if (static_cast<unsigned char>(c) < 32 && c != '\t') fail("control character in an Excellon file");
    }
    if (in_header_) header_line(s);
    else body_line(s);
  }
  end_path();
  out_.metric = fmt_.metric;
  // An Allegro file without its nc_param.txt (nor a header giving units): the number format is only there.
  if (!comment_tools_mm_.empty() && implicit_numbers_ && !fmt_.units_stated && !fmt_.digits_stated && !fmt_.zeros_stated) {
    throw InputError(path_, 0, "an Allegro drill file without its nc_param.txt beside it: the number format is written only "
                               "there; put nc_param.txt beside the file, or give --excellon-format (e.g. inch,2:4,lz)");
  }
  // Say what was assumed, and check that the holes so read make sense.
  if (!fmt_.units_stated) {
    out_.assumptions.push_back(std::string("units: ") + (fmt_.metric ? "mm (from --input-units)" : "inch (the file does not say; Excellon's default)"));
  }
  if (implicit_numbers_) {
    if (!fmt_.zeros_stated) {
      const Format::Zeros z = detected_zeros_;
      out_.assumptions.push_back(z == Format::Zeros::Leading    ? "zeros: leading zeros kept (the numbers' shapes say so)"
                                 : z == Format::Zeros::Trailing ? "zeros: trailing zeros kept (the numbers' shapes say so)"
                                                                : "zeros: trailing zeros kept (the file does not say)");
    }
    if (!fmt_.digits_stated) {
      out_.assumptions.push_back("format: " + std::to_string(fmt_.ints()) + ":" + std::to_string(fmt_.decs()) +
                                 " (the file does not say; the default for its units)");
    }
  }
  if (!out_.assumptions.empty()) check_plausible();
  return std::move(out_);
}

// Read with assumed units or zeros, a board whose holes lie within a
// millimetre, inside one another, or over two metres apart was read wrong.
void Reader::check_plausible() {
  if (out_.holes.size() < 2) return;
  double x0 = out_.holes[0].center.x, x1 = x0, y0 = out_.holes[0].center.y, y1 = y0;
  for (const aco::Hole& h : out_.holes) {
    x0 = std::min(x0, h.center.x), x1 = std::max(x1, h.center.x);
    y0 = std::min(y0, h.center.y), y1 = std::max(y1, h.center.y);
  }
  const double extent = std::max(x1 - x0, y1 - y0);
  // Holes whose centre lies inside another hole, on a grid of the largest
  // diameter laid from the extent's corner (only for a plausible extent, so
  // the grid's cells stay countable).
  std::size_t inside = 0;
  double largest = 0;
  for (const aco::Hole& h : out_.holes) largest = std::max(largest, h.diameter);
  if (largest > 1e-6 && extent >= 1.0 && extent <= 2000.0) {
    std::map<std::pair<long long, long long>, std::vector<std::size_t>> grid;
    auto key = [&](aco::Point2 p) {
      return std::make_pair(std::llround(std::floor((p.x - x0) / largest)), std::llround(std::floor((p.y - y0) / largest)));
    };
    for (std::size_t i = 0; i < out_.holes.size(); ++i) grid[key(out_.holes[i].center)].push_back(i);
    for (std::size_t i = 0; i < out_.holes.size() && inside * 2 <= out_.holes.size(); ++i) {
      const aco::Hole& h = out_.holes[i];
      const auto [cx, cy] = key(h.center);
      bool found = false;
      for (long long dx = -1; dx <= 1 && !found; ++dx) {
        for (long long dy = -1; dy <= 1 && !found; ++dy) {
          auto it = grid.find({cx + dx, cy + dy});
          if (it == grid.end()) continue;
          for (std::size_t j : it->second) {
            const double d = aco::euclidean(h.center, out_.holes[j].center);
            if (j != i && d > 1e-9 && d < std::max(h.diameter, out_.holes[j].diameter) / 2) found = true;
          }
        }
      }
      if (found) ++inside;
    }
  }
  std::string why;
  if (extent < 1.0) why = "lie within " + std::to_string(extent).substr(0, 5) + " mm";
  else if (extent > 2000.0) why = "span " + std::to_string(static_cast<long long>(extent)) + " mm";
  else if (inside * 2 > out_.holes.size()) why = "lie inside one another (" + std::to_string(inside) + " of them)";
  if (why.empty()) return;
  std::string assumed;
  for (const std::string& a : out_.assumptions) assumed += (assumed.empty() ? "" : "; ") + a;
  throw InputError(path_, 0, "the " + std::to_string(out_.holes.size()) + " holes as read " + why +
                                 ": the units or the zeros are likely wrong (" + assumed +
                                 "); give --excellon-format UNITS,I:D,ZEROS (e.g. inch,2:4,lz)");
}

}  // namespace

bool looks_like_excellon(std::string_view head) {
  if (head.rfind("M48", 0) == 0 || head.find("\nM48") != std::string_view::npos) return true;
  // No header (old OrCAD): a tool definition with a diameter, then hits.
  std::size_t t = head.find("\nT");
  if (head.rfind("T", 0) == 0) t = 0;
  if (t != std::string_view::npos) {
    std::size_t start = t == 0 ? 0 : t + 1;
    std::size_t c = head.find('C', start);
    std::size_t end = head.find('\n', start);
    if (c != std::string_view::npos && c < end && std::isdigit(static_cast<unsigned char>(head[start + 1]))) return true;
  }
  return false;
}

LoadedHoles parse_excellon(const std::string& path, std::string_view data, const InputOptions& options) {
  Reader reader(path, options);
  return reader.run(data);
}

}  // namespace formats
