// A small RS274 reader for drilling programs. It tracks the modal state that
// decides where a hole lands (G90/G91, G20/G21, the active cycle, G98/G99,
// the initial plane) and nothing that does not; words it does not need are
// accepted and ignored, so programs from other posts read too.
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "gcode/interpreter.h"

namespace gcode {

namespace {

struct Word {
  char letter;
  double value;
};

std::string_view strip_comments(std::string_view line, std::string& comment, std::uint32_t lineno) {
  // Removes (...) comments and everything after ';'. The first comment is kept for tool diameters.
  static thread_local std::string buffer;
  buffer.clear();
  bool in_comment = false;
  for (char ch : line) {
    if (in_comment) {
      if (ch == ')') in_comment = false;
      else comment += ch;
      continue;
    }
    if (ch == '(') {
      in_comment = true;
      continue;
    }
    if (ch == ';') break;
    buffer += ch;
  }
  if (in_comment) throw ProgramError(lineno, "unclosed comment");
  return buffer;
}

void parse_tool_comment(const std::string& comment, std::map<int, double>& diameters, bool inch) {
  // "(T1 D=6.350 MM ...)" or "(T1 D=0.2010 - #7 DRILL)"; D is in program units unless MM/IN follows.
  std::size_t i = 0;
  while (i < comment.size() && comment[i] == ' ') ++i;
  if (i >= comment.size() || (comment[i] != 'T' && comment[i] != 't')) return;
  int tool = 0;
  auto r = std::from_chars(comment.data() + i + 1, comment.data() + comment.size(), tool);
  if (r.ec != std::errc()) return;
  std::size_t d = comment.find("D=", static_cast<std::size_t>(r.ptr - comment.data()));
  if (d == std::string::npos) return;
  double value = 0.0;
  auto r2 = std::from_chars(comment.data() + d + 2, comment.data() + comment.size(), value);
  if (r2.ec != std::errc()) return;
  std::string rest(r2.ptr, comment.data() + comment.size());
  bool mm = rest.rfind(" MM", 0) == 0;
  bool in = rest.rfind(" IN", 0) == 0;
  diameters[tool] = (mm || (!in && !inch)) ? value : value * 25.4;
}

}  // namespace

Interpretation interpret(std::string_view program) {
  Interpretation out;
  enum class Motion { Rapid, Feed, Cycle, None };
  Motion motion = Motion::Rapid;
  bool absolute = true;
  bool retract_initial = true;  // G98
  double scale = 1.0;      // mm per program unit
  double x = 0, y = 0, z = 0;
  std::optional<double> cycle_z, cycle_r, initial_z;
  int selected_tool = 0, spindle_tool = 0;
  bool percent_seen = false;
  std::size_t pos = 0;
  std::uint32_t lineno = 0;
  while (pos <= program.size()) {
    std::size_t nl = program.find('\n', pos);
    if (nl == std::string_view::npos) nl = program.size();
    std::string_view raw = program.substr(pos, nl - pos);
    pos = nl + 1;
    ++lineno;
    std::string comment;
    std::string_view line = strip_comments(raw, comment, lineno);
    std::size_t first = line.find_first_not_of(" \t\r");
    if (first != std::string_view::npos && line[first] == '/') line = line.substr(first + 1);  // block delete: run it
    if (!comment.empty()) parse_tool_comment(comment, out.tool_diameter_mm, scale != 1.0);
    std::string_view trimmed = line;
    while (!trimmed.empty() && (trimmed.front() == ' ' || trimmed.front() == '\t')) trimmed.remove_prefix(1);
    while (!trimmed.empty() && (trimmed.back() == ' ' || trimmed.back() == '\t' || trimmed.back() == '\r')) trimmed.remove_suffix(1);
    if (trimmed.empty()) continue;
    if (trimmed == "%") {
      if (percent_seen) break;  // text after the closing % is not part of the program
      percent_seen = true;
      continue;
    }
    // Words.
    std::vector<Word> words;
    std::size_t i = 0;
    while (i < trimmed.size()) {
      char ch = trimmed[i];
      if (ch == ' ' || ch == '\t' || ch == '\r') {
        ++i;
        continue;
      }
      if (!std::isalpha(static_cast<unsigned char>(ch))) {
        throw ProgramError(lineno, std::string("unexpected character '") + ch + "'");
      }
      const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      ++i;
      while (i < trimmed.size() && (trimmed[i] == ' ' || trimmed[i] == '\t')) ++i;
      std::size_t start = i;
      if (i < trimmed.size() && (trimmed[i] == '+' || trimmed[i] == '-')) ++i;
      while (i < trimmed.size() && (std::isdigit(static_cast<unsigned char>(trimmed[i])) || trimmed[i] == '.')) ++i;
      std::string num(trimmed.substr(start, i - start));
      if (!num.empty() && num[0] == '+') num.erase(0, 1);
      if (num.empty() || num == "-" || num == ".") {
        throw ProgramError(lineno, std::string("word ") + letter + " has no number");
      }
      double v = 0.0;
      auto r = std::from_chars(num.data(), num.data() + num.size(), v);
      if (r.ec != std::errc() || r.ptr != num.data() + num.size()) {
        throw ProgramError(lineno, std::string("word ") + letter + " has a bad number \"" + num + "\"");
      }
      words.push_back({letter, v});
    }
    if (!words.empty() && words[0].letter == 'O') continue;  // program number line

    std::optional<double> wx, wy, wz, wr;
    bool machine_coords = false, home_return = false, change_tool = false;
    bool cycle_started = false;
    std::optional<Motion> new_motion;
    for (const Word& w : words) {
      const int code = static_cast<int>(std::lround(w.value * 10));  // G43.1 → 431
      switch (w.letter) {
        case 'G':
          switch (code) {
            case 0: new_motion = Motion::Rapid; break;
            case 10: case 20: case 30: new_motion = Motion::Feed; break;
            case 800: new_motion = Motion::None; break;
            case 810: case 820: case 830: case 730: case 850: case 860: case 890:
              new_motion = Motion::Cycle;
              cycle_started = true;
              break;
            case 900: absolute = true; break;
            case 910: absolute = false; break;
            case 200: scale = 25.4; out.inch = true; break;
            case 210: scale = 1.0; out.inch = false; break;
            case 980: retract_initial = true; break;
            case 990: retract_initial = false; break;
            case 530: machine_coords = true; break;
            case 280: case 300: home_return = true; break;
            default: break;  // G17, G40, G43, G49, G54..G59, G4 ...: no effect on where holes land
          }
          break;
        case 'X': wx = w.value * scale; break;
        case 'Y': wy = w.value * scale; break;
        case 'Z': wz = w.value * scale; break;
        case 'R': wr = w.value * scale; break;
        case 'T': selected_tool = static_cast<int>(w.value); break;
        case 'M':
          if (code == 60) change_tool = true;
          if (code == 300 || code == 20) {
            // M30/M2: end of program
          }
          break;
        default: break;
      }
    }
    if (change_tool) {
      spindle_tool = selected_tool;
      ++out.tool_changes;
    }
    if (new_motion) motion = *new_motion;
    if (home_return) {
      // G28/G30 move through an intermediate point to home; drilling programs
      // use them for Z only, and XY travel through home is not modelled.
      if (wz) z = absolute ? *wz : z + *wz;
      continue;
    }
    if (machine_coords) {
      // G53 moves in machine coordinates, usually Z to the tool-change height.
      if (wx || wy) {
        const double nx = wx.value_or(x), ny = wy.value_or(y);
        out.rapid_xy_mm += std::hypot(nx - x, ny - y);
        x = nx;
        y = ny;
      }
      if (wz) z = *wz;
      continue;
    }
    const double nx = wx ? (absolute ? *wx : x + *wx) : x;
    const double ny = wy ? (absolute ? *wy : y + *wy) : y;
    if (motion == Motion::Cycle) {
      if (cycle_started) {
        initial_z = z;  // the initial plane is Z when the cycle begins
        if (!wz) {
          if (!cycle_z) throw ProgramError(lineno, "canned cycle without a depth (Z)");
        }
      }
      if (wz) cycle_z = absolute ? *wz : (wr ? *wr : cycle_r.value_or(0.0)) + *wz;
      if (wr) cycle_r = absolute ? *wr : initial_z.value_or(z) + *wr;
      if (!(wx || wy || cycle_started)) continue;
      if (!cycle_r) throw ProgramError(lineno, "canned cycle without an R plane");
      if (!cycle_z) throw ProgramError(lineno, "canned cycle without a depth (Z)");
      if (*cycle_z >= *cycle_r) throw ProgramError(lineno, "canned cycle depth Z is not below R");
      out.rapid_xy_mm += std::hypot(nx - x, ny - y);
      x = nx;
      y = ny;
      out.holes.push_back({spindle_tool, x, y, *cycle_z, lineno});
      z = retract_initial ? std::max(initial_z.value_or(*cycle_r), *cycle_r) : *cycle_r;
      continue;
    }
    if (motion == Motion::Rapid) out.rapid_xy_mm += std::hypot(nx - x, ny - y);
    if (motion == Motion::Feed) out.feed_xy_mm += std::hypot(nx - x, ny - y);
    x = nx;
    y = ny;
    if (wz) z = absolute ? *wz : z + *wz;
  }
  return out;
}

}  // namespace gcode
