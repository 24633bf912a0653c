// Canned cycles written out as moves, for controls that have none (GRBL,
// Marlin). The moves are the ones LinuxCNC's interpreter makes for each cycle
// (../shared/gcode.md, section 3), so rs274 reads the expanded hole back to
// the same position and depth as the cycle.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "aco/charconv.h"
#include "gcode/drilling.h"

namespace gcode {

std::string work_offset_text(int offset) {
  if (offset > kExtendedWorkOffset) return "G54.1 P" + std::to_string(offset - kExtendedWorkOffset);
  if (offset >= 591 && offset <= 593) return "G59." + std::to_string(offset - 590);
  return "G" + std::to_string(offset);
}

double dwell_seconds(std::string_view p, bool canned_cycle) {
  double v = 0.0;
  auto r = aco::from_chars(p.data(), p.data() + p.size(), v);
  if (r.ec != std::errc() || !std::isfinite(v) || v < 0) return 0.0;
  if (p.find('.') != std::string_view::npos) return v;
  return canned_cycle || v >= 100.0 ? v / 1000.0 : v;
}

std::vector<ZMove> expand_cycle(const HoleCycle& c, double retract_z_mm, std::uint32_t line,
                                std::optional<double> part_top_z_mm) {
  constexpr double kPeckClearance = 0.254;  // LinuxCNC's G83/G73 clearance: 0.010 in
  auto rapid = [](double z) { return ZMove{ZMove::Rapid, z, 0.0, "", 0.0, ""}; };
  auto feed = [&](double z) { return ZMove{ZMove::Feed, z, c.feed_mm_min, "", 0.0, ""}; };
  auto dwell = [&]() { return ZMove{ZMove::Dwell, 0.0, 0.0, c.p, dwell_seconds(c.p, true), ""}; };
  std::vector<ZMove> m{rapid(c.r_mm)};
  const bool pecks = (c.code == 83 || c.code == 73) && c.q_mm && *c.q_mm > 0;
  switch (c.code) {
    case 81: case 82: case 83: case 73:
      if (pecks) {
        double reached = c.r_mm;
        // Where the pecks are counted from: R (LinuxCNC), or the part's top.
        const double counted_from = part_top_z_mm ? std::min(c.r_mm, *part_top_z_mm) : c.r_mm;
        while (reached > c.z_mm + 1e-9) {
          const double next = std::max(c.z_mm, std::min(reached, counted_from) - *c.q_mm);
          if (reached < c.r_mm) {
            // Back to just above the depth already cut: G83 from R, G73 from where it backed off.
            if (c.code == 83) m.push_back(rapid(c.r_mm));
            m.push_back(rapid(reached + kPeckClearance));
          }
          m.push_back(feed(next));
          reached = next;
        }
      } else {
        m.push_back(feed(c.z_mm));
      }
      if (c.code == 82 && !c.p.empty()) m.push_back(dwell());
      m.push_back(rapid(retract_z_mm));
      return m;
    case 85: case 89:
      m.push_back(feed(c.z_mm));
      if (c.code == 89 && !c.p.empty()) m.push_back(dwell());
      m.push_back(feed(c.r_mm));
      if (retract_z_mm > c.r_mm) m.push_back(rapid(retract_z_mm));
      return m;
    default:
      throw ProgramError(line, (c.code == 331 ? std::string("G33.1") : "G" + std::to_string(c.code)) +
                                   (c.code == 84 || c.code == 74 || c.code == 331 ? " (tapping)" : "") +
                                   " cannot be written as moves for a control without canned cycles; "
                                   "choose --dialect haas, fanuc or linuxcnc, or --keep-style");
  }
}

}  // namespace gcode
