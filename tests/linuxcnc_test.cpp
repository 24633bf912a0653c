// An independent oracle: LinuxCNC's own interpreter (rs274, Debian package
// linuxcnc-uspace, installed by scripts/test) reads every program back, and
// the holes it drills must equal the input holes and what `verify` reports.
// Recipe: ../shared/gcode.md section 3.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <regex>

#include "gcode/interpreter.h"
#include "test_util.h"

namespace {

struct CanonHole {
  int tool;
  double x, y;  // program units
};

// Each run of STRAIGHT_FEEDs at one XY, after the XY changed, is one hole.
std::vector<CanonHole> holes_from_canon(const std::string& canon) {
  std::vector<CanonHole> holes;
  static const std::regex call(R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|SELECT_TOOL)\(([^)]*)\))");
  int tool = 0;
  double x = 0, y = 0;
  bool xy_changed = true;
  std::istringstream in(canon);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, call)) continue;
    if (m[1] == "SELECT_TOOL") {
      tool = std::stoi(m[2]);
      continue;
    }
    std::vector<double> v;
    std::istringstream args(m[2]);
    for (std::string a; std::getline(args, a, ',');) v.push_back(std::stod(a));
    if (std::fabs(v[0] - x) > 1e-9 || std::fabs(v[1] - y) > 1e-9) xy_changed = true;
    x = v[0];
    y = v[1];
    if (m[1] == "STRAIGHT_FEED" && xy_changed) {
      holes.push_back({tool, x, y});
      xy_changed = false;
    }
  }
  return holes;
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

void check_program(const std::string& program_path, const std::string& sample, bool inch, const std::string& what) {
  testutil::TempDir t;
  // A tool table naming every T/H number the program uses.
  const std::string prog = testutil::slurp(program_path);
  std::string table;
  static const std::regex tool_word(R"(T(\d+) M06)");
  for (std::sregex_iterator it(prog.begin(), prog.end(), tool_word), end; it != end; ++it) {
    table += "T" + (*it)[1].str() + " P" + (*it)[1].str() + " Z0 D1\n";
  }
  testutil::spit(t / "tool.tbl", table);
  // From a directory of its own: rs274 keeps state files in its working directory.
  auto r = testutil::run("cd " + testutil::shell_quote(t.path()) + " && rs274 -t tool.tbl -g " +
                         testutil::shell_quote(program_path));
  ASSERT_EQ(r.code, 0) << what << ": rs274 rejected the program:\n" << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  std::vector<CanonHole> canon = holes_from_canon(r.out);
  const aco::HoleSet expected = testutil::read_holes_csv(testutil::slurp(sample.substr(0, sample.size() - 4) + ".holes.csv"));
  ASSERT_EQ(canon.size(), expected.size()) << what;
  // Same multiset of positions (within half the last printed digit), and the
  // same holes, in the same order, with the same tools as our interpreter sees.
  const double scale = inch ? 25.4 : 1.0;
  const double tol = (inch ? 0.00005 * 25.4 : 0.0005) + 1e-9;
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
