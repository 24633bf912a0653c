// An independent oracle: LinuxCNC's own interpreter (rs274, Debian package
// linuxcnc-uspace, installed by scripts/test) reads every program back, and
// the holes it drills must equal the input holes and what `verify` reports.
// Recipe: ../shared/gcode.md section 3.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "gcode/interpreter.h"
#include "test_util.h"

namespace {

struct CanonRun {
  struct Hole {
    int tool;
    double x, y, z;  // canon units times the scale read_canon was given
  };
  std::vector<Hole> holes;
  double rapid_xy_mm = 0.0;
  double xy_mm = 0.0;              // XY length of every move, rapid or feed
  std::vector<std::string> unsafe;  // XY moves that cut (feeds) or run at or below Z 0, as rs274 printed them
};

// A hole: downward STRAIGHT_FEEDs at one XY, begun after the XY or the tool
// changed or after a rapid that went nowhere (a "G0 X Y" to the same place:
// the same position drilled again).
CanonRun read_canon(const std::string& canon, double scale) {
  CanonRun out;
  static const std::regex call(R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|SELECT_TOOL)\(([^)]*)\))");
  int tool = 0;
  double x = 0, y = 0, z = 0;
  bool fresh = true;
  std::istringstream in(canon);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, call)) continue;
    if (m[1] == "SELECT_TOOL") {
      tool = std::stoi(m[2]);
      fresh = true;
      continue;
    }
    std::vector<double> v;
    std::istringstream args(m[2]);
    for (std::string a; std::getline(args, a, ',');) v.push_back(std::stod(a) * scale);
    const bool xy_moved = std::fabs(v[0] - x) > 1e-9 || std::fabs(v[1] - y) > 1e-9;
    if (xy_moved) {
      out.xy_mm += std::hypot(v[0] - x, v[1] - y);
      if (m[1] != "STRAIGHT_TRAVERSE" || std::min(z, v[2]) <= 1e-9) out.unsafe.push_back(line);
    }
    if (m[1] == "STRAIGHT_TRAVERSE") {
      out.rapid_xy_mm += std::hypot(v[0] - x, v[1] - y);
      if (xy_moved || std::fabs(v[2] - z) <= 1e-9) fresh = true;
    } else if (xy_moved) {
      fresh = true;
    } else if (v[2] < z - 1e-9) {
      if (fresh) out.holes.push_back({tool, v[0], v[1], v[2]});
      fresh = false;
      out.holes.back().z = std::min(out.holes.back().z, v[2]);
    }
    x = v[0];
    y = v[1];
    z = v[2];
  }
  return out;
}

bool have_rs274() { return std::system("command -v rs274 >/dev/null 2>&1") == 0; }

// The documented HAAS -> LinuxCNC word mapping (../shared/gcode.md, section 2):
// G82's P is integer milliseconds on a HAAS and seconds in LinuxCNC. Every
// other word acodrill writes for HAAS reads the same in LinuxCNC.
std::string haas_to_linuxcnc(const std::string& haas) {
  static const std::regex g82_dwell(R"((G82[^\n]*) P(\d+))");
  std::string out;
  std::sregex_iterator it(haas.begin(), haas.end(), g82_dwell), end;
  std::size_t last = 0;
  for (; it != end; ++it) {
    out += haas.substr(last, static_cast<std::size_t>(it->position()) - last);
    out += (*it)[1].str() + " P" + std::to_string(std::stod((*it)[2].str()) / 1000.0);
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + haas.substr(last);
}

void check_program(const std::string& program_path, const std::string& sample, bool inch, const std::string& what,
                   std::string holes_csv = "") {
  testutil::TempDir t;
  // A tool table naming every T/H number the program uses.
  const std::string prog = testutil::slurp(program_path);
  std::string table;
  static const std::regex tool_word(R"(\bT(\d+))");
  std::set<std::string> tools;
  for (std::sregex_iterator it(prog.begin(), prog.end(), tool_word), end; it != end; ++it) tools.insert((*it)[1].str());
  for (const std::string& n : tools) table += "T" + n + " P" + n + " Z0 D1\n";
  testutil::spit(t / "tool.tbl", table);
  auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g " + testutil::shell_quote(program_path));
  ASSERT_EQ(r.code, 0) << what << ": rs274 rejected the program:\n" << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  const CanonRun canon_run = read_canon(r.out, 1.0);  // program units
  const std::vector<CanonRun::Hole>& canon = canon_run.holes;
  // Every dialect acodrill writes travels with rapids only, above the part
  // (where the program says where Z is: rs274 puts machine Z home, G53/G28, at Z 0).
  const bool z_known = prog.find("G53") == std::string::npos && prog.find("G28") == std::string::npos;
  EXPECT_TRUE(!z_known || canon_run.unsafe.empty()) << what << ": an XY move that cuts or runs at or below Z0: " << canon_run.unsafe[0];
  if (holes_csv.empty()) holes_csv = sample.substr(0, sample.size() - 4) + ".holes.csv";
  aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(holes_csv));
  ASSERT_EQ(canon.size(), expected.size()) << what;
  // Programs put X0 Y0 at the lower left of the holes by default (--origin).
  testutil::move_lower_left_to_zero(expected);
  // Same multiset of positions (within half the last printed digit), and the
  // same holes, in the same order, with the same tools as our interpreter sees.
  const double scale = inch ? 25.4 : 1.0;
  const double tol = (inch ? 0.00005 * 25.4 : 0.0005) + 1e-6;  // half the last digit, and float noise at exactly half
  gcode::Interpretation ours = gcode::interpret(prog);
  ASSERT_EQ(ours.holes.size(), canon.size()) << what;
  std::vector<char> used(expected.size(), 0);
  for (std::size_t i = 0; i < canon.size(); ++i) {
    EXPECT_EQ(canon[i].tool, ours.holes[i].tool) << what << " hole " << i;
    EXPECT_NEAR(canon[i].x * scale, ours.holes[i].x_mm, tol) << what << " hole " << i;
    EXPECT_NEAR(canon[i].y * scale, ours.holes[i].y_mm, tol) << what << " hole " << i;
    bool found = false;
    for (std::size_t j = 0; j < expected.size() && !found; ++j) {
      if (!used[j] && std::fabs(expected[j].center.x - canon[i].x * scale) <= tol &&
          std::fabs(expected[j].center.y - canon[i].y * scale) <= tol) {
        used[j] = 1;
        found = true;
      }
    }
    EXPECT_TRUE(found) << what << ": rs274 drills (" << canon[i].x << ", " << canon[i].y << "), not an input hole";
  }
}

}  // namespace

TEST(linuxcnc_test, rs274_reads_every_sample_program_back) {
  ASSERT_TRUE(have_rs274()) << "rs274 missing: scripts/test installs linuxcnc-uspace";
  testutil::TempDir t;
  for (const auto& e : std::filesystem::directory_iterator(testutil::source_dir() + "/samples")) {
    if (e.path().extension() != ".dxf") continue;
    const std::string sample = e.path().string();
    for (const char* dialect : {"linuxcnc", "haas"}) {
      for (const char* units : {"mm", "inch"}) {
        const std::string nc = t / "p.nc";
        std::string extra = std::string(" --dialect ") + dialect + " --units " + units;
        if (sample.find("pcb") != std::string::npos) extra += " --material pcb --thickness 1.6";
        auto r = testutil::acodrill_run("plan " + testutil::shell_quote(sample) + " -o " + testutil::shell_quote(nc) +
                                        " -q --iterations 20" + extra);
        ASSERT_EQ(r.code, 0) << r.err;
        check_program(nc, sample, std::string(units) == "inch", sample + extra);
      }
    }
  }
}

TEST(linuxcnc_test, peck_cycles_read_back_as_one_hole_each) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  // Steel, 1/4" plate: the 0.4 mm vias get G83 pecks.
  const std::string sample = testutil::source_dir() + "/samples/pcb_mixed.dxf";
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(sample) + " -o " + testutil::shell_quote(t / "p.nc") +
                                  " -q --dialect linuxcnc --iterations 10");
  ASSERT_EQ(r.code, 0);
  ASSERT_THAT(testutil::slurp(t / "p.nc"), ::testing::HasSubstr("G83"));
  check_program(t / "p.nc", sample, false, "G83");
}

TEST(linuxcnc_test, every_cycle_and_clamp_retracts_read_back) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  const std::string sample = testutil::source_dir() + "/samples/pcb_mixed.dxf";
  const std::string tools = testutil::data("tools_all_cycles.json");
  // A clamp across the middle of the board makes G98/G99 switch between holes.
  testutil::spit(t / "machine.json", R"({"clamps": [{"x_min_mm": 32.5, "y_min_mm": -10, "x_max_mm": 33.5, "y_max_mm": 60}]})");
  for (const char* dialect : {"linuxcnc", "haas"}) {
    const std::string nc = t / (std::string(dialect) + ".nc");
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(sample) + " -o " + testutil::shell_quote(nc) +
                                    " -q --iterations 10 --tools " + testutil::shell_quote(tools) + " --machine " +
                                    testutil::shell_quote(t / "machine.json") + " --dialect " + dialect);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string prog = testutil::slurp(nc);
    for (const char* word : {"G73", "G82", "G83", "G81", "G98", "G99"}) {
      EXPECT_THAT(prog, ::testing::HasSubstr(word)) << dialect;
    }
    if (std::string(dialect) == "haas") {
      EXPECT_THAT(prog, ::testing::HasSubstr(" P250 ")) << "HAAS dwell in integer milliseconds";
      testutil::spit(nc, haas_to_linuxcnc(prog));
      EXPECT_THAT(testutil::slurp(nc), ::testing::HasSubstr(" P0.25"));
    } else {
      EXPECT_THAT(prog, ::testing::HasSubstr(" P0.250 ")) << "LinuxCNC dwell in seconds";
    }
    check_program(nc, sample, false, std::string("all cycles, ") + dialect);
    auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(sample) + " -q");
    EXPECT_EQ(v.code, 0) << v.out;
  }
}

// Issue 13: every drawing whose holes fit a VF-2's table (762 x 406 mm, tool
// edges included) plans with default options wherever it sits in CAD space,
// and rs274 reads the program back to the input holes moved to the lower left;
// every other drawing is refused in one line naming both sizes.
// The test's own reading of issue 82's rule on ezdxf's circles: circles whose
// centres lie within 0.01 mm are one hole feature, its smallest circle the hole.
aco::HoleSet smallest_of_concentric(const aco::HoleSet& circles) {
  aco::HoleSet out;
  for (const aco::Hole& c : circles) {
    auto same = std::find_if(out.begin(), out.end(), [&](const aco::Hole& h) { return aco::euclidean(h.center, c.center) <= 0.01; });
    if (same == out.end()) out.push_back(c);
    else if (c.diameter < same->diameter) *same = c;
  }
  return out;
}

TEST(linuxcnc_test, every_fixture_drawing_that_fits_the_machine_plans_wherever_it_sits) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  int planned = 0, refused = 0;
  for (const char* dir : {"dxf", "real-dxf"}) {
    for (const auto& e : std::filesystem::directory_iterator(testutil::data(dir))) {
      if (e.path().extension() != ".dxf") continue;
      const std::string drawing = e.path().string();
      const std::string csv = drawing.substr(0, drawing.size() - 4) + ".holes.csv";
      if (!std::filesystem::exists(csv)) continue;
      // Issue 82: of concentric circles only the smallest is a hole drilled through.
      const aco::HoleSet holes = smallest_of_concentric(testutil::read_holes_csv(testutil::slurp(csv)));
      if (holes.empty()) continue;
      const std::string expected_csv = t / "expected.csv";
      std::string rows = "x_mm,y_mm,diameter_mm,layer\n";
      for (const aco::Hole& h : holes) rows += std::to_string(h.center.x) + "," + std::to_string(h.center.y) + "," + std::to_string(h.diameter) + ",\n";
      testutil::spit(expected_csv, rows);
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (const aco::Hole& h : holes) {
        x0 = std::min(x0, h.center.x - h.diameter / 2);
        x1 = std::max(x1, h.center.x + h.diameter / 2);
        y0 = std::min(y0, h.center.y - h.diameter / 2);
        y1 = std::max(y1, h.center.y + h.diameter / 2);
      }
      const bool fits = x1 - x0 <= 762.0 && y1 - y0 <= 406.0;
      const std::string nc = t / "p.nc";
      std::filesystem::remove(nc);
      auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drawing) + " -o " + testutil::shell_quote(nc) +
                                      " -q --iterations 10");
      if (!fits) {
        EXPECT_EQ(r.code, 2) << drawing;
        EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
        EXPECT_THAT(r.err, ::testing::HasSubstr("the machine travels 762.000 x 406.000 mm")) << drawing;
        const bool turned = y1 - y0 <= 762.0 && x1 - x0 <= 406.0;
        EXPECT_EQ(r.err.find("turned by 90 degrees") != std::string::npos, turned) << r.err;
        EXPECT_FALSE(std::filesystem::exists(nc));
        ++refused;
        continue;
      }
      ASSERT_EQ(r.code, 0) << drawing << ": " << r.err;
      check_program(nc, drawing, false, drawing, expected_csv);
      auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(drawing) + " -q");
      EXPECT_EQ(v.code, 0) << drawing << ": " << v.out;
      ++planned;
    }
  }
  EXPECT_GE(planned, 15);
  EXPECT_GE(refused, 4);
}

TEST(linuxcnc_test, a_larger_machine_plans_what_a_vf2_refuses_and_origins_move_the_program) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  const std::string drawing = testutil::data("dxf/r2010_blocks.dxf");  // 419 x 586 mm: too deep for a VF-2
  testutil::spit(t / "vf5.json", R"({"name": "VF-5/50", "x_max_mm": 1270, "y_max_mm": 660})");
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(drawing) + " -o " + testutil::shell_quote(t / "p.nc") +
                                  " -q --iterations 10 --machine " + testutil::shell_quote(t / "vf5.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  check_program(t / "p.nc", drawing, false, "VF-5");

  // A part drawn a million mm from the drawing's zero: every origin gives the
  // same holes, moved; `drawing` keeps CAD coordinates.
  const std::string far = testutil::data("dxf/r2010_far_offset.dxf");
  const aco::HoleSet holes = testutil::read_holes_csv(testutil::slurp(testutil::data("dxf/r2010_far_offset.holes.csv")));
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const aco::Hole& h : holes) {
    x0 = std::min(x0, h.center.x), x1 = std::max(x1, h.center.x);
    y0 = std::min(y0, h.center.y), y1 = std::max(y1, h.center.y);
  }
  const std::vector<std::pair<std::string, aco::Point2>> origins = {
      {"drawing", {0, 0}}, {"lower-left", {x0, y0}}, {"center", {(x0 + x1) / 2, (y0 + y1) / 2}},
      {"upper-left", {x0, y1}}, {"1000000,-2000000", {1000000, -2000000}}};
  for (const auto& [origin, zero] : origins) {
    const std::string nc = t / "far.nc";
    auto p = testutil::acodrill_run("plan " + testutil::shell_quote(far) + " -o " + testutil::shell_quote(nc) +
                                    " -q --iterations 10 --dialect linuxcnc --origin " + origin);
    ASSERT_EQ(p.code, 0) << origin << ": " << p.err;
    const std::string prog = testutil::slurp(nc);
    // The operator reads where the holes are from the header.
    EXPECT_THAT(prog, ::testing::HasSubstr("(ORIGIN: ")) << origin;
    EXPECT_THAT(prog, ::testing::ContainsRegex(R"(EXTENT X-?[0-9.]+\.\.-?[0-9.]+ Y-?[0-9.]+\.\.-?[0-9.]+ MM\))")) << origin;
    gcode::Interpretation run = gcode::interpret(prog);
    ASSERT_EQ(run.holes.size(), holes.size());
    for (const gcode::DrilledHole& d : run.holes) {
      bool found = false;
      for (const aco::Hole& h : holes) {
        found = found || (std::fabs(h.center.x - zero.x - d.x_mm) <= 0.0006 && std::fabs(h.center.y - zero.y - d.y_mm) <= 0.0006);
      }
      EXPECT_TRUE(found) << origin << ": (" << d.x_mm << ", " << d.y_mm << ")";
    }
    // verify follows the program's stated zero, or the --origin it is given.
    auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(far) + " -q");
    EXPECT_EQ(v.code, 0) << origin << ": " << v.out;
    auto v2 = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(far) +
                                     " -q --origin " + origin);
    EXPECT_EQ(v2.code, 0) << origin << ": " << v2.out;
  }
}

// Issue 16: a Gerber drill file planned; rs274 reads the program back to the
// holes the independent reader found in it (slots skipped: the list holds
// round flashes only).
TEST(linuxcnc_test, gerber_drill_files_plan_to_programs_rs274_reads_back) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  for (const char* input : {"real-gerber/ucamco_ex2_Plated_1-10_PTH_Drill.gbr",
                            "real-gerber/kicad/flat_hierarchy/x2_mm46/flat_hierarchy-PTH-drl.gbr"}) {
    const std::string in = testutil::data(input);
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(in) + " -o " + testutil::shell_quote(t / "p.nc") +
                                    " -q --iterations 10 --slots skip --dialect linuxcnc");
    ASSERT_EQ(r.code, 0) << r.err;
    check_program(t / "p.nc", in, false, input, in + ".holes.csv");
  }
}

// Issue 14: other CAMs' drilling programs, reordered. rs274 reads each output
// to exactly the holes it reads from the input (tests/data/real-gcode/
// NAME.holes.csv: position, deepest Z, tool), and its XY rapid travel is no
// longer than the input's as rs274 runs that.
namespace {

// What makes a real program readable by rs274, as for the fixtures' own hole
// lists (../shared/fixtures/real-gcode/README.md): no byte-order mark, no "%"
// comment lines, a G0 before bare axis words after G80, a program end.
std::string for_rs274(std::string text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  std::istringstream in(text);
  std::string out;
  bool after_g80 = false, ended = false;
  static const std::regex g80(R"(G80\b)"), motion(R"(\bG0*[0-3]\b|\bG8[1-9]\b|\bG7[34]\b)"), bare_axis(R"(^\s*(N\d+\s*)?[XYZ][-+.\d])");
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line[0] == '%' && line.find_first_not_of("% \t") != std::string::npos) continue;
    if (after_g80 && std::regex_search(line, bare_axis)) line = "G0 " + line;
    if (std::regex_search(line, g80)) after_g80 = true;
    else if (std::regex_search(line, motion)) after_g80 = false;
    if (std::regex_search(line, std::regex(R"(\bM0*(2|30)\b)"))) ended = true;
    out += line + "\n";
  }
  if (!ended && out.find("%") == std::string::npos) out += "M2\n";
  return out;
}

CanonRun run_rs274(const std::string& program_text, double scale, const std::string& what) {
  testutil::TempDir t;
  std::string table;
  static const std::regex tool_word(R"(\bT(\d+))");
  std::set<std::string> tools;
  for (std::sregex_iterator it(program_text.begin(), program_text.end(), tool_word), end; it != end; ++it) {
    tools.insert((*it)[1].str());
  }
  for (const std::string& n : tools) table += "T" + n + " P" + n + " Z0 D1\n";
  testutil::spit(t / "tool.tbl", table);
  testutil::spit(t / "p.ngc", for_rs274(program_text));
  auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g p.ngc");
  EXPECT_EQ(r.code, 0) << what << ": rs274 rejected the program:\n" << r.err;
  return read_canon(r.out, scale);
}

std::vector<CanonRun::Hole> sorted(std::vector<CanonRun::Hole> h) {
  std::sort(h.begin(), h.end(), [](const CanonRun::Hole& a, const CanonRun::Hole& b) {
    return std::tie(a.tool, a.x, a.y, a.z) < std::tie(b.tool, b.x, b.y, b.z);
  });
  return h;
}

class ReorderedProgram : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(ReorderedProgram, rs274_reads_the_same_holes_tools_and_depths_and_no_longer_travel) {
  ASSERT_TRUE(have_rs274());
  const std::string input = GetParam();
  const std::string input_text = testutil::slurp(input);
  const bool inch = input_text.find("G20") != std::string::npos;
  const double scale = inch ? 25.4 : 1.0;
  const CanonRun before = run_rs274(input_text, scale, input);
  // The fixture's own list of what rs274 drills: our reading of the input must match it first.
  const aco::HoleSet listed = testutil::read_holes_csv(testutil::slurp(input.substr(0, input.find_last_of('.')) + ".holes.csv"));
  ASSERT_EQ(before.holes.size(), listed.size()) << input;
  testutil::TempDir t;
  for (const char* mode : {"--dialect haas", "--dialect linuxcnc", "--keep-style", "--dialect fanuc --units inch"}) {
    const std::string what = input + " " + mode;
    const std::string out = t / "out.nc";
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(input) + " -o " + out + " -q --iterations 50 " + mode);
    ASSERT_EQ(r.code, 0) << what << "\n" << r.err;
    const std::string text = testutil::slurp(out);
    const double out_scale = text.find("G20") != std::string::npos ? 25.4 : 1.0;
    const CanonRun after = run_rs274(text, out_scale, what);
    auto b_holes = after.holes;
    if (testutil::tools_only_in_comments(input_text)) {
      for (auto& h : b_holes) h.tool = 0;  // rs274 saw no tool in the input: its changes are comments (issue 83)
    }
    const auto a = sorted(before.holes), b = sorted(b_holes);
    ASSERT_EQ(a.size(), b.size()) << what;
    const double tol = 0.00005 * 25.4 + 0.0005;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].tool, b[i].tool) << what << " hole " << i;
      EXPECT_NEAR(a[i].x, b[i].x, tol) << what << " hole " << i;
      EXPECT_NEAR(a[i].y, b[i].y, tol) << what << " hole " << i;
      EXPECT_NEAR(a[i].z, b[i].z, tol) << what << " hole " << i;
    }
    EXPECT_LE(after.rapid_xy_mm, before.rapid_xy_mm + 1e-3) << what;
  }
}


INSTANTIATE_TEST_SUITE_P(real_gcode, ReorderedProgram, ::testing::ValuesIn(testutil::real_gcode_programs()),
                         [](const auto& test_param) { return testutil::file_param_name(test_param.param); });

// Issue 23: GRBL and Marlin. GRBL's own parser (tests/grbl-sim, built by the
// gvalidate target) must accept every line of every grbl program; Marlin
// programs may hold only what Marlin's documented G-code has for a spindle
// machine; LinuxCNC's rs274 reads both back to the input holes.
namespace {

std::string gvalidate() { return std::string(ACO_BUILD_DIR) + "/grbl/gvalidate.exe"; }

// GRBL's answer to the program run in check mode ($C: every line parsed and
// executed as on a machine, but nothing moves and M0 does not wait for the
// operator): empty when it accepted every line, else its refusal.
std::string grbl_refusal(const std::string& program_text) {
  testutil::TempDir t;
  testutil::spit(t / "p.nc", "$C\n" + program_text);
  // From a directory of its own: the simulator keeps its settings in ./EEPROM.DAT.
  auto r = testutil::run("cd " + testutil::shell_quote(t.path()) + " && timeout 120 " + testutil::shell_quote(gvalidate()) +
                         " p.nc");
  if (r.code == 0 && r.out.find("error") == std::string::npos) return "";
  std::istringstream in(program_text);
  std::string refused = r.out.substr(r.out.find("error") == std::string::npos ? 0 : r.out.find("error"), 40);
  // gvalidate answers one "ok" per line: the refused line is the one after the last ok.
  const auto oks = static_cast<std::size_t>(std::count(r.out.begin(), r.out.end(), '\n'));
  std::string line;
  for (std::size_t i = 0; i + 1 < oks && std::getline(in, line);) ++i;
  return "gvalidate exit " + std::to_string(r.code) + ": " + refused + " near: " + line;
}

// Marlin's documented G-code for a machine with a spindle: G0 G1 (X Y Z F),
// G4 (P ms or S s), G20 G21 G90, M0/M1 with a message, M3/M4 (S), M5, and
// comments after ';' (parentheses only with PAREN_COMMENTS built in). No N
// (it wants a checksum), no T (an extruder), no M2 or M30 (M30 deletes a file).
std::string marlin_refusal(const std::string& program_text) {
  static const std::regex allowed(
      R"(^(G0( [XYZF]-?[0-9.]+)+|G1( [XYZF]-?[0-9.]+)+|G4 [PS][0-9.]+|G2[01] G90|G2[01]|G90|M[01]( .*)?|M[34]( S[0-9]+)?|M5)$)");
  std::istringstream in(program_text);
  int no = 0;
  for (std::string line; std::getline(in, line);) {
    ++no;
    const std::string code = line.substr(0, line.find(';'));
    if (code.empty()) continue;
    if (!std::regex_match(code, allowed) || code.find('(') != std::string::npos) {
      return "line " + std::to_string(no) + ": " + line;
    }
  }
  return "";
}

// What rs274 needs of a Marlin program: its pause messages set aside and a program end.
std::string marlin_for_rs274(const std::string& text) {
  return std::regex_replace(text, std::regex(R"(^(M[01]) .*$)", std::regex::multiline), "$1") + "M2\n";
}

}  // namespace

TEST(linuxcnc_test, grbl_and_marlin_programs_from_hole_files_are_accepted_and_read_back) {
  ASSERT_TRUE(have_rs274());
  ASSERT_TRUE(std::filesystem::exists(gvalidate())) << "the gvalidate target builds it";
  testutil::TempDir t;
  struct Case {
    std::string input, holes_csv, extra;
    bool inch_too = true;  // the KiCad list is 0.00003 mm finer than its drill file: inch rounding on top exceeds half a digit
  };
  const std::string root = testutil::source_dir();
  const std::vector<Case> cases = {
      {root + "/samples/plate10.dxf", "", "", true},
      // Steel by default: the 0.4 mm vias are pecked (G83 written out as moves).
      {root + "/samples/pcb_mixed.dxf", "", "", true},
      {testutil::data("kicad/StickHub-mm-decimal.drl"), testutil::data("kicad/StickHub.holes.csv"), " --slots skip", false},
      {testutil::data("real-gerber/kicad/flat_hierarchy/x2_mm46/flat_hierarchy-PTH-drl.gbr"),
       testutil::data("real-gerber/kicad/flat_hierarchy/x2_mm46/flat_hierarchy-PTH-drl.gbr.holes.csv"), " --slots skip", true},
  };
  for (const Case& c : cases) {
    for (const char* dialect : {"grbl", "marlin"}) {
      for (const char* units : {"mm", "inch"}) {
        if (!c.inch_too && std::string(units) == "inch") continue;
        const std::string what = c.input + " " + dialect + " " + units;
        const std::string nc = t / "p.nc";
        auto r = testutil::acodrill_run("plan " + testutil::shell_quote(c.input) + " -o " + testutil::shell_quote(nc) +
                                        " -q --iterations 20 --dialect " + dialect + " --units " + units + c.extra);
        ASSERT_EQ(r.code, 0) << what << ": " << r.err;
        const std::string prog = testutil::slurp(nc);
        // No canned cycle, tool change or length offset anywhere.
        for (const char* word : {"G81", "G83", "G98", "G99", "M6", "M06", "G43", "G53", "%"}) {
          EXPECT_EQ(prog.find(word), std::string::npos) << what << " writes " << word;
        }
        std::string as_rs274 = nc;
        if (std::string(dialect) == "grbl") {
          EXPECT_EQ(grbl_refusal(prog), "") << what;
          EXPECT_THAT(prog, ::testing::HasSubstr("(MSG, PUT IN T1 ")) << what;
        } else {
          EXPECT_EQ(marlin_refusal(prog), "") << what;
          EXPECT_THAT(prog, ::testing::HasSubstr("\nM0 PUT IN T1 ")) << what;
          as_rs274 = t / "marlin.ngc";
          testutil::spit(as_rs274, marlin_for_rs274(prog));
        }
        check_program(as_rs274, c.input, std::string(units) == "inch", what, c.holes_csv);
        // verify reads the program as written (Marlin's messages name the tools).
        auto v = testutil::acodrill_run("verify " + testutil::shell_quote(nc) + " --holes " + testutil::shell_quote(c.input) +
                                        " -q" + c.extra);
        EXPECT_EQ(v.code, 0) << what << ": " << v.out;
        if (std::string(dialect) == "marlin") {
          EXPECT_THAT(v.out, ::testing::Not(::testing::HasSubstr("tool 0 "))) << what << ": tools named in the pauses";
        }
      }
    }
  }
}

// Issue 23: other CAMs' programs — the real ones of tests/data/real-gcode and
// the hobby-post styles of tests/data/hobby (G1 travel above the part, "%"
// note lines) — reordered for GRBL and Marlin: GRBL accepts every line, and
// rs274 reads the same holes (position, deepest Z, tool where the dialect
// has T words) from input and output, with no XY move that cuts or runs at
// or below Z 0, and no longer XY path.
namespace {

std::vector<std::string> programs_for_hobby_dialects() {
  std::vector<std::string> out = testutil::real_gcode_programs();
  for (const char* name : {"g1_travel_grbl.nc", "g1_travel_low_clearance.nc", "percent_notes.nc"}) {
    out.push_back(testutil::data(std::string("hobby/") + name));
  }
  return out;
}

// "%" lines set aside: rs274 stops at the second one, where a hobby sender reads on.
std::string without_percent_lines(const std::string& text) {
  return std::regex_replace(text, std::regex(R"(^%[^\n]*\n)", std::regex::multiline), "");
}

class HobbyDialect : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(HobbyDialect, reordered_for_grbl_and_marlin_drills_the_same_holes) {
  ASSERT_TRUE(have_rs274());
  const std::string input = GetParam();
  const std::string input_text = testutil::slurp(input);
  const double scale = input_text.find("G20") != std::string::npos ? 25.4 : 1.0;
  const CanonRun before = run_rs274(without_percent_lines(input_text), scale, input);
  ASSERT_FALSE(before.holes.empty()) << input;
  const bool hobby_style = input.find("/hobby/") != std::string::npos;
  std::vector<std::string> modes = {"--dialect grbl", "--dialect marlin", "--dialect grbl --units inch"};
  if (hobby_style) modes.insert(modes.end(), {"--keep-style", "--dialect linuxcnc"});
  testutil::TempDir t;
  for (const std::string& mode : modes) {
    const std::string what = input + " " + mode;
    const std::string out = t / "out.nc";
    auto r = testutil::acodrill_run("plan " + testutil::shell_quote(input) + " -o " + out + " -q --iterations 30 " + mode);
    ASSERT_EQ(r.code, 0) << what << "\n" << r.err;
    std::string text = without_percent_lines(testutil::slurp(out));  // --keep-style keeps the input's
    const bool marlin = mode.find("marlin") != std::string::npos;
    if (mode.find("grbl") != std::string::npos) {
      EXPECT_EQ(grbl_refusal(text), "") << what;
    }
    if (marlin) {
      EXPECT_EQ(marlin_refusal(text), "") << what;
      text = marlin_for_rs274(text);
    }
    const CanonRun after = run_rs274(text, text.find("G20") != std::string::npos ? 25.4 : 1.0, what);
    auto a = before.holes, b = after.holes;
    if (marlin) {
      for (auto& h : a) h.tool = 0;  // Marlin has no T word for a spindle; its pauses name the drill
    }
    if (testutil::tools_only_in_comments(testutil::slurp(input))) {
      for (auto& h : b) h.tool = 0;  // rs274 saw no tool in the input: its changes are comments (issue 83)
    }
    a = sorted(a);
    b = sorted(b);
    ASSERT_EQ(a.size(), b.size()) << what;
    const double tol = 0.00005 * 25.4 + 0.0005;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].tool, b[i].tool) << what << " hole " << i;
      EXPECT_NEAR(a[i].x, b[i].x, tol) << what << " hole " << i;
      EXPECT_NEAR(a[i].y, b[i].y, tol) << what << " hole " << i;
      EXPECT_NEAR(a[i].z, b[i].z, tol) << what << " hole " << i;
    }
    // (rs274 puts machine Z home, G53 in the other dialects, at Z 0: only these two say where Z is throughout.)
    if (mode.find("grbl") != std::string::npos || marlin) {
      EXPECT_TRUE(after.unsafe.empty()) << what << ": " << after.unsafe[0];
    }
    EXPECT_LE(after.xy_mm, before.xy_mm + 1e-3) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(hobby, HobbyDialect, ::testing::ValuesIn(programs_for_hobby_dialects()),
                         [](const auto& test_param) { return testutil::file_param_name(test_param.param); });

// A hobby post's G1 travel is travel only above the part: a G1 in X/Y at
// the part's depth is a cut, refused naming its line; a program whose end
// comes before its holes says so; a drilled-twice hole is counted, not lost.
TEST(linuxcnc_test, hobby_programs_say_what_they_are) {
  testutil::TempDir t;
  auto cut = testutil::acodrill_run("plan " + testutil::shell_quote(testutil::data("hobby/g1_cut.nc")) + " -o " +
                                    testutil::shell_quote(t / "o.nc"));
  EXPECT_EQ(cut.code, 2);
  EXPECT_THAT(cut.err, ::testing::HasSubstr("g1_cut.nc:9: G1 moves in X/Y at Z-0.500"));
  EXPECT_FALSE(std::filesystem::exists(t / "o.nc"));
  auto early = testutil::acodrill_run("plan " + testutil::shell_quote(testutil::data("hobby/ends_early.nc")) + " -o " +
                                      testutil::shell_quote(t / "o.nc"));
  EXPECT_EQ(early.code, 2);
  EXPECT_THAT(early.err, ::testing::HasSubstr("ends_early.nc:5: no holes to drill before the program ends here (M30)"));
  EXPECT_EQ(testutil::count_lines(early.err), 1);
  auto notes = testutil::acodrill_run("plan " + testutil::shell_quote(testutil::data("hobby/percent_notes.nc")) + " -o " +
                                      testutil::shell_quote(t / "o.nc") + " --iterations 10");
  EXPECT_EQ(notes.code, 0) << notes.err;
  EXPECT_THAT(notes.err, ::testing::HasSubstr("11 holes from g-code program"));
  // A GRBL sender's system commands ($H, $X) in a program are read past, named in a warning.
  testutil::spit(t / "homed.nc", "$H\n$X\nG21 G90\nM3 S9000\nG0 Z5\nG0 X10 Y10\nG1 Z-1.5 F100\nG0 Z5\nG0 X20 Y10\nG1 Z-1.5\nG0 Z5\nM5\n");
  auto homed = testutil::acodrill_run("plan " + testutil::shell_quote(t / "homed.nc") + " -o " + testutil::shell_quote(t / "o.nc") +
                                      " --iterations 10 --dialect grbl");
  EXPECT_EQ(homed.code, 0) << homed.err;
  EXPECT_THAT(homed.err, ::testing::HasSubstr("2 holes from g-code program; 2 warnings, first: 1: GRBL system command \"$H\""));
  // pcb2gcode drills one of Easy-SDR's 722 holes twice: the summary and the plan agree.
  const std::string sdr = testutil::data("real-gcode/pcb2gcode_Easy-SDR_HF_Upconverter_SMD_Gerbers.drill.ngc");
  auto p = testutil::acodrill_run("plan " + testutil::shell_quote(sdr) + " -o " + testutil::shell_quote(t / "o.nc") +
                                  " --iterations 10");
  EXPECT_EQ(p.code, 0) << p.err;
  EXPECT_THAT(p.err, ::testing::HasSubstr("722 holes from g-code program, 1 drilled again at the same place"));
  EXPECT_THAT(p.err, ::testing::HasSubstr("acodrill: 722 holes,"));
  auto h = testutil::acodrill_run("holes " + testutil::shell_quote(sdr));
  EXPECT_EQ(testutil::count_lines(h.out), 722) << "header and 721 positions";
  EXPECT_THAT(h.err, ::testing::HasSubstr("721 holes from g-code program, 1 duplicates removed"));
}

// Issue 25: the PCB shop's job. KiCad writes plated and non-plated holes to
// two files; planned together they make one program that rs274 reads back to
// every hole of both, once; verify takes the same list.
TEST(linuxcnc_test, plated_and_non_plated_files_are_one_program) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  const std::string dir = testutil::data("real-gerber/kicad/pic_programmer/x2_mm46/");
  const std::string pth = dir + "pic_programmer-PTH-drl.gbr", npth = dir + "pic_programmer-NPTH-drl.gbr";
  // The union of both files' own hole lists (read independently of acodrill).
  const std::string a = testutil::slurp(pth + ".holes.csv"), b = testutil::slurp(npth + ".holes.csv");
  testutil::spit(t / "both.csv", a + b.substr(b.find('\n') + 1));
  const std::size_t both = testutil::read_holes_csv(testutil::slurp(t / "both.csv")).size();
  const std::string list = testutil::shell_quote(pth) + " " + testutil::shell_quote(npth);
  auto r = testutil::acodrill_run("plan " + list + " -o " + testutil::shell_quote(t / "p.nc") + " --report " +
                                  testutil::shell_quote(t / "r.json") + " -q --iterations 20 --slots skip --dialect linuxcnc");
  ASSERT_EQ(r.code, 0) << r.err;
  check_program(t / "p.nc", pth, false, "PTH + NPTH", t / "both.csv");
  const std::string report = testutil::slurp(t / "r.json");
  EXPECT_THAT(report, ::testing::HasSubstr("\"holes\": " + std::to_string(both)));
  EXPECT_THAT(report, ::testing::ContainsRegex("\"sources\": \\[\\s*\\{\\s*\"file\": \"[^\"]*PTH-drl.gbr\",\\s*\"holes\": " +
                                               std::to_string(testutil::read_holes_csv(a).size())));
  auto v = testutil::acodrill_run("verify " + testutil::shell_quote(t / "p.nc") + " --holes " + list + " -q --slots skip");
  EXPECT_EQ(v.code, 0) << v.out;
  // One file alone is not what the program drills.
  auto v1 = testutil::acodrill_run("verify " + testutil::shell_quote(t / "p.nc") + " --holes " + testutil::shell_quote(pth) +
                                   " -q --slots skip");
  EXPECT_EQ(v1.code, 1) << v1.out;
}

// A 3x2 panel drills six copies at the pitch, each tool across the whole
// panel; its route is shorter than six copies of the one-board route joined
// end to end. With max_hits, no physical drill (counted from the program as
// rs274 runs it) makes more holes than its life, and every hole is made once.
TEST(linuxcnc_test, panels_and_drills_that_wear_out) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  const std::string board = testutil::data("kicad/StickHub-mm-decimal.drl");
  const aco::HoleSet one = testutil::read_holes_csv(testutil::slurp(testutil::data("kicad/StickHub.holes.csv")));
  // The expected panel, made here: copy (c, r) moved by (c*60, r*40).
  std::string csv = "x_mm,y_mm,diameter_mm\n";
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      for (const aco::Hole& h : one) {
        csv += std::to_string(h.center.x + 60.0 * c) + "," + std::to_string(h.center.y + 40.0 * r) + "," +
               std::to_string(h.diameter) + "\n";
      }
    }
  }
  testutil::spit(t / "panel.csv", csv);
  const std::string common = " -q --iterations 300 --slots skip --dialect linuxcnc --seed 3";
  auto single = testutil::acodrill_run("plan " + testutil::shell_quote(board) + " -o " + testutil::shell_quote(t / "one.nc") +
                                       " --report " + testutil::shell_quote(t / "one.json") + common);
  ASSERT_EQ(single.code, 0) << single.err;
  auto panel = testutil::acodrill_run("plan " + testutil::shell_quote(board) + " -o " + testutil::shell_quote(t / "six.nc") +
                                      " --report " + testutil::shell_quote(t / "six.json") + " --panel 3x2 --pitch 60,40" + common);
  ASSERT_EQ(panel.code, 0) << panel.err;
  check_program(t / "six.nc", board, false, "3x2 panel", t / "panel.csv");
  // Six copies of the one-board route joined end to end, tool by tool, from the start and back to it.
  const gcode::Interpretation route = gcode::interpret(testutil::slurp(t / "one.nc"));
  std::map<int, std::vector<aco::Point2>> by_tool;
  std::vector<int> tool_order;
  for (const gcode::DrilledHole& h : route.holes) {
    if (!by_tool.count(h.tool)) tool_order.push_back(h.tool);
    by_tool[h.tool].push_back({h.x_mm, h.y_mm});
  }
  double joined = 0;
  aco::Point2 at{0, 0};
  for (int tool : tool_order) {
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 3; ++c) {
        for (const aco::Point2& p : by_tool[tool]) {
          const aco::Point2 q{p.x + 60.0 * c, p.y + 40.0 * r};
          joined += aco::euclidean(at, q);
          at = q;
        }
      }
    }
  }
  joined += aco::euclidean(at, {0, 0});
  const double six = nlohmann::json::parse(testutil::slurp(t / "six.json"))["travel_mm"]["optimized"].get<double>();
  std::printf("3x2 panel of StickHub: whole-panel route %.1f mm, six one-board routes joined %.1f mm (%.1f %% shorter)\n",
              six, joined, 100.0 * (joined - six) / joined);
  EXPECT_LT(six, joined);
  auto v = testutil::acodrill_run("verify " + testutil::shell_quote(t / "six.nc") + " --holes " + testutil::shell_quote(board) +
                                  " --panel 3x2 --pitch 60,40 -q --slots skip");
  EXPECT_EQ(v.code, 0) << v.out;

  // Drills that wear out: 100 hits for the 0.3 mm drill, which makes 486 holes here.
  testutil::spit(t / "tools.json", R"({"tools": [
    {"number": 1, "diameter_mm": 0.3, "rpm": 8000, "feed_mm_min": 200, "depth_mm": -2.2, "max_hits": 100},
    {"number": 2, "diameter_mm": 0.4, "rpm": 8000, "feed_mm_min": 200, "depth_mm": -2.2, "max_hits": 30}]})");
  auto worn = testutil::acodrill_run("plan " + testutil::shell_quote(board) + " -o " + testutil::shell_quote(t / "worn.nc") +
                                     " --report " + testutil::shell_quote(t / "worn.json") + " --panel 3x2 --pitch 60,40 --tools " +
                                     testutil::shell_quote(t / "tools.json") + common);
  ASSERT_EQ(worn.code, 0) << worn.err;
  check_program(t / "worn.nc", board, false, "sister tools", t / "panel.csv");
  const CanonRun canon = run_rs274(testutil::slurp(t / "worn.nc"), 1.0, "sister tools");
  std::map<int, int> hits;
  for (const auto& h : canon.holes) ++hits[h.tool];
  const auto drills = nlohmann::json::parse(testutil::slurp(t / "worn.json"))["drills"];
  std::size_t total = 0;
  for (const auto& d : drills) {
    const int tool = d["tool"].get<int>();
    EXPECT_EQ(hits[tool], d["hits"].get<int>()) << "T" << tool;
    EXPECT_LE(hits[tool], d["max_hits"].get<int>()) << "T" << tool << " drills past its life";
    total += d["hits"].get<std::size_t>();
  }
  EXPECT_EQ(total, one.size() * 6);
  EXPECT_EQ(drills.size(), 5u + 2u) << "486 holes at 100 a drill: T1 and four sisters; 36 at 30: T2 and one sister";
  auto vw = testutil::acodrill_run("verify " + testutil::shell_quote(t / "worn.nc") + " --holes " + testutil::shell_quote(board) +
                                   " --panel 3x2 --pitch 60,40 -q --slots skip");
  EXPECT_EQ(vw.code, 0) << vw.out;
}

// Issue 47: hobby boards drilled the way hobbyists drill them. rs274 runs
// the program; each downward feed at one XY is a stroke, counted per hole.
namespace {

struct Stroke {
  double x, y, from_z, to_z;  // mm
};

std::vector<Stroke> strokes_of(const std::string& program_path) {
  testutil::TempDir t;
  const std::string prog = testutil::slurp(program_path);
  std::string table;
  for (int n = 1; n <= 40; ++n) table += "T" + std::to_string(n) + " P" + std::to_string(n) + " Z0 D1\n";
  testutil::spit(t / "tool.tbl", table);
  auto r = testutil::rs274_in(t.path(), "-t tool.tbl -g " + testutil::shell_quote(program_path));
  EXPECT_EQ(r.code, 0) << r.err;
  static const std::regex call(R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED)\(([^)]*)\))");
  std::vector<Stroke> out;
  double x = 0, y = 0, z = 0;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, call)) continue;
    std::vector<double> v;
    std::istringstream args(m[2]);
    for (std::string a; std::getline(args, a, ',');) v.push_back(std::stod(a));
    if (m[1] == "STRAIGHT_FEED" && std::fabs(v[0] - x) < 1e-9 && std::fabs(v[1] - y) < 1e-9 && v[2] < z) {
      out.push_back({v[0], v[1], z, v[2]});
    }
    x = v[0];
    y = v[1];
    z = v[2];
  }
  return out;
}

// Strokes per drilled position.
std::map<std::pair<long long, long long>, int> strokes_per_hole(const std::vector<Stroke>& strokes) {
  std::map<std::pair<long long, long long>, int> n;
  for (const Stroke& s : strokes) ++n[{std::llround(s.x * 1000), std::llround(s.y * 1000)}];
  return n;
}

}  // namespace

TEST(linuxcnc_test, boards_on_the_router_are_drilled_in_one_stroke_from_close_above) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  const std::string nc = t / "p.nc", sheet = t / "s.html";
  // KiCad's video board: 1720 holes, 11 drills, on the desktop router (GRBL).
  const std::string board = testutil::data("kicad/video-mm-decimal.drl");
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(board) + " --machine router -q --iterations 5 -o " +
                                  testutil::shell_quote(nc) + " --setup-sheet " + testutil::shell_quote(sheet));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string prog = testutil::slurp(nc);
  EXPECT_EQ(grbl_refusal(prog), "");
  const std::vector<Stroke> strokes = strokes_of(nc);
  const auto per_hole = strokes_per_hole(strokes);
  EXPECT_EQ(per_hole.size(), 1720u);
  for (const auto& [at, n] : per_hole) EXPECT_EQ(n, 1) << "hole at " << at.first << "," << at.second << " is pecked";
  for (const Stroke& s : strokes) {
    // The feed starts at the R plane, a millimetre over the board, and goes through it (1.6 mm).
    EXPECT_LE(s.from_z, 1.0 + 1e-9);
    EXPECT_LT(s.to_z, -1.6);
  }
  // Carbide drills: spindle speeds within the router's 10000 rpm.
  static const std::regex speed(R"(\bS(\d+))");
  for (std::sregex_iterator it(prog.begin(), prog.end(), speed), end; it != end; ++it) {
    EXPECT_LE(std::stoi((*it)[1].str()), 10000);
  }
  // The sheet names only what a GRBL program holds: no O-number.
  EXPECT_EQ(testutil::slurp(sheet).find("O1001"), std::string::npos);

  // A machine profile's r_plane_mm is where feeds begin.
  testutil::spit(t / "m.json", R"({"name": "close router", "dialect": "grbl", "tool_changer": false, "max_rpm": 10000,
                                   "r_plane_mm": 0.5})");
  r = testutil::acodrill_run("plan " + testutil::shell_quote(board) + " --machine " + testutil::shell_quote(t / "m.json") +
                             " -q --iterations 5 -o " + testutil::shell_quote(nc));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const Stroke& s : strokes_of(nc)) EXPECT_LE(s.from_z, 0.5 + 1e-9);
  testutil::spit(t / "bad.json", R"({"r_plane_mm": 0})");
  r = testutil::acodrill_run("plan " + testutil::shell_quote(board) + " --machine " + testutil::shell_quote(t / "bad.json") +
                             " -q -o " + testutil::shell_quote(t / "never.nc"));
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("r_plane_mm"));
  EXPECT_FALSE(std::filesystem::exists(t / "never.nc"));
}

TEST(linuxcnc_test, written_out_pecks_count_from_the_top_of_the_part) {
  ASSERT_TRUE(have_rs274());
  testutil::TempDir t;
  const std::string nc = t / "p.nc";
  // A steel plate's small holes are pecked (HSS, deeper than 4 D), R 2.5 mm above it.
  auto r = testutil::acodrill_run("plan " + testutil::shell_quote(testutil::source_dir() + "/samples/pcb_mixed.dxf") +
                                  " --dialect grbl -q --iterations 5 -o " + testutil::shell_quote(nc));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Stroke> strokes = strokes_of(nc);
  std::size_t pecked = 0;
  for (const auto& [at, n] : strokes_per_hole(strokes)) pecked += n > 1;
  EXPECT_GT(pecked, 0u) << "the 0.4 mm holes in steel are pecked";
  for (const Stroke& s : strokes) {
    EXPECT_LT(s.to_z, -1e-9) << "a peck ends in the air at Z" << s.to_z;
    EXPECT_LE(s.from_z, 2.5 + 1e-9);
  }
}
