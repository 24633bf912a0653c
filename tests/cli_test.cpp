// acodrill end to end, as a shop engineer and a CAM pipeline use it: the
// contract's commands, outputs and exit codes (../shared/interface.md).
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <regex>
#include <set>
#include <nlohmann/json.hpp>

#include "gcode/interpreter.h"
#include "test_util.h"

using testutil::acodrill_run;
using testutil::data;
using testutil::shell_quote;
using testutil::slurp;
using testutil::spit;
using testutil::TempDir;

namespace {

std::vector<std::string> samples() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(testutil::source_dir() + "/samples")) {
    if (e.path().extension() == ".dxf") out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string q(const std::string& s) { return shell_quote(s); }

}  // namespace

TEST(cli_test, every_sample_is_drilled_once_per_hole_and_verify_agrees) {
  TempDir t;
  for (const std::string& sample : samples()) {
    const std::string nc = t / "p.nc", json = t / "r.json";
    auto r = acodrill_run("plan " + q(sample) + " -o " + q(nc) + " --report " + q(json) + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err << " in sample " << sample;
    EXPECT_EQ(r.err, "") << "quiet on success";
    // Read the program back: one drilling position per sample hole.
    const aco::HoleSet expected =
        testutil::read_holes_csv(slurp(sample.substr(0, sample.size() - 4) + ".holes.csv"));
    gcode::Interpretation run = gcode::interpret(slurp(nc));
    ASSERT_EQ(run.holes.size(), expected.size()) << " in sample " << sample;
    auto v = acodrill_run("verify " + q(nc) + " --holes " + q(sample));
    EXPECT_EQ(v.code, 0) << v.out << " in sample " << sample;
    // The report agrees with the program and with a recomputation.
    auto report = nlohmann::json::parse(slurp(json));
    EXPECT_EQ(report["holes"].get<std::size_t>(), expected.size());
    const double optimized = report["travel_mm"]["optimized"].get<double>();
    EXPECT_LE(optimized, report["travel_mm"]["nearest_neighbor"].get<double>() + 1e-6) << sample;
    EXPECT_LE(optimized, report["travel_mm"]["input_order"].get<double>() + 1e-6) << sample;
    EXPECT_NEAR(optimized, run.rapid_xy_mm, 0.01 * expected.size() + 0.01) << "report vs the program's rapids, " << sample;
    EXPECT_GT(report["machining_time_s"]["optimized"].get<double>(), 0.0);
    std::size_t tool_holes = 0;
    for (const auto& tool : report["tools"]) tool_holes += tool["holes"].get<std::size_t>();
    EXPECT_EQ(tool_holes, expected.size());
    for (const char* key : {"algorithm", "threads", "seed", "iterations", "wall_s"}) {
      EXPECT_TRUE(report["solver"].contains(key)) << key;
    }
  }
}

TEST(cli_test, program_to_stdout_equals_the_file_and_threads_do_not_change_it) {
  TempDir t;
  const std::string sample = testutil::source_dir() + "/samples/pcb_mixed.dxf";
  ASSERT_EQ(acodrill_run("plan " + q(sample) + " -o " + q(t / "a.nc") + " -q --threads 1").code, 0);
  ASSERT_EQ(acodrill_run("plan " + q(sample) + " -o " + q(t / "b.nc") + " -q --threads 2").code, 0);
  auto out = acodrill_run("plan " + q(sample) + " -o - --threads 2");
  ASSERT_EQ(out.code, 0);
  EXPECT_EQ(slurp(t / "a.nc"), slurp(t / "b.nc"));
  EXPECT_EQ(out.out, slurp(t / "a.nc")) << "-o - writes the program and nothing else to stdout";
  EXPECT_THAT(out.err, ::testing::HasSubstr("optimized"));
}

TEST(cli_test, holes_prints_the_contract_csv) {
  auto r = acodrill_run("holes " + q(data("real-dxf/librecad_arrayed_holes_inch.dxf")) + " --format csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, slurp(data("real-dxf/librecad_arrayed_holes_inch.holes.csv")));
  EXPECT_EQ(testutil::count_lines(r.err), 1) << "one summary line: " << r.err;
  auto stdin_run = acodrill_run("holes - --format csv -q", slurp(data("dxf/r12_plate25.dxf")));
  EXPECT_EQ(stdin_run.out, slurp(data("dxf/r12_plate25.holes.csv")));
  EXPECT_EQ(acodrill_run("holes - -q", slurp(data("dxf/r12_plate25.dxf"))).out, stdin_run.out) << "csv is the default";
}

TEST(cli_test, other_input_formats) {
  TempDir t;
  spit(t / "h.csv", "x,y,d\n10,10,3\n20,10,3\n20,20,6\n");
  auto r = acodrill_run("holes " + q(t / "h.csv") + " --format csv -q");
  EXPECT_EQ(r.out, "x_mm,y_mm,diameter_mm,layer\n10.000000,10.000000,3.000000,\n20.000000,10.000000,3.000000,\n"
                   "20.000000,20.000000,6.000000,\n");
  spit(t / "map.xml", "<holemap units=\"inch\"><hole x=\"1\" y=\"2\" diameter=\"0.25\"/></holemap>\n");
  EXPECT_EQ(acodrill_run("holes " + q(t / "map.xml") + " --format csv -q").out,
            "x_mm,y_mm,diameter_mm,layer\n25.400000,50.800000,6.350000,\n");
  auto tsp = acodrill_run("holes " + q(data("tsplib/d198.tsp")) + " --format csv -q");
  EXPECT_EQ(testutil::count_lines(tsp.out), 199);
}

TEST(cli_test, tsp_prints_the_length_and_writes_a_tour) {
  TempDir t;
  auto r = acodrill_run("tsp " + q(data("tsplib/d198.tsp")) + " --iterations 30 --tour " + q(t / "d198.tour"));
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_THAT(r.out, ::testing::StartsWith("length "));
  const long long length = std::stoll(r.out.substr(7));
  EXPECT_GE(length, 15780);
  EXPECT_LT(length, 15780 * 1.05);
  const std::string tour = slurp(t / "d198.tour");
  EXPECT_THAT(tour, ::testing::HasSubstr("TOUR_SECTION\n"));
  EXPECT_THAT(tour, ::testing::HasSubstr("-1\nEOF\n"));
}

TEST(cli_test, verify_catches_dropped_duplicated_moved_and_wrong_tool_holes) {
  TempDir t;
  const std::string sample = testutil::source_dir() + "/samples/pcb_mixed.dxf";
  ASSERT_EQ(acodrill_run("plan " + q(sample) + " -o " + q(t / "ok.nc") + " -q").code, 0);
  const std::string prog = slurp(t / "ok.nc");
  auto lines_of = [](const std::string& s) {
    std::vector<std::string> v;
    std::istringstream in(s);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
  };
  auto join = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& l : v) s += l + "\n";
    return s;
  };
  std::vector<std::string> lines = lines_of(prog);
  // A bare "N.. X.. Y.." hole line, not the first of its tool.
  std::size_t bare = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i][0] == 'N' && lines[i].find(" X") != std::string::npos && lines[i].find("G8") == std::string::npos &&
        lines[i].find("G98") == std::string::npos) {
      bare = i;
      break;
    }
  }
  ASSERT_GT(bare, 0u);
  auto dropped = lines;
  dropped.erase(dropped.begin() + static_cast<long>(bare));
  auto duplicated = lines;
  duplicated.insert(duplicated.begin() + static_cast<long>(bare), lines[bare]);
  auto moved = lines;
  moved[bare] = moved[bare].substr(0, moved[bare].find(" X")) + " X1.234 Y5.678";
  // Wrong tool: swap the T numbers of the first two tool changes.
  std::string wrong = prog;
  const auto t1 = wrong.find("T1 M06"), t2 = wrong.find("T2 M06");
  ASSERT_NE(t2, std::string::npos);
  wrong[t1 + 1] = '2';
  wrong[t2 + 1] = '1';
  int index = 0;
  for (const std::string& bad : {join(dropped), join(duplicated), join(moved), wrong}) {
    spit(t / "bad.nc", bad);
    auto r = acodrill_run("verify " + q(t / "bad.nc") + " --holes " + q(sample) + " -q");
    EXPECT_EQ(r.code, 1) << "case " << index << ": " << r.out;
    EXPECT_THAT(r.out, ::testing::HasSubstr("fault: ")) << "case " << index;
    ++index;
  }
  EXPECT_EQ(acodrill_run("verify " + q(t / "ok.nc") + " --holes " + q(sample)).code, 0);
}

TEST(cli_test, bad_input_is_one_line_exit_2_and_no_output_file) {
  TempDir t;
  spit(t / "garbage.dxf", "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\nabc\n20\n1\n40\n1\n0\nENDSEC\n0\nEOF\n");
  spit(t / "existing.nc", "KEEP ME\n");
  struct Case {
    std::string args;
    std::string expect;  // substring of the error line
  };
  const std::vector<Case> cases = {
      {"plan " + q(t / "garbage.dxf") + " -o " + q(t / "out.nc"), "garbage.dxf:8: "},
      {"plan " + q(t / "garbage.dxf") + " -o " + q(t / "existing.nc"), "garbage.dxf:8: "},
      {"plan " + q(t / "missing.dxf") + " -o " + q(t / "out.nc"), "missing.dxf: cannot read"},
      {"plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " -o " + q(t / "out.nc") + " --rho 2", "--rho"},
      {"plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " -o " + q(t / "out.nc") + " --dialect mazak",
       "--dialect"},
      {"plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " -o " + q(t / "out.nc") + " --ants 0", "--ants"},
      {"plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " -o " + q(t / "out.nc") + " --algorithm xyz",
       "--algorithm"},
      {"plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " -o " + q(t / "nodir/out.nc"), "cannot write"},
      {"plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " -o " + q(t / "out.nc") + " --resume-from 11",
       "resume-from"},
      {"frobnicate", "frobnicate"},
      {"holes " + q(t / "garbage.dxf") + " --format xml", "--format"},
  };
  for (const Case& c : cases) {
    auto r = acodrill_run(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_THAT(r.err, ::testing::StartsWith("acodrill: error: ")) << c.args;
    EXPECT_THAT(r.err, ::testing::HasSubstr(c.expect)) << c.args;
    EXPECT_FALSE(std::filesystem::exists(t / "out.nc")) << c.args;
  }
  EXPECT_EQ(slurp(t / "existing.nc"), "KEEP ME\n");
  // No temporary files are left behind.
  for (const auto& e : std::filesystem::directory_iterator(t.path())) {
    EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << e.path();
  }
}

TEST(cli_test, refuses_to_overwrite_its_input) {
  TempDir t;
  std::filesystem::copy_file(testutil::source_dir() + "/samples/plate10.dxf", t / "p.dxf");
  const std::string before = slurp(t / "p.dxf");
  auto r = acodrill_run("plan " + q(t / "p.dxf") + " -o " + q(t / "p.dxf"));
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("overwrite the input"));
  EXPECT_EQ(slurp(t / "p.dxf"), before);
}

TEST(cli_test, help_and_version) {
  auto h = acodrill_run("--help");
  EXPECT_EQ(h.code, 0);
  EXPECT_THAT(h.out, ::testing::HasSubstr("plan"));
  auto ph = acodrill_run("plan --help");
  EXPECT_EQ(ph.code, 0);
  EXPECT_THAT(ph.out, ::testing::HasSubstr("Examples"));
  EXPECT_THAT(acodrill_run("--version").out, ::testing::HasSubstr("acodrill"));
  auto bench = testutil::run(q(std::string(ACO_BUILD_DIR) + "/bin/acobench") + " --help");
  EXPECT_EQ(bench.code, 0);
}

TEST(cli_test, golden_programs_are_byte_identical) {
  // tests/golden/cases.txt lists NAME|arguments; scripts/update-golden rewrites them on purpose.
  std::istringstream cases(slurp(testutil::source_dir() + "/tests/golden/cases.txt"));
  int checked = 0;
  TempDir t;
  for (std::string line; std::getline(cases, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::string name = line.substr(0, line.find('|')), args = line.substr(line.find('|') + 1);
    auto r = testutil::run("cd " + q(testutil::source_dir()) + " && " + q(testutil::acodrill()) + " plan " + args +
                           " -o " + q(t / "p.nc") + " --quiet");
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    EXPECT_EQ(slurp(t / "p.nc"), slurp(testutil::source_dir() + "/tests/golden/" + name + ".nc"))
        << name << " changed; if intended, run scripts/update-golden and review the diff";
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST(cli_test, route_pictures_are_well_formed_and_render) {
  TempDir t;
  const std::string sample = testutil::source_dir() + "/samples/pcb_mixed.dxf";
  auto r = acodrill_run("plan " + q(sample) + " -o " + q(t / "p.nc") + " --svg " + q(t / "r.svg") + " --svg-compare " +
                        q(t / "c.svg") + " -q --iterations 20");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* svg : {"r.svg", "c.svg"}) {
    const std::string text = slurp(t / svg);
    EXPECT_THAT(text, ::testing::StartsWith("<?xml"));
    EXPECT_THAT(text, ::testing::HasSubstr("</svg>\n"));
    // One circle per hole (plus none else), and a legend that names the savings.
    std::size_t circles = 0;
    for (std::size_t at = text.find("<circle"); at != std::string::npos; at = text.find("<circle", at + 1)) ++circles;
    EXPECT_EQ(circles, std::string(svg) == "c.svg" ? 212u : 106u);
    EXPECT_THAT(text, ::testing::HasSubstr("min saved"));
    auto render = testutil::run("rsvg-convert " + q(t / svg) + " -o " + q(t / "out.png"));
    EXPECT_EQ(render.code, 0) << "rsvg-convert could not render " << svg << ": " << render.err;
    EXPECT_GT(std::filesystem::file_size(t / "out.png"), 1000u);
  }
  auto xml = acodrill_run("plan " + q(testutil::source_dir() + "/samples/circular21.xml") + " -o " + q(t / "x.nc") + " -q");
  EXPECT_EQ(xml.code, 0) << xml.err;
  EXPECT_EQ(acodrill_run("verify " + q(t / "x.nc") + " --holes " + q(testutil::source_dir() + "/samples/circular21.xml") + " -q").code, 0);
}

// Issue 16: holes that come without a size get the one the user gives, or a
// tool table's; the program never names a 0 mm drill.
TEST(cli_test, holes_without_a_diameter_take_the_default_or_the_tool_table) {
  TempDir t;
  testutil::spit(t / "a.csv", "x,y\n1,1\n5,5\n9,1\n");
  auto r = acodrill_run("plan " + q(t / "a.csv") + " -o " + q(t / "a.nc") + " -q --default-diameter 3.2");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string prog = slurp(t / "a.nc");
  EXPECT_THAT(prog, ::testing::HasSubstr("(T1 D=3.200 MM - 3.200 MM DRILL - 3 HOLES)"));
  EXPECT_EQ(prog.find("0.000 MM DRILL"), std::string::npos);
  testutil::spit(t / "tools.json", R"({"tools": [{"number": 7, "diameter_mm": 2.5, "min_hole_mm": 0, "max_hole_mm": 2.6}]})");
  auto tt = acodrill_run("plan " + q(t / "a.csv") + " -o " + q(t / "b.nc") + " -q --tools " + q(t / "tools.json"));
  ASSERT_EQ(tt.code, 0) << tt.err;
  EXPECT_THAT(slurp(t / "b.nc"), ::testing::HasSubstr("T7 M06"));
  auto none = acodrill_run("plan " + q(t / "a.csv") + " -o " + q(t / "c.nc") + " -q");
  EXPECT_EQ(none.code, 2);
  EXPECT_THAT(none.err, ::testing::HasSubstr("a.csv:2: hole without a diameter"));
}

// Issue 16: one slot policy for every format. Drilled, a slot's holes stay
// together and in their order (ends first) whatever the colony does with the
// rest; skipped, the slot is named in the program, the report and the sheet.
TEST(cli_test, slots_are_drilled_in_their_order_or_named_where_skipped) {
  TempDir t;
  testutil::spit(t / "s.drl", "M48\nMETRIC\nT1C1.0\n%\nT1\nX5.0Y5.0\nX0.0Y0.0G85X2.0Y0.0\nX10.0Y0.0\nX1.0Y8.0\nM30\n");
  auto r = acodrill_run("plan " + q(t / "s.drl") + " -o " + q(t / "d.nc") + " -q --origin drawing --dialect linuxcnc");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string prog = slurp(t / "d.nc");
  EXPECT_THAT(prog, ::testing::HasSubstr("(SLOTS: 1 DRILLED AS 9 HOLES)"));
  gcode::Interpretation run = gcode::interpret(prog);
  ASSERT_EQ(run.holes.size(), 12u);
  std::vector<double> slot_x;
  std::size_t first = run.holes.size();
  for (std::size_t i = 0; i < run.holes.size(); ++i) {
    if (std::fabs(run.holes[i].y_mm) < 1e-9 && run.holes[i].x_mm <= 2.0 + 1e-9) {
      if (first == run.holes.size()) first = i;
      EXPECT_EQ(i, first + slot_x.size()) << "the slot's holes are drilled one after another";
      slot_x.push_back(run.holes[i].x_mm);
    }
  }
  ASSERT_EQ(slot_x.size(), 9u);
  const std::vector<double> bisection = {0.0, 2.0, 1.0, 0.5, 1.5, 0.25, 0.75, 1.25, 1.75};
  EXPECT_TRUE(slot_x == bisection) << "ends first, then midpoints";
  EXPECT_EQ(acodrill_run("verify " + q(t / "d.nc") + " --holes " + q(t / "s.drl") + " -q").code, 0);

  auto s = acodrill_run("plan " + q(t / "s.drl") + " -o " + q(t / "s.nc") + " -q --slots skip --report " + q(t / "r.json") +
                        " --setup-sheet " + q(t / "s.html"));
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(s.err, "") << "quiet";
  EXPECT_THAT(slurp(t / "s.nc"), ::testing::HasSubstr("(NOT MADE: LINE 7: SLOT 1.000 MM WIDE FROM X0.000 Y0.000 TO X2.000 Y0.000 MM,)\n(--SLOTS SKIP)"));
  EXPECT_EQ(gcode::interpret(slurp(t / "s.nc")).holes.size(), 3u);
  auto report = nlohmann::json::parse(slurp(t / "r.json"));
  ASSERT_EQ(report["not_drilled"].size(), 1u);
  EXPECT_EQ(report["not_drilled"][0]["line"].get<int>(), 7);
  EXPECT_THAT(slurp(t / "s.html"), ::testing::HasSubstr("<b>Not made</b>: line 7: slot 1.000 mm wide"));
  auto noisy = acodrill_run("plan " + q(t / "s.drl") + " -o " + q(t / "n.nc") + " --slots skip");
  EXPECT_THAT(noisy.err, ::testing::HasSubstr("NOT MADE: 1 feature(s), first: line 7: slot"));
}

// Issues 23 and 25: the built-in machine classes. `machines` lists them as
// NAME<TAB>description; a class changes the time estimate, the generated
// tools' speeds and the default dialect; its profile printed by --show,
// given back as a file, plans byte for byte the same.
TEST(cli_test, machine_classes_are_listed_and_change_the_plan) {
  TempDir t;
  auto list = acodrill_run("machines");
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_THAT(list.out, ::testing::ContainsRegex("(^|\n)vf2\t[^\n]+\n"));
  EXPECT_THAT(list.out, ::testing::ContainsRegex("(^|\n)router\t[^\n]+\n"));
  const std::string plate = testutil::source_dir() + "/samples/plate10.dxf";
  auto plan = [&](const std::string& extra, const std::string& out) {
    auto r = acodrill_run("plan " + q(plate) + " -o " + q(out) + " --report " + q(out + ".json") + " -q --iterations 10" + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(slurp(out + ".json"));
  };
  const auto vf2 = plan("", t / "vf2.nc");
  const auto router = plan(" --machine router", t / "router.nc");
  // The router has no tool changer and no canned cycles: GRBL, a pause per tool.
  EXPECT_THAT(slurp(t / "router.nc"), ::testing::HasSubstr("(MSG, PUT IN T1 "));
  EXPECT_THAT(slurp(t / "vf2.nc"), ::testing::HasSubstr("G81"));
  // Slower rapids, a manual tool change: the same route takes longer.
  EXPECT_GT(router["machining_time_s"]["optimized"].get<double>(), vf2["machining_time_s"]["optimized"].get<double>());
  // --dialect grbl without a machine plans for the router.
  plan(" --dialect grbl", t / "grbl.nc");
  EXPECT_EQ(slurp(t / "grbl.nc"), slurp(t / "router.nc"));
  auto show = acodrill_run("machines --show router");
  ASSERT_EQ(show.code, 0);
  spit(t / "my-router.json", show.out);
  plan(" --machine " + q(t / "my-router.json"), t / "file.nc");
  EXPECT_EQ(slurp(t / "file.nc"), slurp(t / "router.nc"));
  auto unknown = acodrill_run("machines --show bridgeport");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_THAT(unknown.err, ::testing::HasSubstr("built in: vf2, router"));
}

// Issue 25: time as the machine spends it. On real boards, with the PCB
// drilling class and the VF-2 class, the report splits each order's time into
// moves, drilling, tool changes and pauses that add up to the total; only the
// moves depend on the route, so the time saved is the moving time saved.
TEST(cli_test, time_split_adds_up_and_the_route_changes_only_the_moves) {
  TempDir t;
  const std::vector<std::string> boards = {data("real-excellon/altium_pic18f14k50_inch_lz_pth_npth.txt"),
                                           data("real-excellon/eagle_arduino_uno_inch_tz.drd"),
                                           data("real-excellon/orcad_thruhole_noheader.tap"),
                                           data("kicad/kit-dev-coldfire-xilinx_5213-mm-decimal.drl")};
  for (const std::string& board : boards) {
    for (const char* machine : {"pcb-drill", "pcb-proto", "vf2", "router"}) {
      const std::string what = board + " " + machine;
      auto r = acodrill_run("plan " + q(board) + " -o " + q(t / "p.nc") + " --report " + q(t / "r.json") +
                            " -q --iterations 30 --slots skip --batch 20 --machine " + machine);
      ASSERT_EQ(r.code, 0) << what << ": " << r.err;
      const auto j = nlohmann::json::parse(slurp(t / "r.json"));
      double moves[2] = {0, 0};
      int k = 0;
      for (const char* order : {"input_order", "optimized"}) {
        const auto& s = j["time_split_s"][order];
        const double sum = s["moves"].get<double>() + s["drilling"].get<double>() + s["tool_changes"].get<double>() +
                           s["pauses"].get<double>();
        EXPECT_NEAR(sum, j["machining_time_s"][order].get<double>(), 1e-5) << what << " " << order;
        moves[k++] = s["moves"].get<double>();
      }
      EXPECT_LE(moves[1], moves[0] + 1e-9) << what;
      // Never a longer route than the ones reported beside it (13-hole OrCAD board: nearest neighbour is best).
      const double travel = j["travel_mm"]["optimized"].get<double>();
      EXPECT_LE(travel, j["travel_mm"]["input_order"].get<double>() + 1e-9) << what;
      EXPECT_LE(travel, j["travel_mm"]["nearest_neighbor"].get<double>() + 1e-9) << what;
      for (const char* part : {"drilling", "tool_changes", "pauses"}) {
        EXPECT_NEAR(j["time_split_s"]["input_order"][part].get<double>(), j["time_split_s"]["optimized"][part].get<double>(), 1e-6)
            << what << " " << part;
      }
      const double saved = j["machining_time_s"]["input_order"].get<double>() - j["machining_time_s"]["optimized"].get<double>();
      EXPECT_NEAR(saved, moves[0] - moves[1], 1e-5) << what;
      EXPECT_NEAR(j["batch"]["time_s"]["optimized"].get<double>(), 20 * j["machining_time_s"]["optimized"].get<double>(), 1e-3);
      EXPECT_EQ(j["batch"]["panels"].get<int>(), 20);
    }
  }
}

// Several inputs: holes of one diameter share a tool unless the files are
// kept apart; a hole in both files is drilled once.
TEST(cli_test, several_inputs_share_tools_unless_kept_apart) {
  TempDir t;
  spit(t / "a.csv", "x,y,d\n0,0,1.0\n10,0,1.0\n20,0,0.8\n");
  spit(t / "b.csv", "x,y,d\n0,10,1.0\n10,10,1.0\n20,0,0.8\n");
  auto shared = acodrill_run("plan " + q(t / "a.csv") + " " + q(t / "b.csv") + " -o " + q(t / "s.nc") + " --report " +
                             q(t / "s.json") + " -q --iterations 10");
  ASSERT_EQ(shared.code, 0) << shared.err;
  auto j = nlohmann::json::parse(slurp(t / "s.json"));
  EXPECT_EQ(j["holes"].get<int>(), 5) << "(20, 0) D0.8 is in both files";
  EXPECT_EQ(j["tools"].size(), 2u);
  EXPECT_EQ(j["sources"][0]["holes"].get<int>(), 3);
  EXPECT_EQ(j["sources"][1]["holes"].get<int>(), 2);
  auto apart = acodrill_run("plan " + q(t / "a.csv") + " " + q(t / "b.csv") + " -o " + q(t / "k.nc") + " --report " +
                            q(t / "k.json") + " -q --iterations 10 --keep-files-apart");
  ASSERT_EQ(apart.code, 0) << apart.err;
  j = nlohmann::json::parse(slurp(t / "k.json"));
  ASSERT_EQ(j["tools"].size(), 3u) << "a.csv: D0.8 and D1.0; b.csv: D1.0";
  EXPECT_EQ(j["tools"][2]["diameter_mm"].get<double>(), 1.0);
  EXPECT_EQ(j["tools"][2]["holes"].get<int>(), 2);
  auto v = acodrill_run("verify " + q(t / "k.nc") + " --holes " + q(t / "a.csv") + " " + q(t / "b.csv") + " -q");
  EXPECT_EQ(v.code, 0) << v.out;
  // A program is reordered alone.
  auto mixed = acodrill_run("plan " + q(t / "a.csv") + " " + q(data("real-gcode/pcb2gcode_D1MiniGSR.drill.ngc")) + " -o " +
                            q(t / "m.nc"));
  EXPECT_EQ(mixed.code, 2);
  EXPECT_THAT(mixed.err, ::testing::HasSubstr("a drilling program is reordered on its own"));
}

// Pictures a shop reads at a glance: a 14-tool job gives every tool its own colour.
TEST(cli_test, every_tool_has_its_own_colour) {
  TempDir t;
  const std::string dir = data("real-gerber/kicad/pic_programmer/x2_mm46/");
  auto r = acodrill_run("plan " + q(dir + "pic_programmer-PTH-drl.gbr") + " " + q(dir + "pic_programmer-NPTH-drl.gbr") + " -o " +
                        q(t / "p.nc") + " --svg " + q(t / "p.svg") + " -q --iterations 10 --slots skip");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = slurp(t / "p.svg");
  std::set<std::string> fills;
  std::size_t legend = 0;
  static const std::regex entry(R"re(<rect x="[^"]+" y="[^"]+" width="12" height="12" fill="(#[0-9A-Fa-f]{6})"/><text[^>]*>T)re");
  for (std::sregex_iterator it(svg.begin(), svg.end(), entry), end; it != end; ++it) {
    fills.insert((*it)[1].str());
    ++legend;
  }
  EXPECT_EQ(legend, 14u);
  EXPECT_EQ(fills.size(), legend) << "two tools share a colour";
}

// TSPLIB's own distances (interface: EUC_2D rounded, CEIL_2D rounded up; ATT
// pseudo-Euclidean as TSPLIB 95 defines it): on this triangle the three give
// 4, 6 and 3 for the only tour there is (legs sqrt 2, sqrt 2 and 2).
TEST(cli_test, tsp_lengths_use_the_instances_own_rounding) {
  TempDir t;
  const std::string head = "NAME : tri\nTYPE : TSP\nDIMENSION : 3\nEDGE_WEIGHT_TYPE : ";
  const std::string nodes = "\nNODE_COORD_SECTION\n1 0 0\n2 1 1\n3 2 0\nEOF\n";
  for (const auto& [type, length] : {std::pair{"EUC_2D", "4"}, {"CEIL_2D", "6"}, {"ATT", "3"}}) {
    spit(t / "tri.tsp", head + type + nodes);
    auto r = acodrill_run("tsp " + q(t / "tri.tsp") + " -q --iterations 5");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, std::string("length ") + length + "\n") << type;
  }
}

// Issue 47: the same file given twice (or under another name) is one input:
// read once, named once in the program, with a warning.
TEST(cli_test, a_file_given_twice_is_read_once_with_a_warning) {
  TempDir t;
  const std::string drl = data("kicad/pic_programmer-mm-decimal.drl");
  const std::string nc_once = t / "once.nc", nc_twice = t / "twice.nc";
  auto once = acodrill_run("plan " + q(drl) + " -o " + q(nc_once) + " --iterations 5");
  ASSERT_EQ(once.code, 0) << once.err;
  std::filesystem::create_symlink(drl, t / "alias.drl");
  auto twice = acodrill_run("plan " + q(drl) + " " + q(t / "alias.drl") + " " + q(drl) + " -o " + q(nc_twice) + " --iterations 5");
  ASSERT_EQ(twice.code, 0) << twice.err;
  EXPECT_THAT(twice.err, ::testing::HasSubstr("warning: " + t / "alias.drl" + " is given more than once; it is read once"));
  EXPECT_THAT(twice.err, ::testing::HasSubstr("warning: " + drl + " is given more than once; it is read once"));
  EXPECT_EQ(slurp(nc_once), slurp(nc_twice)) << "the same program, the file named once in its header";
  // verify --holes takes the same list.
  auto v = acodrill_run("verify " + q(nc_twice) + " --holes " + q(drl) + " " + q(drl));
  EXPECT_EQ(v.code, 0) << v.out << v.err;
  // Quiet stays quiet.
  auto quiet = acodrill_run("plan " + q(drl) + " " + q(drl) + " -o " + q(nc_twice) + " --iterations 5 --quiet");
  EXPECT_EQ(quiet.err, "");
}

// Issue 71: a drawing whose holes are all round contours, planned with and without --round-contours.
TEST(cli_test, plan_on_a_drawing_of_round_contours_only_says_how_to_read_them) {
  testutil::TempDir t;
  const std::string in = testutil::data("dxf-contours/inkscape_r12_line_polygons.dxf");
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(in) + " -o " + (t / "a.nc"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
  EXPECT_THAT(r.err, ::testing::HasSubstr("no CIRCLE to drill, but 4 round closed contour(s) drawn without one (4 LINE): "
                                          "--round-contours reads them as holes"));
  EXPECT_FALSE(std::filesystem::exists(t / "a.nc"));
  r = testutil::acodrill_run("plan " + testutil::shell_quote(in) + " -o " + (t / "a.nc") + " --round-contours --report " +
                             (t / "r.json") + " -q");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(testutil::slurp(t / "r.json"), ::testing::HasSubstr("\"round_contours\""));
  EXPECT_THAT(testutil::slurp(t / "r.json"), ::testing::HasSubstr("\"read_as_holes\": 4"));
  auto v = testutil::acodrill_run("verify " + (t / "a.nc") + " --holes " + testutil::shell_quote(in) + " --round-contours -q");
  EXPECT_EQ(v.code, 0) << v.out;
}

// Issue 73: what the operator reads at the machine. Over every dialect and
// option mix: no line over 78 characters (GRBL's 80-character buffer; senders
// cut or refuse longer ones: UGS 70 after comments and blanks), no word of a
// message or comment cut (the whole instruction reads back from the comment
// lines joined), every pause with its instruction on the pause line itself,
// no M6, %msg or %wait in a GRBL program, and no pause in the first 10 lines
// (gSender drops one there).
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The words of every comment, in order, joined by single blanks ("(A B)\n(C)" -> "A B C").
std::string comment_words(const std::vector<std::string>& lines, bool marlin) {
  std::string words;
  for (const std::string& l : lines) {
    std::string text;
    if (marlin && l.rfind("; ", 0) == 0) text = l.substr(2);
    else if (marlin && l.rfind("M0 ", 0) == 0) text = l.substr(3);
    else if (!marlin && l.find('(') != std::string::npos) text = l.substr(l.find('(') + 1, l.rfind(')') - l.find('(') - 1);
    if (text.rfind("MSG, ", 0) == 0) text = text.substr(5);
    if (!text.empty()) words += (words.empty() ? "" : " ") + text;
  }
  return words;
}

}  // namespace

TEST(cli_test, the_operator_reads_every_message_whole_on_lines_every_sender_takes) {
  testutil::TempDir t;
  // A board: small holes, a large one (milled with the end mill), 1.3 mm holes for a long-named tool.
  std::string csv = "x,y,d\n";
  for (int i = 0; i < 8; ++i) csv += std::to_string(5 + 7 * i) + "," + std::to_string(5 + (i % 3) * 6) + ",0.6\n";
  for (int i = 0; i < 4; ++i) csv += std::to_string(10 + 9 * i) + ",30,0.8\n";
  csv += "60,30,3.2\n60,5,1.3\n20,40,1.3\n";
  spit(t / "board.csv", csv);
  const std::string long_name = "CARBIDE MICRO DRILL 1.3 MM FROM THE BLUE BOX ON THE SECOND SHELF, REGRIND NUMBER FOUR";
  spit(t / "tools.json", "{\"tools\": [{\"number\": 1, \"diameter_mm\": 0.6}, {\"number\": 2, \"diameter_mm\": 0.8}, "
                         "{\"number\": 3, \"diameter_mm\": 1.3, \"name\": \"" + long_name + "\"}, {\"number\": 4, \"diameter_mm\": 3.2}]}");
  struct Mix {
    std::string dialects, options;
  };
  const std::vector<Mix> mixes = {
      {"haas fanuc linuxcnc grbl marlin", ""},
      {"haas fanuc linuxcnc grbl marlin", "--tools " + (t / "tools.json")},
      {"linuxcnc grbl marlin", "--machine router --drills 0.6,0.8,1.3 --end-mill 1.0 --probe-plate 0.5"},
      {"grbl marlin", "--machine router --drills 0.6,0.8,1.3 --end-mill 1.0 --side back --alignment-pins 3.0"},
      {"haas grbl marlin", "--panel 2x2 --pitch 80,60"},
      {"grbl marlin", "--machine router --tools " + (t / "tools.json") + " --probe-plate 1.5"},
  };
  for (const Mix& mix : mixes) {
    std::istringstream ds(mix.dialects);
    for (std::string dialect; ds >> dialect;) {
      const std::string what = dialect + " " + mix.options;
      auto r = testutil::acodrill_run("plan " + (t / "board.csv") + " -o " + (t / "p.nc") + " -q --iterations 5 --dialect " +
                                      dialect + " " + mix.options);
      ASSERT_EQ(r.code, 0) << what << "\n" << r.err;
      const std::string text = slurp(t / "p.nc");
      const std::vector<std::string> lines = lines_of(text);
      const bool marlin = dialect == "marlin", grbl = dialect == "grbl";
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        EXPECT_LE(l.size(), 78u) << what << ": line " << i + 1 << ": " << l;
        if (grbl) {
          std::string code = std::regex_replace(l, std::regex(R"(\([^)]*\))"), "");
          code.erase(std::remove(code.begin(), code.end(), ' '), code.end());
          EXPECT_LE(code.size(), 70u) << what << ": " << l;
          EXPECT_EQ(l.find("M6"), std::string::npos) << what << ": " << l;
          EXPECT_EQ(l.find("%msg"), std::string::npos) << what << ": " << l;
          EXPECT_EQ(l.find("%wait"), std::string::npos) << what << ": " << l;
        }
        const bool pause = l == "M0" || l == "M00" || l.rfind("M0 ", 0) == 0 || l.rfind("M00 ", 0) == 0;
        if (!pause) continue;
        EXPECT_GE(i, 10u) << what << ": a pause within the first 10 lines";
        if (marlin) EXPECT_THAT(l, ::testing::MatchesRegex("M0 [A-Z0-9].*")) << what;
        else EXPECT_THAT(l, ::testing::MatchesRegex("M0+ \\([A-Z0-9][^()]*\\)")) << what;
      }
      // Whole words: every instruction reads back from the comments joined.
      const std::string words = comment_words(lines, marlin);
      if (grbl || marlin) {
        EXPECT_THAT(words, ::testing::HasSubstr("AT EACH TOOL THE SPINDLE STOPS AND RISES AND THE PROGRAM PAUSES: PUT IN "
                                                "THE TOOL NAMED BELOW,"))
            << what;
        EXPECT_THAT(words, ::testing::ContainsRegex("PUT IN T1 [0-9.]+ MM DRILL, (ZERO Z ON THE PART TOP|TOUCH PLATE ON THE PART "
                                                    "UNDER IT, CLIP ON), RESUME"))
            << what;
        if (mix.options.find("probe-plate") != std::string::npos) {
          EXPECT_THAT(words, ::testing::HasSubstr("TAKE THE CLIP AND THE PLATE AWAY, RESUME.")) << what;
          EXPECT_THAT(words, ::testing::HasSubstr("TAKE THE PROBE CLIP AND THE TOUCH PLATE AWAY, RESUME")) << what;
        }
      }
      if (mix.options.find("tools.json") != std::string::npos) {
        EXPECT_THAT(words, ::testing::HasSubstr(long_name)) << what << ": the long name whole";
      }
    }
  }
}

// Issue 73: the setup sheet and the report name how the program makes each
// tool's holes in its dialect: a GRBL program has no G81.
TEST(cli_test, the_setup_sheet_and_report_name_the_cycle_the_program_really_runs) {
  testutil::TempDir t;
  spit(t / "a.csv", "x,y,d\n0,0,0.8\n10,0,0.8\n20,5,3.2\n");
  for (const std::string dialect : {"grbl", "marlin", "haas"}) {
    // The router with an end mill for GRBL and Marlin; HAAS on its own mill, drills only.
    const std::string machine = dialect == "haas" ? "" : " --machine router --drills 0.8 --end-mill 1.0";
    auto r = testutil::acodrill_run("plan " + (t / "a.csv") + " -o " + (t / "a.nc") + " -q --iterations 5 --dialect " + dialect +
                                    machine + " --setup-sheet " + (t / "s.html") + " --report " + (t / "r.json"));
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string program = slurp(t / "a.nc"), sheet = slurp(t / "s.html");
    const auto report = nlohmann::json::parse(slurp(t / "r.json"));
    for (const auto& tool : report["tools"]) {
      const std::string cycle = tool["cycle"];
      if (dialect == "haas") {
        EXPECT_THAT(cycle, ::testing::MatchesRegex("G8[123]|G73"));
        EXPECT_THAT(program, ::testing::HasSubstr(cycle + " X"));
        continue;
      }
      EXPECT_NE(cycle, "G81") << "a bare G81 the program does not contain";
      EXPECT_THAT(cycle, ::testing::StartsWith("G")) << cycle;
      EXPECT_THAT(program, ::testing::Not(::testing::HasSubstr("G81"))) << dialect;
      EXPECT_THAT(sheet, ::testing::HasSubstr(cycle)) << dialect;
      if (tool["kind"] == "end_mill") EXPECT_EQ(cycle, "G2 helix");
      else EXPECT_THAT(cycle, ::testing::StartsWith("G1 ")) << "drilled with G1 down, G0 out";
    }
  }
}

// Issue 73: the README says the filter is in build/bin after scripts/demo; the demo builds it.
TEST(cli_test, scripts_demo_builds_every_program_the_readme_places_in_build_bin) {
  const std::string demo = slurp(testutil::source_dir() + "/scripts/demo");
  const std::string readme = slurp(testutil::source_dir() + "/README.md");
  std::smatch targets;
  ASSERT_TRUE(std::regex_search(demo, targets, std::regex("BUILD_TARGETS=\"([^\"]*)\"")));
  ASSERT_THAT(readme, ::testing::HasSubstr("`acodrill-linuxcnc-filter` (built beside `acodrill` in `build/bin`"));
  for (const std::string program : {"acodrill", "acobench", "acodrill-linuxcnc-filter"}) {
    EXPECT_THAT(" " + targets[1].str() + " ", ::testing::HasSubstr(" " + program + " ")) << program;
  }
}

// Issue 85: only a regular file (or a name not taken yet) is replaced by a
// rename; a FIFO is written in place, and its reader gets the program.
TEST(cli_test, a_fifo_given_as_an_output_is_written_in_place_and_stays_a_fifo) {
  TempDir t;
  const std::string plate = q(testutil::source_dir() + "/samples/plate10.dxf");
  auto plain = acodrill_run("plan " + plate + " --iterations 20 -q -o " + q(t / "plain.nc") + " --report " + q(t / "plain.json"));
  ASSERT_EQ(plain.code, 0) << plain.err;
  for (const std::string option : {"-o", "--report"}) {
    ASSERT_EQ(::mkfifo((t / "pipe").c_str(), 0600), 0);
    // The reader is cat, started first; the writer's open waits for it (a minute at most: a FIFO
    // replaced by a file leaves cat waiting for a writer that never comes).
    const std::string other = option == "-o" ? " --report " + q(t / "r.json") : " -o " + q(t / "p.nc");
    auto r = testutil::run("timeout 60 cat " + q(t / "pipe") + " > " + q(t / "got") + " & " + q(testutil::acodrill()) + " plan " + plate +
                           " --iterations 20 -q " + option + " " + q(t / "pipe") + other + "; code=$?; wait; exit $code");
    EXPECT_EQ(r.code, 0) << option << ": " << r.err;
    struct stat st {};
    ASSERT_EQ(::lstat((t / "pipe").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << option << ": the FIFO was replaced";
    if (option == "-o") {
      EXPECT_EQ(slurp(t / "got"), slurp(t / "plain.nc"));
    } else {  // the same report but for the clock and the program's name
      auto got = nlohmann::json::parse(slurp(t / "got")), as_file = nlohmann::json::parse(slurp(t / "plain.json"));
      for (auto* j : {&got, &as_file}) {
        (*j)["solver"].erase("wall_s"), (*j)["solver"].erase("thread_busy_s"), j->erase("program");
      }
      EXPECT_EQ(got, as_file);
    }
    std::filesystem::remove(t / "pipe");
  }
}

TEST(cli_test, a_directory_given_as_an_output_is_one_line_before_any_work) {
  TempDir t;
  std::filesystem::create_directory(t / "out");
  const std::string plate = q(testutil::source_dir() + "/samples/plate70.dxf");
  for (const std::string option : {"-o", "--report", "--svg", "--setup-sheet"}) {
    // A minute of iterations: refused before them, or the test's own timeout says it was not.
    const std::string program = option == "-o" ? "" : " -o " + q(t / "p.nc");
    auto r = acodrill_run("plan " + plate + " --time-limit 60 --iterations 1000000 " + option + " " + q(t / "out") + program);
    EXPECT_EQ(r.code, 2) << option << ": " << r.err;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::StartsWith("acodrill: error: " + t / "out" + ": is a directory")) << option;
    EXPECT_TRUE(std::filesystem::is_directory(t / "out"));
    EXPECT_TRUE(std::filesystem::is_empty(t / "out"));
    EXPECT_FALSE(std::filesystem::exists(t / "p.nc")) << option << ": nothing is written when one output cannot be";
  }
  auto tsp = acodrill_run("tsp " + q(data("tsplib/d198.tsp")) + " --iterations 100000 --tour " + q(t / "out"));
  EXPECT_EQ(tsp.code, 2) << tsp.err;
  EXPECT_THAT(tsp.err, ::testing::HasSubstr("is a directory"));
}

// /dev/stdout names the descriptor the shell opened: the program goes there,
// appended after `>>` as any output is; a symbolic link stays a link.
TEST(cli_test, dev_stdout_and_a_symbolic_link_are_written_through) {
  TempDir t;
  const std::string plate = q(testutil::source_dir() + "/samples/plate10.dxf");
  ASSERT_EQ(acodrill_run("plan " + plate + " --iterations 20 -q -o " + q(t / "plain.nc")).code, 0);
  spit(t / "log", "before\n");
  auto r = testutil::run("(" + q(testutil::acodrill()) + " plan " + plate + " --iterations 20 -q -o /dev/stdout >> " + q(t / "log") + ")");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(t / "log"), "before\n" + slurp(t / "plain.nc"));
  spit(t / "target.nc", "old\n");
  std::filesystem::create_symlink(t / "target.nc", t / "link.nc");
  ASSERT_EQ(acodrill_run("plan " + plate + " --iterations 20 -q -o " + q(t / "link.nc")).code, 0);
  EXPECT_TRUE(std::filesystem::is_symlink(t / "link.nc"));
  EXPECT_EQ(slurp(t / "target.nc"), slurp(t / "plain.nc"));
}

// A character device, as root only: made by mknod in a temporary folder, and
// /dev/null itself inside a mount namespace of the test's own, where /dev is
// a fresh tmpfs holding a fresh null device; never the machine's /dev/null.
TEST(cli_test, a_character_device_is_written_in_place_never_replaced) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod and mount namespaces need root";
  TempDir t;
  const std::string plate = q(testutil::source_dir() + "/samples/plate10.dxf");
  if (::mknod((t / "null").c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) GTEST_SKIP() << "no device nodes here (nodev)";
  auto r = acodrill_run("plan " + plate + " --iterations 20 -q -o " + q(t / "null") + " --report " + q(t / "null"));
  EXPECT_EQ(r.code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::lstat((t / "null").c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "the device was replaced by a file";
  auto probe = testutil::run("unshare --mount --propagation private true");
  if (probe.code != 0) GTEST_SKIP() << "no mount namespace here: " << probe.err;
  auto ns = testutil::run("unshare --mount --propagation private sh -c " +
                          q("mount -t tmpfs tmpfs /dev && mknod -m 666 /dev/null c 1 3 && " + q(testutil::acodrill()) + " plan " +
                            plate + " --iterations 20 -q -o /dev/null --report /dev/null --svg /dev/null && test -c /dev/null && ls /dev"));
  EXPECT_EQ(ns.code, 0) << ns.err;
  EXPECT_EQ(ns.out, "null\n") << "/dev/null is still the device and nothing was left beside it";
}

// Issue 85: the demo says where each output went once, in its closing lines,
// and how to check the program; acodrill's own summary keeps its file lines
// for everyone else.
TEST(cli_test, scripts_demo_names_each_output_once_and_the_command_to_check_it) {
  TempDir t;
  auto r = testutil::run("ACO_BUILD_DIR=" + q(ACO_BUILD_DIR) + " ACO_DEMO_OUT=" + q(t / "out") + " " +
                         q(testutil::source_dir() + "/scripts/demo"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string said = r.out + r.err;
  for (const std::string file : {"plate70.nc", "plate70.json", "plate70.convergence.csv", "plate70.svg", "plate70.compare.svg",
                                 "plate70.setup.html"}) {
    const std::string path = t / "out/" + file;
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
    std::size_t times = 0;
    for (std::size_t at = said.find(path); at != std::string::npos; at = said.find(path, at + 1)) ++times;
    EXPECT_EQ(times, file == "plate70.nc" ? 2u : 1u) << file << " in:\n" << said;  // the program: where, and in the check
  }
  EXPECT_THAT(said, ::testing::HasSubstr("acodrill verify " + t / "out/plate70.nc --holes samples/plate70.dxf"));
  EXPECT_THAT(said, ::testing::HasSubstr("saved vs input order"));  // acodrill's summary, the rest of it
  // And the summary still names its files for everyone else.
  auto plan = acodrill_run("plan " + q(testutil::source_dir() + "/samples/plate10.dxf") + " --iterations 5 -o " + q(t / "p.nc"));
  EXPECT_THAT(plan.err, ::testing::HasSubstr("  program: " + t / "p.nc"));
}
