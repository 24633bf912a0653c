// The G-code writer and the interpreter behind `acodrill verify`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <clocale>
#include <locale>
#include <sstream>

#include "gcode/interpreter.h"
#include "gcode/motion_time.h"
#include "gcode/program.h"

namespace {

gcode::ToolPass pass(int tool, double d, std::vector<aco::Point2> holes, std::size_t first_index = 1) {
  gcode::ToolPass p;
  p.tool.number = tool;
  p.tool.diameter_mm = d;
  p.holes = std::move(holes);
  for (std::size_t i = 0; i < p.holes.size(); ++i) p.index.push_back(first_index + i);
  return p;
}

std::string emit(const std::vector<gcode::ToolPass>& passes, gcode::ProgramSettings s = {}) {
  std::ostringstream out;
  gcode::write_program(out, passes, s);
  return out.str();
}

}  // namespace

TEST(gcode_test, numbers_always_have_a_point_and_never_read_minus_zero) {
  EXPECT_EQ(gcode::format_number(5, 3), "5.000");
  EXPECT_EQ(gcode::format_number(-0.0001, 3), "0.000");
  EXPECT_EQ(gcode::format_number(-0.0004, 3), "0.000");
  EXPECT_EQ(gcode::format_number(-0.0006, 3), "-0.001");
  EXPECT_EQ(gcode::format_number(1.23456, 4), "1.2346");
  EXPECT_EQ(gcode::format_number(12, 0), "12.");
}

TEST(gcode_test, output_does_not_depend_on_the_locale) {
  const std::string before = emit({pass(1, 6.35, {{1.5, 2.25}, {10.125, 3}})});
  // A decimal-comma locale, where available, must not change a byte.
  const char* set = std::setlocale(LC_ALL, "de_DE.UTF-8");
  try {
    std::locale::global(std::locale("de_DE.UTF-8"));
  } catch (const std::exception&) {
  }
  const std::string after = emit({pass(1, 6.35, {{1.5, 2.25}, {10.125, 3}})});
  std::setlocale(LC_ALL, "C");
  std::locale::global(std::locale::classic());
  EXPECT_EQ(before, after) << (set ? "with de_DE" : "de_DE not installed");
  EXPECT_THAT(before, ::testing::HasSubstr("X1.500 Y2.250"));
}

TEST(gcode_test, haas_skeleton) {
  const std::string prog = emit({pass(1, 3.0, {{1, 1}, {2, 1}, {3, 1}}), pass(2, 6.0, {{5, 5}}, 4)});
  const std::vector<std::string> in_order = {
      "%\nO01001 (ACODRILL)\n", "G00 G17 G40 G49 G80 G90\nG21\nG53 G00 Z0.\n", "T1 M06 (3.000 MM DRILL)\n",
      "G00 G90 G54 X1.000 Y1.000 S3000 M03\nG43 H01 Z25.000 M08\n",
      "N1 G99 G81 X1.000 Y1.000 Z-8.000 R2.500 F250.0\nN2 X2.000 Y1.000\nN3 G98 X3.000 Y1.000\nG80\nM09\nM05\nG53 G00 Z0.\nM01\n",
      "T2 M06", "N4 G98 G81 X5.000 Y5.000", "M30\n%\n"};
  std::size_t at = 0;
  for (const auto& piece : in_order) {
    std::size_t found = prog.find(piece, at);
    ASSERT_NE(found, std::string::npos) << "missing, or out of order: " << piece << "\n" << prog;
    at = found + piece.size();
  }
}

TEST(gcode_test, inch_units_and_dialects) {
  gcode::ProgramSettings s;
  s.units = gcode::Units::Inch;
  std::string inch = emit({pass(1, 6.35, {{25.4, 50.8}})}, s);
  EXPECT_THAT(inch, ::testing::HasSubstr("G20\n"));
  EXPECT_THAT(inch, ::testing::HasSubstr("X1.0000 Y2.0000"));
  EXPECT_THAT(inch, ::testing::HasSubstr("D=0.2500 IN"));
  s = {};
  s.dialect = gcode::Dialect::Fanuc;
  EXPECT_THAT(emit({pass(1, 3, {{0, 0}})}, s), ::testing::HasSubstr("G91 G28 Z0.\nG90\n"));
}

TEST(gcode_test, peck_and_dwell_cycles_per_dialect) {
  auto p = pass(1, 3.0, {{0, 0}, {1, 0}});
  p.tool.cycle = gcode::Cycle::G83;
  p.tool.peck_mm = 1.5;
  EXPECT_THAT(emit({p}), ::testing::HasSubstr("G83 X0.000 Y0.000 Z-8.000 R2.500 Q1.500 F250.0"));
  p.tool.cycle = gcode::Cycle::G82;
  p.tool.dwell_s = 0.5;
  EXPECT_THAT(emit({p}), ::testing::HasSubstr(" P500 F"));  // HAAS: integer milliseconds
  gcode::ProgramSettings lc;
  lc.dialect = gcode::Dialect::LinuxCnc;
  EXPECT_THAT(emit({p}, lc), ::testing::HasSubstr(" P0.500 F"));  // LinuxCNC: seconds
}

TEST(gcode_test, resume_from_restates_the_tool_and_the_cycle) {
  gcode::ProgramSettings s;
  s.resume_from = 3;
  const std::string prog = emit({pass(1, 3.0, {{1, 1}, {2, 1}}), pass(2, 6.0, {{5, 5}, {6, 5}, {7, 5}}, 3)}, s);
  EXPECT_THAT(prog, ::testing::Not(::testing::HasSubstr("T1 M06")));
  EXPECT_THAT(prog, ::testing::HasSubstr("T2 M06"));
  EXPECT_THAT(prog, ::testing::HasSubstr("N3 G99 G81 X5.000 Y5.000 Z-8.000 R2.500"));
  gcode::Interpretation run = gcode::interpret(prog);
  ASSERT_EQ(run.holes.size(), 3u);
  EXPECT_EQ(run.holes[0].tool, 2);
  s.resume_from = 6;
  EXPECT_THROW(emit({pass(1, 3.0, {{1, 1}})}, s), std::invalid_argument);
}

TEST(gcode_test, interpreter_reads_back_what_the_writer_wrote) {
  gcode::ProgramSettings s;
  for (auto units : {gcode::Units::Mm, gcode::Units::Inch}) {
    s.units = units;
    const std::string prog = emit({pass(1, 3.0, {{10, 10}, {20, 10}, {20, 30}}), pass(7, 6.0, {{50, 50}}, 4)}, s);
    gcode::Interpretation run = gcode::interpret(prog);
    ASSERT_EQ(run.holes.size(), 4u);
    EXPECT_EQ(run.holes[0].tool, 1);
    EXPECT_EQ(run.holes[3].tool, 7);
    EXPECT_NEAR(run.holes[2].x_mm, 20.0, 0.003);
    EXPECT_NEAR(run.holes[2].y_mm, 30.0, 0.003);
    EXPECT_NEAR(run.holes[0].bottom_z_mm, -8.0, 0.003);
    EXPECT_NEAR(run.tool_diameter_mm.at(7), 6.0, 0.003);
    // Rapid XY: 0,0 → 10,10 → 20,10 → 20,30 → 50,50.
    EXPECT_NEAR(run.rapid_xy_mm, std::hypot(10, 10) + 10 + 20 + std::hypot(30, 20), 0.01);
  }
}

TEST(gcode_test, interpreter_reads_other_posts) {
  // Incremental XY, G99/G98, modal cycle words, a comment with a semicolon, G0 between holes.
  const std::string prog =
      "%\nO1000\nT3 M6\nG90 G0 X1. Y1. S1000 M3\nG43 H3 Z1.\nG81 G99 X1. Y1. Z-.25 R.1 F10.\nG91 X1.\nY1. ; next\n"
      "G90 G80\nG0 X5. Y5.\nG83 X5. Y5. Z-1. R.1 Q.2 F5.\nM30\n%\nX99 Y99\n";
  gcode::Interpretation run = gcode::interpret(prog);
  ASSERT_EQ(run.holes.size(), 4u);
  EXPECT_EQ(run.holes[1].x_mm, 2.0);
  EXPECT_EQ(run.holes[2].y_mm, 2.0);
  EXPECT_EQ(run.holes[3].x_mm, 5.0);
  EXPECT_EQ(run.holes[0].tool, 3);
}

TEST(gcode_test, interpreter_errors_name_the_line) {
  try {
    gcode::interpret("G0 X1\nG81 X1 Y1 F10\n");
    FAIL();
  } catch (const gcode::ProgramError& e) {
    EXPECT_EQ(e.line(), 2u);
  }
  EXPECT_THROW(gcode::interpret("G0 X1 (open comment\n"), gcode::ProgramError);
  EXPECT_THROW(gcode::interpret("G0 X1.2.3\n"), gcode::ProgramError);
  EXPECT_THROW(gcode::interpret("G0 X\n"), gcode::ProgramError);
  EXPECT_THROW(gcode::interpret("G0 #1\n"), gcode::ProgramError);
}

TEST(gcode_test, clamps_switch_to_the_initial_plane_only_where_needed) {
  auto p = pass(1, 3.0, {{0, 0}, {10, 0}, {20, 0}, {30, 0}});
  p.clear_after = {false, true, false, false};  // the move 10 -> 20 crosses a clamp
  const std::string prog = emit({p});
  EXPECT_THAT(prog, ::testing::HasSubstr("N1 G99 G81 X0.000"));
  EXPECT_THAT(prog, ::testing::HasSubstr("N2 G98 X10.000 Y0.000\nN3 G99 X20.000 Y0.000\nN4 G98 X30.000"));
  // And the interpreter agrees on where each hole is.
  EXPECT_EQ(gcode::interpret(prog).holes.size(), 4u);
}

// Issue 85: the program stays ASCII for the control; a name in another
// script reads as one character a character, letters with diacritics as
// their base letters.
TEST(gcode_test, comments_write_names_in_any_script_one_character_a_character) {
  EXPECT_EQ(gcode::comment_text("Łukasz Müller, façade"), "LUKASZ MULLER, FACADE");
  EXPECT_EQ(gcode::comment_text("плата 測試 board v2.drl"), "????? ?? BOARD V2.DRL");
  EXPECT_EQ(gcode::comment_text("Æbleø Straße Œuvre Þór ĳs"), "AEBLEO STRASSE OEUVRE THOR IJS");
  EXPECT_EQ(gcode::comment_text("Ștefan Țară Ñandú Åsa Đorđe ÿ"), "STEFAN TARA NANDU ASA DORDE Y");
  EXPECT_EQ(gcode::comment_text("3×4 ÷ 2 (µm) ° 😀"), "3?4 ? 2 /?M/ ? ?");
  // Malformed UTF-8: each stray byte is one '?', and what follows reads on.
  EXPECT_EQ(gcode::comment_text(std::string("a\xC3") + "b\xE2\x82" + "c\xFF" + "d\xC3"), "A?B?C?D?");  // E2 82 is one character cut short
  for (const std::string& s : {std::string("плата 測試 board v2.drl"), std::string("\xF0\x9F\x98\x80\x80\x80 é")}) {
    for (char c : gcode::comment_text(s)) EXPECT_LT(static_cast<unsigned char>(c), 128) << s;
  }
}

// A canned cycle's P is milliseconds without a decimal point on HAAS and
// Fanuc and seconds on LinuxCNC; a G84 tap waits for its spindle to reverse
// and feeds out.
TEST(gcode_test, canned_cycle_dwells_and_taps_are_timed_in_the_controls_units) {
  const auto dwell_of = [](const std::string& p, bool integer_ms) {
    gcode::Kinematics k;
    k.cycle_p_integer_ms = integer_ms;
    return gcode::time_program("G21 G90\nG0 X0 Y0 Z5\nG82 X10 Y0 Z-1 R1 " + p + " F100\nG80\n", k).dwell_s;
  };
  EXPECT_DOUBLE_EQ(dwell_of("P500", true), 0.5);
  EXPECT_DOUBLE_EQ(dwell_of("P0.5", true), 0.5);
  EXPECT_DOUBLE_EQ(dwell_of("P2", false), 2.0);
  EXPECT_DOUBLE_EQ(dwell_of("P0.5", false), 0.5);
  gcode::Kinematics k;
  auto cycle = [&](const std::string& g) {
    return gcode::time_program("G21 G90\nG0 X0 Y0 Z5\n" + g + " X10 Y0 Z-6 R1 F120\nG80\n", k).drilling_s;
  };
  // Down 7 mm at 120 mm/min each; a ream (G85) feeds the 7 mm back up (3.5
  // s) where the drill rapids out 11 mm, the ream then 4 mm; a tap is the
  // ream and its spindle's reversal at the bottom.
  const double feed_out = cycle("G85") - cycle("G81");
  EXPECT_GT(feed_out, 3.0);
  EXPECT_LT(feed_out, 3.5);
  EXPECT_NEAR(cycle("G84") - cycle("G85"), k.tap_reverse_s, 1e-9);
  EXPECT_NEAR(cycle("G74") - cycle("G85"), k.tap_reverse_s, 1e-9);
  // LinuxCNC's G33.1 (issue 82) taps at K a turn of the spindle: K0.5 at
  // S240 is G84's F120, down and up with the same reversal, from where Z is.
  const double rigid = gcode::time_program("G21 G90\nS240 M3\nG0 X0 Y0 Z5\nG0 X10 Y0 Z1\nG33.1 X10 Y0 Z-6 K0.5\nG0 Z5\n", k).drilling_s;
  EXPECT_NEAR(rigid, cycle("G84"), 1e-6);
  const double inch = gcode::time_program("G20 G90\nS240 M3\nG0 X0 Y0 Z0.2\nG0 X0.4 Y0 Z0.04\nG33.1 X0.4 Y0 Z-0.24 K0.02\nG0 Z0.2\n", k).drilling_s;
  EXPECT_NEAR(inch, 2 * (0.28 * 25.4) / (0.02 * 25.4 * 240) * 60 + k.tap_reverse_s, 0.05);
}
