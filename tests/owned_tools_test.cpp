// Issue 53: the hobbyist's own tools. The choice of drills is checked on its
// own (fewest drills, then the closest fit); whole jobs are checked against
// independent oracles: GRBL 1.1h's own parser accepts every line, and
// LinuxCNC's rs274 reads back every hole made exactly once — drilled by an
// owned drill that fits it, or milled about its centre to its diameter and
// through the board — on KiCad's own drill files of its demo boards.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "formats/error.h"
#include "planning/owned_tools.h"
#include "planning/tools.h"
#include "oracles.h"
#include "test_util.h"

namespace {

using oracles::Canon;
using oracles::grbl_refusal;
using oracles::Made;
using oracles::run_rs274;
using oracles::tool_diameters;
using planning::choose_drills;
using planning::parse_owned_drills;
using planning::Tooling;

// The drill (its diameter) or "milled" that each designed diameter gets.
std::map<double, std::string> made_with(const std::vector<std::pair<double, std::size_t>>& diameters, const Tooling& t) {
  std::map<double, std::string> out;
  for (const planning::DiameterChoice& c : choose_drills(diameters, t, "job")) {
    out[c.designed_mm] = c.drill ? std::to_string(t.drills[*c.drill].diameter_mm).substr(0, 4) : "milled";
  }
  return out;
}

TEST(owned_drills, the_list_reads_diameters_and_fits_and_refuses_what_is_not_one) {
  const auto d = parse_owned_drills("1.0, 0.6,0.8:-0.02:+0.2", "--drills");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_DOUBLE_EQ(d[0].diameter_mm, 0.6);  // ascending
  EXPECT_DOUBLE_EQ(d[0].minus_mm, planning::kDrillMinusMm);
  EXPECT_DOUBLE_EQ(d[1].minus_mm, 0.02);
  EXPECT_DOUBLE_EQ(d[1].plus_mm, 0.2);
  for (const char* bad : {"", "0.8,,1.0", "abc", "0.8:0.1:0.1", "0.8:-0.1", "-1", "0.8,0.8", "0.8:-x:+0.1"}) {
    EXPECT_THROW(parse_owned_drills(bad, "--drills"), formats::InputError) << bad;
  }
}

TEST(owned_drills, fewest_drills_beat_rounding_each_hole_to_its_nearest) {
  // Nearest-drill rounding (pcb2gcode) takes 0.7 for 0.72 and 0.8 for 0.84:
  // two drills. The 0.8 fits both (+0.08, -0.04): one drill, one change fewer.
  Tooling t{parse_owned_drills("0.7,0.8,0.9", "t"), std::nullopt};
  const auto m = made_with({{0.72, 10}, {0.84, 10}}, t);
  EXPECT_EQ(m.at(0.72), "0.80");
  EXPECT_EQ(m.at(0.84), "0.80");
}

TEST(owned_drills, among_the_fewest_the_closest_fit_wins_and_each_hole_takes_its_closest_drill) {
  // One drill cannot cover 0.6 and 1.0: two are needed; 0.6 and 1.0 fit exactly.
  Tooling t{parse_owned_drills("0.6,0.65,0.95,1.0", "t"), std::nullopt};
  auto m = made_with({{0.6, 5}, {1.0, 5}}, t);
  EXPECT_EQ(m.at(0.6), "0.60");
  EXPECT_EQ(m.at(1.0), "1.00");
  // A tie in misfit goes to the larger drill: room for the lead.
  Tooling tie{parse_owned_drills("0.95,1.05", "t"), std::nullopt};
  EXPECT_EQ(made_with({{1.0, 3}}, tie).at(1.0), "1.05");
}

TEST(owned_drills, what_no_drill_fits_is_milled_or_named_with_its_count) {
  Tooling t{parse_owned_drills("0.8,1.0", "t"), 1.0};
  auto m = made_with({{0.8, 4}, {3.2, 2}, {1.0, 1}}, t);
  EXPECT_EQ(m.at(3.2), "milled");
  EXPECT_EQ(m.at(1.0), "1.00");
  // Smaller than the end mill and no drill fits: an error naming each diameter and count.
  try {
    choose_drills({{0.3, 7}, {0.8, 4}, {0.35, 2}}, t, "board.drl");
    FAIL() << "no error";
  } catch (const formats::InputError& e) {
    const std::string what = e.where_what();
    EXPECT_THAT(what, ::testing::HasSubstr("board.drl: 9 hole(s) no owned drill fits"));
    EXPECT_THAT(what, ::testing::HasSubstr("0.300 mm (7 holes)"));
    EXPECT_THAT(what, ::testing::HasSubstr("0.350 mm (2 holes)"));
  }
  Tooling no_mill{parse_owned_drills("0.8", "t"), std::nullopt};
  EXPECT_THROW(choose_drills({{3.2, 1}}, no_mill, "x"), formats::InputError);
}

TEST(owned_drills, a_tool_table_of_diameters_only_gets_a_boards_cycle_not_a_plates) {
  planning::ToolTable t = planning::parse_tool_table(
      R"({"tools": [{"number": 1, "diameter_mm": 0.8, "min_hole_mm": 0.7, "max_hole_mm": 0.9},
                    {"number": 2, "diameter_mm": 4.3, "min_hole_mm": 3.0, "max_hole_mm": 5.0},
                    {"number": 3, "diameter_mm": 1.0, "rpm": 5000, "depth_mm": -2.5}]})", "t.json");
  planning::Machine router = *planning::builtin_machine("router");
  planning::complete_tool_table(t, planning::Material::Pcb, 1.6, router);
  for (const auto& e : t.entries) {
    EXPECT_GE(e.tool.depth_mm, -3.0) << "T" << e.tool.number;
    EXPECT_LT(e.tool.depth_mm, -1.6) << "T" << e.tool.number << " through the board";
    EXPECT_LE(e.tool.spindle_rpm, router.max_rpm);
    EXPECT_EQ(e.tool.cycle, gcode::Cycle::G81);
  }
  EXPECT_EQ(t.entries[2].tool.spindle_rpm, 5000) << "what the table gives stays";
  EXPECT_DOUBLE_EQ(t.entries[2].tool.depth_mm, -2.5);
}

// ---------------------------------------------------------------------------
// Whole jobs, read back by the oracles.

// Every expected hole made exactly once by rs274's reading: by an owned drill
// that fits it, or milled to its diameter (0.01 mm) about its centre (0.003
// mm) with the end mill; through the board. `tools`: the tools used.
void check_made(const Canon& canon, const aco::HoleSet& expected, const std::map<int, double>& diameters,
                const std::vector<planning::OwnedDrill>& drills, double end_mill, double thickness, const std::string& what,
                std::set<int>* tools_used = nullptr) {
  std::vector<char> used(canon.made.size(), 0);
  std::set<int> tools;
  for (const aco::Hole& h : expected) {
    std::vector<std::size_t> at;
    for (std::size_t i = 0; i < canon.made.size(); ++i) {
      const Made& m = canon.made[i];
      const double tol = m.path_radius > 0 ? 0.003 : 0.0006;
      if (std::fabs(m.x - h.center.x) <= tol && std::fabs(m.y - h.center.y) <= tol) at.push_back(i);
    }
    ASSERT_EQ(at.size(), 1u) << what << ": hole (" << h.center.x << ", " << h.center.y << ") D" << h.diameter << " made "
                             << at.size() << " times";
    const Made& m = canon.made[at[0]];
    used[at[0]] = 1;
    tools.insert(m.tool);
    ASSERT_TRUE(diameters.count(m.tool)) << what << ": T" << m.tool << " has no diameter in the program";
    const double tool_d = diameters.at(m.tool);
    EXPECT_LE(m.bottom, -thickness) << what << ": not through the board at (" << m.x << ", " << m.y << ")";
    if (m.path_radius > 0) {
      EXPECT_NEAR(tool_d, end_mill, 1e-6) << what << ": milled with T" << m.tool;
      EXPECT_NEAR(2 * m.path_radius + tool_d, h.diameter, 0.01) << what << ": milled to size at (" << m.x << ", " << m.y << ")";
      EXPECT_FALSE(std::any_of(drills.begin(), drills.end(), [&](const auto& o) { return o.fits(h.diameter); }))
          << what << ": D" << h.diameter << " milled though a drill fits it";
    } else {
      const bool owned_fit = std::any_of(drills.begin(), drills.end(), [&](const planning::OwnedDrill& o) {
        return std::fabs(o.diameter_mm - tool_d) < 1e-6 && o.fits(h.diameter);
      });
      const bool plunged = std::fabs(tool_d - end_mill) < 1e-6 && std::fabs(tool_d - h.diameter) <= 0.01;
      EXPECT_TRUE(owned_fit || plunged) << what << ": D" << h.diameter << " drilled with T" << m.tool << " D" << tool_d;
    }
  }
  for (std::size_t i = 0; i < used.size(); ++i) {
    EXPECT_TRUE(used[i]) << what << ": rs274 makes a hole at (" << canon.made[i].x << ", " << canon.made[i].y << ") the input has not";
  }
  if (tools_used) *tools_used = tools;
}

// The fewest owned drills that cover the diameters (those some drill fits),
// by trying every subset: the oracle for the planner's greedy choice.
std::size_t fewest_drills(const aco::HoleSet& holes, const std::vector<planning::OwnedDrill>& drills) {
  std::set<double> need;
  for (const aco::Hole& h : holes) {
    if (std::any_of(drills.begin(), drills.end(), [&](const auto& o) { return o.fits(h.diameter); })) need.insert(h.diameter);
  }
  std::size_t best = drills.size();
  for (unsigned mask = 0; mask < (1u << drills.size()); ++mask) {
    bool all = true;
    for (double d : need) {
      bool any = false;
      for (std::size_t j = 0; j < drills.size(); ++j) any = any || ((mask >> j) & 1u && drills[j].fits(d));
      all = all && any;
    }
    if (all) best = std::min<std::size_t>(best, static_cast<std::size_t>(__builtin_popcount(mask)));
  }
  return best;
}

// A board and the drills its maker owns (vias need a small one).
struct Bench {
  std::string board, drills;
};

void PrintTo(const Bench& b, std::ostream* os) { *os << b.board << " with drills " << b.drills; }

class OwnedToolsOnBoards : public ::testing::TestWithParam<Bench> {};

TEST_P(OwnedToolsOnBoards, the_router_drills_with_owned_drills_and_mills_the_rest_as_the_oracles_read_it) {
  const std::string board = GetParam().board;
  const std::string drl = testutil::data("kicad/" + board + "-mm-decimal.drl");
  const aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(testutil::data("kicad/" + board + ".holes.csv")));
  const std::string drills_text = GetParam().drills;
  const auto drills = parse_owned_drills(drills_text, "t");
  testutil::TempDir t;
  // KiCad's hole lists hold the round holes: slots (StickHub's oval pads) are left out here.
  const std::string opts = " --machine router --origin drawing --iterations 30 --seed 1 -q --slots skip --drills " + drills_text +
                           " --end-mill 1.0";
  for (const char* dialect : {"grbl", "linuxcnc", "marlin", "haas", "fanuc"}) {
    const std::string what = board + " " + dialect;
    const std::string nc = t / (std::string(dialect) + ".nc");
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(nc) + opts +
                                    " --dialect " + dialect + " --report " + testutil::shell_quote(t / "r.json"));
    ASSERT_EQ(r.code, 0) << what << ": " << r.err;
    const std::string prog = testutil::slurp(nc);
    if (std::string(dialect) == "grbl") {
      EXPECT_EQ(grbl_refusal(prog), "") << what;
    }
    if (std::string(dialect) == "marlin") {
      if (prog.find("\nG2 ") != std::string::npos) {
        EXPECT_NE(prog.find("ARC_SUPPORT"), std::string::npos) << what;
      }
      EXPECT_EQ(prog.find('('), std::string::npos) << what << ": Marlin reads ';' comments only";
    }
    {
      // Marlin's "M0 message" pauses are not RS274, and Marlin has no T words:
      // rs274 reads "M0 PUT IN T2 ..." as the change to T2 it asks for, other messages as plain M0s.
      std::string as_rs274 = nc;
      if (std::string(dialect) == "marlin") {
        as_rs274 = t / "marlin.ngc";
        std::string text = std::regex_replace(prog, std::regex(R"(^M0 PUT IN T([0-9]+) .*$)", std::regex::multiline), "T$1 M6");
        text = std::regex_replace(text, std::regex(R"(^(M[01]) .*$)", std::regex::multiline), "$1");
        testutil::spit(as_rs274, text + "M2\n");
      }
      const Canon canon = run_rs274(as_rs274);
      std::set<int> tools;
      check_made(canon, expected, tool_diameters(prog), drills, 1.0, 1.6, what, &tools);
      EXPECT_LE(tools.size(), fewest_drills(expected, drills) + 1) << what;
    }
    auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(drl) + " -q --slots skip --drills " +
                                    drills_text + " --end-mill 1.0");
    EXPECT_EQ(v.code, 0) << what << ": " << v.out;
    // Without the owned tools, verify sees holes drilled by drills not of their size.
    auto strict = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(drl) + " -q --slots skip");
    EXPECT_EQ(strict.code, 1) << what;
  }
  // Fewer tool changes than one drill per designed diameter: less time.
  auto one_each = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "each.nc") +
                                         " --machine router --origin drawing --iterations 30 --seed 1 -q --slots skip --report " +
                                         testutil::shell_quote(t / "each.json"));
  ASSERT_EQ(one_each.code, 0) << one_each.err;
  const auto owned = nlohmann::json::parse(testutil::slurp(t / "r.json"));
  const auto each = nlohmann::json::parse(testutil::slurp(t / "each.json"));
  EXPECT_LT(owned["machining_time_s"]["optimized"].get<double>(), each["machining_time_s"]["optimized"].get<double>()) << board;
  EXPECT_FALSE(owned["drill_map"].empty());
  std::size_t mapped = 0;
  for (const auto& d : owned["drill_map"]) mapped += d["holes"].get<std::size_t>();
  EXPECT_EQ(mapped, expected.size());
}

INSTANTIATE_TEST_SUITE_P(kicad, OwnedToolsOnBoards,
                         ::testing::Values(Bench{"pic_programmer", "0.6,0.8,1.0,1.2"}, Bench{"video", "0.4,0.6,0.8,1.0"},
                                           Bench{"StickHub", "0.3,0.4,0.8,1.0"}),
                         [](const auto& p) { return p.param.board; });

// --slots mill: StickHub's one routed oval (its drill file: T3C1.500, G00X148.75Y-109.25 M15
// G01X151.25Y-109.25 M16) milled along its length: rs274 reads arcs round its two ends, 1.5 mm.
TEST(owned_tools, a_slot_is_milled_along_its_length_round_both_ends) {
  testutil::TempDir t;
  const std::string drl = testutil::data("kicad/StickHub-mm-decimal.drl");
  aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(testutil::data("kicad/StickHub.holes.csv")));
  expected.push_back({{148.75, -109.25}, 1.5, "", 0});
  expected.push_back({{151.25, -109.25}, 1.5, "", 0});
  const std::string opts = " --origin drawing --drills 0.3,0.4 --end-mill 1.0 --slots mill";
  for (const char* dialect : {"linuxcnc", "grbl"}) {
    const std::string nc = t / (std::string(dialect) + ".nc");
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(nc) +
                                    " -q --iterations 20 --machine router --dialect " + dialect + opts);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string prog = testutil::slurp(nc);
    if (std::string(dialect) == "grbl") {
      EXPECT_EQ(grbl_refusal(prog), "");
    }
    const Canon canon = run_rs274(nc);
    check_made(canon, expected, tool_diameters(prog), parse_owned_drills("0.3,0.4", "t"), 1.0, 1.6, std::string("slot ") + dialect);
    auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(drl) + " -q" + opts);
    EXPECT_EQ(v.code, 0) << v.out;
  }
  // Resumed at the slot's second end (87 round holes, then the slot's two ends): the whole slot again.
  auto resumed = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "r.ngc") +
                                        " -q --iterations 5 --machine router --dialect linuxcnc --resume-from 89" + opts);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_THAT(testutil::slurp(t / "r.ngc"), ::testing::HasSubstr("(HOLES 88-89: A SLOT 1.500 WIDE, MILLED)"));
  // Milling slots needs the end mill, narrower than the slot.
  auto no_mill = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "x.nc") +
                                        " -q --machine router --drills 0.3,0.4 --slots mill");
  EXPECT_EQ(no_mill.code, 2);
  EXPECT_THAT(no_mill.err, ::testing::HasSubstr("--end-mill"));
  auto wide = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "x.nc") +
                                     " -q --machine router --drills 0.3,0.4 --end-mill 1.5 --slots mill");
  EXPECT_EQ(wide.code, 2);
  EXPECT_EQ(testutil::count_lines(wide.err), 1) << wide.err;
  EXPECT_FALSE(std::filesystem::exists(t / "x.nc"));
}

TEST(owned_tools, a_hole_nothing_can_make_is_refused_naming_it_and_nothing_is_written) {
  testutil::TempDir t;
  const std::string drl = testutil::data("kicad/pic_programmer-mm-decimal.drl");
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "p.nc") +
                                  " --machine router --drills 0.8,1.0 --iterations 5");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
  EXPECT_THAT(r.err, ::testing::HasSubstr("acodrill: error: "));
  EXPECT_THAT(r.err, ::testing::HasSubstr("4.300 mm (6 holes)"));
  EXPECT_FALSE(std::filesystem::exists(t / "p.nc"));
}

TEST(owned_tools, a_tool_table_of_diameters_drills_a_board_no_deeper_than_3_mm) {
  testutil::TempDir t;
  testutil::spit(t / "tools.json", R"({"tools": [
    {"number": 1, "diameter_mm": 0.8, "min_hole_mm": 0, "max_hole_mm": 0.85},
    {"number": 2, "diameter_mm": 1.0, "min_hole_mm": 0.85, "max_hole_mm": 1.1},
    {"number": 3, "diameter_mm": 1.3, "min_hole_mm": 1.1, "max_hole_mm": 2.5},
    {"number": 4, "diameter_mm": 3.5, "min_hole_mm": 2.5, "max_hole_mm": 5}]})");
  const std::string drl = testutil::data("kicad/pic_programmer-mm-decimal.drl");
  for (const char* machine : {"router", "vf2"}) {
    const std::string nc = t / "p.nc";
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(nc) + " -q --iterations 5 --dialect linuxcnc --machine " +
                                    machine + " --tools " + testutil::shell_quote(t / "tools.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    const Canon canon = run_rs274(nc);
    ASSERT_EQ(canon.made.size(), 251u);
    for (const Made& m : canon.made) {
      EXPECT_GE(m.bottom, -3.0) << machine << ": T" << m.tool;
      EXPECT_LE(m.bottom, -1.6) << machine << ": T" << m.tool;
    }
  }
}

TEST(owned_tools, the_back_of_the_board_is_the_front_mirrored_about_the_extents_centre_line_pins_first) {
  testutil::TempDir t;
  const std::string drl = testutil::data("kicad/StickHub-mm-decimal.drl");
  aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(testutil::data("kicad/StickHub.holes.csv")));
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const aco::Hole& h : expected) {
    x0 = std::min(x0, h.center.x), x1 = std::max(x1, h.center.x);
    y0 = std::min(y0, h.center.y), y1 = std::max(y1, h.center.y);
  }
  const double axis = (x0 + x1) / 2;
  for (aco::Hole& h : expected) h.center.x = 2 * axis - h.center.x;
  const std::string nc = t / "back.ngc";
  const std::string opts = " --slots skip --origin drawing --side back --alignment-pins 3.0 --drills 0.3,0.4,0.8,1.0,3.0 --end-mill 1.0";
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(nc) +
                                  " -q --iterations 20 --machine router --dialect linuxcnc" + opts);
  ASSERT_EQ(r.code, 0) << r.err;
  const Canon canon = run_rs274(nc);
  // The pins come first, on the mirror line outside the holes.
  ASSERT_GE(canon.made.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(canon.made[k].x, axis, 0.0006);
    EXPECT_TRUE(canon.made[k].y < y0 - 5 || canon.made[k].y > y1 + 5) << canon.made[k].y;
  }
  Canon rest = canon;
  rest.made.erase(rest.made.begin(), rest.made.begin() + 2);
  check_made(rest, expected, tool_diameters(testutil::slurp(nc)), parse_owned_drills("0.3,0.4,0.8,1.0,3.0", "t"), 1.0, 1.6, "back");
  auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(drl) + " -q" + opts);
  EXPECT_EQ(v.code, 0) << v.out;
  // The front's program is not the back's.
  auto front = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(drl) +
                                      " -q --slots skip --drills 0.3,0.4,0.8,1.0,3.0 --end-mill 1.0");
  EXPECT_EQ(front.code, 1);
}

TEST(owned_tools, a_touch_plate_is_probed_after_every_tool_change_and_refused_where_the_control_measures_its_own) {
  testutil::TempDir t;
  const std::string drl = testutil::data("kicad/pic_programmer-mm-decimal.drl");
  const std::string opts = " -q --iterations 5 --machine router --drills 0.6,0.8,1.0,1.2 --end-mill 1.0 --probe-plate 0.5";
  for (const char* dialect : {"grbl", "linuxcnc", "marlin"}) {
    const std::string nc = t / (std::string(dialect) + ".nc");
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(nc) + opts + " --dialect " + dialect);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string prog = testutil::slurp(nc);
    std::size_t probes = 0;
    for (std::size_t at = prog.find("\nG91 G38.2"); at != std::string::npos; at = prog.find("\nG91 G38.2", at + 1)) ++probes;
    EXPECT_EQ(probes, 5u) << dialect << ": one probe per tool";
    EXPECT_THAT(prog, ::testing::HasSubstr(std::string(dialect) == "marlin" ? "G92 Z0.500" : "G10 L20 P0 Z0.500"));
    if (std::string(dialect) == "grbl") {
      EXPECT_EQ(grbl_refusal(prog), "");
    }
    if (std::string(dialect) == "linuxcnc") {
      const Canon canon = run_rs274(nc);
      EXPECT_EQ(canon.probes.size(), 5u);
      EXPECT_EQ(canon.made.size(), 251u);
    }
  }
  for (const char* dialect : {"haas", "fanuc"}) {
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "no.nc") + opts + " --dialect " + dialect);
    EXPECT_EQ(r.code, 2) << dialect;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr("--probe-plate"));
    EXPECT_FALSE(std::filesystem::exists(t / "no.nc"));
  }
}

TEST(owned_tools, a_machine_profile_holds_the_same_and_the_options_win) {
  testutil::TempDir t;
  testutil::spit(t / "m.json", R"({"dialect": "grbl", "tool_changer": false, "tool_change_s": 60, "max_rpm": 10000,
    "drills_owned": [0.6, 0.8, "1.0:-0.05:+0.1", 1.2], "end_mill_mm": 1.0, "probe_plate_mm": 0.5})");
  const std::string drl = testutil::data("kicad/pic_programmer-mm-decimal.drl");
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "p.nc") +
                                  " -q --iterations 5 --machine " + testutil::shell_quote(t / "m.json") + " --report " + testutil::shell_quote(t / "r.json") +
                                  " --setup-sheet " + testutil::shell_quote(t / "s.html"));
  ASSERT_EQ(r.code, 0) << r.err;
  // The operator's sheet says which drill makes which designed hole, and by how much.
  const std::string sheet = testutil::slurp(t / "s.html");
  EXPECT_THAT(sheet, ::testing::HasSubstr("Designed holes and the tools that make them"));
  EXPECT_THAT(sheet, ::testing::HasSubstr("T2 0.800 mm drill</td><td class=\"n\">+0.050"));
  EXPECT_THAT(sheet, ::testing::HasSubstr("end mill, milled to size"));
  const auto j = nlohmann::json::parse(testutil::slurp(t / "r.json"));
  EXPECT_EQ(j["tools"].size(), 5u);
  EXPECT_THAT(testutil::slurp(t / "p.nc"), ::testing::HasSubstr("G38.2"));
  auto o = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "p.nc") +
                                  " -q --iterations 5 --drills 0.6,0.8,1.0 --end-mill 0.8 --machine " + testutil::shell_quote(t / "m.json") +
                                  " --report " + testutil::shell_quote(t / "r.json"));
  ASSERT_EQ(o.code, 0) << o.err;
  const auto k = nlohmann::json::parse(testutil::slurp(t / "r.json"));
  ASSERT_EQ(k["tools"].size(), 4u);
  EXPECT_EQ(k["tools"][3]["kind"], "end_mill");
  EXPECT_EQ(k["tools"][3]["diameter_mm"].get<double>(), 0.8);
  testutil::spit(t / "bad.json", R"({"drills_owned": "0.8,abc"})");
  auto bad = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + testutil::shell_quote(t / "q.nc") +
                                    " -q --machine " + testutil::shell_quote(t / "bad.json"));
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr("drills_owned"));
}

}  // namespace
