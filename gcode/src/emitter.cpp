// The program skeleton follows ../shared/gcode.md section 1 (after Autodesk's
// HAAS post and HAAS training examples): %, O-number with the name, tool
// comments, safe-start line, units, then per tool: T M06, spindle on at the
// first hole, G43 H Z with coolant, the full cycle on the first hole, bare X Y
// after, G80 M09 M05, Z home, M01; at the end Z home before XY, M30, %.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "aco/charconv.h"
#include "aco/utf8.h"
#include "gcode/drilling.h"
#include "gcode/program.h"
#include "hobby_writer.h"
#include "milling.h"

namespace gcode {

namespace {

constexpr double kMmPerInch = 25.4;

class Writer {
 public:
  Writer(std::ostream& out, const ProgramSettings& s) : out_(out), s_(s) {}

  int coord_decimals() const { return s_.units == Units::Inch ? 4 : 3; }
  int feed_decimals() const { return s_.units == Units::Inch ? 3 : 1; }
  double to_units(double mm) const { return s_.units == Units::Inch ? mm / kMmPerInch : mm; }
  std::string c(double mm) const { return format_number(to_units(mm), coord_decimals()); }
  std::string f(double mm_min) const { return format_number(to_units(mm_min), feed_decimals()); }
  // A thread's pitch (G33.1 K): to 0.1 µm a turn, so that its error over a hole's depth stays far below a thread's tolerance.
  std::string pitch(double mm) const { return format_number(to_units(mm), s_.units == Units::Inch ? 6 : 4); }

  void line(const std::string& text) { out_ << text << '\n'; }

  // "(TEXT)", wrapped between words into lines that fit.
  void comment(const std::string& text) {
    for (const std::string& l : comment_lines(text)) line(l);
  }
  void with_comment(const std::string& code, const std::string& text) {
    for (const std::string& l : code_with_comment(code, text)) line(l);
  }

  std::string z_home() const { return z_home_block(s_.dialect); }

  std::string dwell(double seconds) const {
    // HAAS and Fanuc read P without a decimal point as milliseconds; LinuxCNC
    // reads P as seconds (gcode.md, dialect table).
    if (s_.dialect == Dialect::LinuxCnc) return "P" + format_number(seconds, 3);
    return "P" + std::to_string(static_cast<long long>(std::llround(seconds * 1000.0)));
  }

  std::string label(std::size_t index) const {
    // The hole's number, shown by the control, so the operator sees where it stopped.
    if (index <= 99999) return "N" + std::to_string(index) + " ";
    return "";
  }
  std::string trailing_label(std::size_t index) const {
    if (index <= 99999) return "";
    return " (H" + std::to_string(index) + ")";
  }

  // The milling moves of one hole (milling.h), the spindle over its start.
  void milled_hole(aco::Point2 start, const std::vector<PathMove>& moves) {
    auto in_units = [&](double mm) { return rounded(to_units(mm), coord_decimals()); };
    // Where the spindle is, as printed: each arc's I J are from there.
    double sx = in_units(start.x), sy = in_units(start.y);
    for (const PathMove& m : moves) {
      if (m.kind == PathMove::Rapid) {
        line("G00 Z" + c(*m.z));
        continue;
      }
      std::string text = m.kind == PathMove::ArcCw ? "G02" : "G01";
      if (m.x) text += " X" + c(*m.x);
      if (m.y) text += " Y" + c(*m.y);
      if (m.kind == PathMove::ArcCw) {
        // I J from the start as printed: the arc's centre is the hole's to the last digit.
        text += " I" + format_number(in_units(m.centre.x) - sx, coord_decimals()) + " J" +
                format_number(in_units(m.centre.y) - sy, coord_decimals());
      }
      if (m.x) sx = in_units(*m.x);
      if (m.y) sy = in_units(*m.y);
      if (m.z) text += " Z" + c(*m.z);
      line(text + " F" + f(m.feed_mm_min));
    }
  }

  // After a manual tool change, Z probed on a touch plate on the part
  // (LinuxCNC): a pause to put it under the tool and clip on, down at most
  // the probe's travel until it touches, that point set as Z plate (G10 L20
  // P0: the active work offset), up 5 mm over the plate, a pause to take the
  // clip off.
  void probe_plate(const Tool& t, double plate_mm) {
    // LinuxCNC shows (MSG, ...); the instruction stands on the M00 line too, for what shows only that.
    line("(MSG, TOUCH PLATE ON THE PART UNDER T" + std::to_string(t.number) + ", CLIP ON, RESUME)");
    line("M00 (PLATE UNDER T" + std::to_string(t.number) + ", CLIP ON)");
    line("G91 G38.2 Z-" + c(s_.probe_travel_mm) + " F" + f(s_.probe_feed_mm_min));
    line("G90");
    line("G10 L20 P0 Z" + c(plate_mm));
    line("G00 Z" + c(plate_mm + 5.0));
    line("(MSG, TAKE THE PROBE CLIP AND THE TOUCH PLATE AWAY, RESUME)");
    line("M00 (CLIP AND PLATE AWAY)");
  }

 private:
  std::ostream& out_;
  const ProgramSettings& s_;
};

// The letters with diacritics of Latin-1 Supplement and Latin Extended-A,
// U+00C0..U+017F, as their base letters (uppercase: comments are), one
// character a code point: '?' for what is no letter (the multiplication and
// division signs), '*' for the letters written with two (latin_pair).
constexpr char kLatinBase[] =
    "AAAAAA*CEEEEIIIIDNOOOOO?OUUUUY**"   // U+00C0 À..ß
    "AAAAAA*CEEEEIIIIDNOOOOO?OUUUUY*Y"   // U+00E0 à..ÿ
    "AAAAAACCCCCCCCDDDDEEEEEEEEEEGGGG"   // U+0100 Ā..ğ
    "GGGGHHHHIIIIIIIIII**JJKKKLLLLLLL"   // U+0120 Ġ..Ŀ
    "LLLNNNNNNNNNOOOOOO**RRRRRRSSSSSS"   // U+0140 ŀ..ş
    "SSTTTTTTUUUUUUUUUUUUWWYYYZZZZZZS";  // U+0160 Š..ſ
constexpr char32_t kLatinFirst = 0x00C0;

const char* latin_pair(char32_t cp) {
  switch (cp) {
    case 0x00C6: case 0x00E6: return "AE";  // Æ æ
    case 0x00DE: case 0x00FE: return "TH";  // Þ þ
    case 0x00DF: case 0x1E9E: return "SS";  // ß ẞ
    case 0x0132: case 0x0133: return "IJ";  // Ĳ ĳ
    case 0x0152: case 0x0153: return "OE";  // Œ œ
    default: return nullptr;
  }
}

// UTF-8 as ASCII, one character a code point (see comment_text); what is
// outside ASCII comes out uppercase, as comments are.
std::string ascii_text(const std::string& utf8) {
  std::string out;
  out.reserve(utf8.size());
  for (std::size_t at = 0; at < utf8.size();) {
    const char32_t cp = aco::next_code_point(utf8, at);
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (const char* pair = latin_pair(cp)) {
      out += pair;
    } else if (cp >= kLatinFirst && cp < kLatinFirst + sizeof kLatinBase - 1) {
      out += kLatinBase[cp - kLatinFirst];
    } else if (cp >= 0x0218 && cp <= 0x021B) {  // Romanian Ș ș Ț ț, written with a comma below
      out += cp < 0x021A ? 'S' : 'T';
    } else {
      out += '?';
    }
  }
  return out;
}

}  // namespace

std::string comment_text(std::string text) {
  // Comments in parentheses cannot nest; keep them short, uppercase and plain
  // ASCII for the control (issue 85: a name in any script, one '?' for each
  // character that has no Latin letter to stand for it, not one a byte).
  text = ascii_text(text);
  for (char& ch : text) {
    if (ch == '(' || ch == ')') ch = '/';
    else if (ch == '\n' || ch == '\r') ch = ' ';
    else ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  }
  return text;
}

std::vector<std::string> comment_lines(const std::string& text) {
  std::vector<std::string> lines = wrap_words(comment_text(text), kMaxLineChars - 2);
  for (std::string& l : lines) l = "(" + l + ")";
  return lines;
}

std::vector<std::string> code_with_comment(const std::string& code, const std::string& text) {
  const std::string one = code + " (" + comment_text(text) + ")";
  if (one.size() <= kMaxLineChars) return {one};
  std::vector<std::string> lines = comment_lines(text);
  lines.push_back(code);
  return lines;
}

std::vector<std::string> wrap_words(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string current;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ') ++j;
    if (j == i) break;
    const std::string word = text.substr(i, j - i);
    if (!current.empty() && current.size() + 1 + word.size() > width) {
      lines.push_back(current);
      current.clear();
    }
    current += (current.empty() ? "" : " ") + word;
    i = j;
  }
  if (!current.empty() || lines.empty()) lines.push_back(current);
  return lines;
}

std::string z_home_block(Dialect d) {
  if (d == Dialect::Fanuc) return "G91 G28 Z0.\nG90";  // HAAS and LinuxCNC: G53, non-modal machine Z
  return "G53 G00 Z0.";
}

std::string cycle_description(const Tool& t, Dialect d) {
  if (t.end_mill) return has_canned_cycles(d) ? "G02 helix" : "G2 helix";
  if (has_canned_cycles(d)) {
    if (is_tapping(t.cycle) && d == Dialect::Fanuc) return std::string("M29 ") + to_string(t.cycle) + " (rigid)";
    if (taps_by_g33_1(t, d)) return "G33.1 (rigid, spindle-synchronized)";
    return to_string(t.cycle);
  }
  switch (t.cycle) {
    case Cycle::G82: return "G1 down, G4 dwell, G0 out (as G82)";
    case Cycle::G83: return "G1 pecks, G0 out after each (as G83)";
    case Cycle::G73: return "G1 pecks, G0 back-off (as G73)";
    case Cycle::G85: return "G1 down, G1 out (as G85)";
    case Cycle::G84: case Cycle::G74: return "by hand (no tapping here)";
    case Cycle::G81: break;
  }
  return "G1 down, G0 out (as G81)";
}

std::string tool_name(const Tool& t) {
  if (!t.name.empty()) return t.name;
  const std::string d = format_number(t.diameter_mm, 3);
  if (t.end_mill) return d + " MM END MILL";  // whatever it mills: holes, slots, counterbores
  switch (t.operation) {
    case Operation::Tap: return comment_text(t.thread.empty() ? d + " MM" : t.thread) + " TAP" + (t.cycle == Cycle::G74 ? " LH" : "");
    case Operation::Countersink: return std::to_string(std::lround(t.angle_deg)) + " DEG COUNTERSINK TO D" + d;
    case Operation::Counterbore: return d + " MM COUNTERBORE";
    case Operation::Spot: return std::to_string(std::lround(t.angle_deg)) + " DEG SPOT DRILL";
    case Operation::Ream: return d + " MM REAMER";
    case Operation::Drill: break;
  }
  return d + " MM DRILL";
}

const char* to_string(Dialect d) {
  switch (d) {
    case Dialect::Haas: return "haas";
    case Dialect::Fanuc: return "fanuc";
    case Dialect::LinuxCnc: return "linuxcnc";
    case Dialect::Grbl: return "grbl";
    case Dialect::Marlin: return "marlin";
  }
  return "?";
}

std::optional<std::string> probe_plate_refusal(Dialect d) {
  if (d != Dialect::Haas && d != Dialect::Fanuc) return std::nullopt;
  return std::string("--probe-plate: a ") + (d == Dialect::Haas ? "HAAS" : "Fanuc") +
         " control measures its tools with its own probing cycles and length offsets; touch-plate probing is written "
         "for --dialect grbl, marlin or linuxcnc";
}

bool has_canned_cycles(Dialect d) { return d != Dialect::Grbl && d != Dialect::Marlin; }

std::optional<Dialect> dialect_from_string(const std::string& name) {
  for (Dialect d : {Dialect::Haas, Dialect::Fanuc, Dialect::LinuxCnc, Dialect::Grbl, Dialect::Marlin}) {
    if (name == to_string(d)) return d;
  }
  return std::nullopt;
}

const char* to_string(Cycle c) {
  switch (c) {
    case Cycle::G81: return "G81";
    case Cycle::G82: return "G82";
    case Cycle::G83: return "G83";
    case Cycle::G73: return "G73";
    case Cycle::G84: return "G84";
    case Cycle::G74: return "G74";
    case Cycle::G85: return "G85";
  }
  return "?";
}

std::optional<Cycle> cycle_from_string(const std::string& name) {
  for (Cycle c : {Cycle::G81, Cycle::G82, Cycle::G83, Cycle::G73, Cycle::G84, Cycle::G74, Cycle::G85}) {
    std::string n = to_string(c);
    if (name == n || name == "g" + n.substr(1) || name == n.substr(1)) return c;
  }
  return std::nullopt;
}

const char* to_string(Operation o) {
  switch (o) {
    case Operation::Spot: return "spot";
    case Operation::Drill: return "drill";
    case Operation::Ream: return "ream";
    case Operation::Countersink: return "countersink";
    case Operation::Counterbore: return "counterbore";
    case Operation::Tap: return "tap";
  }
  return "?";
}

std::optional<Operation> operation_from_string(const std::string& name) {
  for (Operation o : {Operation::Spot, Operation::Drill, Operation::Ream, Operation::Countersink, Operation::Counterbore,
                      Operation::Tap}) {
    if (name == to_string(o)) return o;
  }
  return std::nullopt;
}

bool is_tapping(Cycle c) { return c == Cycle::G84 || c == Cycle::G74; }

bool taps_by_g33_1(const Tool& t, Dialect d) {
  return d == Dialect::LinuxCnc && t.spindle_synchronized && is_tapping(t.cycle) && !t.end_mill;
}

void append_number(std::string& out, double value, int decimals) {
  char buf[64];
  auto res = aco::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  if (res.ec != std::errc()) {
    out += "0.";
    return;
  }
  const char* begin = buf;
  // "-0.000" is a rounding artefact; a machinist should never read it.
  if (buf[0] == '-' && std::all_of(buf + 1, res.ptr, [](char c) { return c == '0' || c == '.'; })) ++begin;
  out.append(begin, static_cast<std::size_t>(res.ptr - begin));
  if (decimals == 0) out += '.';
}

std::string format_number(double value, int decimals) {
  std::string s;
  append_number(s, value, decimals);
  return s;
}

std::string format_short(double value, int decimals) {
  std::string s = format_number(value, decimals);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

std::size_t first_written(const ToolPass& p, std::size_t resume_from) {
  std::size_t first = 0;
  while (first < p.holes.size() && p.index[first] < resume_from) ++first;
  if (first > 0 && first < p.slot_to_next.size() && p.slot_to_next[first - 1]) --first;
  return first;
}

namespace {

// The tool's canned cycle as the words a canned-cycle control would be given.
HoleCycle cycle_of(const Tool& t, const ProgramSettings& s) {
  HoleCycle c;
  c.code = std::atoi(to_string(t.cycle) + 1);
  c.z_mm = t.depth_mm;
  c.r_mm = s.r_plane_mm;
  if (c.code == 83 || c.code == 73) c.q_mm = t.peck_mm;
  if (c.code == 82) c.p = format_number(t.dwell_s, 3);  // with a decimal point: seconds
  c.feed_mm_min = t.feed_mm_min;
  return c;
}

// GRBL and Marlin: the same holes, each written out as the moves its cycle
// makes; a tool change is a pause that names the drill.
void write_hobby_program(std::ostream& out, const std::vector<ToolPass>& passes, const ProgramSettings& s) {
  const bool inch = s.units == Units::Inch;
  HobbyWriter w(out, s.dialect, inch, inch ? 4 : 3, s.travel_feed_mm_min);
  w.header(s.program_name, s.header_comments);
  if (s.resume_from > 1) w.comment("RESUMED AT HOLE " + std::to_string(s.resume_from));
  for (const ToolPass& p : passes) w.tool_line(p.tool.number, p.tool.diameter_mm, tool_name(p.tool), p.holes.size());
  const bool milled = std::any_of(passes.begin(), passes.end(), [](const ToolPass& p) { return p.tool.end_mill; });
  if (milled && s.dialect == Dialect::Marlin) w.comment("MILLED HOLES ARE G2 ARCS: MARLIN NEEDS ARC_SUPPORT");
  if (s.probe_plate_mm && s.dialect == Dialect::Marlin) w.comment("TOUCH PLATE PROBING IS G38.2: MARLIN NEEDS G38_PROBE_TARGET");
  w.tool_change_sequence(s.probe_plate_mm.has_value());
  w.start();
  w.rapid_z(s.initial_z_mm);
  for (const ToolPass& p : passes) {
    const std::size_t first = first_written(p, s.resume_from);
    if (first == p.holes.size()) continue;
    const Tool& t = p.tool;
    w.comment("T" + std::to_string(t.number) + " " + tool_name(t) + ", " + std::to_string(p.holes.size() - first) + " HOLES");
    const char* kind = t.end_mill ? "END MILL"
                       : t.operation == Operation::Countersink ? "COUNTERSINK"
                       : t.operation == Operation::Counterbore ? "COUNTERBORE"
                       : t.operation == Operation::Spot        ? "SPOT DRILL"
                       : t.operation == Operation::Ream        ? "REAMER"
                                                               : "DRILL";
    w.pause_for_tool(t.number, tool_name(t), t.diameter_mm, kind, s.probe_plate_mm.has_value(), s.initial_z_mm);
    w.select_tool(t.number);
    if (s.probe_plate_mm) w.probe_plate(*s.probe_plate_mm, s.probe_feed_mm_min, s.probe_travel_mm);
    w.spindle_on(3, t.spindle_rpm, s.spindle_start_s);
    if (t.end_mill) {
      for (std::size_t i = first; i < p.holes.size();) {
        const MilledStop m = milled_stop(p, i, s);
        w.comment(m.span == 2 ? "HOLES " + std::to_string(p.index[i]) + "-" + std::to_string(p.index[i + 1]) + " A SLOT " +
                                    format_number(m.diameter_mm, 3) + " WIDE, MILLED"
                              : "HOLE " + std::to_string(p.index[i]) + " MILLED D" + format_number(m.diameter_mm, 3));
        w.milled_hole(m.start, m.moves, s.r_plane_mm);
        i += m.span;
      }
      continue;
    }
    // As G99/G98: back to R between holes, to the initial plane after a
    // tool's last hole and before a move over a clamp. Every hole of the
    // tool is one of these two.
    const HoleCycle cycle = cycle_of(t, s);
    // Pecks count from the top of the part (work Z 0), never in the air above it.
    const std::vector<ZMove> to_r = expand_cycle(cycle, s.r_plane_mm, 0, 0.0);
    const std::vector<ZMove> to_initial = expand_cycle(cycle, s.initial_z_mm, 0, 0.0);
    for (std::size_t i = first; i < p.holes.size(); ++i) {
      const bool last = i + 1 == p.holes.size();
      const bool clear = i < p.clear_after.size() && p.clear_after[i];
      w.comment("HOLE " + std::to_string(p.index[i]));
      w.hole(p.holes[i], !s.retract_to_r || last || clear ? to_initial : to_r, s.r_plane_mm);
    }
  }
  // What is left to do by hand (taps), said where the operator stops last.
  if (!s.final_pause.empty()) {
    for (const std::string& text : s.final_pause) w.comment(text);
    w.pause_for("TAP THE HOLES LISTED ABOVE BY HAND, THEN RESUME TO END", "TAP BY HAND: SEE ABOVE", s.initial_z_mm);
  }
  w.end(s.initial_z_mm, s.home);
}

}  // namespace

void write_program(std::ostream& out, const std::vector<ToolPass>& passes, const ProgramSettings& s) {
  if (s.program_number < 1 || s.program_number > 99999) {
    throw std::invalid_argument("program number must be 1..99999");
  }
  if (!(s.r_plane_mm < s.initial_z_mm)) throw std::invalid_argument("the R plane must lie below the initial Z");
  if (s.probe_plate_mm) {
    if (auto refusal = probe_plate_refusal(s.dialect)) throw std::invalid_argument(*refusal);
  }
  std::size_t total = 0;
  for (const ToolPass& p : passes) total += p.holes.size();
  if (s.resume_from < 1 || (total > 0 && s.resume_from > total)) {
    throw std::invalid_argument("--resume-from " + std::to_string(s.resume_from) + " is outside 1.." +
                                std::to_string(total));
  }
  if (!has_canned_cycles(s.dialect)) {
    write_hobby_program(out, passes, s);
    return;
  }
  Writer w(out, s);

  w.line("%");
  char oline[16];
  std::snprintf(oline, sizeof oline, "O%05d", s.program_number);
  w.with_comment(oline, s.program_name);
  for (const std::string& text : s.header_comments) w.comment(text);
  if (s.resume_from > 1) w.line("(RESUMED AT HOLE " + std::to_string(s.resume_from) + ")");
  for (const ToolPass& p : passes) {
    w.comment("T" + std::to_string(p.tool.number) + " D=" + w.c(p.tool.diameter_mm) + " " +
              (s.units == Units::Inch ? "IN" : "MM") + " - " + tool_name(p.tool) + " - " + std::to_string(p.holes.size()) +
              " HOLES");
  }
  w.line("G00 G17 G40 G49 G80 G90");
  w.line(s.units == Units::Inch ? "G20" : "G21");
  w.line(w.z_home());

  for (const ToolPass& p : passes) {
    const std::size_t first = first_written(p, s.resume_from);
    if (first == p.holes.size()) continue;
    const Tool& t = p.tool;
    const std::size_t count = p.holes.size() - first;
    w.comment("T" + std::to_string(t.number) + " " + tool_name(t) + ", " + std::to_string(count) + " HOLES");
    w.with_comment("T" + std::to_string(t.number) + " M06", tool_name(t));
    if (s.probe_plate_mm) w.probe_plate(t, *s.probe_plate_mm);
    const aco::Point2 h0 = t.end_mill ? milled_stop(p, first, s).start : p.holes[first];
    // A left-hand tap turns the spindle counter-clockwise: G74 with M04.
    w.line("G00 G90 G54 X" + w.c(h0.x) + " Y" + w.c(h0.y) + " S" + std::to_string(t.spindle_rpm) +
           (t.cycle == Cycle::G74 ? " M04" : " M03"));
    char hbuf[16];
    std::snprintf(hbuf, sizeof hbuf, "H%02d", t.number);
    // Probed on the plate, the work offset already holds this tool's length.
    if (s.probe_plate_mm) w.line("G00 Z" + w.c(s.initial_z_mm) + " M08");
    else w.line("G43 " + std::string(hbuf) + " Z" + w.c(s.initial_z_mm) + " M08");
    if (t.end_mill) {
      for (std::size_t i = first; i < p.holes.size();) {
        const MilledStop m = milled_stop(p, i, s);
        w.line(w.label(p.index[i]) + "G00 X" + w.c(m.start.x) + " Y" + w.c(m.start.y) + w.trailing_label(p.index[i]) +
               (m.span == 2 ? " (HOLES " + std::to_string(p.index[i]) + "-" + std::to_string(p.index[i + 1]) + ": A SLOT " +
                                  w.c(m.diameter_mm) + " WIDE, MILLED)"
                            : " (MILLED D" + w.c(m.diameter_mm) + ")"));
        w.milled_hole(m.start, m.moves);
        i += m.span;
      }
    } else if (taps_by_g33_1(t, s.dialect)) {
      // LinuxCNC's rigid tapping: G33.1 feeds from where Z is (R) to the
      // depth at K a turn, reverses the spindle and comes back to R; the
      // travel between holes is ours, at R or over a clamp at the initial plane.
      bool at_r = false;
      for (std::size_t i = first; i < p.holes.size(); ++i) {
        const aco::Point2& h = p.holes[i];
        if (i != first) w.line("G00 X" + w.c(h.x) + " Y" + w.c(h.y));
        if (!at_r) w.line("G00 Z" + w.c(s.r_plane_mm));
        w.line(w.label(p.index[i]) + "G33.1 X" + w.c(h.x) + " Y" + w.c(h.y) + " Z" + w.c(t.depth_mm) + " K" + w.pitch(t.pitch_mm) +
               w.trailing_label(p.index[i]));
        const bool clear = i < p.clear_after.size() && p.clear_after[i];
        at_r = s.retract_to_r && !clear && i + 1 < p.holes.size();
        if (!at_r) w.line("G00 Z" + w.c(s.initial_z_mm));
      }
    } else {
      bool mode_initial = false;
      for (std::size_t i = first; i < p.holes.size(); ++i) {
        const aco::Point2& h = p.holes[i];
        const bool last = i + 1 == p.holes.size();
        // G99 (back to R) between holes saves time; G98 (back to the initial
        // plane) for the last hole of a tool and before a move over a clamp.
        const bool clear = i < p.clear_after.size() && p.clear_after[i];
        const bool want_initial = !s.retract_to_r || last || clear;
        std::string retract;
        if (i == first || want_initial != mode_initial) retract = want_initial ? "G98 " : "G99 ";
        mode_initial = want_initial;
        std::string text = w.label(p.index[i]) + retract;
        if (i == first) {
          // Fanuc taps rigidly only with M29 S before the cycle (its manuals'
          // rigid tapping; without it G84 is a floating-holder cycle).
          if (is_tapping(t.cycle) && s.dialect == Dialect::Fanuc) w.line("M29 S" + std::to_string(t.spindle_rpm));
          text += std::string(to_string(t.cycle)) + " X" + w.c(h.x) + " Y" + w.c(h.y) + " Z" + w.c(t.depth_mm) + " R" +
                  w.c(s.r_plane_mm);
          if (t.cycle == Cycle::G83 || t.cycle == Cycle::G73) text += " Q" + w.c(t.peck_mm);
          if (t.cycle == Cycle::G82) text += " " + w.dwell(t.dwell_s);
          text += " F" + w.f(t.feed_mm_min);
        } else {
          text += "X" + w.c(h.x) + " Y" + w.c(h.y);
        }
        w.line(text + w.trailing_label(p.index[i]));
      }
    }
    if (!taps_by_g33_1(t, s.dialect)) w.line("G80");
    w.line("M09");
    w.line("M05");
    w.line(w.z_home());
    w.line("M01");
  }
  if (s.home) w.line("G00 X" + w.c(s.home->x) + " Y" + w.c(s.home->y));
  w.line("M30");
  w.line("%");
}

}  // namespace gcode
