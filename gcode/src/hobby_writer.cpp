#include "hobby_writer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gcode {

namespace {

constexpr double kMmPerInch = 25.4;
// GRBL's line buffer holds 80 characters (protocol.h, LINE_BUFFER_SIZE);
// comments do not count there, but some senders cut long lines: keep every
// line under it.
constexpr std::size_t kMaxLine = 78;

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
  const std::string t = plain(text);
  if (dialect_ == Dialect::Marlin) line(("; " + t).substr(0, kMaxLine));
  else line("(" + t.substr(0, kMaxLine - 2) + ")");
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
  if (g != 54) line("G" + std::to_string(g));
}

void HobbyWriter::pause_for(const std::string& message, double clear_z_mm) {
  spindle_off();
  coolant_off();
  rapid_z(clear_z_mm);
  message_pause(message);
}

void HobbyWriter::message_pause(const std::string& message) {
  const std::string t = plain(message);
  if (dialect_ == Dialect::Marlin) {
    line(("M0 " + t).substr(0, kMaxLine));
  } else {
    line("(MSG, " + t.substr(0, kMaxLine - 7) + ")");
    line("M0");
  }
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
  message_pause("TAKE THE PROBE CLIP AND THE TOUCH PLATE AWAY, RESUME");
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
