// Issue 14: other CAMs' drilling programs read as a control runs them. The
// oracle for the real programs is LinuxCNC's rs274: tests/data/real-gcode/
// NAME.holes.csv lists the positions it drills, in program order, with the
// deepest Z and the tool (../shared/fixtures/real-gcode/README.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
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

std::vector<std::string> real_programs() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(testutil::data("real-gcode"))) {
    const std::string name = e.path().filename().string();
    if (name.find(".holes.csv") != std::string::npos) continue;
    const std::string ext = e.path().extension().string();
    if (ext == ".nc" || ext == ".ngc" || ext == ".tap" || (ext == ".txt" && name.find("drill") != std::string::npos)) {
      out.push_back(e.path().string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string holes_csv_of(const std::string& program) {
  return program.substr(0, program.find_last_of('.')) + ".holes.csv";
}

class RealProgram : public ::testing::TestWithParam<std::string> {};

std::string param_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = std::filesystem::path(info.param).filename().string();
  for (char& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

}  // namespace

TEST_P(RealProgram, reads_the_holes_rs274_drills_in_order_with_tool_and_depth) {
  const gcode::DrillingProgram p = gcode::read_drilling(testutil::slurp(GetParam()));
  const std::vector<Expected> expected = read_expected(testutil::slurp(holes_csv_of(GetParam())));
  std::vector<std::pair<const gcode::ToolRun*, const gcode::ProgramHole*>> got;
  for (const auto& run : p.runs) for (const auto& h : run.holes) got.push_back({&run, &h});
  ASSERT_EQ(got.size(), expected.size());
  // rs274 prints four decimals of the program's units; inch is converted to mm and rounded again.
  const double tol = (p.inch ? 0.00005 * 25.4 : 0.0) + 0.00005 + 1e-6;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].second->at.x, expected[i].x, tol) << "hole " << i << " line " << got[i].second->line;
    EXPECT_NEAR(got[i].second->at.y, expected[i].y, tol) << "hole " << i << " line " << got[i].second->line;
    EXPECT_NEAR(got[i].second->cycle.bottom_mm(), expected[i].z, tol) << "hole " << i << " line " << got[i].second->line;
    EXPECT_EQ(got[i].first->tool, expected[i].tool) << "hole " << i << " line " << got[i].second->line;
  }
}

INSTANTIATE_TEST_SUITE_P(real_gcode, RealProgram, ::testing::ValuesIn(real_programs()), param_name);
