// Issue 14: other CAMs' drilling programs read as a control runs them. The
// oracle for the real programs is LinuxCNC's rs274: tests/data/real-gcode/
// NAME.holes.csv lists the positions it drills, in program order, with the
// deepest Z and the tool (../shared/fixtures/real-gcode/README.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <algorithm>
#include <sstream>

#include "gcode/drilling.h"
#include "test_util.h"

namespace {

struct Expected {
  double x, y, z;
  int tool;
};

std::vector<Expected> read_expected(const std::string& csv) {
  std::vector<Expected> out;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    Expected e{};
    char c;
    std::istringstream row(line);
    row >> e.x >> c >> e.y >> c >> e.z >> c >> e.tool;
    out.push_back(e);
  }
  return out;
}

std::string holes_csv_of(const std::string& program) {
  return program.substr(0, program.find_last_of('.')) + ".holes.csv";
}

class RealProgram : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(RealProgram, reads_the_holes_rs274_drills_in_order_with_tool_and_depth) {
  const gcode::DrillingProgram p = gcode::read_drilling(testutil::slurp(GetParam()));
  const std::vector<Expected> expected = read_expected(testutil::slurp(holes_csv_of(GetParam())));
  std::vector<std::pair<const gcode::ToolRun*, const gcode::ProgramHole*>> got;
  for (const auto& run : p.runs) for (const auto& h : run.holes) got.push_back({&run, &h});
  ASSERT_EQ(got.size(), expected.size());
  // rs274 prints four decimals of the program's units; inch is converted to mm and rounded again.
  const double tol = (p.inch ? 0.00005 * 25.4 : 0.0) + 0.00005 + 1e-6;
  const bool rs274_sees_tools = !testutil::tools_only_in_comments(testutil::slurp(GetParam()));
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].second->at.x, expected[i].x, tol) << "hole " << i << " line " << got[i].second->line;
    EXPECT_NEAR(got[i].second->at.y, expected[i].y, tol) << "hole " << i << " line " << got[i].second->line;
    EXPECT_NEAR(got[i].second->cycle.bottom_mm(), expected[i].z, tol) << "hole " << i << " line " << got[i].second->line;
    if (rs274_sees_tools) {
      EXPECT_EQ(got[i].first->tool, expected[i].tool) << "hole " << i << " line " << got[i].second->line;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(real_gcode, RealProgram, ::testing::ValuesIn(testutil::real_gcode_programs()),
                         [](const auto& test_param) { return testutil::file_param_name(test_param.param); });

namespace {
std::vector<const gcode::ProgramHole*> all_holes(const gcode::DrillingProgram& p) {
  std::vector<const gcode::ProgramHole*> out;
  for (const auto& r : p.runs) for (const auto& h : r.holes) out.push_back(&h);
  return out;
}
}  // namespace

TEST(program_test, incremental_cycles_measure_r_from_the_initial_plane_and_z_from_r) {
  // G91: R is below the initial plane, Z below R; X Y are steps.
  const auto p = gcode::read_drilling("G21 G90\nG0 X10 Y10 Z5\nG91 G99 G81 X0 Y0 R-3 Z-4 F100\nX5\nX5\nG80 G90\nM30\n");
  const auto h = all_holes(p);
  ASSERT_EQ(h.size(), 3u);
  EXPECT_DOUBLE_EQ(h[0]->cycle.r_mm, 2.0);
  EXPECT_DOUBLE_EQ(h[0]->cycle.bottom_mm(), -2.0);
  EXPECT_DOUBLE_EQ(h[2]->at.x, 20.0);
  EXPECT_FALSE(h[0]->cycle.retract_initial);
}

TEST(program_test, inch_programs_are_read_in_mm_and_keep_their_decimals) {
  const auto p = gcode::read_drilling("G20\nG0 Z0.1\nG81 R0.05 Z-0.0625 F10. X1.25 Y0.5\nX2.00001 Y0.5\nG80\nM2\n");
  ASSERT_EQ(p.hole_count(), 2u);
  EXPECT_TRUE(p.inch);
  EXPECT_EQ(p.decimals, 5);
  EXPECT_NEAR(all_holes(p)[0]->at.x, 31.75, 1e-9);
  EXPECT_NEAR(all_holes(p)[0]->cycle.bottom_mm(), -1.5875, 1e-9);
  EXPECT_NEAR(all_holes(p)[0]->cycle.feed_mm_min, 254.0, 1e-9);
}

TEST(program_test, tools_come_from_t_words_with_or_without_m6_and_a_manual_stop_starts_a_run) {
  const auto p = gcode::read_drilling(
      "(T1 D=0.8 MM)\nT1 M6\nS9000 M3\nG0 X0 Y0 Z2\nG81 R1 Z-1 F50\nX1\nG80\n"  // T1 with a change
      "T2\nG0 X5 Y5\nG81 R1 Z-1 F50\nG80\n"                                   // T2 selected only
      "M0 (CHANGE TO 1.2 MM)\nG0 X9 Y9\nG81 R1 Z-1 F50\nG80\nM30\n");        // a manual change: same T
  ASSERT_EQ(p.runs.size(), 3u);
  EXPECT_EQ(p.runs[0].tool, 1);
  EXPECT_TRUE(p.runs[0].tool_change);
  ASSERT_TRUE(p.runs[0].diameter_mm);
  EXPECT_DOUBLE_EQ(*p.runs[0].diameter_mm, 0.8);
  EXPECT_EQ(p.runs[0].spindle, 3);
  EXPECT_EQ(p.runs[1].tool, 2);
  EXPECT_FALSE(p.runs[1].tool_change);
  EXPECT_EQ(p.runs[2].tool, 2);
  EXPECT_TRUE(p.runs[2].pause);
  EXPECT_EQ(p.runs[2].message, "CHANGE TO 1.2 MM");
}

TEST(program_test, comments_marks_and_numbers_of_every_style_are_read_past) {
  const auto p = gcode::read_drilling(
      "\xEF\xBB\xBF%\n% a comment line\nO1234\nN10 g21 (nested (comment) here) g90 ; to the end\n"
      "N20 G0 X1 Y2 Z3\n/N30 G81 R1 Z-1 F50\n(G0 X99 Y99 in a comment)\nN40 G80\nN50 M30\n%\nafter the program X1\n");
  ASSERT_EQ(p.hole_count(), 1u);
  EXPECT_TRUE(p.uses_line_numbers);
  EXPECT_DOUBLE_EQ(all_holes(p)[0]->at.y, 2.0);
}

TEST(program_test, expanded_drilling_with_pecks_and_a_dwell_is_one_hole_at_its_deepest) {
  const auto p = gcode::read_drilling(
      "G21 G90\nG0 Z5\nG0 X1 Y1\nG1 Z-1 F60\nG0 Z1\nG1 Z-2\nG4 P0.5\nG0 Z5\n"
      "G0 X3 Y1\nG1 Z-2\nG0 Z5\nG0 X3 Y1\nG1 Z-2\nG0 Z5\nM30\n");
  const auto h = all_holes(p);
  ASSERT_EQ(h.size(), 3u) << "a rapid to the same place starts another hole there";
  EXPECT_EQ(h[0]->cycle.code, 0);
  EXPECT_DOUBLE_EQ(h[0]->cycle.bottom_mm(), -2.0);
  int feeds = 0, dwells = 0;
  for (const auto& m : h[0]->cycle.moves) {
    feeds += m.kind == gcode::ZMove::Feed;
    dwells += m.kind == gcode::ZMove::Dwell;
  }
  EXPECT_EQ(feeds, 2);
  EXPECT_EQ(dwells, 1);
  ASSERT_TRUE(h[0]->arrive_z_mm);
  EXPECT_DOUBLE_EQ(*h[0]->arrive_z_mm, 5.0);
}

TEST(program_test, tapping_and_boring_cycles_keep_their_words) {
  const auto p = gcode::read_drilling(
      "G21\nT3 M6\nS500 M3\nG0 X0 Y0 Z10\nM29 S500\nG98 G84 X1 Y1 Z-8 R2 F625\nG80\n"
      "G99 G89 X5 Y5 Z-6 R2 P500 F100\nG85 X6 Y6 Z-6 R2 F100\nG80\nM30\n");
  const auto h = all_holes(p);
  ASSERT_EQ(h.size(), 3u);
  EXPECT_EQ(h[0]->cycle.code, 84);
  EXPECT_TRUE(h[0]->cycle.rigid);
  EXPECT_DOUBLE_EQ(h[0]->cycle.feed_mm_min, 625.0);
  EXPECT_EQ(h[1]->cycle.code, 89);
  EXPECT_EQ(h[1]->cycle.p, "500");
  EXPECT_EQ(h[2]->cycle.code, 85);
  EXPECT_TRUE(h[2]->cycle.p.empty()) << "a new cycle forgets the last one's dwell";
}

// Issue 83: a cycle without the word it needs, where nothing earlier stated
// it, is said once (a note by its line) and written as what the control
// would do: G82 without P dwells 0 s (P0); G83 and G73 without Q drill in one
// stroke (Q the whole way from R to Z). HAAS's I J K pecks need no Q.
TEST(program_test, a_cycle_missing_its_word_is_said_once_and_written_as_the_control_runs_it) {
  const auto p = gcode::read_drilling("G21 G90\nT1 M6\nS900 M3\nG0 X0 Y0 Z10\nG99 G82 X1 Y1 Z-5 R2 F100\nX2\nG80\n"
                                      "G98 G83 X3 Y3 Z-5 R2 F100\nX4\nG80\nG73 X5 Y5 Z-4 R1 F100\nG80\nG83 X6 Y6 Z-5 R2 I2 J0.5 K1 F100\nG80\nM30\n");
  const auto h = all_holes(p);
  ASSERT_EQ(h.size(), 6u);
  EXPECT_EQ(h[0]->cycle.p, "0");
  EXPECT_EQ(h[1]->cycle.p, "0");
  ASSERT_TRUE(h[2]->cycle.q_mm && h[3]->cycle.q_mm && h[4]->cycle.q_mm);
  EXPECT_DOUBLE_EQ(*h[2]->cycle.q_mm, 7.0);
  EXPECT_DOUBLE_EQ(*h[3]->cycle.q_mm, 7.0);
  EXPECT_DOUBLE_EQ(*h[4]->cycle.q_mm, 5.0);
  EXPECT_FALSE(h[5]->cycle.q_mm) << "HAAS pecks by I J K";
  ASSERT_EQ(p.notes.size(), 3u);
  EXPECT_EQ(p.notes[0].line, 5u);
  EXPECT_THAT(p.notes[0].message, ::testing::HasSubstr("G82 without P"));
  EXPECT_EQ(p.notes[1].line, 8u);
  EXPECT_THAT(p.notes[1].message, ::testing::HasSubstr("G83 without Q (its peck) and none in force"));
  EXPECT_THAT(p.notes[1].message, ::testing::HasSubstr("written as Q7.000"));
  EXPECT_EQ(p.notes[2].line, 11u);
  EXPECT_THAT(p.notes[2].message, ::testing::HasSubstr("G73 without Q"));
  // Written back for LinuxCNC, which refuses a G83 without Q, it has one.
  gcode::DrillingWriteSettings s;
  s.dialect = gcode::Dialect::LinuxCnc;
  std::ostringstream out;
  gcode::write_drilling(out, p, s);
  EXPECT_THAT(out.str(), ::testing::HasSubstr("G83 X3.000 Y3.000 Z-5.000 R2.000 Q7.000"));
}

// A hole fed with no F ever stated (a post that leaves the feed out): the
// control's feed is 0, which it refuses; said once, by the first such line,
// for a cycle and for expanded drilling alike, and written as F0.
TEST(program_test, a_hole_fed_with_no_feed_stated_is_said_once_and_written_as_f0) {
  for (const std::string& body : {std::string("G0 X0 Y0 Z5\nG81 X0 Y0 Z-3 R1\nX10\nX5 Y5\nG80\n"),
                                  std::string("G0 X0 Y0 Z5\nG1 Z-3\nG0 Z5\nG0 X10\nG1 Z-3\nG0 Z5\n")}) {
    const auto p = gcode::read_drilling("G21 G90\nT1 M6\nM3 S1000\n" + body + "M30\n");
    ASSERT_EQ(p.notes.size(), 1u) << body;
    EXPECT_EQ(p.notes[0].line, 5u);
    EXPECT_THAT(p.notes[0].message, ::testing::HasSubstr("without F (its feed) and none in force"));
    std::ostringstream out;
    gcode::write_drilling(out, p, {});
    EXPECT_THAT(out.str(), ::testing::HasSubstr("F0.000")) << out.str();
  }
  // With a feed in force before the hole, nothing to say.
  EXPECT_TRUE(gcode::read_drilling("G21 G90\nG1 F100\nG0 X0 Y0 Z5\nG81 X0 Y0 Z-3 R1\nM30\n").notes.empty());
}

// LinuxCNC's G33.1 (issue 82): a tapped hole from where Z is, its K the
// pitch (inch too); refused in one line without K, without Z, from a Z not
// known, or moving in X/Y at the part's top.
TEST(program_test, a_rigid_tap_g33_1_is_a_tapped_hole_begun_where_z_is) {
  const auto p = gcode::read_drilling("G20\nT4 M6\nS400 M3\nG0 X0 Y0 Z1\nG0 Z0.1\nG33.1 X0 Y0 Z-0.5 K0.05\nG0 X1\nG33.1 X1 Z-0.5 K0.05\nG0 Z1\nM30\n");
  const auto h = all_holes(p);
  ASSERT_EQ(h.size(), 2u);
  for (const auto* hole : h) {
    EXPECT_EQ(hole->cycle.code, 331);
    EXPECT_NEAR(hole->cycle.r_mm, 2.54, 1e-9);
    EXPECT_NEAR(hole->cycle.z_mm, -12.7, 1e-9);
    EXPECT_NEAR(hole->cycle.pitch_mm, 1.27, 1e-9);
    EXPECT_NEAR(hole->cycle.feed_mm_min, 1.27 * 400, 1e-9);
  }
  EXPECT_NEAR(h[1]->at.x, 25.4, 1e-9);
  // GRBL cannot tap: the writer refuses the G33.1 by its own name and line.
  gcode::DrillingWriteSettings grbl;
  grbl.dialect = gcode::Dialect::Grbl;
  std::ostringstream ignored;
  try {
    gcode::write_drilling(ignored, p, grbl);
    ADD_FAILURE() << "G33.1 written for GRBL";
  } catch (const gcode::ProgramError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_THAT(e.what(), ::testing::HasSubstr("G33.1 (tapping) cannot be written as moves"));
  }
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {"G21\nS400 M3\nG0 X0 Y0 Z2\nG33.1 X0 Y0 Z-5\n", "G33.1 without K"},
           {"G21\nS400 M3\nG0 X0 Y0 Z2\nG33.1 X0 Y0 K1\n", "G33.1 without Z"},
           {"G21\nS400 M3\nG53 G0 Z0\nG33.1 X0 Y0 Z-5 K1\n", "G33.1 from a Z not known"},
           {"G21\nS400 M3\nG0 X0 Y0 Z2\nG33.1 X0 Y0 Z5 K1\n", "G33.1 depth Z is not below where it starts"},
           {"G21\nS400 M3\nG0 X0 Y0 Z0\nG33.1 X5 Y0 Z-5 K1\n", "G33.1 moves in X/Y at Z0.000"}}) {
    try {
      gcode::read_drilling(text);
      ADD_FAILURE() << "read: " << text;
    } catch (const gcode::ProgramError& e) {
      EXPECT_EQ(e.line(), 4u) << text;
      EXPECT_THAT(e.what(), ::testing::HasSubstr(says));
    }
  }
}

TEST(program_test, a_reordered_program_reads_back_to_the_same_holes_in_both_styles) {
  const std::string text = testutil::slurp(testutil::data("real-gcode/fusion360_mach3_heatsunk_drill.tap"));
  gcode::DrillingProgram p = gcode::read_drilling(text);
  std::reverse(p.runs[0].holes.begin(), p.runs[0].holes.end());
  for (bool keep : {false, true}) {
    gcode::DrillingWriteSettings s;
    s.keep_style = keep;
    std::ostringstream out;
    gcode::write_drilling(out, p, s);
    const gcode::DrillingProgram reread = gcode::read_drilling(out.str());
    const auto back = all_holes(reread);
    const auto want = all_holes(p);
    ASSERT_EQ(back.size(), want.size()) << out.str();
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_NEAR(back[i]->at.x, want[i]->at.x, 1e-3) << keep;
      EXPECT_NEAR(back[i]->at.y, want[i]->at.y, 1e-3) << keep;
      EXPECT_NEAR(back[i]->cycle.r_mm, want[i]->cycle.r_mm, 1e-3) << keep;
      EXPECT_EQ(back[i]->cycle.code, 73);
    }
    if (keep) {
      EXPECT_THAT(out.str(), ::testing::HasSubstr("(HEATSUNK_DRILL)\n"));
    }
  }
}

// The CLI: overlapping holes keep their input order; verify checks a reordered
// program against its input, tools and depths included.
TEST(program_test, overlapping_holes_keep_their_input_order_and_verify_confirms_the_result) {
  testutil::TempDir t;
  const std::string in = testutil::data("real-gcode/pcb2gcode_slots-with-drill.drill.ngc");
  const std::string out = t / "out.ngc";
  auto r = testutil::acodrill_run("plan " + in + " -o " + out + " -q --report " + (t / "r.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  // Independently: the holes each tool drills closer than its drill (the MSG comment's size) overlap.
  const auto before = gcode::read_drilling(testutil::slurp(in));
  const auto after = gcode::read_drilling(testutil::slurp(out));
  ASSERT_EQ(before.runs.size(), after.runs.size());
  std::size_t overlapping = 0;
  for (std::size_t k = 0; k < before.runs.size(); ++k) {
    const auto& a = before.runs[k].holes;
    const auto& b = after.runs[k].holes;
    ASSERT_TRUE(before.runs[k].diameter_mm);
    const double d = *before.runs[k].diameter_mm;
    auto position = [&](const gcode::ProgramHole& h) {
      for (std::size_t i = 0; i < b.size(); ++i) {
        if (std::hypot(b[i].at.x - h.at.x, b[i].at.y - h.at.y) < 1e-4) return i;
      }
      return b.size();
    };
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t j = i + 1; j < a.size(); ++j) {
        if (std::hypot(a[i].at.x - a[j].at.x, a[i].at.y - a[j].at.y) >= d) continue;
        ++overlapping;
        EXPECT_LT(position(a[i]), position(a[j])) << "T" << before.runs[k].tool << " holes of lines " << a[i].line
                                                  << " and " << a[j].line << " overlap and changed order";
      }
    }
  }
  EXPECT_GT(overlapping, 20u);
  EXPECT_THAT(testutil::slurp(t / "r.json"), ::testing::HasSubstr("\"overlapping_holes_in_input_order\": 45"));
  auto v = testutil::acodrill_run("verify " + out + " --holes " + in + " -q");
  EXPECT_EQ(v.code, 0) << v.out;
  EXPECT_THAT(v.out, ::testing::HasSubstr("ok: 67 holes"));
  // One hole a little shallower: verify says which.
  std::string text = testutil::slurp(out);
  const auto at = text.find("Z-0.06299");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 9, "Z-0.06200");
  testutil::spit(t / "bad.ngc", text);
  v = testutil::acodrill_run("verify " + (t / "bad.ngc") + " --holes " + in + " -q");
  EXPECT_EQ(v.code, 1);
  EXPECT_THAT(v.out, ::testing::HasSubstr("to Z-1.575"));
}

// A program piped in is read once: keep-style copies the text the reader read.
TEST(program_test, a_program_from_standard_input_is_reordered_in_its_own_style) {
  testutil::TempDir t;
  const std::string text = testutil::slurp(testutil::data("real-gcode/fusion360_mach3_heatsunk_drill.tap"));
  auto r = testutil::acodrill_run("plan - -o " + (t / "out.tap") + " -q --keep-style", text);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string out = testutil::slurp(t / "out.tap");
  EXPECT_THAT(out, ::testing::HasSubstr("(HEATSUNK_DRILL)\n"));
  EXPECT_EQ(gcode::read_drilling(out).hole_count(), gcode::read_drilling(text).hole_count());
}
