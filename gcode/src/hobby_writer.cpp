#include "hobby_writer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gcode {

namespace {

constexpr double kMmPerInch = 25.4;
// "0.6", "1", "0.0236": a size as short as it is exact to the program's digits.
std::string short_number(double v, int decimals) {
  std::string s = format_number(v, decimals);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::string rpm_text(double rpm) {
  const std::string s = format_number(std::round(rpm), 0);
  return s.substr(0, s.size() - 1);  // "12000." -> "12000"
}

}  // namespace

HobbyWriter::HobbyWriter(std::ostream& out, Dialect dialect, bool inch, int decimals, double travel_feed_mm_min)
    : out_(out), dialect_(dialect), inch_(inch), decimals_(decimals), travel_feed_(travel_feed_mm_min) {}

std::string HobbyWriter::n(double mm) const { return format_number(inch_ ? mm / kMmPerInch : mm, decimals_); }

std::string HobbyWriter::f(double mm_min) const {
  return format_number(inch_ ? mm_min / kMmPerInch : mm_min, inch_ ? 3 : 1);
}

void HobbyWriter::line(const std::string& text) { out_ << text << '\n'; }

std::string HobbyWriter::plain(const std::string& text) const {
  std::string t = comment_text(text);
  // Marlin ends a line's code at ';': a message or note must not hold one.
  if (dialect_ == Dialect::Marlin) std::replace(t.begin(), t.end(), ';', ',');
  return t;
}

void HobbyWriter::comment(const std::string& text) {
  for (const std::string& piece : wrap_words(plain(text), kMaxLineChars - 2)) {
    if (dialect_ == Dialect::Marlin) line("; " + piece);
    else line("(" + piece + ")");
  }
}

void HobbyWriter::tool_change_sequence(bool touch_plate) {
  comment(touch_plate ? "AT EACH TOOL THE SPINDLE STOPS AND RISES AND THE PROGRAM PAUSES: PUT IN THE TOOL NAMED BELOW, LAY "
                        "THE TOUCH PLATE ON THE PART UNDER IT, CLIP THE PROBE ON, RESUME. Z IS PROBED ON THE PLATE, THEN "
                        "A SECOND PAUSE: TAKE THE CLIP AND THE PLATE AWAY, RESUME."
                      : "AT EACH TOOL THE SPINDLE STOPS AND RISES AND THE PROGRAM PAUSES: PUT IN THE TOOL NAMED BELOW, "
                        "ZERO Z ON THE PART TOP, RESUME.");
}

void HobbyWriter::pause_for_tool(int number, const std::string& name, std::optional<double> diameter_mm, const std::string& kind,
                                 bool touch_plate, double clear_z_mm) {
  const std::string t = number > 0 ? "T" + std::to_string(number) : std::string("THE DRILL");
  const std::string put_in = "PUT IN " + t + (name.empty() ? std::string() : " " + name);
  // The short form names the tool by its size, whatever a tool table called it.
  std::string shortly = "PUT IN " + t;
  if (diameter_mm) {
    shortly += " " + short_number(inch_ ? *diameter_mm / kMmPerInch : *diameter_mm, inch_ ? 4 : 3) + (inch_ ? " IN " : " MM ") +
               kind;
  }
  if (touch_plate) {
    pause_for(put_in + ", TOUCH PLATE ON THE PART UNDER IT, CLIP ON, RESUME", shortly + ", PLATE AND CLIP ON", clear_z_mm);
  } else {
    pause_for(put_in + ", ZERO Z ON THE PART TOP, RESUME", shortly + ", ZERO Z", clear_z_mm);
  }
}

void HobbyWriter::header(const std::string& program_name, const std::vector<std::string>& comments) {
  comment(program_name + " - FOR " + (dialect_ == Dialect::Grbl ? "GRBL 1.1" : "MARLIN"));
  for (const std::string& text : comments) comment(text);
}

std::string HobbyWriter::size(double mm) const {
  return format_number(inch_ ? mm / kMmPerInch : mm, inch_ ? 4 : 3) + (inch_ ? " IN" : " MM");
}

void HobbyWriter::tool_line(int tool, std::optional<double> diameter_mm, const std::string& what, std::size_t holes) {
  comment("T" + std::to_string(tool) + (diameter_mm ? " D=" + size(*diameter_mm) : std::string()) +
          (what.empty() ? std::string() : " - " + what) + " - " + std::to_string(holes) + " HOLES");
}

void HobbyWriter::start() {
  line(std::string(inch_ ? "G20" : "G21") + " G90" + (dialect_ == Dialect::Grbl ? " G94 G17" : ""));
}

void HobbyWriter::work_offset(int g) {
  // Said when it changes: a program that drills two fixtures goes back to G54 too.
  if (g != work_offset_) line(work_offset_text(g));
  work_offset_ = g;
}

void HobbyWriter::pause_for(const std::string& message, const std::string& short_message, double clear_z_mm) {
  spindle_off();
  coolant_off();
  rapid_z(clear_z_mm);
  message_pause(message, short_message);
}

void HobbyWriter::message_pause(const std::string& message, const std::string& short_message) {
  // The short message fits on the pause line; should it not, its words go on
  // lines of their own before a plain pause rather than being cut.
  const std::string brief = plain(short_message);
  if (dialect_ == Dialect::Marlin) {
    comment(message);
    if (3 + brief.size() <= kMaxLineChars) {
      line("M0 " + brief);
    } else {
      comment(brief);
      line("M0");
    }
    return;
  }
  for (const std::string& piece : wrap_words(plain(message), kMaxLineChars - 7)) line("(MSG, " + piece + ")");
  if (5 + brief.size() <= kMaxLineChars) line("M0 (" + brief + ")");
  else line("M0");
}

void HobbyWriter::select_tool(int tool) {
  // GRBL takes T0..T255 and does nothing with it; readers (verify, LinuxCNC)
  // learn the tool from it. Marlin's T selects an extruder.
  if (dialect_ == Dialect::Grbl && tool > 0 && tool <= 255) line("T" + std::to_string(tool));
}

void HobbyWriter::spindle_on(int direction, double rpm, double start_s) {
  line(std::string(direction == 4 ? "M4" : "M3") + (rpm > 0 ? " S" + rpm_text(rpm) : std::string()));
  spindle_ = true;
  if (start_s > 0) dwell(start_s);
}

void HobbyWriter::dwell(double seconds) {
  // GRBL's P is seconds; Marlin's P is milliseconds (its S, seconds, is not RS274).
  if (dialect_ == Dialect::Marlin) line("G4 P" + std::to_string(std::llround(seconds * 1000.0)));
  else line("G4 P" + format_number(seconds, 3));
}

void HobbyWriter::spindle_off() {
  if (!spindle_) return;
  line("M5");
  spindle_ = false;
}

void HobbyWriter::coolant_on() {
  if (dialect_ != Dialect::Grbl) return;  // Marlin: only with COOLANT_FLOOD built in; left to the operator
  line("M8");
  coolant_ = true;
}

void HobbyWriter::coolant_off() {
  if (!coolant_) return;
  line("M9");
  coolant_ = false;
}

void HobbyWriter::rapid_z(double z_mm) {
  if (z_ && std::fabs(*z_ - z_mm) <= 1e-9) return;
  std::string text = "G0 Z" + n(z_mm);
  if (dialect_ == Dialect::Marlin && travel_feed_ > 0) text += " F" + f(travel_feed_);
  line(text);
  if (dialect_ == Dialect::Marlin && travel_feed_ > 0) feed_ = travel_feed_;
  z_ = z_mm;
}

void HobbyWriter::hole(aco::Point2 at, const std::vector<ZMove>& moves, double travel_z_mm) {
  if (!(travel_z_mm > 1e-9)) {
    throw std::invalid_argument("the spindle would travel between holes at Z" + n(travel_z_mm) +
                                ", at or below the top of the part");
  }
  if (!z_ || *z_ < travel_z_mm - 1e-9) rapid_z(travel_z_mm);
  std::string xy = "G0 X" + n(at.x) + " Y" + n(at.y);
  if (dialect_ == Dialect::Marlin && travel_feed_ > 0) {
    xy += " F" + f(travel_feed_);
    feed_ = travel_feed_;
  }
  line(xy);
  for (const ZMove& m : moves) {
    switch (m.kind) {
      case ZMove::Rapid: rapid_z(m.z_mm); break;
      case ZMove::Feed: {
        std::string text = "G1 Z" + n(m.z_mm);
        if (!feed_ || std::fabs(*feed_ - m.feed_mm_min) > 1e-9) text += " F" + f(m.feed_mm_min);
        feed_ = m.feed_mm_min;
        line(text);
        z_ = m.z_mm;
        break;
      }
      case ZMove::Dwell: dwell(m.dwell_s); break;
    }
  }
}

void HobbyWriter::milled_hole(aco::Point2 start, const std::vector<PathMove>& moves, double travel_z_mm) {
  hole(start, {}, travel_z_mm);
  auto in_units = [&](double mm) { return rounded(inch_ ? mm / kMmPerInch : mm, decimals_); };
  // Where the spindle is, as printed: each arc's I J are from there.
  double sx = in_units(start.x), sy = in_units(start.y);
  for (const PathMove& m : moves) {
    if (m.kind == PathMove::Rapid) {
      rapid_z(*m.z);
      continue;
    }
    std::string text = m.kind == PathMove::ArcCw ? "G2" : "G1";
    if (m.x) text += " X" + n(*m.x);
    if (m.y) text += " Y" + n(*m.y);
    if (m.kind == PathMove::ArcCw) {
      // I J from the start as printed: the arc's centre is the hole's to the last digit.
      text += " I" + format_number(in_units(m.centre.x) - sx, decimals_) + " J" + format_number(in_units(m.centre.y) - sy, decimals_);
    }
    if (m.x) sx = in_units(*m.x);
    if (m.y) sy = in_units(*m.y);
    if (m.z) {
      text += " Z" + n(*m.z);
      z_ = *m.z;
    }
    if (!feed_ || std::fabs(*feed_ - m.feed_mm_min) > 1e-9) text += " F" + f(m.feed_mm_min);
    feed_ = m.feed_mm_min;
    line(text);
  }
}

void HobbyWriter::probe_plate(double plate_mm, double feed_mm_min, double travel_mm) {
  spindle_off();
  line("G91 G38.2 Z-" + n(travel_mm) + " F" + f(feed_mm_min));
  line("G90");
  feed_ = feed_mm_min;
  // GRBL: G10 L20 P0 sets the active work offset so that here is Z plate;
  // Marlin has no G10 L20 and sets the position with G92.
  if (dialect_ == Dialect::Marlin) line("G92 Z" + n(plate_mm));
  else line("G10 L20 P0 Z" + n(plate_mm));
  z_ = plate_mm;
  rapid_z(plate_mm + 5.0);
  message_pause("TAKE THE PROBE CLIP AND THE TOUCH PLATE AWAY, RESUME", "CLIP AND PLATE AWAY, RESUME");
}

void HobbyWriter::end(double clear_z_mm, std::optional<aco::Point2> home) {
  spindle_off();
  coolant_off();
  rapid_z(clear_z_mm);
  if (home) {
    std::string xy = "G0 X" + n(home->x) + " Y" + n(home->y);
    if (dialect_ == Dialect::Marlin && travel_feed_ > 0) xy += " F" + f(travel_feed_);
    line(xy);
  }
  if (dialect_ == Dialect::Grbl) line("M2");
}

}  // namespace gcode
