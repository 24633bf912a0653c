// Issue 83: FreeCAD's programs read right. Its four defects, each on a small
// program written as FreeCAD's posts write them, each failing before its fix:
// a work offset changed within one tool's run (two fixtures), a cycle's Q
// stated on the first hole only, tool changes said only in comments (the
// grbl and jtech posts), Marlin's G4 S dwell in seconds. The oracle is
// LinuxCNC's rs274: the input and every program plan writes from it drill
// the same holes, in the same work offsets, to the same depths.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "oracles.h"
#include "test_util.h"

namespace {

using testutil::shell_quote;

// offset, tool, x, y, bottom (µm)
using Holes = std::vector<std::tuple<int, int, double, double, double>>;

Holes holes_of(const oracles::Canon& c, bool with_tools = true) {
  Holes out;
  auto um = [](double v) { return std::round(v * 1000.0) / 1000.0; };
  for (const oracles::Made& m : c.made) out.emplace_back(m.offset, with_tools ? m.tool : 0, um(m.x), um(m.y), um(m.bottom));
  std::sort(out.begin(), out.end());
  return out;
}

Holes rs274_holes(const std::string& text, bool with_tools = true) {
  testutil::TempDir t;
  testutil::spit(t / "p.ngc", text);
  return holes_of(oracles::run_rs274(t / "p.ngc"), with_tools);
}

std::string plan(const std::string& input, const std::string& options) {
  testutil::TempDir t;
  testutil::spit(t / "in.nc", input);
  auto r = testutil::acodrill_run("plan " + shell_quote(t / "in.nc") + " -o " + shell_quote(t / "out.nc") + " -q --seed 1 " + options);
  EXPECT_EQ(r.code, 0) << options << ": " << r.err;
  return testutil::slurp(t / "out.nc");
}

// FreeCAD, two fixtures, "order by tool": each tool drills G54's holes, then G55's, with no tool change between.
const std::string kTwoFixtures =
    "G21 G90 G17\n"
    "T1 M06\n"
    "S1000 M03\n"
    "G54\n"
    "G00 Z5\n"
    "G00 X10 Y10 Z5\n"
    "G81 X10 Y10 Z-3 R1 F100\n"
    "X40 Y10\n"
    "X15 Y30\n"
    "G80\n"
    "G55\n"
    "G00 X10 Y10 Z5\n"
    "G81 X10 Y10 Z-3 R1 F100\n"
    "X40 Y10\n"
    "X15 Y30\n"
    "G80\n"
    "G54\n"
    "T2 M06\n"
    "S1500 M03\n"
    "G00 X25 Y20 Z5\n"
    "G81 X25 Y20 Z-4 R1 F80\n"
    "G80\n"
    "G55\n"
    "G81 X25 Y20 Z-4 R1 F80\n"
    "G80\n"
    "M05\n"
    "M30\n";

TEST(FreeCadPrograms, AWorkOffsetChangedWithinAToolsRunKeepsItsHoles) {
  const Holes want = rs274_holes(kTwoFixtures);
  ASSERT_EQ(want.size(), 8u);
  ASSERT_EQ(std::count_if(want.begin(), want.end(), [](const auto& h) { return std::get<0>(h) == 2; }), 4) << "4 holes in G55";
  for (const std::string options : {"", "--keep-style", "--dialect linuxcnc", "--dialect fanuc"}) {
    const std::string out = plan(kTwoFixtures, options);
    EXPECT_EQ(rs274_holes(out), want) << options << "\n" << out;
  }
  // GRBL: no tool changer, the same holes in the same offsets.
  EXPECT_EQ(rs274_holes(plan(kTwoFixtures, "--dialect grbl"), false), rs274_holes(kTwoFixtures, false));
  // verify compares the offsets too: the program is right, and wrong with the second fixture's holes in G54.
  testutil::TempDir t;
  testutil::spit(t / "in.nc", kTwoFixtures);
  std::string out = plan(kTwoFixtures, "");
  testutil::spit(t / "out.nc", out);
  auto v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
  EXPECT_EQ(v.code, 0) << v.out << v.err;
  for (std::size_t at = out.find("G55"); at != std::string::npos; at = out.find("G55")) out.replace(at, 3, "G54");
  testutil::spit(t / "out.nc", out);
  v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
  EXPECT_EQ(v.code, 1) << v.out;
  EXPECT_THAT(v.out, ::testing::HasSubstr("in G55 of line"));
}

// FreeCAD's uccnc and fanuc posts: Q and R on the first hole, then each hole
// "G0 X Y" and "G83 ..." without Q, which Fanuc and UCCNC keep in force until
// G80 (LinuxCNC does not after a G0, so rs274 cannot read the input itself:
// the holes are written out here).
const std::string kModalQ =
    "G21 G90\n"
    "T1 M6\n"
    "S1000 M3\n"
    "G0 Z15\n"
    "G0 X50 Y50\n"
    "G99 G83 X50 Y50 Z-10 Q2.5 R11.5 F100\n"
    "G0 X10 Y10\n"
    "G83 X10 Y10 Z-10 F100\n"
    "G0 X30 Y30\n"
    "G83 X30 Y30 Z-10 F100\n"
    "G80\n"
    "M5\n"
    "M30\n";

TEST(FreeCadPrograms, AModalQIsStatedWhereverReorderingMovesAHole) {
  const Holes want = {{1, 1, 10, 10, -10}, {1, 1, 30, 30, -10}, {1, 1, 50, 50, -10}};
  for (const std::string options : {"", "--keep-style", "--dialect linuxcnc"}) {
    const std::string out = plan(kModalQ, options);
    // rs274 refuses a G83 without a Q in force ("Q word missing with g83"): run_rs274 fails the test then.
    EXPECT_EQ(rs274_holes(out), want) << options << "\n" << out;
    EXPECT_THAT(out, ::testing::HasSubstr("Q2.5")) << options;
  }
  // verify compares pecks and dwells: the right program passes, one with other pecks or another dwell does not.
  testutil::TempDir t;
  const std::string with_dwell = std::string(kModalQ).replace(kModalQ.find("G83 X10 Y10"), 3, "G82").replace(kModalQ.find("G83 X30"), 3, "G82");
  for (const std::string& input : {kModalQ, with_dwell}) {
    std::string out = plan(input, "--dialect linuxcnc");
    testutil::spit(t / "in.nc", input);
    testutil::spit(t / "out.nc", out);
    auto v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
    EXPECT_EQ(v.code, 0) << v.out << out;
  }
  std::string out = plan(kModalQ, "--dialect linuxcnc");
  out.replace(out.find("Q2.5"), 4, "Q1.0");
  testutil::spit(t / "in.nc", kModalQ);
  testutil::spit(t / "out.nc", out);
  auto v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
  EXPECT_EQ(v.code, 1) << v.out;
  EXPECT_THAT(v.out, ::testing::HasSubstr("with pecks of 1.000 where the input dwells 0.000 s with pecks of 2.500"));
  // Expanded for GRBL, G82's P500 (HAAS: milliseconds) is each hole's G4 P0.500: verify adds up a hole's
  // G4s and compares them with the input's P, and finds a dwell changed in the output.
  std::string g82 = with_dwell;
  for (std::size_t at = g82.find("G82 X"); at != std::string::npos; at = g82.find("G82 X", at + 1)) g82.insert(g82.find(" F100", at), " P500");
  testutil::spit(t / "in.nc", g82);
  std::string grbl = plan(g82, "--dialect grbl");
  EXPECT_THAT(grbl, ::testing::HasSubstr("G4 P0.500"));
  testutil::spit(t / "out.nc", grbl);
  EXPECT_EQ(testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc")).code, 0) << grbl;
  grbl.replace(grbl.find("G4 P0.500"), 9, "G4 P0.100");
  testutil::spit(t / "out.nc", grbl);
  v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
  EXPECT_EQ(v.code, 1) << v.out;
  EXPECT_THAT(v.out, ::testing::HasSubstr("dwelling 0.100 s where the input dwells 0.500 s"));
}

// FreeCAD's grbl post: no T words and no M6 (GRBL has neither); a tool change is a comment.
const std::string kGrblPost =
    "(Exported by FreeCAD)\n"
    "(Begin preamble)\n"
    "G17 G90\n"
    "G21\n"
    "(Begin operation: TC: 3.5 mm Drill)\n"
    "(Begin toolchange)\n"
    "( M6 T1 )\n"
    "M3 S1000\n"
    "(Begin operation: Drilling)\n"
    "G0 Z15\n"
    "G0 X40 Y10\n"
    "G0 Z5\n"
    "G1 Z-3 F100\n"
    "G0 Z5\n"
    "G0 X10 Y12\n"
    "G1 Z-3 F100\n"
    "G0 Z5\n"
    "G0 X60 Y10\n"
    "G1 Z-3 F100\n"
    "G0 Z15\n"
    "(Begin operation: TC: 6.6 mm Drill)\n"
    "(Begin toolchange)\n"
    "( M6 T2 )\n"
    "M3 S800\n"
    "G0 X30 Y30\n"
    "G0 Z5\n"
    "G1 Z-5 F80\n"
    "G0 Z5\n"
    "G0 X5 Y40\n"
    "G1 Z-5 F80\n"
    "G0 Z5\n"
    "G0 X50 Y42\n"
    "G1 Z-5 F80\n"
    "G0 Z15\n"
    "M5\n"
    "M2\n";

// Which holes (x, y) each tool of a program drills, as rs274 reads it.
std::vector<std::vector<std::pair<double, double>>> per_tool(const std::string& text) {
  testutil::TempDir t;
  testutil::spit(t / "p.ngc", text);
  const oracles::Canon c = oracles::run_rs274(t / "p.ngc");
  std::vector<std::vector<std::pair<double, double>>> out;
  int tool = -1;
  for (const oracles::Made& m : c.made) {
    if (out.empty() || m.tool != tool) out.emplace_back();
    tool = m.tool;
    out.back().emplace_back(std::round(m.x * 1000) / 1000, std::round(m.y * 1000) / 1000);
  }
  for (auto& run : out) std::sort(run.begin(), run.end());
  return out;
}

TEST(FreeCadPrograms, ToolChangesSaidOnlyInCommentsAreToolBoundaries) {
  const std::vector<std::vector<std::pair<double, double>>> want = {{{10, 12}, {40, 10}, {60, 10}}, {{5, 40}, {30, 30}, {50, 42}}};
  // HAAS: each of the post's tools a tool of its own, T1 then T2, the holes of each its own.
  std::string out = plan(kGrblPost, "--dialect haas");
  EXPECT_EQ(per_tool(out), want) << out;
  EXPECT_THAT(out, ::testing::HasSubstr("T2 M06"));
  // Kept in the program's own style: the comments stay, between the tools' holes.
  out = plan(kGrblPost, "--keep-style");
  const std::size_t change = out.find("( M6 T2 )");
  ASSERT_NE(change, std::string::npos) << out;
  for (const char* t1 : {"X10.000 Y12.000", "X40.000 Y10.000", "X60.000 Y10.000"}) EXPECT_LT(out.find(t1), change) << t1 << "\n" << out;
  for (const char* t2 : {"X30.000 Y30.000", "X5.000 Y40.000", "X50.000 Y42.000"}) EXPECT_GT(out.find(t2), change) << t2 << "\n" << out;
  // The jtech post names the tool and its diameter in one label.
  std::string jtech = kGrblPost;
  for (const auto& [from, to] : {std::pair{std::string("( M6 T1 )"), std::string("(TC1_3.5)")}, {"( M6 T2 )", "(TC2_6.6)"}}) {
    jtech.replace(jtech.find(from), from.size(), to);
  }
  for (const std::string begin : {"(Begin toolchange)\n"}) {
    for (std::size_t at = jtech.find(begin); at != std::string::npos; at = jtech.find(begin)) jtech.erase(at, begin.size());
  }
  out = plan(jtech, "--dialect haas");
  EXPECT_EQ(per_tool(out), want) << out;
  EXPECT_THAT(out, ::testing::HasSubstr("T2 D=6.600 MM"));
}

// Marlin (and RepRapFirmware): G4 S is a dwell in seconds, not a spindle speed.
const std::string kMarlin =
    "G21\n"
    "G90\n"
    "M3 S255\n"
    "G4 S3\n"
    "G0 Z5\n"
    "G0 X30 Y10\n"
    "G1 Z-2 F100\n"
    "G4 S0.5\n"
    "G0 Z5\n"
    "G0 X10 Y10\n"
    "G1 Z-2 F100\n"
    "G4 S0.5\n"
    "G0 Z5\n"
    "M5\n";

TEST(FreeCadPrograms, MarlinsG4SIsSecondsNotASpindleSpeed) {
  // In its own style (the default for a program) the dwell stays Marlin's, seconds.
  const std::string own = plan(kMarlin, "");
  EXPECT_THAT(own, ::testing::HasSubstr("G4 S0.5"));
  EXPECT_THAT(own, ::testing::Not(::testing::HasSubstr("P0.5")));
  EXPECT_EQ(own, plan(kMarlin, "--keep-style"));
  for (const std::string options : {"--dialect haas", "--dialect linuxcnc"}) {
    const std::string out = plan(kMarlin, options);
    EXPECT_THAT(out, ::testing::Not(::testing::HasSubstr("S3 ")));
    EXPECT_THAT(out, ::testing::HasSubstr("S255"));
    testutil::TempDir t;
    testutil::spit(t / "p.ngc", out);
    testutil::spit(t / "tool.tbl", "T1 P1 Z0 D1\n");
    const auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g p.ngc");
    // Half a second over each hole, as the input dwells.
    std::size_t dwells = 0;
    for (std::size_t at = r.out.find("DWELL(0.5000)"); at != std::string::npos; at = r.out.find("DWELL(0.5000)", at + 1)) ++dwells;
    EXPECT_EQ(dwells, 2u) << options << "\n" << out << r.out;
  }
}

// A FreeCAD Job that mills as well as drills (its linuxcnc post; Z 0 the
// part's bottom, its top at Z 8): T2 drills, T3 profiles the plate with lines
// and an arc, T2 drills again, T2 (the same tool, no change) mills a line-only
// slot at Z 6 -- above Z 0, below the top -- and drills once more.
const std::string kMixedJob =
    "(Exported by FreeCAD)\n"
    "G17 G54 G40 G49 G80 G90\n"
    "G21\n"
    "(begin operation: Drill1)\n"
    "M6 T2\n"
    "M3 S2000\n"
    "G0 Z14\n"
    "G98\n"
    "G0 X10 Y10\n"
    "G81 X10 Y10 Z0 R12 F100\n"
    "G0 X90 Y10\n"
    "G81 X90 Y10 Z0 R12 F100\n"
    "G0 X20 Y10\n"
    "G81 X20 Y10 Z0 R12 F100\n"
    "G0 X80 Y10\n"
    "G81 X80 Y10 Z0 R12 F100\n"
    "G80\n"
    "G0 Z14\n"
    "(begin operation: Profile)\n"
    "M6 T3\n"
    "M3 S10000\n"
    "G0 X-3 Y0\n"
    "G0 Z12\n"
    "G1 X-3 Y0 Z3 F100\n"
    "G1 X-3 Y50 F600\n"
    "G2 X0 Y53 I3 J0\n"
    "G1 X100 Y53\n"
    "G1 X100 Y-3\n"
    "G1 X-3 Y-3\n"
    "G0 Z14\n"
    "(begin operation: Drill2)\n"
    "M6 T2\n"
    "M3 S2000\n"
    "G0 X15 Y45\n"
    "G81 X15 Y45 Z0 R12 F100\n"
    "G0 X85 Y40\n"
    "G81 X85 Y40 Z0 R12 F100\n"
    "G0 X16 Y40\n"
    "G81 X16 Y40 Z0 R12 F100\n"
    "G80\n"
    "G0 Z14\n"
    "(begin operation: Slot)\n"
    "G0 X40 Y25\n"
    "G0 Z12\n"
    "G1 Z6 F100\n"
    "G1 X60 Y25 F600\n"
    "G1 X40 Y25\n"
    "G0 Z14\n"
    "(begin operation: Drill3)\n"
    "G0 X70 Y30\n"
    "G81 X70 Y30 Z0 R12 F100\n"
    "G0 X30 Y30\n"
    "G81 X30 Y30 Z0 R12 F100\n"
    "G0 X50 Y45\n"
    "G81 X50 Y45 Z0 R12 F100\n"
    "G80\n"
    "G0 Z14\n"
    "M5\n"
    "M2\n";

// rs274's reading of a program that mills: in canon order, each hole (a feed
// down at one XY left by a rapid) as "H tool x y bottom", each cut (a feed in
// XY, an arc, the plunge a cut goes on from) as "C tool feed from -> call".
// A rapid in XY at or below `top` (the part's top) fails the test. `ok`:
// false where rs274 cannot read the program (then nothing else is said).
struct Canon {
  std::vector<std::string> events;
  double rapid_xy = 0;
  bool ok = true;
};

Canon milling_canon(const std::string& text, double top = 8.0, bool must_read = true) {
  testutil::TempDir t;
  testutil::spit(t / "p.ngc", text);
  std::string table;
  static const std::regex tool_word(R"(\bT(\d+))");
  std::set<std::string> tools;
  for (std::sregex_iterator it(text.begin(), text.end(), tool_word), end; it != end; ++it) tools.insert((*it)[1].str());
  for (const std::string& n : tools) table += "T" + n + " P" + n + " Z0 D1\n";
  testutil::spit(t / "tool.tbl", table);
  const auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g p.ngc");
  Canon c;
  c.ok = r.code == 0 && r.out.find("rror") == std::string::npos && r.err.find("rror") == std::string::npos;
  if (!c.ok) {
    EXPECT_FALSE(must_read) << r.out << r.err;
    return c;
  }
  struct Call {
    std::string kind;
    int tool;
    double feed;
    std::vector<double> v;
  };
  std::vector<Call> calls;
  static const std::regex call(R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|SELECT_TOOL|SET_FEED_RATE)\(([^)]*)\))");
  int tool = 0;
  double feed = 0;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, call)) continue;
    const std::vector<double> v = oracles::numbers(m[2]);
    if (m[1] == "SELECT_TOOL") tool = static_cast<int>(v.at(0));
    else if (m[1] == "SET_FEED_RATE") feed = v.at(0);
    else calls.push_back({m[1], tool, feed, v});
  }
  double x = 0, y = 0, z = 0;
  auto f = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", std::fabs(v) < 5e-4 ? 0.0 : v);
    return std::string(text);
  };
  for (std::size_t i = 0; i < calls.size(); ++i) {
    const Call& k = calls[i];
    const double end_z = k.kind == "ARC_FEED" ? k.v.at(5) : k.v.at(2);
    const bool moved = std::hypot(k.v[0] - x, k.v[1] - y) > 1e-9;
    const std::string from = f(x) + " " + f(y) + " " + f(z) + " -> ";
    std::string args;
    for (double a : k.v) args += f(a) + " ";
    if (k.kind == "STRAIGHT_TRAVERSE") {
      c.rapid_xy += std::hypot(k.v[0] - x, k.v[1] - y);
      if (moved) EXPECT_GT(std::min(z, end_z), top) << "a rapid in XY at or below the top: " << from << args;
    } else if (k.kind == "ARC_FEED" || moved) {
      c.events.push_back("C " + std::to_string(k.tool) + " " + f(k.feed) + " " + from + k.kind + " " + args);
    } else if (end_z < z) {
      const Call* next = i + 1 < calls.size() ? &calls[i + 1] : nullptr;
      const bool cut_on = next && next->kind != "STRAIGHT_TRAVERSE" &&
                          (next->kind == "ARC_FEED" || std::hypot(next->v[0] - k.v[0], next->v[1] - k.v[1]) > 1e-9);
      c.events.push_back((cut_on ? "C " : "H ") + std::to_string(k.tool) + " " + (cut_on ? f(k.feed) + " " + from : "") +
                         f(k.v[0]) + " " + f(k.v[1]) + " " + f(end_z));
    }
    x = k.v[0], y = k.v[1], z = end_z;
  }
  return c;
}

// The events between two cuts as a set: the holes a run drills, in any order.
std::vector<std::vector<std::string>> stretches(const std::vector<std::string>& events) {
  std::vector<std::vector<std::string>> out(1);
  for (const std::string& e : events) {
    if (e[0] == 'C') {
      if (!out.back().empty()) out.emplace_back();
      out.back().push_back(e);
      out.emplace_back();
    } else {
      out.back().push_back(e);
    }
  }
  if (out.back().empty()) out.pop_back();
  for (auto& s : out) std::sort(s.begin(), s.end());
  return out;
}

TEST(FreeCadPrograms, MillingIsKeptAsWrittenAndTheDrillingReorderedAroundIt) {
  // Without --keep-milling a program that mills is refused at its first cut, as before.
  testutil::TempDir t;
  testutil::spit(t / "job.ngc", kMixedJob);
  auto refused = testutil::acodrill_run("plan " + shell_quote(t / "job.ngc") + " -o " + shell_quote(t / "out.ngc"));
  EXPECT_EQ(refused.code, 2);
  // (Its G1 at Z 3 reads as travel there, hobby posts' way above Z 0; the arc is a cut.)
  EXPECT_THAT(refused.err, ::testing::HasSubstr("job.ngc:26: an arc (G2)"));
  EXPECT_FALSE(std::filesystem::exists(t / "out.ngc"));
  refused = testutil::acodrill_run("plan " + shell_quote(t / "job.ngc") + " -o " + shell_quote(t / "out.ngc") +
                                   " --keep-milling --dialect haas");
  EXPECT_EQ(refused.code, 2);
  EXPECT_THAT(refused.err, ::testing::HasSubstr("--keep-milling writes the program in its own style"));

  const Canon in = milling_canon(kMixedJob);
  const std::string out = plan(kMixedJob, "--keep-milling");
  const Canon got = milling_canon(out);
  // Every cut the same, in the same place among the holes; the holes between
  // two cuts the same ones, drilled by the same tool to the same depth.
  ASSERT_EQ(std::count_if(in.events.begin(), in.events.end(), [](const std::string& e) { return e[0] == 'C'; }), 9);
  EXPECT_EQ(stretches(got.events), stretches(in.events)) << out;
  EXPECT_NE(got.events, in.events) << "nothing was reordered";
  EXPECT_LT(got.rapid_xy, in.rapid_xy) << out;
  // The drilling between cuts, reordered: the first drilling's line, now 10 20 80 90 or its reverse.
  const std::size_t x20 = out.find("X20."), x80 = out.find("X80.");
  ASSERT_NE(x20, std::string::npos);
  EXPECT_LT(std::min(x20, x80), out.find("M6 T3"));
  // Every line that mills, as the input wrote it.
  for (const char* line : {"G1 X-3 Y0 Z3 F100\n", "G2 X0 Y53 I3 J0\n", "G1 X100 Y-3\n", "G1 Z6 F100\n", "G1 X60 Y25 F600\n"}) {
    EXPECT_THAT(out, ::testing::HasSubstr(line));
  }
  // verify, given the input, reads both so: the same holes.
  testutil::spit(t / "out.ngc", out);
  const auto verified = testutil::acodrill_run("verify " + shell_quote(t / "out.ngc") + " --holes " + shell_quote(t / "job.ngc"));
  EXPECT_EQ(verified.code, 0) << verified.out << verified.err;
  EXPECT_THAT(verified.out, ::testing::HasSubstr("holes 10\n"));
}

// A cut that follows the last hole with no rapid in X/Y between begins where
// that hole left the spindle: the reordered run goes back there before it.
TEST(FreeCadPrograms, ACutRightAfterTheLastHoleBeginsWhereTheInputsLastHoleLeftTheSpindle) {
  const std::string job =
      "G21 G90\n"
      "T1 M6\n"
      "M3 S3000\n"
      "G0 Z12\n"
      "G0 X10 Y10\n"
      "G1 Z0 F100\n"
      "G0 Z12\n"
      "G0 X50 Y10\n"
      "G1 Z0 F100\n"
      "G0 Z12\n"
      "G0 X30 Y40\n"
      "G1 Z0 F100\n"
      "G0 Z12\n"
      "G0 X31 Y11\n"
      "G1 Z0 F100\n"
      "G0 Z12\n"
      "G1 X40 Y11 Z6 F300\n"  // a ramp into a slot, from over the last hole
      "G0 Z12\n"
      "M5\n"
      "M30\n";
  const Canon in = milling_canon(job);
  const std::string out = plan(job, "--keep-milling");
  const Canon got = milling_canon(out);
  EXPECT_EQ(stretches(got.events), stretches(in.events)) << out;
  EXPECT_NE(got.events, in.events) << "nothing was reordered";
}

}  // namespace

// The corpus (tests/data/freecad/make_corpus.py): real Jobs made headless by
// FreeCAD 0.20, posted by each post it ships. The oracle is FreeCAD's own
// list of the Job's holes (PART.holes.csv: fixture, tool, centre, depth).
namespace corpus {

const char* const kGcodePosts[] = {"KineticNCBeamicon2", "centroid", "dynapath", "fablin", "fanuc", "grbl", "jtech",
                                   "linuxcnc", "mach3_mach4", "marlin", "rrf", "smoothie", "uccnc"};
const char* const kParts[] = {"plate3", "fixtures2", "stepped", "board333"};

Holes freecad_holes(const std::string& part, bool with_tools) {
  Holes out;
  std::istringstream in(testutil::slurp(testutil::data("freecad/" + part + ".holes.csv")));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    char fixture[8] = {};
    int tool = 0;
    double x = 0, y = 0, bottom = 0;
    if (std::sscanf(line.c_str(), "G%7[^,],%d,%lf,%lf,%lf", fixture, &tool, &x, &y, &bottom) != 5) continue;
    out.emplace_back(std::atoi(fixture) - 53, with_tools ? tool : 0, x, y, bottom);
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool rs274_reads(const std::string& text) {
  testutil::TempDir t;
  testutil::spit(t / "p.ngc", text);
  testutil::spit(t / "tool.tbl", "T1 P1 Z0 D1\nT2 P2 Z0 D1\nT3 P3 Z0 D1\n");
  const auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g p.ngc");
  return r.code == 0 && r.out.find("rror") == std::string::npos && r.err.find("rror") == std::string::npos;
}

}  // namespace corpus

TEST(FreeCadPrograms, EveryGcodePostsProgramIsReorderedToFreeCadsOwnHoles) {
  for (const char* post : corpus::kGcodePosts) {
    for (const char* part : corpus::kParts) {
      SCOPED_TRACE(std::string(post) + "/" + part);
      std::string input = testutil::slurp(testutil::data(std::string("freecad/") + post + "/" + part + ".nc"));
      ASSERT_FALSE(input.empty());
      if (std::string(post) == "fanuc") {
        // FreeCAD's fanuc post writes the file's name as line 3: refused, naming it; without it, read.
        testutil::TempDir t;
        testutil::spit(t / "in.nc", input);
        auto r = testutil::acodrill_run("plan " + shell_quote(t / "in.nc") + " -o " + shell_quote(t / "out.nc"));
        EXPECT_EQ(r.code, 2);
        EXPECT_THAT(r.err, ::testing::HasSubstr(":3: not G-code (FreeCAD's fanuc post writes the output file's name here"));
        input.erase(input.find("\n", input.find("FREECAD-FILENAME")) == std::string::npos ? 0 : input.rfind('\n', input.find("FREECAD-FILENAME")) + 1,
                    input.find('\n', input.find("FREECAD-FILENAME")) - input.rfind('\n', input.find("FREECAD-FILENAME")));
      }
      // fablin marks nothing between tools: its holes are right, its tools one run.
      const bool tools_marked = std::string(post) != "fablin";
      const Holes want = corpus::freecad_holes(part, tools_marked);
      const std::string out = plan(input, "--dialect haas");
      EXPECT_EQ(rs274_holes(out, tools_marked), want) << out;
      const std::string kept = plan(input, "");  // a program comes back in its own style
      EXPECT_EQ(kept, plan(input, "--keep-style"));
      testutil::TempDir t;
      testutil::spit(t / "in.nc", input);
      testutil::spit(t / "out.nc", kept);
      auto v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
      EXPECT_EQ(v.code, 0) << v.out << kept;
      // Where LinuxCNC reads the post's own style, it reads the kept program to FreeCAD's holes too.
      // (Tools by number only where the post writes T words: grbl and jtech keep theirs in comments, which verify checked.)
      if (corpus::rs274_reads(input)) {
        EXPECT_EQ(rs274_holes(kept, false), corpus::freecad_holes(part, false)) << kept;
      }
    }
  }
}

// The Job that mills too ("milled": a drilling, a profile by an end mill,
// another drilling), from every post: refused without --keep-milling, and
// with it the same holes as FreeCAD lists them and the profile cut for cut.
TEST(FreeCadPrograms, EveryPostsJobThatMillsKeepsItsMillingAndDrillsFreeCadsHoles) {
  const Holes want = corpus::freecad_holes("milled", false);
  ASSERT_EQ(want.size(), 21u);
  std::size_t read_by_rs274 = 0;
  for (const char* post : corpus::kGcodePosts) {
    SCOPED_TRACE(post);
    std::string input = testutil::slurp(testutil::data(std::string("freecad/") + post + "/milled.nc"));
    ASSERT_FALSE(input.empty());
    if (std::string(post) == "fanuc") input.erase(input.rfind('\n', input.find("FREECAD-FILENAME")) + 1,
                                                  input.find('\n', input.find("FREECAD-FILENAME")) - input.rfind('\n', input.find("FREECAD-FILENAME")));
    testutil::TempDir t;
    testutil::spit(t / "in.nc", input);
    auto refused = testutil::acodrill_run("plan " + shell_quote(t / "in.nc") + " -o " + shell_quote(t / "out.nc"));
    EXPECT_EQ(refused.code, 2) << refused.err;
    const std::string out = plan(input, "--keep-milling");
    testutil::spit(t / "out.nc", out);
    auto v = testutil::acodrill_run("verify " + shell_quote(t / "out.nc") + " --holes " + shell_quote(t / "in.nc"));
    EXPECT_EQ(v.code, 0) << v.out << out;
    EXPECT_THAT(v.out, ::testing::HasSubstr("ok: 21 holes"));
    // rs274 (where it reads the post's own style): every cut as posted, the
    // holes between two cuts the same, and those FreeCAD's own.
    const Canon in = milling_canon(input, 8.0, false);
    const Canon got = milling_canon(out, 8.0, false);
    if (in.ok) {
      // Where LinuxCNC reads the post's own style, it reads acodrill's program too.
      ++read_by_rs274;
      EXPECT_TRUE(got.ok);
      EXPECT_EQ(stretches(got.events), stretches(in.events)) << out;
      EXPECT_LT(got.rapid_xy, in.rapid_xy);
    }
    if (!got.ok) continue;
    std::map<std::pair<double, double>, double> deepest;  // a peck's strokes are one hole: its deepest
    std::size_t cuts = 0;
    for (const std::string& e : got.events) {
      if (e[0] == 'C') {
        ++cuts;
        continue;
      }
      int tool = 0;
      double x = 0, y = 0, bottom = 0;
      ASSERT_EQ(std::sscanf(e.c_str(), "H %d %lf %lf %lf", &tool, &x, &y, &bottom), 4) << e;
      auto [it, fresh] = deepest.try_emplace({x, y}, bottom);
      if (!fresh) it->second = std::min(it->second, bottom);
    }
    Holes drilled;
    for (const auto& [at, bottom] : deepest) drilled.emplace_back(1, 0, at.first, at.second, bottom);
    std::sort(drilled.begin(), drilled.end());
    EXPECT_EQ(drilled, want);
    EXPECT_GE(cuts, 8u);
  }
  // linuxcnc, mach3_mach4, smoothie, dynapath, KineticNCBeamicon2 at least: LinuxCNC reads them as posted.
  EXPECT_GE(read_by_rs274, 5u);
}

// FreeCAD's marlin and rrf posts move to each hole twice ("G0 X Y", "G0 Z",
// a comment, "G0 X Y"): the hole's lines begin at the first, so no run's first
// hole in the input is visited on the way, before the reordered run begins.
TEST(FreeCadPrograms, AHoleMovedToTwiceIsVisitedOnce) {
  for (const char* post : {"marlin", "rrf"}) {
    const std::string out = plan(testutil::slurp(testutil::data(std::string("freecad/") + post + "/plate3.nc")), "");
    std::map<std::string, int> visits;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("G0 X", 0) == 0) ++visits[line];
    }
    ASSERT_EQ(visits.size(), 19u) << post << "\n" << out;  // plate3's 19 holes
    for (const auto& [move, count] : visits) EXPECT_EQ(count, 1) << post << ": " << move;
  }
}

TEST(FreeCadPrograms, PostsThatWriteNoGcodeAreNamedInOneLine) {
  testutil::TempDir t;
  for (const auto& [post, says] : {std::pair{"opensbp", "an OpenSBP (ShopBot) part file, not G-code"},
                                   {"rml", "a Roland RML file, not G-code"}}) {
    auto r = testutil::acodrill_run("plan " + shell_quote(testutil::data(std::string("freecad/") + post + "/plate3.nc")) + " -o " +
                                    shell_quote(t / "out.nc"));
    EXPECT_EQ(r.code, 2) << post;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr(says));
  }
  testutil::spit(t / "h.h", "0 BEGIN PGM PLATE MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-10\n2 END PGM PLATE MM\n");
  auto r = testutil::acodrill_run("plan " + shell_quote(t / "h.h") + " -o " + shell_quote(t / "out.nc"));
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("HEIDENHAIN conversational (Klartext), not G-code"));
}
