// Reads a drilling program the way a control runs it (RS274NGC's order of
// execution within a block), keeping the modal state that decides where and
// how a hole is made — units, distance mode, the cycle and its words, G98/G99,
// feed, spindle, tool — and nothing else. Words it does not need are accepted
// and ignored, so programs from any post read; what would make a hole list
// wrong (cutting moves, arcs, offsets changed in the program, other axes) is
// refused naming its line.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "aco/charconv.h"
#include "block_text.h"
#include "gcode/drilling.h"

namespace gcode {

namespace {

constexpr double kTiny = 1e-9;
constexpr double kAtHome = std::numeric_limits<double>::infinity();  // Z at machine home: above everything

struct Word {
  char letter;
  double value;
  std::string text;  // the number as written
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// G-codes (times ten: G91.1 is 911) that do not change where or how a hole
// is made: planes, compensation and offsets cancelled, exact stop and path
// modes, look-ahead and smoothing (Fanuc G5.1, G8; HAAS G103, G187), spindle
// speed modes and limits (G50, G96, G97), arc centre modes, rotation,
// scaling and polar coordinates cancelled (G69, G50.1, G15). Every other G
// word a reordered program would have to model is refused by name.
bool harmless_g(int code) {
  static const int known[] = {51, 80, 90, 150, 170, 400, 490, 500, 501, 610, 611, 640, 690, 901, 911, 960, 970, 1030, 1870};
  return std::find(std::begin(known), std::end(known), code) != std::end(known);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

// Removes "(...)" comments (nested ones too, as several controls accept) and
// everything after ';'; returns the code and appends the comments' text.
std::string strip_comments(std::string_view line, std::string& comment, std::uint32_t lineno) {
  std::string code;
  int depth = 0;
  for (const char& ch : line) {
    if (depth > 0) {
      if (ch == '(') ++depth;
      if (ch == ')') --depth;
      if (depth > 0) comment += ch;
      continue;
    }
    if (ch == '(') {
      depth = 1;
      if (!comment.empty()) comment += ' ';
      continue;
    }
    if (ch == ';') {
      // The rest of the line is a comment (Marlin's only kind, and common on
      // GRBL): its text counts like a (...) comment's, for tool diameters.
      const std::size_t at = static_cast<std::size_t>(&ch - line.data());
      std::string_view rest = trim(line.substr(at + 1));
      if (!rest.empty()) {
        if (!comment.empty()) comment += ' ';
        comment += rest;
      }
      break;
    }
    code += ch;
  }
  if (depth > 0) throw ProgramError(lineno, "unclosed comment");
  return code;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Tool diameters the program's comments state: "(T1 D=6.350 MM ...)" (Fusion,
// acodrill) or "(MSG, Change tool bit to drill size 0.8mm)" (pcb2gcode).
void parse_tool_comment(const std::string& raw, int selected_tool, bool inch, std::map<int, double>& diameters) {
  const std::string comment = upper(raw);
  std::size_t i = comment.find_first_not_of(' ');
  if (i != std::string::npos && comment[i] == 'T') {
    int tool = 0;
    auto r = aco::from_chars(comment.data() + i + 1, comment.data() + comment.size(), tool);
    if (r.ec != std::errc()) return;
    std::size_t d = comment.find("D=", static_cast<std::size_t>(r.ptr - comment.data()));
    if (d == std::string::npos) return;
    double value = 0.0;
    auto r2 = aco::from_chars(comment.data() + d + 2, comment.data() + comment.size(), value);
    if (r2.ec != std::errc() || !(value > 0)) return;
    std::string rest(r2.ptr, comment.data() + comment.size());
    const bool mm = rest.rfind(" MM", 0) == 0, in = rest.rfind(" IN", 0) == 0;
    diameters[tool] = (mm || (!in && !inch)) ? value : value * 25.4;
    return;
  }
  const std::size_t size = comment.find("DRILL SIZE ");
  if (size != std::string::npos && selected_tool > 0) {
    double value = 0.0;
    const char* begin = comment.data() + size + 11;
    auto r = aco::from_chars(begin, comment.data() + comment.size(), value);
    if (r.ec != std::errc() || !(value > 0)) return;
    std::string unit(r.ptr, comment.data() + comment.size());
    if (unit.rfind("MM", 0) == 0) diameters[selected_tool] = value;
    else if (unit.rfind("INCH", 0) == 0 || unit.rfind("IN", 0) == 0) diameters[selected_tool] = value * 25.4;
  }
}

std::vector<Word> parse_words(std::string_view code, std::uint32_t lineno) {
  std::vector<Word> words;
  std::size_t i = 0;
  while (i < code.size()) {
    const char ch = code[i];
    if (is_blank(ch)) {
      ++i;
      continue;
    }
    if (ch == '#' || ch == '[') throw ProgramError(lineno, "parameters and expressions (# and [...]) are not read; post the program without them");
    if (!std::isalpha(static_cast<unsigned char>(ch))) {
      throw ProgramError(lineno, std::string("unexpected character '") + ch + "'");
    }
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    ++i;
    while (i < code.size() && is_blank(code[i])) ++i;
    const std::size_t start = i;
    if (i < code.size() && (code[i] == '+' || code[i] == '-')) ++i;
    while (i < code.size() && (std::isdigit(static_cast<unsigned char>(code[i])) || code[i] == '.')) ++i;
    std::string num(code.substr(start, i - start));
    if (!num.empty() && num[0] == '+') num.erase(0, 1);
    if (num.empty() || num == "-" || num == "." || num == "-.") {
      throw ProgramError(lineno, std::string("word ") + letter + " has no number");
    }
    double v = 0.0;
    auto r = aco::from_chars(num.data(), num.data() + num.size(), v);
    if (r.ec != std::errc() || r.ptr != num.data() + num.size() || !std::isfinite(v)) {
      throw ProgramError(lineno, std::string("word ") + letter + " has a bad number \"" + num + "\"");
    }
    if (std::fabs(v) > 1e9) throw ProgramError(lineno, std::string("word ") + letter + num + " is out of range");
    words.push_back({letter, v, num});
  }
  return words;
}

int decimals_of(const std::string& number) {
  const std::size_t dot = number.find('.');
  return dot == std::string::npos ? 0 : static_cast<int>(number.size() - dot - 1);
}

enum class Motion { Rapid, Feed, Arc, Cycle, RigidTap };  // RigidTap: LinuxCNC's G33.1

// The hole being made by expanded drilling: open from the first feed down at
// an XY until the spindle leaves that XY.
struct OpenHole {
  bool open = false;
  std::size_t run = 0, index = 0;  // where it was stored
  double feed_start_z = 0.0;
  bool out = false;                // back at or above the feed start: later Z moves are travel
  std::vector<ZMove> trailing;     // moves after it came out, kept if it goes down again here
  std::vector<std::size_t> cut;    // milled: every hole this cut makes (a slot's two ends), indices in the run
};

class Reader {
 public:
  explicit Reader(const ReadOptions& options) : options_(options) {}

  DrillingProgram run(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // byte-order mark
    std::size_t pos = 0;
    int percents = 0;
    while (pos <= text.size() && !ended_) {
      std::size_t nl = text.find('\n', pos);
      if (nl == std::string_view::npos) nl = text.size();
      std::string_view raw = text.substr(pos, nl - pos);
      pos = nl + 1;
      ++lineno_;
      std::string comment;
      std::string code = strip_comments(raw, comment, lineno_);
      if (!comment.empty()) {
        parse_tool_comment(comment, selected_tool_, inch_, out_.tool_diameter_mm);
        last_comment_ = std::string(trim(comment));
        tool_change_from_comment(comment);
      }
      std::string_view line = trim(code);
      if (!line.empty() && line.front() == '/') line = trim(line.substr(1));  // block delete off: run it
      if (line.empty()) continue;
      if (line.front() == '%') {
        // A lone % opens and closes the program; text after the closing one is
        // not part of it. "%..." with text is a comment line (some posts), and
        // so is a lone % with more of the program after it: hobby posts write
        // "%" lines as notes, and their senders skip them.
        if (trim(line.substr(1)).empty() && ++percents == 2) {
          if (code_lines_in(text.substr(std::min(pos, text.size())), true) == 0) {
            end_at("the closing %", text.substr(std::min(pos, text.size())));
            break;
          }
          out_.notes.push_back({lineno_, "a % line with more of the program after it: read as a note"});
          percents = 1;
        }
        continue;
      }
      if (line.front() == '$') {
        // A GRBL system command ($H homing, $X unlock, $J= jog) some senders keep in a program: not G-code.
        out_.notes.push_back({lineno_, "GRBL system command \"" + std::string(line.substr(0, 20)) + "\" read past"});
        continue;
      }
      if (auto message = pause_message(line)) {
        // Marlin's "M0 Put in the 1 mm drill": a pause and what it tells the operator.
        last_comment_ = *message;
        tool_from_message(*message);
        block(parse_words(line.substr(0, line.size() - message->size()), lineno_));
        continue;
      }
      if (line.front() == 'O' || line.front() == 'o') {
        // "O1001": the program's number. "o100 sub", "o100 call", "O10 if ...": subroutines and flow control.
        const std::string rest = upper(std::string(line.substr(1)));
        if (options_.drilling_only && rest.find_first_not_of("0123456789 \t") != std::string::npos) {
          refuse("a subroutine or flow control (O-word)");
        }
        continue;
      }
      if (raw.find("FREECAD-FILENAME-GOES-HERE") != std::string_view::npos) {
        throw ProgramError(lineno_, "not G-code (FreeCAD's fanuc post writes the output file's name here: delete the line)");
      }
      block(parse_words(line, lineno_));
      if (ended_) end_at(ended_by_, text.substr(std::min(pos, text.size())));
    }
    close_hole();
    // Where the program leaves the spindle, when it moved on from the last hole.
    if (holes_seen_) {
      const ProgramHole& last = out_.runs.back().holes.back();
      if (aco::euclidean(last.at, xy_) > kTiny) out_.end = xy_;
    }
    out_.inch = holes_seen_ ? first_hole_inch_ : inch_;
    out_.decimals = std::clamp(decimals_, out_.inch ? 4 : 3, 6);
    return std::move(out_);
  }

 private:
  // Lines with code (not blank, not only comments, not "%") in `rest`; with
  // `first_only`, stops at the first (so a program of many "%" notes is read
  // in linear time, each look ahead ending at the next line of code).
  static std::size_t code_lines_in(std::string_view rest, bool first_only = false) {
    std::size_t count = 0;
    for (std::size_t pos = 0; pos < rest.size();) {
      std::size_t nl = rest.find('\n', pos);
      if (nl == std::string_view::npos) nl = rest.size();
      const std::string code = code_of(rest.substr(pos, nl - pos));
      std::string_view c = trim(code);
      if (!c.empty() && c.front() != '%' && ++count && first_only) return count;
      pos = nl + 1;
    }
    return count;
  }

  void end_at(const std::string& reason, std::string_view rest) {
    out_.end_line = lineno_;
    out_.end_reason = reason;
    out_.code_lines_after_end = code_lines_in(rest);
    if (out_.code_lines_after_end > 0) {
      out_.notes.push_back({lineno_, "the program ends here (" + reason + "); " +
                                         std::to_string(out_.code_lines_after_end) +
                                         " line(s) of code after it are not read"});
    }
  }

  // "M0 text", "M1 text", "M117 text": Marlin shows the text; returns it.
  static std::optional<std::string> pause_message(std::string_view line) {
    if (line.size() < 3 || (line[0] != 'M' && line[0] != 'm')) return std::nullopt;
    std::size_t i = 1;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
    int code = -1;
    aco::from_chars(line.data() + 1, line.data() + i, code);
    if (code != 0 && code != 1 && code != 117 && code != 118) return std::nullopt;
    if (i >= line.size() || !is_blank(line[i])) return std::nullopt;
    std::string_view rest = trim(line.substr(i));
    if (rest.empty()) return std::nullopt;
    // Words ("M0 P500", "M1 S2") are not a message.
    try {
      parse_words(rest, 0);
      return std::nullopt;
    } catch (const ProgramError&) {
      return std::string(rest);
    }
  }

  // A program without T words (Marlin has none for a spindle) that names the
  // tool in a pause message ("M0 Put in T2 ...") changes to it there.
  void tool_from_message(const std::string& message) {
    if (t_words_seen_) return;
    const std::string m = upper(message);
    for (std::size_t i = 0; i + 1 < m.size(); ++i) {
      if (m[i] != 'T' || (i > 0 && std::isalnum(static_cast<unsigned char>(m[i - 1])))) continue;
      int tool = 0;
      auto r = aco::from_chars(m.data() + i + 1, m.data() + m.size(), tool);
      if (r.ec != std::errc() || tool <= 0 || (r.ptr < m.data() + m.size() && std::isalnum(static_cast<unsigned char>(*r.ptr)))) {
        continue;
      }
      if (tool != selected_tool_) boundary_ = true;
      selected_tool_ = tool;
      return;
    }
  }

  // Issue 83: a tool change said only in a comment, in a program with no T
  // word of its own (GRBL has no M6): FreeCAD's grbl post writes "(Begin
  // toolchange)" and "( M6 T2 )", its jtech post "(TC2_6.6)" (tool 2, 6.6
  // wide), and every post the tool controller's label, "(TC: 3.5mm Drill)".
  // Recognised, blanks and case aside, as the whole comment: "M6 T2", "M06
  // T2", "T2 M6" (Marlin's "M6 T2.0" too), "TC2" or "TC2_6.6"; and
  // "TOOLCHANGE", "TOOL CHANGE", "BEGIN TOOLCHANGE" and "TC: label", a change
  // to the next tool number unless the next such comment names it. A tool
  // boundary, kept in the output.
  void tool_change_from_comment(std::string_view comment) {
    if (t_words_seen_) return;
    std::string m;
    for (char c : comment) {
      if (!std::isspace(static_cast<unsigned char>(c))) m += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    // A tool number: digits, or Marlin's "T1.0".
    auto number_at = [&](std::size_t at, int& out) {
      double v = 0;
      const auto r = aco::from_chars(m.data() + std::min(at, m.size()), m.data() + m.size(), v);
      if (r.ec != std::errc() || !(v >= 1 && v <= 100000) || v != std::floor(v)) return std::string::npos;
      out = static_cast<int>(v);
      return static_cast<std::size_t>(r.ptr - m.data());
    };
    int tool = 0;
    std::size_t end = std::string::npos;
    if (m.rfind("M6T", 0) == 0) end = number_at(3, tool);
    else if (m.rfind("M06T", 0) == 0) end = number_at(4, tool);
    else if (m.rfind("TC", 0) == 0 && m.rfind("TC:", 0) != 0) end = number_at(2, tool);
    else if (m.rfind("T", 0) == 0) {
      end = number_at(1, tool);
      if (end != std::string::npos) end = m.compare(end, 2, "M6") == 0 ? end + 2 : m.compare(end, 3, "M06") == 0 ? end + 3 : std::string::npos;
    }
    if (end != std::string::npos && m.rfind("TC", 0) == 0 && end < m.size()) {
      // jtech: "TC2_6.6", the tool's diameter after the underscore.
      double d = 0;
      const bool read = m[end] == '_' && aco::from_chars(m.data() + end + 1, m.data() + m.size(), d).ptr == m.data() + m.size();
      if (!read || !(d > 0)) return;
      out_.tool_diameter_mm[tool] = inch_ ? d * 25.4 : d;
      end = m.size();
    }
    if (end == m.size()) {
      if (tool != selected_tool_) boundary_ = true;
      selected_tool_ = tool;
      comment_tools_ = std::max(comment_tools_, tool);
      if (!comment_change_pending_) {
        boundary_ = pending_change_ = true;
        ++out_.tool_changes;
      }
      comment_change_pending_ = false;
      return;
    }
    // "(TC: 3.5mm Drill)": FreeCAD's tool controller's label (the jtech post writes only that); a tool of its own, numbered on.
    const bool controller = m.rfind("TC:", 0) == 0;
    if (m == "TOOLCHANGE" || m == "BEGINTOOLCHANGE" || controller) {
      if (comment_change_pending_) return;  // the same change, said twice
      boundary_ = pending_change_ = true;
      ++out_.tool_changes;
      comment_change_pending_ = true;  // the comment that names the tool is the same change
      // A controller's label names one tool however often it comes (an operation each).
      if (controller) {
        auto [it, fresh] = controller_tools_.try_emplace(m, 0);
        if (fresh) it->second = ++comment_tools_;
        selected_tool_ = it->second;
      } else {
        selected_tool_ = ++comment_tools_;
      }
    }
  }

  [[noreturn]] void refuse(const std::string& what) {
    throw ProgramError(lineno_, what + ": not a drilling program acodrill can reorder");
  }

  double scale() const { return inch_ ? 25.4 : 1.0; }

  // A line that mills: refused in a drilling program; with keep_milling
  // kept where it is, ending the tool run it is in.
  void cutting(const std::string& what) {
    if (!options_.drilling_only) return;
    if (!options_.keep_milling) refuse(what);
    if (out_.milling_lines.empty() || out_.milling_lines.back() != lineno_) out_.milling_lines.push_back(lineno_);
    boundary_ = true;
  }

  // A hole fed with no F stated before it: a feed of 0, which controls
  // refuse (LinuxCNC: "Cannot feed with zero feed rate"); said once, and the
  // output says F0 as the control reads it.
  void no_feed(const std::string& what) {
    if (feed_ > 0 || told_no_feed_) return;
    told_no_feed_ = true;
    out_.notes.push_back({lineno_, what + " without F (its feed) and none in force: a feed of 0, which the control refuses; written as F0 (give the tool's feed in the CAM)"});
  }

  // keep_milling: the feed down this cut goes on from was its plunge, not a
  // hole (a hole is only what the spindle leaves at the XY it went down at).
  void drop_plunge() {
    if (!hole_.open || hole_.out) {
      note_cut_follows();
      return;
    }
    std::vector<ToolRun>& runs = out_.runs;
    runs[hole_.run].holes.erase(runs[hole_.run].holes.begin() + static_cast<std::ptrdiff_t>(hole_.index));
    if (runs[hole_.run].holes.empty() && hole_.run + 1 == runs.size()) {
      // The run held only the plunge: what began it begins the next one.
      pending_change_ = pending_change_ || runs.back().tool_change;
      pending_pause_ = pending_pause_ || runs.back().pause;
      runs.pop_back();
      if (runs.empty()) holes_seen_ = false;
    }
    hole_ = OpenHole{};
    moved_since_hole_ = moved_before_plunge_;  // as the last hole left it
    note_cut_follows();
  }

  // A cut with no rapid in X/Y since the last hole begins where that hole left the spindle.
  void note_cut_follows() {
    if (!moved_since_hole_ && !out_.runs.empty() && !out_.runs.back().holes.empty()) out_.runs.back().cut_follows = true;
  }

  void block(const std::vector<Word>& words) {
    std::optional<double> wx, wy, wz, wr, wq, wi, wj;
    std::optional<std::string> wp;
    std::string extra;
    std::optional<Motion> motion;
    std::optional<Word> k_word, l_word;
    int cycle_code = 0;
    bool g43 = false;
    std::optional<int> h_word;
    bool g80 = false, dwell = false, home = false, machine = false, change = false, stop = false, g54_1 = false;
    std::optional<int> spindle_dir, offset;
    // Marlin and RepRapFirmware dwell "G4 S3" in seconds; on LinuxCNC, HAAS
    // and Fanuc G4 takes P alone (S there is a spindle speed, and G4 without
    // P an error), so a G4 with S and no P can only be the former (issue 83).
    const bool g4_seconds = std::any_of(words.begin(), words.end(), [](const Word& w) { return w.letter == 'G' && std::lround(w.value * 10) == 40; }) &&
                            std::none_of(words.begin(), words.end(), [](const Word& w) { return w.letter == 'P'; });
    std::optional<std::string> dwell_s_word;
    for (const Word& w : words) {
      const int code = static_cast<int>(std::lround(w.value * 10));  // G91.1 -> 911
      switch (w.letter) {
        case 'N': out_.uses_line_numbers = true; break;
        case 'G':
          switch (code) {
            case 0: motion = Motion::Rapid; break;
            case 10: motion = Motion::Feed; break;
            case 20: case 30: cutting("an arc (G" + w.text + ")"); motion = Motion::Arc; break;
            case 40: dwell = true; break;
            case 730: case 740: case 810: case 820: case 830: case 840: case 850: case 860: case 870: case 880: case 890:
              motion = Motion::Cycle;
              cycle_code = code / 10;
              break;
            case 800: g80 = true; break;
            case 331: motion = Motion::RigidTap; break;
            case 170: break;
            case 180: case 190: if (options_.drilling_only) refuse("another plane (G" + w.text + ")"); break;
            case 200: inch_ = true; break;
            case 210: inch_ = false; break;
            case 900: absolute_ = true; out_.incremental_from.push_back({lineno_, false}); break;
            case 910: absolute_ = false; out_.incremental_from.push_back({lineno_, true}); break;
            case 940: break;
            case 950: if (options_.drilling_only) refuse("feed per revolution (G95); post it with G94"); break;
            case 980: retract_initial_ = true; break;
            case 990: retract_initial_ = false; break;
            case 530: machine = true; break;
            case 280: case 300: home = true; break;
            // A work offset is where the holes after it are: a change starts a run of its own
            // (issue 83: FreeCAD drills each fixture's holes again in G55 within one tool's run).
            case 540: case 550: case 560: case 570: case 580: case 590: offset = code / 10; break;
            case 591: case 592: case 593: offset = code; break;  // G59.1-G59.3 (LinuxCNC)
            case 541: g54_1 = true; break;                       // G54.1 Pn (HAAS, Fanuc: extended offsets)
            case 100: case 520: case 920: case 921: case 922: case 923: case 510: case 511: case 680: case 682:
              if (options_.drilling_only) refuse("G" + w.text + " changes the coordinate system");
              break;
            case 160: if (options_.drilling_only) refuse("G" + w.text + " polar coordinates (X the radius, Y the angle)"); break;
            case 70: case 71: case 700: case 710: case 720:
              // HAAS G70-G72 drill a bolt-hole pattern from one block; G7 and G7.1 change what X means.
              if (options_.drilling_only) refuse("G" + w.text + " (a hole pattern or another reading of X and Y) is not one acodrill models; write each hole");
              break;
            case 430: g43 = true; break;
            case 490: length_offset_ = 0; break;
            case 410: case 420: cutting("cutter compensation (G" + w.text + ")"); break;
            case 650: if (options_.drilling_only) refuse("a macro call (G65)"); break;
            case 760: if (options_.drilling_only) refuse("G76 (threading or fine boring)"); break;
            default:
              if (code >= 382 && code <= 385 && options_.drilling_only) refuse("probing (G" + w.text + ")");
              if (options_.drilling_only && !harmless_g(code)) {
                refuse("G" + w.text + " is not a G-code acodrill models; it may change where or how holes are made");
              }
              break;
          }
          break;
        case 'M':
          switch (code) {
            case 0: case 10: stop = true; break;
            case 20: case 300:
              ended_ = true;
              ended_by_ = "M" + w.text;
              break;
            case 30: spindle_dir = 3; break;
            case 40: spindle_dir = 4; break;
            case 50: spindle_dir = 0; break;
            case 60: change = true; break;
            case 290: rigid_ = true; break;
            case 70: coolant_ = 7; break;
            case 80: coolant_ = 8; break;
            case 90: coolant_ = 0; break;
            case 970: case 980: if (options_.drilling_only) refuse("a subprogram call (M" + w.text + ")"); break;
            case 990:
              // M99 in a main program returns to its start, which a program's last line means
              // as its end (FreeCAD's centroid post ends so); acodrill reads no subprograms (M98 is refused).
              ended_ = true;
              ended_by_ = "M" + w.text;
              break;
            default: break;
          }
          break;
        case 'X': wx = w.value * scale(); track(w.text); break;
        case 'Y': wy = w.value * scale(); track(w.text); break;
        case 'Z': wz = w.value * scale(); track(w.text); break;
        case 'R': wr = w.value * scale(); break;
        case 'Q': wq = w.value * scale(); break;
        case 'P': wp = w.text; break;
        case 'F': feed_ = w.value * scale(); break;
        case 'S':
          if (g4_seconds) {
            dwell_s_word = w.text;
            break;
          }
          if (w.value != rpm_) boundary_ = true;
          rpm_ = w.value;
          break;
        case 'T': {
          t_words_seen_ = true;
          const int t = static_cast<int>(w.value);
          if (t != selected_tool_) boundary_ = true;
          selected_tool_ = t;
          break;
        }
        case 'I': case 'J': case 'E':
          if (w.letter == 'I') wi = w.value * scale();
          if (w.letter == 'J') wj = w.value * scale();
          extra += (extra.empty() ? "" : " ") + std::string(1, w.letter) + w.text;
          break;
        case 'K': k_word = w; break;
        case 'L': l_word = w; break;
        case 'A': case 'B': case 'C': case 'U': case 'V': case 'W':
          if (options_.drilling_only) refuse(std::string("the ") + w.letter + " axis");
          break;
        case 'H': h_word = static_cast<int>(w.value); break;
        default: break;  // D: a radius register
      }
    }
    if (g43) length_offset_ = h_word.value_or(selected_tool_);
    if (g54_1) {
      // Its P is the offset's number, not a dwell.
      double number = 0;
      const bool read = wp && aco::from_chars(wp->data(), wp->data() + wp->size(), number).ec == std::errc();
      if (!read || number < 1 || number > 300 || number != std::floor(number)) {
        refuse("G54.1 without P1..P300 (its extended work offset)");
      }
      offset = kExtendedWorkOffset + static_cast<int>(number);
      wp.reset();
    }
    if (offset && *offset != work_offset_) {
      boundary_ = true;
      work_offset_ = *offset;
    }
    // Order of execution: tool change, spindle, dwell, then the motion, then stops.
    if (change) {
      boundary_ = true;
      pending_change_ = true;
      ++out_.tool_changes;
    }
    if (spindle_dir && *spindle_dir != spindle_) {
      boundary_ = true;
      spindle_ = *spindle_dir;
    }
    if (dwell) {
      if (dwell_s_word) {
        // Seconds: written back as P with a decimal point, seconds on every control.
        double seconds = 0;
        aco::from_chars(dwell_s_word->data(), dwell_s_word->data() + dwell_s_word->size(), seconds);
        std::string p = *dwell_s_word;
        if (p.find('.') == std::string::npos) p += ".0";
        if (hole_.open && !hole_.out) hole_move({ZMove::Dwell, 0.0, 0.0, p, seconds, "S" + *dwell_s_word});
      } else if (hole_.open && !hole_.out) {
        hole_move({ZMove::Dwell, 0.0, 0.0, wp.value_or("0"), dwell_seconds(wp.value_or("0"), false), ""});
      }
      wp.reset();
    }
    if (g80) {
      motion_ = Motion::Rapid;  // what a control does with axis words after G80
      rigid_ = false;
      cycle_words_cancelled_ = true;
    }
    if (motion) {
      if (*motion == Motion::Cycle && (motion_ != Motion::Cycle || cycle_code != cycle_.code)) {
        cycle_started_ = true;
        if (cycle_code != cycle_.code) cycle_words_cancelled_ = true;
      }
      if (*motion == Motion::Cycle && cycle_code != cycle_.code) cycle_.code = cycle_code;
      motion_ = *motion;
    }
    if (home) {
      // G28/G30: to home through an intermediate point; drilling programs use
      // them for Z. The spindle is then at machine Z home.
      if (wx || wy) close_hole();
      if (wz) {
        z_.reset();
        z_homed_ = true;
      }
      stopped(stop);
      return;
    }
    if (machine) {
      if (wx || wy) {
        const aco::Point2 to{wx.value_or(xy_.x), wy.value_or(xy_.y)};
        rapid_to(to);
      }
      if (wz) {
        z_.reset();  // machine Z, usually home
        z_homed_ = true;
      }
      stopped(stop);
      return;
    }
    const aco::Point2 to{wx ? (absolute_ ? *wx : xy_.x + *wx) : xy_.x, wy ? (absolute_ ? *wy : xy_.y + *wy) : xy_.y};
    if (motion_ == Motion::RigidTap) {
      if (wx || wy || wz) rigid_tap(to, wz, k_word);
      stopped(stop);
      return;
    }
    // K: HAAS's least peck beside I and J (G83, G73); anywhere else in a
    // cycle, like L, how many times the block drills (Fanuc, HAAS, LinuxCNC).
    const bool peck_k = k_word && (motion_ == Motion::Cycle || motion == Motion::Cycle) && (wi || wj) &&
                        (cycle_.code == 83 || cycle_.code == 73 || cycle_code == 83 || cycle_code == 73);
    if (k_word && (peck_k || motion_ != Motion::Cycle)) {
      if (peck_k) extra += (extra.empty() ? "" : " ") + std::string("K") + k_word->text;
      k_word.reset();  // outside a cycle: an arc's centre in another plane, refused there
    }
    if (motion_ == Motion::Cycle) {
      const int repeats = cycle_repeats(k_word, l_word);
      const bool drills = (wx || wy || wz || motion.has_value()) && repeats > 0;
      aco::Point2 at = to;
      cycle_block(drills, at, wz, wr, wq, wp, extra);
      // Each further repeat moves by the block's X and Y steps (G91) first.
      for (int k = 1; drills && k < repeats; ++k) {
        at = {at.x + wx.value_or(0.0), at.y + wy.value_or(0.0)};
        cycle_block(true, at, std::nullopt, std::nullopt, std::nullopt, std::nullopt, std::string());
      }
    } else if (motion_ == Motion::Arc) {
      if (wx || wy || wz) arc(to, wz, {wi.value_or(0.0), wj.value_or(0.0)});  // (a line without axis words does not move)
    } else {
      wx_given_ = wx.has_value();
      wy_given_ = wy.has_value();
      move(to, wz);
    }
    stopped(stop);
  }

  // How many times a cycle block drills: its K or L word (1 without).
  // Repeats move by the block's X and Y steps, so in G90 they would drill
  // one place again and again: refused there, expanded in G91.
  int cycle_repeats(const std::optional<Word>& k, const std::optional<Word>& l) {
    if (k && l) throw ProgramError(lineno_, "both K and L repeat the cycle; give one");
    const std::optional<Word>& w = k ? k : l;
    if (!w) return 1;
    if (w->value < 0 || w->value > 9999 || w->value != std::floor(w->value)) {
      throw ProgramError(lineno_, std::string(1, w->letter) + w->text + ": a cycle's repeat count is a whole number from 0 to 9999");
    }
    const int n = static_cast<int>(w->value);
    if (n > 1 && absolute_ && options_.drilling_only) {
      refuse(std::string(1, w->letter) + w->text + " in absolute mode (G90) drills one place " + w->text +
             " times; write each hole");
    }
    return n;
  }

  void stopped(bool stop) {
    if (!stop) return;
    boundary_ = true;
    pending_pause_ = true;
  }

  void track(const std::string& number) { decimals_ = std::max(decimals_, decimals_of(number)); }

  ToolRun& current_run() {
    if (boundary_ || out_.runs.empty()) {
      close_hole();
      ToolRun run;
      run.tool = selected_tool_;
      run.spindle_rpm = rpm_;
      run.spindle = spindle_;
      run.tool_change = pending_change_;
      run.pause = pending_pause_;
      run.message = last_comment_;
      run.work_offset = work_offset_;
      run.length_offset = length_offset_;
      run.coolant = coolant_;
      out_.runs.push_back(std::move(run));
      boundary_ = pending_change_ = pending_pause_ = comment_change_pending_ = false;
    }
    if (!holes_seen_) {
      holes_seen_ = true;
      first_hole_inch_ = inch_;
    } else if (inch_ != first_hole_inch_ && options_.drilling_only) {
      // Every hole is written in one unit (in the input's style, the first hole's).
      refuse(std::string("a hole in ") + (inch_ ? "inch" : "mm") + " after holes in " + (first_hole_inch_ ? "inch" : "mm"));
    }
    return out_.runs.back();
  }

  void close_hole() {
    hole_ = OpenHole{};
  }

  void rapid_to(aco::Point2 to) {
    const double d = aco::euclidean(xy_, to);
    if (d <= kTiny) return;
    moved_since_hole_ = true;
    out_.rapid_xy_mm += d;
    close_hole();
    xy_ = to;
    arrive_z_ = z_;
    arrive_line_ = lineno_;
    approach_.clear();
  }

  void hole_move(const ZMove& m) {
    ProgramHole& h = out_.runs[hole_.run].holes[hole_.index];
    h.cycle.moves.push_back(m);
    h.last_line = lineno_;
    last_hole_line_ = lineno_;
    if (m.kind != ZMove::Dwell) h.leave_z_mm = m.z_mm;
    moved_since_hole_ = false;
  }

  void move(aco::Point2 to, std::optional<double> wz) {
    const double d = aco::euclidean(xy_, to);
    std::optional<double> nz;
    if (wz) nz = absolute_ ? *wz : z_.value_or(0.0) + *wz;
    if (motion_ == Motion::Feed && d > kTiny) {
      // Hobby posts travel between holes with G1 well above the part: above
      // the top of the stock (Z > 0), or where the last hole's feed began.
      // Z not known after a move to machine Z home: the spindle is at the top.
      std::optional<double> low = z_ ? z_ : z_homed_ ? std::optional<double>(kAtHome) : std::nullopt;
      if (low && nz) low = std::min(*low, *nz);
      // Kept milling (FreeCAD: Z 0 is the part's bottom, its top anywhere above)
      // cuts above Z 0 too: there only travel where the last hole's feed began is travel.
      const bool above_feed_start = low && feed_start_z_ && *low >= *feed_start_z_ - kTiny;
      const bool above = options_.keep_milling ? above_feed_start : low && (*low > kTiny || above_feed_start);
      if (!above && hole_.open && !hole_.out && out_.runs[hole_.run].holes[hole_.index].milled_radius_mm) {
        // Inside a hole being milled (along a slot, to the centre): the cut goes on.
        xy_ = to;
        if (nz) {
          hole_move({ZMove::Feed, *nz, feed_, "", 0.0, ""});
          z_ = nz;
        }
        return;
      }
      if (!above) {
        cutting("G1 moves in X/Y at Z" + (z_ ? format_number(*z_, 3) : std::string(" unknown")) +
                ", at or below the top of the part: a cutting move");
        if (options_.keep_milling) {
          drop_plunge();
          arrive_line_ = 0;  // a hole begun here begins after the cut, which stays as written
        }
        close_hole();
        xy_ = to;
        approach_.clear();
        if (nz) z_ = nz;
        arrive_z_ = z_;  // where the cut left the spindle, over the next hole
        return;
      }
      if (nz && (!z_ || *nz > *z_)) z_ = nz;
      rapid_to(to);
      if (nz && *nz < z_.value_or(std::numeric_limits<double>::infinity())) {
        approach_.push_back({ZMove::Feed, *nz, feed_, "", 0.0, ""});
        z_ = nz;
      }
      return;
    }
    if (d <= kTiny && (wx_given_ || wy_given_)) {
      // A rapid to where the spindle is ends the hole here: the next feed down
      // is another hole at the same place (drilled twice), not a deeper peck.
      const bool hole_here = hole_.open;
      close_hole();
      arrive_z_ = z_;
      // With no hole made since the spindle came here, the hole's lines begin
      // where it came: FreeCAD's marlin and rrf posts move to each hole twice
      // ("G0 X Y", "G0 Z", a comment, "G0 X Y"), and a first move kept as
      // written would send the reordered program there first.
      if (hole_here || arrive_line_ == 0 || arrive_line_ <= last_hole_line_) arrive_line_ = lineno_;
      approach_.clear();
    }
    if (d > kTiny) {
      // A rapid in XY (with Z, moving both: the higher of the two is the plane it travelled at).
      if (nz && (!z_ || *nz > *z_)) z_ = nz;
      rapid_to(to);
      if (nz && *nz < z_.value_or(std::numeric_limits<double>::infinity())) {
        approach_.push_back({ZMove::Rapid, *nz, 0.0, "", 0.0, ""});
        z_ = nz;
      }
      return;
    }
    if (!nz) return;
    const bool down = z_ ? *nz < *z_ - kTiny : true;
    if (motion_ == Motion::Feed && down && z_) {
      // Feeding down at an XY: a hole, or the next plunge of the one here.
      if (hole_.open) {
        for (const ZMove& m : hole_.trailing) hole_move(m);
        hole_.trailing.clear();
        hole_.out = false;
      } else {
        no_feed("G1 down in Z");
        moved_before_plunge_ = moved_since_hole_;
        ToolRun& run = current_run();
        ProgramHole h;
        h.at = xy_;
        h.arrive_z_mm = arrive_z_;
        h.line = lineno_;
        h.first_line = arrive_line_ ? arrive_line_ : lineno_;
        h.last_line = lineno_;
        h.cycle.moves = approach_;
        run.holes.push_back(std::move(h));
        hole_ = OpenHole{true, out_.runs.size() - 1, run.holes.size() - 1, *z_, false, {}, {}};
        feed_start_z_ = *z_;
        approach_.clear();
      }
      hole_move({ZMove::Feed, *nz, feed_, "", 0.0, ""});
      z_ = nz;
      return;
    }
    const ZMove m{motion_ == Motion::Feed ? ZMove::Feed : ZMove::Rapid, *nz, feed_, "", 0.0, ""};
    z_ = nz;
    if (!hole_.open) {
      approach_.push_back(m);
      return;
    }
    if (hole_.out) {
      hole_.trailing.push_back(m);
      return;
    }
    hole_move(m);
    if (*nz >= hole_.feed_start_z - kTiny) hole_.out = true;  // out of the hole: the rest is travel
  }

  // An arc (a drilling program refuses them, or keeps them as milling). Read
  // leniently, arcs that go on from a feed down where a hole was opened, all
  // about one centre, mill that hole: it is made about the arc's centre, to
  // the depth the helix reaches, `milled_radius_mm` from it. Any other arc is
  // read past.
  void arc(aco::Point2 to, std::optional<double> wz, aco::Point2 ij) {
    std::optional<double> nz;
    if (wz) nz = absolute_ ? *wz : z_.value_or(0.0) + *wz;
    if (options_.keep_milling) {
      // Milling kept as written (a helix too), read past as any other arc.
      cutting("an arc");  // (a modal arc's line, after the G2/G3 that began them)
      drop_plunge();
      arrive_line_ = 0;
    }
    const aco::Point2 centre{xy_.x + ij.x, xy_.y + ij.y};
    const double radius = std::hypot(ij.x, ij.y);
    bool helix = false;
    if (!options_.keep_milling && hole_.open && !hole_.out && radius > kTiny) {
      std::vector<ProgramHole>& run = out_.runs[hole_.run].holes;
      ProgramHole& h = run[hole_.index];
      if (!h.milled_radius_mm) {
        h.milled_radius_mm = radius;
        h.at = centre;
        hole_.cut = {hole_.index};
        helix = true;
      } else if (std::fabs(*h.milled_radius_mm - radius) <= 1e-3) {
        // The same cut round another centre (a slot's other end): a hole of its own, once.
        helix = true;
        auto same = std::find_if(hole_.cut.begin(), hole_.cut.end(),
                                 [&](std::size_t k) { return aco::euclidean(run[k].at, centre) <= 1e-3; });
        if (same != hole_.cut.end()) {
          hole_.index = *same;
        } else {
          ProgramHole other = h;
          other.at = centre;
          other.cycle.moves.clear();
          other.line = other.first_line = other.last_line = lineno_;
          run.push_back(std::move(other));
          hole_.index = run.size() - 1;
          hole_.cut.push_back(hole_.index);
        }
      }
    }
    if (!helix) {
      close_hole();
      xy_ = to;
      arrive_z_ = nz ? nz : z_;
      approach_.clear();
      if (nz) z_ = nz;
      return;
    }
    xy_ = to;
    if (nz) {
      hole_move({ZMove::Feed, *nz, feed_, "", 0.0, ""});
      z_ = nz;
    }
  }

  // LinuxCNC's G33.1 X Y Z K: over X Y at the height Z is at (a rapid),
  // then a tap down to Z at K a turn and back up to that height: one tapped
  // hole, as a cycle whose R is where it began (HoleCycle code 331).
  void rigid_tap(aco::Point2 to, std::optional<double> wz, const std::optional<Word>& k) {
    close_hole();
    if (!k || !(k->value > 0)) throw ProgramError(lineno_, "G33.1 without K (the thread's pitch, a positive length a turn)");
    if (!wz) throw ProgramError(lineno_, "G33.1 without Z (the tap's depth)");
    if (!z_) throw ProgramError(lineno_, "G33.1 from a Z not known: it taps from where Z is, so move Z above the hole first");
    const double start = *z_;
    const double bottom = absolute_ ? *wz : start + *wz;
    if (bottom >= start) throw ProgramError(lineno_, "G33.1 depth Z is not below where it starts");
    const bool moved = aco::euclidean(xy_, to) > kTiny;
    if (moved && start <= kTiny && options_.drilling_only) {
      refuse("G33.1 moves in X/Y at Z" + format_number(start, 3) + ", at or below the top of the part");
    }
    const std::uint32_t arrived_on = arrive_line_;
    if (moved) rapid_to(to);
    ToolRun& run = current_run();
    ProgramHole h;
    h.at = xy_;
    h.cycle.code = 331;
    h.cycle.z_mm = bottom;
    h.cycle.r_mm = start;
    h.cycle.pitch_mm = k->value * scale();
    h.cycle.feed_mm_min = h.cycle.pitch_mm * rpm_;
    h.cycle.rigid = true;
    h.arrive_z_mm = moved ? std::optional<double>(start) : arrive_z_;
    h.line = lineno_;
    h.first_line = !moved && arrived_on && arrived_on >= last_hole_line_ ? arrived_on : lineno_;
    h.last_line = lineno_;
    h.leave_z_mm = start;
    run.holes.push_back(std::move(h));
    last_hole_line_ = lineno_;
    moved_since_hole_ = false;
    arrive_z_ = start;
    arrive_line_ = 0;
    approach_.clear();
  }

  void cycle_block(bool drills, aco::Point2 to, std::optional<double> wz, std::optional<double> wr,
                   std::optional<double> wq, const std::optional<std::string>& wp, const std::string& extra) {
    close_hole();
    if (cycle_started_) {
      initial_z_ = z_;
      cycle_started_ = false;
      // Q, P and the others stay in force when the same cycle comes back after
      // a G0 without a G80 between (FreeCAD's uccnc and fanuc posts state Q on
      // the first hole only; LinuxCNC and Fanuc keep it); G80 or another
      // cycle ends them.
      if (cycle_words_cancelled_) {
        cycle_.q_mm.reset();
        cycle_.p.clear();
        cycle_.extra.clear();
      }
      cycle_words_cancelled_ = false;
    }
    // G91: R is measured from the initial plane, Z from R.
    if (wr) cycle_.r_mm = absolute_ ? *wr : initial_z_.value_or(0.0) + *wr;
    if (wr) have_r_ = true;
    if (wz) {
      cycle_.z_mm = absolute_ ? *wz : cycle_.r_mm + *wz;
      have_z_ = true;
    }
    if (wq) cycle_.q_mm = std::fabs(*wq);
    if (wp) cycle_.p = *wp;
    if (!extra.empty()) cycle_.extra = extra;
    if (!drills) return;
    if ((cycle_.code == 82 || cycle_.code == 89) && cycle_.p.empty()) {
      // FreeCAD's smoothie, uccnc, dynapath, fablin and centroid posts leave G82's P
      // out; a control dwells 0 then (LinuxCNC refuses the line): said once, and written.
      out_.notes.push_back({lineno_, "G" + std::to_string(cycle_.code) + " without P (its dwell) and none in force: the control dwells 0 s; written as P0"});
      cycle_.p = "0";
    }
    if (!have_r_) throw ProgramError(lineno_, "canned cycle without an R plane");
    if (!have_z_) throw ProgramError(lineno_, "canned cycle without a depth (Z)");
    if (cycle_.z_mm >= cycle_.r_mm) throw ProgramError(lineno_, "canned cycle depth Z is not below R");
    if ((cycle_.code == 83 || cycle_.code == 73) && !cycle_.q_mm && cycle_.extra.find('I') == std::string::npos) {
      // A peck cycle without its peck (and no HAAS I J K pecks): LinuxCNC
      // refuses the line, other controls differ. Said once, and written as
      // what it can only mean, one stroke to the depth: Q the whole of R to Z.
      cycle_.q_mm = cycle_.r_mm - cycle_.z_mm;
      out_.notes.push_back({lineno_, "G" + std::to_string(cycle_.code) + " without Q (its peck) and none in force: LinuxCNC refuses it and other controls differ; drilled in one stroke, written as Q" +
                                         format_number(*cycle_.q_mm / scale(), inch_ ? 4 : 3)});
    }
    cycle_.feed_mm_min = feed_;
    no_feed("G" + std::to_string(cycle_.code));
    cycle_.retract_initial = retract_initial_;
    cycle_.rigid = rigid_ && (cycle_.code == 84 || cycle_.code == 74);
    // The control first rises to R if below it, then moves in XY.
    std::optional<double> arrive = z_;
    if (arrive && *arrive < cycle_.r_mm) arrive = cycle_.r_mm;
    const bool moved = aco::euclidean(xy_, to) > kTiny;
    const std::uint32_t arrived_on = arrive_line_;
    z_ = arrive;
    if (moved) rapid_to(to);
    ToolRun& run = current_run();
    ProgramHole h;
    h.at = xy_;
    h.cycle = cycle_;
    h.arrive_z_mm = moved ? arrive : arrive_z_;
    h.line = lineno_;
    // A rapid to this very XY just before the cycle (FreeCAD: "G0 X Y" then "G83 X Y ...") belongs to the hole.
    h.first_line = !moved && arrived_on && arrived_on >= last_hole_line_ ? arrived_on : lineno_;
    h.last_line = lineno_;
    const double clear = retract_initial_ ? std::max(initial_z_.value_or(cycle_.r_mm), cycle_.r_mm) : cycle_.r_mm;
    h.leave_z_mm = clear;
    run.holes.push_back(std::move(h));
    last_hole_line_ = lineno_;
    moved_since_hole_ = false;
    z_ = clear;
    arrive_z_ = clear;
    arrive_line_ = 0;
  }

  const ReadOptions& options_;
  DrillingProgram out_;
  std::uint32_t lineno_ = 0;
  bool ended_ = false;
  bool inch_ = false, absolute_ = true, retract_initial_ = true, rigid_ = false;
  bool holes_seen_ = false, first_hole_inch_ = false;
  int decimals_ = 0;
  Motion motion_ = Motion::Rapid;
  aco::Point2 xy_{0.0, 0.0};
  std::optional<double> z_;             // nullopt: at machine Z home (or not yet known)
  std::optional<double> arrive_z_;      // Z when the spindle arrived at this XY
  std::uint32_t arrive_line_ = 0, last_hole_line_ = 0;
  std::vector<ZMove> approach_;         // Z moves at this XY before any feed down
  OpenHole hole_;
  HoleCycle cycle_;
  bool cycle_started_ = false, have_r_ = false, have_z_ = false;
  bool cycle_words_cancelled_ = true;    // by G80 or another cycle: a cycle's Q, P, I, J, K start afresh
  bool comment_change_pending_ = false;  // a "Begin toolchange" comment whose tool is not named yet
  int comment_tools_ = 0;                // the highest tool a comment named or numbered
  std::map<std::string, int> controller_tools_;  // "TC:3.5MMDRILL" -> the tool numbered for it
  std::optional<double> initial_z_;
  double feed_ = 0.0, rpm_ = 0.0;
  int spindle_ = 0, selected_tool_ = 0, work_offset_ = 54, length_offset_ = 0, coolant_ = 0;
  bool wx_given_ = false, wy_given_ = false;  // the block being run has X / Y words
  bool t_words_seen_ = false;
  bool told_no_feed_ = false;
  bool moved_since_hole_ = false;  // a rapid in X/Y since the last hole was made (keep_milling: cut_follows)
  bool moved_before_plunge_ = false;  // the same before the hole now open began (a plunge, if a cut follows)
  bool z_homed_ = false;  // z_ unknown means at machine Z home (G28/G53 Z), not "never said"
  std::string ended_by_;
  // The Z where the last hole's feed began: the spindle is above the part
  // there, so a G1 in X/Y at or above it travels, it does not cut.
  std::optional<double> feed_start_z_;
  bool boundary_ = false, pending_change_ = false, pending_pause_ = false;
  std::string last_comment_;
};

}  // namespace

double HoleCycle::bottom_mm() const {
  if (code != 0) return z_mm;
  double bottom = std::numeric_limits<double>::infinity();
  for (const ZMove& m : moves) {
    if (m.kind == ZMove::Feed) bottom = std::min(bottom, m.z_mm);
  }
  return bottom;
}

double HoleCycle::dwell_s() const {
  if (code != 0) return p.empty() ? 0.0 : dwell_seconds(p, true);
  double total = 0.0;
  for (const ZMove& m : moves) {
    if (m.kind == ZMove::Dwell) total += m.dwell_s;
  }
  return total;
}

std::optional<double> HoleCycle::tap_pitch_mm(double spindle_rpm) const {
  if (code == 331) return pitch_mm;
  if ((code == 84 || code == 74) && spindle_rpm > 0) return feed_mm_min / spindle_rpm;
  return std::nullopt;
}

bool HoleCycle::same_words(const HoleCycle& o) const {
  return code == o.code && z_mm == o.z_mm && r_mm == o.r_mm && q_mm == o.q_mm && p == o.p && feed_mm_min == o.feed_mm_min &&
         extra == o.extra && rigid == o.rigid && pitch_mm == o.pitch_mm;
}

bool DrillingProgram::incremental_after(std::uint32_t line) const {
  bool incremental = false;
  for (const auto& [at, mode] : incremental_from) {
    if (at > line) break;
    incremental = mode;
  }
  return incremental;
}

std::size_t DrillingProgram::hole_count() const {
  std::size_t n = 0;
  for (const ToolRun& r : runs) n += r.holes.size();
  return n;
}

DrillingProgram read_drilling(std::string_view text, const ReadOptions& options) {
  Reader reader(options);
  DrillingProgram p = reader.run(text);
  p.text = std::string(text);
  for (ToolRun& run : p.runs) {
    auto d = p.tool_diameter_mm.find(run.tool);
    if (d != p.tool_diameter_mm.end()) run.diameter_mm = d->second;
  }
  return p;
}

bool looks_like_gcode(std::string_view head) {
  // Excellon has M48 and no Z words; Gerber ends its blocks with '*'. A
  // drilling program moves Z: a Z word with a number, beside G or M words.
  std::size_t pos = 0, z_blocks = 0, g_blocks = 0;
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  while (pos < head.size()) {
    std::size_t nl = head.find('\n', pos);
    if (nl == std::string_view::npos) nl = head.size();
    std::string_view raw = head.substr(pos, nl - pos);
    pos = nl + 1;
    const std::string code = code_of(raw);
    std::string_view line = trim(code);
    if (line.empty() || line.front() == '%') continue;
    if (line.back() == '*') return false;
    if (line.rfind("M48", 0) == 0) return false;
    bool g = false, z = false;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const char c = line[i], next = line[i + 1];
      const bool number = std::isdigit(static_cast<unsigned char>(next)) || next == '-' || next == '.' || next == '+' || next == ' ';
      if ((c == 'G' || c == 'M') && number) g = true;
      if (c == 'Z' && number && (i == 0 || !std::isalpha(static_cast<unsigned char>(line[i - 1])))) z = true;
    }
    if (g) ++g_blocks;
    if (z) ++z_blocks;
  }
  return z_blocks > 0 && g_blocks > 0;
}

}  // namespace gcode
