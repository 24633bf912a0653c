// Issue 66: the minutes acodrill prints are the minutes the machine takes.
// The oracle is GRBL 1.1h's own planner and stepper on a simulated clock
// (tests/grbl-sim: gtime), given the router profile's settings: for KiCad
// boards in every router variant, acodrill's moves + drilling is within 2 %
// of GRBL's motion; and the parts of the time add up to the total.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

#include "test_util.h"

namespace {

using testutil::TempDir;

std::string gtime() { return testutil::source_dir() + "/tests/grbl-sim/gtime"; }
std::string grbl_sim() { return std::string(ACO_BUILD_DIR) + "/grbl/grbl_sim.exe"; }

// GRBL's settings written from the router profile (acodrill machines --show router).
std::string settings_of_router() {
  const auto shown = testutil::acodrill_run("machines --show router");
  const nlohmann::json m = nlohmann::json::parse(shown.out);
  const double xy = m["rapid_xy_mm_min"], z = m["rapid_z_mm_min"], a = m["accel_mm_s2"];
  const double jd = m.value("junction_deviation_mm", 0.01), arc = m.value("arc_tolerance_mm", 0.002);
  std::ostringstream s;
  s << "$0=10\n$1=255\n$11=" << jd << "\n$12=" << arc << "\n$30=10000\n$100=40\n$101=40\n$102=40\n$110=" << xy
    << "\n$111=" << xy << "\n$112=" << z << "\n$120=" << a << "\n$121=" << a << "\n$122=" << a
    << "\n$130=425\n$131=465\n$132=80\n";
  return s.str();
}

double field(const std::string& text, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(key + "=([0-9.]+)"))) return NAN;
  return std::stod(m[1]);
}

struct Variant {
  const char* name;
  const char* options;
};

}  // namespace

TEST(time_model_test, moves_and_drilling_are_grbls_own_motion_within_2_percent) {
  TempDir t;
  testutil::spit(t / "router.settings", settings_of_router());
  const Variant variants[] = {
      {"defaults", ""},
      {"owned drills and an end mill", "--drills 0.4,0.6,0.8,1.0,1.2 --end-mill 0.8"},
      {"touch plate", "--probe-plate 0.5"},
      {"back side with pins", "--side back --alignment-pins 3"},
  };
  // Boards the model was not tuned on, and one it was (pic_programmer).
  for (const char* board : {"kit-dev-coldfire-xilinx_5213", "StickHub", "pic_programmer"}) {
    for (const Variant& v : variants) {
      SCOPED_TRACE(std::string(board) + ", " + v.name);
      const std::string drl = testutil::data("kicad/" + std::string(board) + "-mm-decimal.drl");
      const auto plan = testutil::acodrill_run("plan " + testutil::shell_quote(drl) + " -o " + t / "p.nc" + " --report " +
                                               t / "r.json -q --machine router --iterations 10 " + v.options);
      ASSERT_EQ(plan.code, 0) << plan.err;
      const nlohmann::json r = nlohmann::json::parse(testutil::slurp(t / "r.json"));
      const nlohmann::json& split = r["time_split_s"]["optimized"];
      const auto g = testutil::run("GTIME_EXE=" + testutil::shell_quote(grbl_sim()) + " " + testutil::shell_quote(gtime()) +
                                   " " + t / "p.nc" + " " + t / "router.settings");
      ASSERT_EQ(g.code, 0) << g.err << g.out;
      // GRBL's motion leaves the dwells out; acodrill's spindle run-ups are its pauses, any other dwell is drilling.
      const double grbl = field(g.out, "motion_s") + field(g.out, "dwell_s") - split["pauses"].get<double>();
      const double ours = split["moves"].get<double>() + split["drilling"].get<double>();
      EXPECT_NEAR(ours / grbl, 1.0, 0.02) << "acodrill " << ours << " s, GRBL " << grbl << " s (" << g.out << ")";
      // The parts add up to the total, and the total is the header's estimate.
      const double total = split["moves"].get<double>() + split["drilling"].get<double>() +
                           split["tool_changes"].get<double>() + split["pauses"].get<double>();
      EXPECT_NEAR(total, r["machining_time_s"]["optimized"].get<double>(), 1e-3);
    }
  }
}
