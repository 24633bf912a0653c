// Writes a reordered drilling program. Each hole is made exactly as the input
// made it (its cycle words, or its Z moves); what changes is the order, and
// the plane the spindle crosses between holes, chosen so that no reordered
// move runs lower than the input ever travelled over that run's holes.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "block_text.h"
#include "gcode/drilling.h"
#include "hobby_writer.h"

namespace gcode {

namespace {

constexpr double kMmPerInch = 25.4;

std::string rpm_text(double rpm) {
  std::string s = format_number(rpm, 0);
  return s.substr(0, s.size() - 1);  // "12000." -> "12000"
}

// The plane a run's holes are joined at, and whether that is each hole's R (G99).
struct Travel {
  double z_mm = 0.0;
  bool at_r = false;
};

Travel travel_of(const ToolRun& run) {
  double z = -std::numeric_limits<double>::infinity();
  bool all_g99 = true, any_canned = false, any_expanded = false;
  for (const ProgramHole& h : run.holes) {
    if (h.arrive_z_mm) z = std::max(z, *h.arrive_z_mm);
    if (h.cycle.code != 0) {
      any_canned = true;
      z = std::max(z, h.cycle.r_mm);
      if (h.cycle.retract_initial) all_g99 = false;
    } else {
      any_expanded = true;
    }
  }
  if (!std::isfinite(z)) {
    // No hole says where the spindle crossed to it (each came from machine Z
    // home): the highest rapid the holes make.
    for (const ProgramHole& h : run.holes) {
      for (const ZMove& m : h.cycle.moves) {
        if (m.kind == ZMove::Rapid) z = std::max(z, m.z_mm);
      }
    }
  }
  if (!std::isfinite(z)) z = 0.0;
  Travel t{z, false};
  if (any_canned && !any_expanded && all_g99) {
    t.at_r = std::all_of(run.holes.begin(), run.holes.end(), [&](const ProgramHole& h) { return h.cycle.r_mm == z; });
  }
  return t;
}

class Writer {
 public:
  Writer(std::ostream& out, const DrillingWriteSettings& s, std::string_view input)
      : out_(out), s_(s) {
    two_digit_ = !s.keep_style || input.find("G00") != std::string_view::npos || input.find("G01") != std::string_view::npos;
  }

  std::string n(double mm) const { return format_number(s_.inch ? mm / kMmPerInch : mm, s_.decimals); }
  const char* rapid() const { return two_digit_ ? "G00" : "G0"; }
  const char* feed() const { return two_digit_ ? "G01" : "G1"; }

  void line(const std::string& text) {
    out_ << prefix_ << text << '\n';
    prefix_.clear();
  }
  // Words the next line written starts with ("G90 ": the mode its coordinates are in).
  void prefix_next(std::string words) { prefix_ = std::move(words); }

  std::string z_home() const { return z_home_block(s_.dialect); }

  // The holes of one run, from wherever the spindle is (`z`: nullopt = not known).
  // `at_first`: the spindle is already over the first hole.
  // `close_cycle`: end with G80 (else the lines after the stretch do, as in the input).
  void holes(const ToolRun& run, std::optional<double> z, bool at_first, bool close_cycle) {
    const Travel travel = travel_of(run);
    bool cycle_on = false;
    const HoleCycle* words = nullptr;
    std::optional<double> last_feed;
    for (std::size_t i = 0; i < run.holes.size(); ++i) {
      const ProgramHole& h = run.holes[i];
      const HoleCycle& c = h.cycle;
      const std::string xy = "X" + n(h.at.x) + " Y" + n(h.at.y);
      // A hole made of moves (expanded, G33.1): out of any cycle, over it at the travel plane.
      auto over_the_hole = [&] {
        if (cycle_on) {
          line("G80");
          cycle_on = false;
          words = nullptr;
        }
        if (!z || *z < travel.z_mm - 1e-9) line(std::string(rapid()) + " Z" + n(travel.z_mm));
        if (!(i == 0 && at_first)) line(std::string(rapid()) + " " + xy);
        z = travel.z_mm;
      };
      if (c.code == 0) {
        over_the_hole();
        for (const ZMove& m : c.moves) {
          switch (m.kind) {
            case ZMove::Rapid: line(std::string(rapid()) + " Z" + n(m.z_mm)); break;
            case ZMove::Feed: {
              std::string text = std::string(feed()) + " Z" + n(m.z_mm);
              if (!last_feed || *last_feed != m.feed_mm_min) text += " F" + n(m.feed_mm_min);
              last_feed = m.feed_mm_min;
              line(text);
              break;
            }
            case ZMove::Dwell:
              // In the input's own style a Marlin "G4 S3" stays so (its G4 P counts milliseconds).
              line(s_.keep_style && !m.dwell_as_written.empty() ? "G4 " + m.dwell_as_written : "G04 P" + m.dwell);
              break;
          }
          if (m.kind != ZMove::Dwell) z = m.z_mm;
        }
        continue;
      }
      if (c.code == 331) {
        // G33.1 (LinuxCNC's rigid tap): from the travel plane over the hole,
        // down to where the input began it, and it comes back there.
        over_the_hole();
        if (std::fabs(travel.z_mm - c.r_mm) > 1e-9) line(std::string(rapid()) + " Z" + n(c.r_mm));
        line("G33.1 " + xy + " Z" + n(c.z_mm) + " K" + format_number(s_.inch ? c.pitch_mm / kMmPerInch : c.pitch_mm, s_.inch ? 6 : 4));
        if (std::fabs(travel.z_mm - c.r_mm) > 1e-9) line(std::string(rapid()) + " Z" + n(travel.z_mm));
        continue;
      }
      if (!cycle_on && (!z || std::fabs(*z - travel.z_mm) > 1e-9)) {
        // The initial plane (G98's retract) is where the cycle starts.
        line(std::string(rapid()) + " Z" + n(travel.z_mm));
        z = travel.z_mm;
      }
      if (cycle_on && words && words->same_words(c)) {
        line(xy);
        continue;
      }
      if (c.rigid && s_.dialect != Dialect::LinuxCnc) {
        line("M29 S" + rpm_text(run.spindle_rpm));
      }
      std::string text = std::string(travel.at_r ? "G99" : "G98") + " G" + std::to_string(c.code) + " " + xy + " Z" +
                         n(c.z_mm) + " R" + n(c.r_mm);
      if (c.q_mm) text += " Q" + n(*c.q_mm);
      if (!c.p.empty()) text += " P" + c.p;
      if (!c.extra.empty()) text += " " + c.extra;
      text += " F" + n(c.feed_mm_min);
      line(text);
      cycle_on = true;
      words = &c;
      last_feed = c.feed_mm_min;
    }
    if (cycle_on && close_cycle) line("G80");
  }

 private:
  std::ostream& out_;
  const DrillingWriteSettings& s_;
  bool two_digit_ = true;
  std::string prefix_;
};

void write_dialect(std::ostream& out, const DrillingProgram& p, const DrillingWriteSettings& s) {
  Writer w(out, s, p.text);
  w.line("%");
  char oline[16];
  std::snprintf(oline, sizeof oline, "O%05d", s.program_number);
  for (const std::string& l : code_with_comment(oline, s.program_name)) w.line(l);
  for (const std::string& text : s.header_comments) {
    for (const std::string& l : comment_lines(text)) w.line(l);
  }
  for (const ToolRun& run : p.runs) {
    if (run.tool <= 0) continue;
    std::string d = run.diameter_mm ? " D=" + w.n(*run.diameter_mm) + (s.inch ? " IN" : " MM") : "";
    w.line("(T" + std::to_string(run.tool) + d + " - " + std::to_string(run.holes.size()) + " HOLES)");
  }
  w.line("G00 G17 G40 G49 G80 G90");
  w.line(s.inch ? "G20" : "G21");
  w.line(w.z_home());
  for (const ToolRun& run : p.runs) {
    if (run.holes.empty()) continue;
    for (const std::string& l : comment_lines((run.tool > 0 ? "T" + std::to_string(run.tool) + ", " : std::string("NO TOOL NUMBER, ")) +
                                               std::to_string(run.holes.size()) + " HOLES" +
                                               (run.message.empty() ? "" : ": " + run.message))) {
      w.line(l);
    }
    if (run.tool > 0) w.line("T" + std::to_string(run.tool) + (run.tool_change ? " M06" : ""));
    if (run.pause) w.line("M00");
    const ProgramHole& first = run.holes.front();
    std::string move = "G00 G90 " + work_offset_text(run.work_offset) + " X" + w.n(first.at.x) + " Y" + w.n(first.at.y);
    if (run.spindle != 0) {
      move += (run.spindle_rpm > 0 ? " S" + rpm_text(run.spindle_rpm) : std::string()) + (run.spindle == 4 ? " M04" : " M03");
    }
    w.line(move);
    const Travel travel = travel_of(run);
    std::string down = run.length_offset > 0 ? "G43 H" + std::string(run.length_offset < 10 ? "0" : "") +
                                                   std::to_string(run.length_offset) + " Z" + w.n(travel.z_mm)
                                             : "G00 Z" + w.n(travel.z_mm);
    if (run.coolant) down += run.coolant == 7 ? " M07" : " M08";
    w.line(down);
    w.holes(run, travel.z_mm, true, true);
    if (run.coolant) w.line("M09");
    if (run.spindle != 0) w.line("M05");
    w.line(w.z_home());
  }
  if (p.end) w.line("G00 X" + w.n(p.end->x) + " Y" + w.n(p.end->y));
  w.line("M30");
  w.line("%");
}

// GRBL and Marlin: the dialect's skeleton with every hole written out as
// moves, each tool a pause that names its drill. The spindle crosses between
// holes at the run's travel plane and changes tools at the highest of them.
void write_hobby(std::ostream& out, const DrillingProgram& p, const DrillingWriteSettings& s) {
  HobbyWriter w(out, s.dialect, s.inch, s.decimals, s.travel_feed_mm_min);
  w.header(s.program_name, s.header_comments);
  double clear_z = -std::numeric_limits<double>::infinity();
  for (const ToolRun& run : p.runs) {
    if (run.holes.empty()) continue;
    clear_z = std::max(clear_z, travel_of(run).z_mm);
    if (run.tool > 0) w.tool_line(run.tool, run.diameter_mm, "", run.holes.size());
  }
  w.start();
  std::optional<int> tool_in;
  for (const ToolRun& run : p.runs) {
    if (run.holes.empty()) continue;
    const Travel travel = travel_of(run);
    w.comment((run.tool > 0 ? "T" + std::to_string(run.tool) + ", " : std::string("NO TOOL NUMBER, ")) +
              std::to_string(run.holes.size()) + " HOLES" + (run.message.empty() ? "" : ": " + run.message));
    if (!tool_in || *tool_in != run.tool || run.pause) {
      w.pause_for_tool(run.tool, run.diameter_mm ? w.size(*run.diameter_mm) + " DRILL" : std::string(), run.diameter_mm, "DRILL",
                       false, clear_z);
      tool_in = run.tool;
    }
    w.select_tool(run.tool);
    w.work_offset(run.work_offset);
    if (run.spindle != 0) w.spindle_on(run.spindle, run.spindle_rpm, s.spindle_start_s);
    if (run.coolant) w.coolant_on();
    for (const ProgramHole& h : run.holes) {
      if (h.cycle.code == 0) {
        w.hole(h.at, h.cycle.moves, travel.z_mm);
        continue;
      }
      const double retract = h.cycle.retract_initial ? std::max(travel.z_mm, h.cycle.r_mm) : h.cycle.r_mm;
      w.hole(h.at, expand_cycle(h.cycle, retract, h.line), travel.z_mm);
    }
    w.coolant_off();
  }
  w.end(clear_z, p.end);
}

// Does the line only move, cycle or set cycle words (what a regenerated
// stretch writes anew), or does it also do something else (G43, M8, S...)?
bool hole_making_only(std::string_view raw) {
  const std::string code = code_of(raw);
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (!std::isalpha(static_cast<unsigned char>(c))) continue;
    if (std::string_view("XYZRQPFIJKELN").find(c) != std::string_view::npos) continue;
    if (c != 'G') return false;
    double g = std::strtod(code.c_str() + i + 1, nullptr);
    const int k = static_cast<int>(std::lround(g * 10));
    static const int allowed[] = {0, 10, 40, 331, 730, 740, 800, 810, 820, 830, 840, 850, 860, 870, 880, 890, 900, 980, 990};
    if (std::find(std::begin(allowed), std::end(allowed), k) == std::end(allowed)) return false;
  }
  return true;
}

// A line that drills a hole and does something else too ("G91 G98 G81 X10
// Z-7 R-8 M8"): what is left without the words that make the hole ("G91
// M8"), comments kept; empty when nothing is left. The hole itself is
// written anew with the others.
std::string without_hole_words(std::string_view raw) {
  std::string kept, comments;
  int depth = 0;
  std::string code;
  for (std::size_t c = 0; c < raw.size(); ++c) {
    const char ch = raw[c];
    if (depth == 0 && ch == ';') {  // the rest of the line is a comment
      comments += std::string(raw.substr(c));
      break;
    }
    if (ch == '(') ++depth;
    if (depth > 0) {
      comments += ch;
      if (ch == ')') --depth;
      continue;
    }
    code += ch;
  }
  bool any = false;
  for (std::size_t i = 0; i < code.size();) {
    if (!std::isalpha(static_cast<unsigned char>(code[i]))) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.' || code[j] == '-' ||
                               code[j] == '+' || code[j] == ' ' || code[j] == '\t')) {
      if ((code[j] == ' ' || code[j] == '\t') && j + 1 < code.size() && std::isalpha(static_cast<unsigned char>(code[j + 1]))) break;
      ++j;
    }
    const std::string word = code.substr(i, j - i);
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(code[i])));
    bool drop = std::string_view("XYZRQPFIJKLE").find(letter) != std::string_view::npos;
    if (letter == 'G') {
      const int k = static_cast<int>(std::lround(std::strtod(word.c_str() + 1, nullptr) * 10));
      drop = k == 0 || k == 10 || k == 40 || k == 331 || (k >= 730 && k <= 890) || k == 980 || k == 990;
    }
    if (!drop) {
      std::string w = word;
      while (!w.empty() && (w.back() == ' ' || w.back() == '\t')) w.pop_back();
      kept += (kept.empty() ? "" : " ") + w;
      if (letter != 'N') any = true;
    }
    i = j;
  }
  if (!any) return comments.empty() ? std::string() : comments;
  return comments.empty() ? kept : kept + " " + comments;
}

// An axis word without G0/G1 (or a cycle) on the line.
bool moves_without_motion_word(std::string_view raw) {
  const std::string code = code_of(raw);
  bool axis = false;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == 'X' || c == 'Y' || c == 'Z') axis = true;
    if (c == 'G') {
      const int k = static_cast<int>(std::lround(std::strtod(code.c_str() + i + 1, nullptr) * 10));
      if (k == 0 || k == 10 || k == 280 || k == 300 || k == 331 || k == 530 || (k >= 730 && k <= 890)) return false;
    }
  }
  return axis;
}

void write_keep_style(std::ostream& out, const DrillingProgram& p, const DrillingWriteSettings& s) {
  std::vector<std::string_view> lines;
  const std::string_view source = p.text;
  for (std::size_t pos = 0; pos <= source.size();) {
    std::size_t nl = source.find('\n', pos);
    if (nl == std::string_view::npos) nl = source.size();
    std::string_view l = source.substr(pos, nl - pos);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines.push_back(l);
    pos = nl + 1;
  }
  if (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (!lines.empty() && lines[0].substr(0, 3) == "\xEF\xBB\xBF") lines[0].remove_prefix(3);
  // Each run's stretch: from the move onto its first hole to its last hole's last line.
  struct Span {
    std::uint32_t first, last;
    const ToolRun* run;
  };
  std::vector<Span> spans;
  for (const ToolRun& run : p.runs) {
    if (run.holes.empty()) continue;
    Span sp{run.holes[0].first_line, run.holes[0].last_line, &run};
    for (const ProgramHole& h : run.holes) {
      sp.first = std::min(sp.first, h.first_line);
      sp.last = std::max(sp.last, h.last_line);
    }
    spans.push_back(sp);
  }
  std::ostringstream body;
  Writer w(body, s, p.text);
  // The lines on which holes are drilled (a cycle line, a first feed down).
  std::vector<char> drills(lines.size() + 2, 0);
  for (const ToolRun& run : p.runs) {
    for (const ProgramHole& h : run.holes) {
      if (h.line < drills.size()) drills[h.line] = 1;
    }
  }
  const bool any_incremental = std::any_of(p.incremental_from.begin(), p.incremental_from.end(),
                                           [](const auto& change) { return change.second; });
  std::size_t next = 0;
  for (std::uint32_t no = 1; no <= lines.size(); ++no) {
    if (next < spans.size() && no == spans[next].first) {
      const Span& sp = spans[next++];
      for (std::uint32_t k = sp.first; k <= sp.last && k <= lines.size(); ++k) {
        if (hole_making_only(lines[k - 1])) continue;
        if (drills[k]) {
          // Its hole is written anew below; what else the line does stays.
          const std::string rest = without_hole_words(lines[k - 1]);
          if (!rest.empty()) body << rest << '\n';
          continue;
        }
        // The line's move ran in the input's modal rapid, set by a line now
        // rewritten: say it (G43 Z10. H1 -> G00 G43 Z10. H1).
        std::string kept(lines[k - 1]);
        if (moves_without_motion_word(kept)) {
          std::size_t at = kept.find_first_not_of(" \t");
          if (at != std::string::npos && (kept[at] == 'N' || kept[at] == 'n')) {
            at = kept.find_first_not_of("0123456789", at + 1);
            at = at == std::string::npos ? kept.size() : kept.find_first_not_of(" \t", at);
          }
          kept.insert(at == std::string::npos ? 0 : at, std::string(w.rapid()) + " ");
        }
        body << kept << '\n';
      }
      // The input's own lines after the stretch cancel its cycle when its last hole was canned.
      const ProgramHole* last = &sp.run->holes[0];
      for (const ProgramHole& h : sp.run->holes) {
        if (h.last_line > last->last_line) last = &h;
      }
      // The holes are written in absolute values: say so where the input
      // ever went incremental, and give the input's own lines after the
      // stretch back the mode they ran in.
      if (any_incremental) w.prefix_next("G90 ");
      w.holes(*sp.run, std::nullopt, false, last->cycle.code == 0);
      if (sp.run->cut_follows && last->leave_z_mm) {
        // A cut follows the input's last hole from where it left the spindle
        // (keep_milling): back there, over the run's travel plane.
        const Travel travel = travel_of(*sp.run);
        if (any_incremental) w.prefix_next("G90 ");
        w.line(std::string(w.rapid()) + " Z" + w.n(std::max(travel.z_mm, *last->leave_z_mm)));
        w.line(std::string(w.rapid()) + " X" + w.n(last->at.x) + " Y" + w.n(last->at.y));
        if (*last->leave_z_mm < travel.z_mm) w.line(std::string(w.rapid()) + " Z" + w.n(*last->leave_z_mm));
      }
      if (p.incremental_after(sp.last)) body << "G91\n";
      no = sp.last;
      continue;
    }
    body << lines[no - 1] << '\n';
  }
  if (!p.uses_line_numbers) {
    out << body.str();
    return;
  }
  // Line numbers as the input counted them, on every line that has code.
  long start = 10, step = 10;
  std::vector<long> seen;
  for (std::string_view l : lines) {
    std::size_t i = l.find_first_not_of(" \t");
    if (i == std::string_view::npos || (l[i] != 'N' && l[i] != 'n')) continue;
    seen.push_back(std::strtol(std::string(l.substr(i + 1, 12)).c_str(), nullptr, 10));
    if (seen.size() == 2) break;
  }
  if (!seen.empty()) start = seen[0];
  if (seen.size() == 2 && seen[1] > seen[0]) step = seen[1] - seen[0];
  std::istringstream in(body.str());
  long number = start;
  for (std::string l; std::getline(in, l);) {
    std::size_t i = l.find_first_not_of(" \t");
    if (i != std::string::npos && (l[i] == 'N' || l[i] == 'n')) {
      std::size_t j = i + 1;
      while (j < l.size() && std::isdigit(static_cast<unsigned char>(l[j]))) ++j;
      while (j < l.size() && (l[j] == ' ' || l[j] == '\t')) ++j;
      l = l.substr(j);
      i = 0;
    }
    // The program number (O0025) stands first on its line: no N before it.
    const bool code = i != std::string::npos && !l.empty() && l[0] != '(' && l[0] != '%' && l[0] != ';' && l[0] != 'O' &&
                      l[0] != 'o';
    if (code) {
      out << 'N' << number << ' ' << l << '\n';
      number += step;
    } else {
      out << l << '\n';
    }
  }
}

}  // namespace

void write_drilling(std::ostream& out, const DrillingProgram& program, const DrillingWriteSettings& settings) {
  if (settings.program_number < 1 || settings.program_number > 99999) {
    throw std::invalid_argument("program number must be 1..99999");
  }
  if (settings.keep_style) {
    write_keep_style(out, program, settings);
    return;
  }
  // G33.1 is LinuxCNC's: for another control with canned cycles a rigid tap
  // is its G84 at the same pitch (F = K x S; Fanuc's with M29); a control
  // without them cannot tap (expand_cycle refuses the G33.1, naming its line).
  const auto rigid_tap = [](const ProgramHole& h) { return h.cycle.code == 331; };
  const bool convert = settings.dialect != Dialect::LinuxCnc && has_canned_cycles(settings.dialect) &&
                       std::any_of(program.runs.begin(), program.runs.end(), [&](const ToolRun& r) {
                         return std::any_of(r.holes.begin(), r.holes.end(), rigid_tap);
                       });
  DrillingProgram as_g84;
  if (convert) {
    as_g84 = program;
    for (ToolRun& run : as_g84.runs) {
      for (ProgramHole& h : run.holes) {
        if (!rigid_tap(h)) continue;
        h.cycle.code = run.spindle == 4 ? 74 : 84;
        h.cycle.feed_mm_min = h.cycle.pitch_mm * run.spindle_rpm;
        h.cycle.pitch_mm = 0.0;
        h.cycle.retract_initial = false;
      }
    }
  }
  const DrillingProgram& p = convert ? as_g84 : program;
  if (!has_canned_cycles(settings.dialect)) write_hobby(out, p, settings);
  else write_dialect(out, p, settings);
}

}  // namespace gcode
