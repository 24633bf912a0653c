// Issue 72: another CAM's program reordered, on the idioms real posts and
// hand programs use: incremental mode left on (Fanuc's G91 G28), cycles in
// G91 with K or L repeats, polar coordinates. Each is either refused with one
// line or reordered into a program that LinuxCNC's rs274 runs to exactly the
// input's holes (tool, place and depth). And plan's own check: a program that
// does not drill what was read is never written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <tuple>

#include "gcode/drilling.h"
#include "oracles.h"
#include "test_util.h"

namespace {

using Holes = std::vector<std::tuple<int, double, double, double>>;  // tool, x, y, bottom (rounded to µm)

Holes sorted_holes(const oracles::Canon& c) {
  Holes out;
  auto um = [](double v) { return std::round(v * 1000.0) / 1000.0; };
  for (const oracles::Made& m : c.made) out.emplace_back(m.tool, um(m.x), um(m.y), um(m.bottom));
  std::sort(out.begin(), out.end());
  return out;
}

Holes rs274_holes(const std::string& program_text) {
  testutil::TempDir t;
  testutil::spit(t / "p.ngc", program_text);
  return sorted_holes(oracles::run_rs274(t / "p.ngc"));
}

// The input's holes as rs274 drills them, and the program plan writes (in
// keep-style or in `dialect`) drills exactly those.
void expect_reordered_exactly(const std::string& name, const std::string& input, const std::string& options,
                              std::size_t holes) {
  SCOPED_TRACE(name + " " + options);
  testutil::TempDir t;
  testutil::spit(t / "in.nc", input);
  const Holes want = rs274_holes(input);
  ASSERT_EQ(want.size(), holes) << "the test program itself";
  auto r = testutil::acodrill_run("plan " + (t / "in.nc") + " -o " + (t / "out.nc") + " -q --seed 1 " + options);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string out = testutil::slurp(t / "out.nc");
  EXPECT_EQ(rs274_holes(out), want) << out;
}

// The return to reference "G91 G28" (Fanuc's, written so LinuxCNC reads it
// too) leaves G91 on; the holes after it are incremental.
const std::string kIncrementalAfterG28 =
    "%\n"
    "O0025 (PLATE)\n"
    "N10 G21 G17 G40 G80 G90\n"
    "N20 G91 G28 Z1.\n"
    "N30 T1 M06 (T1 D=5.000 MM DRILL)\n"
    "N40 S1200 M03\n"
    "N50 G00 G43 H01 Z14.\n"
    "N60 G00 X10. Y20.\n"
    "N70 G98 G81 X0. Y0. Z-15. R-13. F120.\n"
    "N80 X30. Y20.\n"
    "N90 X-20. Y-10.\n"
    "N100 X50. Y-5.\n"
    "N110 X-60. Y30.\n"
    "N120 G80\n"
    "N130 G28 Z0.\n"
    "N140 M30\n"
    "%\n";

// The cycle itself incremental: R from the initial plane, Z from R, each further hole a step.
const std::string kIncrementalCycle =
    "G21 G90 G17\n"
    "T2 M06\n"
    "S1000 M03\n"
    "G00 Z10.\n"
    "G00 X5. Y5.\n"
    "G91 G98 G81 X10. Z-7. R-8. F100.\n"
    "X10.\n"
    "Y25.\n"
    "X-30.\n"
    "X45. Y-12.\n"
    "G80 G90\n"
    "G00 Z30.\n"
    "M30\n";

std::string repeats(const std::string& word) {
  return "G21 G90 G17\n"
         "T3 M06\n"
         "S1000 M03\n"
         "G00 Z10.\n"
         "G00 X0. Y0.\n"
         "G91 G99 G81 X10. Z-7. R-8. " + word + " F100.\n"
         "G90 G80\n"
         "G00 Z10.\n"
         "G00 X0. Y30.\n"
         "G91 G99 G81 Y-8. X3. Z-7. R-8. " + word + " F100.\n"
         "G90 G80\n"
         "G00 Z30.\n"
         "M30\n";
}

}  // namespace

TEST(reorder_idioms_test, incremental_mode_left_on_by_g28_is_stated_and_restored) {
  for (const std::string options : {"--keep-style", "", "--dialect linuxcnc", "--dialect fanuc"}) {
    expect_reordered_exactly("G91 after G28", kIncrementalAfterG28, options, 5);
  }
  testutil::TempDir t;
  testutil::spit(t / "in.nc", kIncrementalAfterG28);
  auto r = testutil::acodrill_run("plan " + (t / "in.nc") + " -o " + (t / "out.nc") + " -q --keep-style");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string out = testutil::slurp(t / "out.nc");
  // The program number stands first on its line, before any block number.
  EXPECT_THAT(out, ::testing::HasSubstr("\nO0025 (PLATE)\n"));
  EXPECT_THAT(out, ::testing::Not(::testing::ContainsRegex("N[0-9]+ O")));
  EXPECT_THAT(out, ::testing::HasSubstr(" G90 ")) << "the absolute values written say so";
}

TEST(reorder_idioms_test, an_incremental_cycle_is_rewritten_whole_not_kept_beside_the_new_one) {
  for (const std::string options : {"--keep-style", "", "--dialect linuxcnc", "--dialect grbl"}) {
    expect_reordered_exactly("G91 cycle", kIncrementalCycle, options, 5);
  }
}

TEST(reorder_idioms_test, a_cycle_line_that_does_more_keeps_the_rest_without_its_hole) {
  // Coolant and a ';' note on the first cycle line: they stay, the hole is written anew.
  std::string text = kIncrementalCycle;
  const std::string first = "G91 G98 G81 X10. Z-7. R-8. F100.\n";
  text.replace(text.find(first), first.size(), "G91 G98 G81 X10. Z-7. R-8. F100. M8 ; first hole\n");
  expect_reordered_exactly("a cycle line with more", text, "--keep-style", 5);
  testutil::TempDir t;
  testutil::spit(t / "in.nc", text);
  auto r = testutil::acodrill_run("plan " + (t / "in.nc") + " -o - -q --keep-style");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("\nG91 M8 ; first hole\n"));
}

TEST(reorder_idioms_test, k_and_l_repeats_drill_each_step_in_incremental_mode) {
  // rs274 repeats a G91 cycle by L; K is Fanuc's word for the same: both give the same holes.
  const Holes by_l = rs274_holes(repeats("L4"));
  ASSERT_EQ(by_l.size(), 8u);
  for (const std::string word : {"L4", "K4"}) {
    const gcode::DrillingProgram p = gcode::read_drilling(repeats(word));
    Holes read;
    for (const auto& run : p.runs) {
      for (const auto& h : run.holes) {
        read.emplace_back(run.tool, std::round(h.at.x * 1000) / 1000, std::round(h.at.y * 1000) / 1000,
                          std::round(h.cycle.bottom_mm() * 1000) / 1000);
      }
    }
    std::sort(read.begin(), read.end());
    EXPECT_EQ(read, by_l) << word;
    testutil::TempDir t;
    testutil::spit(t / "in.nc", repeats(word));
    for (const std::string options : {"--keep-style", "--dialect linuxcnc"}) {
      auto r = testutil::acodrill_run("plan " + (t / "in.nc") + " -o " + (t / "out.nc") + " -q " + options);
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(rs274_holes(testutil::slurp(t / "out.nc")), by_l) << word << " " << options;
    }
  }
  // K0: the cycle's words are stored, no hole drilled (Fanuc).
  EXPECT_EQ(gcode::read_drilling("G21\nG0 X0 Y0 Z10\nG91 G81 X10 Z-7 R-8 K0 F100\nX5\nG80\nM30\n").hole_count(), 1u);
  // HAAS's K beside I and J in G83 is the least peck, not a repeat.
  const auto peck = gcode::read_drilling("G21\nG0 X0 Y0 Z10\nG83 X1 Y1 Z-7 R1 I2 J0.5 K1 F100\nG80\nM30\n");
  ASSERT_EQ(peck.hole_count(), 1u);
  EXPECT_EQ(peck.runs[0].holes[0].cycle.extra, "I2 J0.5 K1");
}

TEST(reorder_idioms_test, what_acodrill_does_not_model_is_refused_with_one_line) {
  struct Case {
    std::string program, message;
  };
  const std::vector<Case> cases = {
      {"G21\nG0 X0 Y0 Z10\nG81 X10 Z-7 R1 K4 F100\nG80\nM30\n", "a.nc:3: K4 in absolute mode (G90) drills one place 4 times"},
      {"G21\nG0 X0 Y0 Z10\nG81 X10 Z-7 R1 L3 F100\nG80\nM30\n", "a.nc:3: L3 in absolute mode (G90) drills one place 3 times"},
      {"G21\nG0 X0 Y0 Z10\nG91 G81 X10 Z-7 R-8 K2.5 F100\nM30\n", "a.nc:3: K2.5: a cycle's repeat count is a whole number"},
      {"G21\nG16\nG0 X20 Y90 Z10\nG81 R1 Z-1 F100\nG80\nM30\n", "a.nc:2: G16 polar coordinates"},
      {"G21\nG0 X0 Y0 Z10\nG51.1 X0\nG81 X5 Y5 R1 Z-1 F100\nM30\n", "a.nc:3: G51.1 changes the coordinate system"},
      {"G21\nG0 X0 Y0 Z10\nG70 I20 J0 L6\nM30\n", "a.nc:3: G70 (a hole pattern"},
      {"G21\nG0 X0 Y0 Z10\nG12 I5 Z-1 F100\nM30\n", "a.nc:3: G12 is not a G-code acodrill models"},
      {"G21\nG0 X0 Y0 Z10\nG44 H1 Z10\nG81 X5 Y5 R1 Z-1 F100\nM30\n", "a.nc:3: G44 is not a G-code acodrill models"},
  };
  for (const Case& c : cases) {
    testutil::TempDir t;
    testutil::spit(t / "a.nc", c.program);
    auto r = testutil::run("cd " + testutil::shell_quote(t.path()) + " && " + testutil::shell_quote(testutil::acodrill()) +
                           " plan a.nc -o out.nc -q");
    EXPECT_EQ(r.code, 2) << c.program;
    EXPECT_THAT(r.err, ::testing::HasSubstr("acodrill: error: " + c.message)) << c.program;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(t / "out.nc"));
  }
}

// The guard for every case to come: a program that fails the check is never
// written, whatever the input kind; an existing file stays as it was.
TEST(reorder_idioms_test, a_program_that_fails_its_own_check_is_never_written) {
  testutil::TempDir t;
  testutil::spit(t / "plate.csv", "x,y,d\n0,0,5\n10,0,5\n20,5,5\n5,15,5\n");
  testutil::spit(t / "prog.nc", kIncrementalCycle);
  for (const std::string input : {"plate.csv", "prog.nc"}) {
    std::filesystem::remove(t / "r.json");
    const std::string cmd = "cd " + testutil::shell_quote(t.path()) + " && ";
    auto ok = testutil::run(cmd + testutil::shell_quote(testutil::acodrill()) + " plan " + input + " -o out.nc -q");
    ASSERT_EQ(ok.code, 0) << ok.err;
    testutil::spit(t / "out.nc", "an older program\n");
    auto r = testutil::run(cmd + "ACODRILL_TEST_BREAK_WRITER=1 " + testutil::shell_quote(testutil::acodrill()) + " plan " + input +
                           " -o out.nc --report r.json -q");
    EXPECT_EQ(r.code, 3) << input;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr("acodrill: error: the program for out.nc fails acodrill's own check"));
    EXPECT_THAT(r.err, ::testing::HasSubstr("is not drilled"));
    EXPECT_THAT(r.err, ::testing::HasSubstr("a fault in acodrill"));
    EXPECT_EQ(testutil::slurp(t / "out.nc"), "an older program\n");
    EXPECT_FALSE(std::filesystem::exists(t / "r.json"));
  }
}

// The check takes a tool table's ranges as plan does: a 0.8 mm drill that
// the table gives holes from 0.75 to 0.85 mm drills them, no fault.
TEST(reorder_idioms_test, the_check_takes_a_tool_tables_ranges_as_plan_chose_them) {
  testutil::TempDir t;
  testutil::spit(t / "plate.csv", "x,y,d\n0,0,0.78\n10,0,0.82\n20,5,0.8\n");
  testutil::spit(t / "tools.json", "{\"tools\": [{\"number\": 4, \"diameter_mm\": 0.8, \"min_hole_mm\": 0.75, \"max_hole_mm\": 0.85}]}");
  auto r = testutil::acodrill_run("plan " + (t / "plate.csv") + " -o " + (t / "a.nc") + " -q --tools " + (t / "tools.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(testutil::slurp(t / "a.nc"), ::testing::HasSubstr("T4 M06"));
  // verify without the table knows nothing of the range: the 0.78 and 0.82 mm holes are faults there.
  auto v = testutil::acodrill_run("verify " + (t / "a.nc") + " --holes " + (t / "plate.csv") + " -q");
  EXPECT_EQ(v.code, 1) << v.out;
}
