// Issue 55: acodrill-linuxcnc-filter run exactly as LinuxCNC's AXIS runs a
// [FILTER] program — `sh -c "PROGRAM 'FILE'"`, no standard input, the INI in
// INI_FILE_NAME — on KiCad's own drill files and an ezdxf drawing; LinuxCNC's
// rs274 reads what it prints back to exactly the file's holes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "oracles.h"
#include "test_util.h"

namespace {

std::string filter() { return std::string(ACO_BUILD_DIR) + "/bin/acodrill-linuxcnc-filter"; }

// As AXIS does it (axis.py, open_file_guts: os.popen-style `sh -c` with the
// file quoted, stdin closed); `ini`: the INI path LinuxCNC would export.
testutil::Run run_as_axis(const std::string& file, const std::string& ini = "") {
  const std::string command = filter() + " '" + file + "'";
  return testutil::run((ini.empty() ? std::string("env -u INI_FILE_NAME") : "INI_FILE_NAME=" + testutil::shell_quote(ini)) +
                       " sh -c " + testutil::shell_quote(command) + " </dev/null");
}

// The holes rs274 reads, moved back to the file's own coordinates by the
// zero the program states, against the file's hole list.
void expect_holes(const std::string& program, const std::string& holes_csv, const std::string& what) {
  testutil::TempDir t;
  testutil::spit(t / "p.ngc", program);
  const oracles::Canon canon = oracles::run_rs274(t / "p.ngc");
  const aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(holes_csv));
  ASSERT_EQ(canon.made.size(), expected.size()) << what;
  std::vector<char> used(expected.size(), 0);
  for (const oracles::Made& m : canon.made) {
    bool found = false;
    for (std::size_t j = 0; j < expected.size() && !found; ++j) {
      if (!used[j] && std::fabs(expected[j].center.x - m.x) <= 0.0006 && std::fabs(expected[j].center.y - m.y) <= 0.0006) {
        used[j] = found = true;
      }
    }
    EXPECT_TRUE(found) << what << ": rs274 drills (" << m.x << ", " << m.y << "), not a hole of the file";
  }
}

TEST(linuxcnc_filter, axis_gets_the_program_of_a_drill_file_and_its_progress) {
  testutil::TempDir t;
  // ORIGIN drawing: the program in the file's own coordinates, to compare with its hole list.
  testutil::spit(t / "mill.ini", "[EMC]\nMACHINE = test\n[TRAJ]\nLINEAR_UNITS = mm\n[ACODRILL]\n# the shop's settings\n"
                                 "ORIGIN = drawing\nTIME_LIMIT = 1\n");
  for (const char* board : {"pic_programmer", "video"}) {
    const std::string drl = testutil::data(std::string("kicad/") + board + "-mm-decimal.drl");
    const auto r = run_as_axis(drl, t / "mill.ini");
    ASSERT_EQ(r.code, 0) << board << ": " << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr("FILTER_PROGRESS=")) << board;
    // Nothing on stderr but progress on success.
    std::istringstream lines(r.err);
    for (std::string line; std::getline(lines, line);) EXPECT_THAT(line, ::testing::MatchesRegex("FILTER_PROGRESS=[0-9]+")) << board;
    EXPECT_THAT(r.out, ::testing::HasSubstr("M30"));
    expect_holes(r.out, testutil::data(std::string("kicad/") + board + ".holes.csv"), board);
  }
}

TEST(linuxcnc_filter, a_dxf_opens_too_and_the_ini_chooses_units_and_tools) {
  testutil::TempDir t;
  // A drawing written by ezdxf, in inches on an inch machine: the program in inches.
  testutil::spit(t / "inch.ini", "[TRAJ]\nLINEAR_UNITS = inch\n[ACODRILL]\nORIGIN = drawing\nTIME_LIMIT = 0.5\nMACHINE = vf2\n");
  const std::string dxf = testutil::source_dir() + "/samples/plate70.dxf";
  const auto r = run_as_axis(dxf, t / "inch.ini");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("G20"));
  testutil::spit(t / "p.ngc", r.out);
  const oracles::Canon canon = oracles::run_rs274(t / "p.ngc");
  const aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(testutil::source_dir() + "/samples/plate70.holes.csv"));
  ASSERT_EQ(canon.made.size(), expected.size());
  for (const oracles::Made& m : canon.made) {
    bool found = false;
    for (const aco::Hole& h : expected) {
      found = found || (std::fabs(h.center.x - m.x * 25.4) <= 0.003 && std::fabs(h.center.y - m.y * 25.4) <= 0.003);
    }
    EXPECT_TRUE(found) << "(" << m.x << ", " << m.y << ") in";
  }
  // The drills the shop owns, from the INI.
  testutil::spit(t / "owned.ini", "[ACODRILL]\nDRILLS = 0.6,0.8,1.0,1.2\nEND_MILL = 1.0\nTIME_LIMIT = 0.5\n");
  const auto o = run_as_axis(testutil::data("kicad/pic_programmer-mm-decimal.drl"), t / "owned.ini");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_THAT(o.out, ::testing::HasSubstr("END MILL"));
  EXPECT_THAT(o.out, ::testing::HasSubstr("G02 "));
  // No INI at all: the defaults (a router, 5 s) and still a program.
  const auto d = run_as_axis(testutil::data("kicad/StickHub-mm-decimal.drl"));
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_THAT(d.out, ::testing::HasSubstr("M30"));
}

// Issue 71 and 70: a DXF whose holes are polygons opens in AXIS with ROUND_CONTOURS = YES, and
// EXCELLON_FORMAT reads a drill file that states nothing.
TEST(linuxcnc_filter, the_ini_reads_round_contours_and_states_an_excellon_format) {
  testutil::TempDir t;
  const std::string dxf = testutil::data("dxf-contours/inkscape_r12_line_polygons.dxf");
  testutil::spit(t / "no.ini", "[ACODRILL]\nTIME_LIMIT = 0.5\nORIGIN = drawing\nROUND_CONTOURS = no\n");
  const auto refused = run_as_axis(dxf, t / "no.ini");
  EXPECT_NE(refused.code, 0);
  EXPECT_THAT(refused.err, ::testing::HasSubstr("--round-contours reads them as holes"));
  testutil::spit(t / "yes.ini", "[ACODRILL]\nTIME_LIMIT = 0.5\nORIGIN = drawing\nROUND_CONTOURS = YES\n");
  const auto read = run_as_axis(dxf, t / "yes.ini");
  ASSERT_EQ(read.code, 0) << read.err;
  expect_holes(read.out, testutil::data("dxf-contours/inkscape_r12_line_polygons.round.csv"), "round contours");
  // One-digit numbers a default 2:4 reading puts within a millimetre; the INI states LZ.
  testutil::spit(t / "a.drl", "M48\nINCH\nT1C0.02\n%\nT1\nX1Y1\nX2Y1\nX3Y2\nM30\n");
  const auto refused_drl = run_as_axis(t / "a.drl", t / "no.ini");
  EXPECT_THAT(refused_drl.err, ::testing::HasSubstr("--excellon-format"));
  testutil::spit(t / "lz.ini", "[ACODRILL]\nTIME_LIMIT = 0.5\nEXCELLON_FORMAT = inch,2:4,lz\nMACHINE = vf2\n");
  const auto lz = run_as_axis(t / "a.drl", t / "lz.ini");
  ASSERT_EQ(lz.code, 0) << lz.err;
  testutil::spit(t / "bad.ini", "[ACODRILL]\nROUND_CONTOURS = maybe\n");
  EXPECT_THAT(run_as_axis(dxf, t / "bad.ini").err, ::testing::HasSubstr("bad.ini:2: [ACODRILL] ROUND_CONTOURS is YES or NO"));
}

// Issue 82: the INI's PROCESSES and SPOT are --processes and --spot: the
// build plate drawn without its callout gets its counterbores from the
// table and every hole a spot first; rs274 reads the program back.
TEST(linuxcnc_filter, the_ini_names_a_process_table_and_spots) {
  testutil::TempDir t;
  testutil::spit(t / "shop.json", R"({"processes": [{"kind": "undecided", "operations": ["drill", {"operation": "counterbore", "depth_mm": 3}]}]})");
  testutil::spit(t / "shop.ini", "[ACODRILL]\nTIME_LIMIT = 0.5\nORIGIN = drawing\nPROCESSES = " + t / "shop.json" + "\nSPOT = YES\n");
  const auto read = run_as_axis(testutil::data("dxf-features/build_plate_no_callout.dxf"), t / "shop.ini");
  ASSERT_EQ(read.code, 0) << read.err;
  EXPECT_THAT(read.out, ::testing::HasSubstr("90 DEG SPOT DRILL - 6 HOLES"));
  EXPECT_THAT(read.out, ::testing::HasSubstr("6.500 MM COUNTERBORE - 4 HOLES"));
  EXPECT_THAT(read.out, ::testing::HasSubstr("M3 TAP - 2 HOLES"));
  testutil::spit(t / "p.ngc", read.out);
  // 6 spots, 6 holes drilled, 4 counterbores, 2 taps.
  EXPECT_EQ(oracles::run_rs274(t / "p.ngc").made.size(), 18u);
}

TEST(linuxcnc_filter, a_bad_file_or_setting_is_one_line_a_failure_and_no_program) {
  testutil::TempDir t;
  testutil::spit(t / "bad.drl", "M48\nMETRIC\nT1C0.8\n%\nT1\nX1.0Y\n");
  testutil::spit(t / "ok.ini", "[ACODRILL]\nTIME_LIMIT = 0.5\n");
  testutil::spit(t / "unknown.ini", "[ACODRILL]\nTIME_LIMIT = 0.5\nDRILL = 0.8\n");
  testutil::spit(t / "value.ini", "[ACODRILL]\nORIGIN = somewhere\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {t / "bad.drl", t / "ok.ini"},
      {t / "missing.drl", t / "ok.ini"},
      {testutil::data("kicad/StickHub-mm-decimal.drl"), t / "unknown.ini"},
      {testutil::data("kicad/StickHub-mm-decimal.drl"), t / "value.ini"},
      {testutil::data("kicad/StickHub-mm-decimal.drl"), t / "no-such.ini"}};
  for (const auto& [file, ini] : cases) {
    const auto r = run_as_axis(file, ini);
    EXPECT_NE(r.code, 0) << file << " " << ini;
    EXPECT_EQ(r.out, "") << file << " " << ini;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::StartsWith("acodrill: error: ")) << r.err;
  }
  EXPECT_THAT(run_as_axis(testutil::data("kicad/StickHub-mm-decimal.drl"), t / "unknown.ini").err,
              ::testing::HasSubstr("unknown.ini:3: [ACODRILL] DRILL is not an acodrill setting"));
}

}  // namespace
