#pragma once
// The independent oracles the tests read programs back with: GRBL 1.1h's own
// parser (tests/grbl-sim, the gvalidate target) and LinuxCNC's rs274, its
// canonical calls made into what the program drills and mills.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.h"

namespace oracles {

inline std::string gvalidate() { return std::string(ACO_BUILD_DIR) + "/grbl/gvalidate.exe"; }

// Empty when GRBL 1.1h's parser, in check mode, accepts every line.
inline std::string grbl_refusal(const std::string& program_text) {
  testutil::TempDir t;
  testutil::spit(t / "p.nc", "$C\n" + program_text);
  auto r = testutil::run("cd " + testutil::shell_quote(t.path()) + " && timeout 120 " + testutil::shell_quote(gvalidate()) + " p.nc");
  if (r.code == 0 && r.out.find("error") == std::string::npos) return "";
  return "gvalidate exit " + std::to_string(r.code) + ": " + r.out.substr(r.out.find("error") == std::string::npos ? 0 : r.out.find("error"), 60);
}

// What rs274 makes: a drilled hole is a feed down at one XY; a milled one is
// a feed down followed by arcs about one centre (ARC_FEED), its diameter
// twice the arcs' radius plus the tool's.
struct Made {
  int tool = 0;
  double x = 0, y = 0;      // the centre
  double bottom = 0;
  double path_radius = 0;   // 0: drilled
  int offset = 1;           // the work offset it is drilled in: rs274's G5X index (1 G54 ... 6 G59, 7-9 G59.1-G59.3)
  // Tapped (the spindle reversed at the bottom, or RIGID_TAP): length a turn,
  // the feed over the spindle's speed (G84, G74) or the synchronized motion's (G33.1); 0: not tapped.
  double pitch = 0;
  bool synchronized = false;  // RIGID_TAP (G33.1)
};

struct Canon {
  std::vector<Made> made;
  std::vector<std::string> probes;  // STRAIGHT_PROBE lines
  std::vector<int> tools;           // SELECT_TOOL in order
};

inline std::vector<double> numbers(const std::string& args) {
  std::vector<double> v;
  std::istringstream in(args);
  for (std::string a; std::getline(in, a, ',');) v.push_back(std::stod(a));
  return v;
}

inline Canon run_rs274(const std::string& program_path) {
  testutil::TempDir t;
  std::string prog = testutil::slurp(program_path);
  // rs274 puts machine Z home (G53 Z0) at work Z 0; on the machine it is the
  // top of the travel, above everything: say so, so that the rapids that
  // follow it are seen where they run.
  for (const std::string home : {"G53 G00 Z0.", "G91 G28 Z0."}) {  // HAAS and LinuxCNC; Fanuc
    for (std::size_t at = prog.find(home); at != std::string::npos; at = prog.find(home, at)) prog.replace(at, home.size(), "G90 G00 Z100.");
  }
  // Fanuc's rigid tapping M29 S before G84 is no LinuxCNC M code: the line
  // goes, as Fanuc would run G84 rigidly after it and LinuxCNC runs G84 anyway.
  static const std::regex rigid(R"((^|\n)M29 S\d+\n)");
  prog = std::regex_replace(prog, rigid, "$1");
  testutil::spit(t / "p.ngc", prog);
  std::string table;
  std::set<std::string> tools;
  static const std::regex tool_word(R"(\bT(\d+))");
  for (std::sregex_iterator it(prog.begin(), prog.end(), tool_word), end; it != end; ++it) tools.insert((*it)[1].str());
  for (const std::string& n : tools) table += "T" + n + " P" + n + " Z0 D1\n";
  testutil::spit(t / "tool.tbl", table);
  auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g p.ngc");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  Canon c;
  static const std::regex call(
      R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SELECT_TOOL|STRAIGHT_PROBE|SET_G5X_OFFSET|SET_SPINDLE_SPEED|SET_FEED_RATE|START_SPEED_FEED_SYNC|RIGID_TAP|START_SPINDLE_CLOCKWISE|START_SPINDLE_COUNTERCLOCKWISE)\(([^)]*)\))");
  int tool = 0, offset = 1;
  double speed = 0, feed = 0, sync_pitch = 0;
  double x = 0, y = 0, z = 0;
  bool open = false;  // a hole is being made here
  bool here = false;  // the last hole made is where the spindle is, with this tool (a G83 peck goes on in it)
  std::vector<std::size_t> cut;  // the holes the milling cut under way makes
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, call)) continue;
    if (m[1] == "SELECT_TOOL") {
      tool = std::stoi(m[2]);
      c.tools.push_back(tool);
      open = false;
      here = false;
      continue;
    }
    const std::vector<double> v = numbers(m[2]);
    if (m[1] == "SET_SPINDLE_SPEED") {
      speed = v.at(1);
      continue;
    }
    if (m[1] == "SET_FEED_RATE") {
      feed = v.at(0);
      continue;
    }
    if (m[1] == "START_SPEED_FEED_SYNC") {
      sync_pitch = v.at(0);
      continue;
    }
    if (m[1] == "START_SPINDLE_CLOCKWISE" || m[1] == "START_SPINDLE_COUNTERCLOCKWISE") {
      // Turned the other way at the bottom of a hole: a tap (G84, G74), fed at its pitch a turn.
      if (open && cut.empty() && !c.made.empty() && speed > 0) c.made.back().pitch = feed / speed;
      continue;
    }
    if (m[1] == "RIGID_TAP") {
      // G33.1: over the hole already (rs274 writes the traverse before), down and back where it began.
      EXPECT_NEAR(v[0], x, 1e-9) << "a rigid tap moving in XY: " << line;
      EXPECT_NEAR(v[1], y, 1e-9) << "a rigid tap moving in XY: " << line;
      EXPECT_GT(z, 1e-9) << "a rigid tap begun at or below the top: " << line;
      Made tap{tool, v[0], v[1], v[2], 0.0, offset};
      tap.pitch = sync_pitch;
      tap.synchronized = true;
      c.made.push_back(tap);
      open = here = false;
      cut.clear();
      continue;
    }
    if (m[1] == "SET_G5X_OFFSET") {
      offset = static_cast<int>(v[0]);
      open = here = false;
      continue;
    }
    if (m[1] == "STRAIGHT_PROBE") {
      c.probes.push_back(line);
      x = v[0], y = v[1], z = v[2];
      open = false;
      continue;
    }
    if (m[1] == "ARC_FEED") {
      // ARC_FEED(end x, end y, centre x, centre y, turn, end z, ...)
      // One cut: a helix (one centre) or a slot's racetrack (its two ends' centres), one radius.
      EXPECT_TRUE(open) << "an arc that does not go on from a feed down: " << line;
      if (open) {
        const double r0 = std::hypot(x - v[2], y - v[3]);
        if (c.made.back().path_radius == 0) {
          c.made.back().x = v[2], c.made.back().y = v[3], c.made.back().path_radius = r0;
          cut = {c.made.size() - 1};
        }
        EXPECT_NEAR(c.made.back().path_radius, r0, 0.002) << line;
        std::size_t at = c.made.size();
        for (std::size_t k : cut) {
          if (std::hypot(c.made[k].x - v[2], c.made[k].y - v[3]) < 1e-6) at = k;
        }
        if (at == c.made.size()) {
          c.made.push_back({tool, v[2], v[3], v[5], r0, offset});
          cut.push_back(at);
        }
        c.made[at].bottom = std::min(c.made[at].bottom, v[5]);
      }
      x = v[0], y = v[1], z = v[5];
      continue;
    }
    const bool xy_moved = std::fabs(v[0] - x) > 1e-9 || std::fabs(v[1] - y) > 1e-9;
    if (xy_moved) here = false;
    if (xy_moved) {
      // Travel only with rapids above the part; a feed in XY only inside a hole being milled (to its centre).
      if (m[1] == "STRAIGHT_TRAVERSE") EXPECT_GT(std::min(z, v[2]), 1e-9) << "a rapid at or below the top: " << line;
      else EXPECT_TRUE(open && !cut.empty()) << "a feed in XY outside a milled hole: " << line;
      if (m[1] == "STRAIGHT_TRAVERSE") open = false, cut.clear();
    } else if (m[1] == "STRAIGHT_FEED" && v[2] < z - 1e-9) {
      if (!open && !here) c.made.push_back({tool, v[0], v[1], v[2], 0.0, offset});
      if (!open) cut.clear();
      open = here = true;
      c.made.back().bottom = std::min(c.made.back().bottom, v[2]);
    } else if (m[1] == "STRAIGHT_TRAVERSE" && v[2] > z + 1e-9 && v[2] > 0) {
      open = false;  // out of the hole
      cut.clear();
    }
    x = v[0], y = v[1], z = v[2];
  }
  return c;
}

inline std::map<int, double> tool_diameters(const std::string& program) {
  std::map<int, double> d;
  static const std::regex comment(R"((?:\(|; )T(\d+) D=([0-9.]+) MM)");  // "(T1 D=" or Marlin's "; T1 D="
  for (std::sregex_iterator it(program.begin(), program.end(), comment), end; it != end; ++it) {
    d[std::stoi((*it)[1])] = std::stod((*it)[2]);
  }
  return d;
}

}  // namespace oracles
