// Issue 82: holes as a machinist draws them. Drawings written by ezdxf
// (tests/data/make_feature_cases.py) with the features each holds, computed
// there from ezdxf's own entities and an independent thread table; programs
// read back by LinuxCNC's rs274.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "formats/features.h"
#include "formats/threads.h"
#include "oracles.h"
#include "test_util.h"

using testutil::acodrill_run;
using testutil::shell_quote;
using testutil::slurp;

namespace {

struct Row {
  double x = 0, y = 0;
  std::string kind;
  double diameter = 0, drill = 0, outer = 0;  // outer 0: none
  std::string thread;
  double depth = 0, angle = 0;
};

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string f;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.push_back(f), f.clear();
    else f += c;
  }
  out.push_back(f);
  return out;
}

double number(const std::string& s) { return s.empty() ? 0.0 : std::stod(s); }

// The oracle's rows: x_mm,y_mm,kind,diameter_mm,drill_mm,outer_diameter_mm,thread,depth_mm,angle_deg
std::vector<Row> expected_rows(const std::string& path) {
  std::vector<Row> rows;
  std::istringstream in(slurp(path));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = fields(line);
    rows.push_back({number(f[0]), number(f[1]), f[2], number(f[3]), number(f[4]), number(f[5]), f[6], number(f[7]), number(f[8])});
  }
  return rows;
}

// acodrill's rows: x_mm,y_mm,kind,diameter_mm,outer_diameter_mm,thread,layer,evidence
std::vector<Row> features_of(const std::string& text) {
  std::vector<Row> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "x_mm,y_mm,kind,diameter_mm,outer_diameter_mm,thread,layer,evidence");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = fields(line);
    EXPECT_EQ(f.size(), 8u) << line;
    if (f.size() < 8) continue;
    rows.push_back({number(f[0]), number(f[1]), f[2], number(f[3]), 0, number(f[4]), f[5], 0, 0});
  }
  return rows;
}

const Row* at(const std::vector<Row>& rows, double x, double y) {
  for (const Row& r : rows) {
    if (std::fabs(r.x - x) <= 1e-5 && std::fabs(r.y - y) <= 1e-5) return &r;
  }
  return nullptr;
}

std::vector<std::string> cases() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(testutil::data("dxf-features"))) {
    if (e.path().extension() == ".dxf") out.push_back(e.path().stem().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string drawing(const std::string& name) { return testutil::data("dxf-features/" + name + ".dxf"); }

class FeatureCase : public ::testing::TestWithParam<std::string> {};

}  // namespace

// Every feature where ezdxf drew it, of the kind, diameters and thread drawn;
// plain `holes` lists the holes plan drills: one a feature, at its drill.
TEST_P(FeatureCase, holes_features_lists_what_was_drawn_and_holes_what_is_drilled) {
  const std::vector<Row> want = expected_rows(testutil::data("dxf-features/" + GetParam() + ".features.csv"));
  ASSERT_FALSE(want.empty());
  auto r = acodrill_run("holes " + shell_quote(drawing(GetParam())) + " --features -q");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Row> got = features_of(r.out);
  EXPECT_EQ(got.size(), want.size());
  for (const Row& w : want) {
    const Row* g = at(got, w.x, w.y);
    ASSERT_NE(g, nullptr) << "no feature at " << w.x << "," << w.y;
    EXPECT_EQ(g->kind, w.kind) << "at " << w.x << "," << w.y;
    EXPECT_NEAR(g->diameter, w.diameter, 1e-5) << "at " << w.x << "," << w.y;
    EXPECT_NEAR(g->outer, w.outer, 1e-5) << "at " << w.x << "," << w.y;
    EXPECT_EQ(g->thread, w.thread) << "at " << w.x << "," << w.y;
  }
  auto plain = acodrill_run("holes " + shell_quote(drawing(GetParam())) + " -q");
  ASSERT_EQ(plain.code, 0) << plain.err;
  const aco::HoleSet holes = testutil::read_holes_csv(plain.out);
  EXPECT_EQ(holes.size(), want.size());
  for (const Row& w : want) {
    const auto h = std::find_if(holes.begin(), holes.end(), [&](const aco::Hole& k) {
      return std::fabs(k.center.x - w.x) <= 1e-5 && std::fabs(k.center.y - w.y) <= 1e-5;
    });
    ASSERT_NE(h, holes.end()) << "no hole at " << w.x << "," << w.y;
    EXPECT_NEAR(h->diameter, w.drill, 1e-5) << "drilled at " << w.x << "," << w.y;
  }
}

// The report lists every feature that is more than a plain hole, with the
// depth and angle its callout gives.
TEST_P(FeatureCase, the_report_lists_the_features_with_their_callouts_depths) {
  const std::vector<Row> want = expected_rows(testutil::data("dxf-features/" + GetParam() + ".features.csv"));
  testutil::TempDir t;
  auto r = acodrill_run("plan " + shell_quote(drawing(GetParam())) + " -o " + t / "p.nc" + " --report " + t / "r.json" +
                        " --iterations 5 -q --thickness 20");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(slurp(t / "r.json"));
  std::size_t listed = 0;
  for (const Row& w : want) {
    if (w.kind == "plain") continue;
    ++listed;
    const auto f = std::find_if(report["features"].begin(), report["features"].end(), [&](const nlohmann::json& j) {
      return std::fabs(j["x_mm"].get<double>() - w.x) <= 1e-5 && std::fabs(j["y_mm"].get<double>() - w.y) <= 1e-5;
    });
    ASSERT_NE(f, report["features"].end()) << w.x << "," << w.y;
    EXPECT_EQ((*f)["kind"], w.kind);
    EXPECT_NEAR((*f)["drill_mm"].get<double>(), w.drill, 1e-5);
    EXPECT_NEAR(f->value("depth_mm", 0.0), w.depth, 1e-5) << w.x << "," << w.y;
    EXPECT_NEAR(f->value("angle_deg", 0.0), w.angle, 1e-5) << w.x << "," << w.y;
  }
  EXPECT_EQ(report["features"].size(), listed);
}

INSTANTIATE_TEST_SUITE_P(ezdxf_drawings, FeatureCase, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

namespace {

// What the program makes at each feature, by the issue's rules, from the
// oracle's rows: the drill, then a tap (the thread's major, through the part
// and 3 pitches, never below the drill's tip), a counterbore (its depth, the callout's or ISO 4762's) or a
// countersink (a pointed tool to the drawn diameter, 90 degrees unless the
// callout says); an undecided circle nothing.
struct Make {
  double x, y, tool_mm, bottom;
  std::string kind;
};

double socket_head_depth(double counterbore) {
  const double rows[][2] = {{6.5, 3.4}, {8, 4.4}, {10, 5.4}, {11, 6.4}, {15, 8.6}, {18, 10.6}, {20, 12.6}, {26, 16.6}, {33, 20.6}};
  for (const auto& r : rows) {
    if (std::fabs(r[0] - counterbore) < 0.01) return r[1];
  }
  return 0;
}

std::vector<Make> makes_of(const std::vector<Row>& rows, double thickness, bool taps) {
  std::vector<Make> out;
  for (const Row& w : rows) {
    out.push_back({w.x, w.y, w.drill, std::nan(""), "drill"});
    if (w.kind == "tapped" && taps) {
      const double pitch = w.thread == "M3" ? 0.5 : w.thread == "M6" ? 1.0 : std::nan("");
      out.push_back({w.x, w.y, w.outer, -std::min(thickness + 3 * pitch, thickness + 0.3 * w.drill + 0.5), "tap"});
    } else if (w.kind == "counterbore") {
      out.push_back({w.x, w.y, w.outer, -(w.depth > 0 ? w.depth : socket_head_depth(w.outer)), "counterbore"});
    } else if (w.kind == "countersink") {
      const double angle = w.angle > 0 ? w.angle : 90.0;
      out.push_back({w.x, w.y, w.outer, -0.5 * w.outer / std::tan(0.5 * angle * M_PI / 180.0), "countersink"});
    }
  }
  return out;
}

// The S and F of tool `tool`'s first cycle line of the program.
std::pair<double, double> speed_and_feed(const std::string& program, int tool) {
  std::smatch m;
  const std::string from = program.substr(program.find("T" + std::to_string(tool) + " M06"));
  double s = 0, f = 0;
  if (std::regex_search(from, m, std::regex(R"(S(\d+) M0[34])"))) s = std::stod(m[1]);
  if (std::regex_search(from, m, std::regex(R"(G(?:84|74|81|82|83|85)[^\n]* F([0-9.]+))"))) f = std::stod(m[1]);
  return {s, f};
}

}  // namespace

// The issue's drawings as HAAS, Fanuc and LinuxCNC programs, read back by
// LinuxCNC's rs274: every hole drilled once at its drill, then its tap,
// counterbore or countersink at its place, deeper than nothing else, after
// the drill, each with a tool of its own diameter; the tap's feed the pitch
// times its speed (Fanuc tapping rigidly, M29 first); the larger circles
// nothing says a counterbore or countersink of never machined, and named
// under NOT MADE. --concentric separate drills every circle through.
TEST(features_test, each_feature_is_drilled_then_tapped_counterbored_or_countersunk_in_order) {
  testutil::TempDir t;
  struct Case {
    std::string name;
    double thickness;
  };
  for (const Case& c : {Case{"build_plate", 6.35}, Case{"build_plate_no_callout", 6.35}, Case{"m6_tapped_and_counterbored", 6.35},
                        Case{"by_layer", 12.0}, Case{"callouts", 20.0}}) {
    for (const std::string dialect : {"haas", "fanuc", "linuxcnc"}) {
      SCOPED_TRACE(c.name + ", " + dialect);
      const std::vector<Row> want = expected_rows(testutil::data("dxf-features/" + c.name + ".features.csv"));
      auto r = acodrill_run("plan " + shell_quote(drawing(c.name)) + " -o " + t / "p.nc" + " --dialect " + dialect +
                            " --origin drawing --iterations 20 --thickness " + std::to_string(c.thickness));
      ASSERT_EQ(r.code, 0) << r.err;
      const std::string program = slurp(t / "p.nc");
      const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
      const std::map<int, double> tools = oracles::tool_diameters(program);
      const std::vector<Make> makes = makes_of(want, c.thickness, true);
      ASSERT_EQ(canon.made.size(), makes.size());
      std::vector<char> used(canon.made.size(), 0);
      std::map<std::pair<long long, long long>, std::size_t> drilled_at;  // place → the drill's turn
      for (const Make& k : makes) {
        std::size_t found = canon.made.size();
        for (std::size_t i = 0; i < canon.made.size() && found == canon.made.size(); ++i) {
          const oracles::Made& m = canon.made[i];
          if (!used[i] && std::fabs(m.x - k.x) <= 0.0006 && std::fabs(m.y - k.y) <= 0.0006 && tools.count(m.tool) &&
              std::fabs(tools.at(m.tool) - k.tool_mm) <= 0.001) {
            found = i;
          }
        }
        ASSERT_NE(found, canon.made.size()) << k.kind << " D" << k.tool_mm << " at " << k.x << "," << k.y;
        used[found] = 1;
        const auto place = std::make_pair(std::llround(k.x * 1000), std::llround(k.y * 1000));
        if (k.kind == "drill") {
          drilled_at[place] = found;
          EXPECT_LT(canon.made[found].bottom, -c.thickness) << "drilled through at " << k.x << "," << k.y;
          continue;
        }
        EXPECT_NEAR(canon.made[found].bottom, k.bottom, 0.001) << k.kind << " at " << k.x << "," << k.y;
        ASSERT_TRUE(drilled_at.count(place));
        EXPECT_GT(found, drilled_at[place]) << k.kind << " before the drill at " << k.x << "," << k.y;
        const std::pair<double, double> sf = speed_and_feed(program, canon.made[found].tool);
        if (k.kind == "tap") {
          EXPECT_NE(program.find("G84"), std::string::npos);
          EXPECT_NEAR(sf.second, sf.first * (k.tool_mm > 5 ? 1.0 : 0.5), 0.05) << "F = pitch x S";
          EXPECT_NEAR(canon.made[found].pitch, k.tool_mm > 5 ? 1.0 : 0.5, 1e-3) << "rs274: reversed at the bottom, fed at the pitch";
          EXPECT_EQ(program.find("M29") != std::string::npos, dialect == "fanuc") << "rigid tapping: Fanuc's M29";
        }
      }
      // The larger circles nothing decided are named, never made.
      std::size_t said = 0;
      for (std::size_t at = program.find("(NOT MADE: "); at != std::string::npos; at = program.find("(NOT MADE: ", at + 1)) ++said;
      std::size_t undecided = 0;
      for (const Row& w : want) undecided += w.kind == "undecided";
      EXPECT_EQ(said, undecided) << program;
      auto v = acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing(c.name)) + " -q");
      EXPECT_EQ(v.code, 0) << v.out;
    }
  }
  auto with_callout = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --iterations 5");
  EXPECT_THAT(with_callout.err, ::testing::HasSubstr("hole features: 2 tapped (M3), 4 counterbored"));
  auto without = acodrill_run("plan " + shell_quote(drawing("build_plate_no_callout")) + " -o " + t / "p.nc" + " --iterations 5");
  EXPECT_EQ(without.code, 0);
  EXPECT_THAT(without.err, ::testing::HasSubstr("warning: 4 circle(s) around a smaller hole (D6.5 x4) not machined"));
  auto separate = acodrill_run("holes " + shell_quote(drawing("build_plate")) + " --concentric separate -q");
  EXPECT_EQ(testutil::read_holes_csv(separate.out).size(), 10u) << "every circle, as before issue 82";
  auto bad = acodrill_run("holes " + shell_quote(drawing("build_plate")) + " --concentric sometimes");
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr("--concentric must be features or separate"));
}

// A thread's pitch in mm, from its name: ISO 261's coarse series (M1.6 to
// M20), a fine "MxP", or an inch thread's threads per inch ("1/4-20 UNC").
double thread_pitch(const std::string& thread) {
  static const std::map<std::string, double> coarse{{"M1.6", 0.35}, {"M2", 0.4}, {"M2.5", 0.45}, {"M3", 0.5},  {"M4", 0.7},
                                                    {"M5", 0.8},    {"M6", 1.0}, {"M8", 1.25},   {"M10", 1.5}, {"M12", 1.75},
                                                    {"M16", 2.0},   {"M20", 2.5}};
  const std::size_t x = thread.find('x');
  if (thread[0] == 'M' && x != std::string::npos) return std::stod(thread.substr(x + 1));
  if (thread[0] == 'M') return coarse.at(thread);
  return 25.4 / std::stod(thread.substr(thread.find('-') + 1));
}

// Issue 82: a LinuxCNC mill whose spindle has an encoder (profile
// "spindle_encoder") taps by G33.1, the Z motion synchronized with the
// spindle. rs274 reads every tap back as a RIGID_TAP at its hole, begun
// above the part, at its thread's pitch (metric coarse and fine, UNC and UNF,
// in mm and inch programs), after its drill; verify agrees, and finds a tap
// whose K is not its thread's pitch. The same profile on HAAS keeps G84.
TEST(features_test, a_spindle_with_an_encoder_taps_by_g33_1_at_the_threads_pitch) {
  testutil::TempDir t;
  testutil::spit(t / "encoder.json", R"({"name": "knee mill, LinuxCNC, spindle encoder", "dialect": "linuxcnc", "spindle_encoder": true})");
  struct Case {
    std::string drawing, units;
  };
  for (const Case& c : {Case{"tapped_metric_quadrants", "mm"}, Case{"tapped_inch", "inch"}, Case{"build_plate", "mm"}}) {
    SCOPED_TRACE(c.drawing + ", " + c.units);
    auto r = acodrill_run("plan " + shell_quote(drawing(c.drawing)) + " -o " + t / "p.ngc" + " --machine " + t / "encoder.json" +
                          " --units " + c.units + " --origin drawing --iterations 5 --thickness 12 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string program = slurp(t / "p.ngc");
    EXPECT_EQ(program.find("G84"), std::string::npos);
    const double unit = c.units == "inch" ? 25.4 : 1.0;
    const oracles::Canon canon = oracles::run_rs274(t / "p.ngc");
    std::size_t tapped = 0;
    for (const Row& w : expected_rows(testutil::data("dxf-features/" + c.drawing + ".features.csv"))) {
      if (w.kind != "tapped") continue;
      ++tapped;
      std::size_t tap = canon.made.size(), drill = canon.made.size();
      for (std::size_t i = 0; i < canon.made.size(); ++i) {
        const oracles::Made& m = canon.made[i];
        if (std::fabs(m.x * unit - w.x) > 0.002 || std::fabs(m.y * unit - w.y) > 0.002) continue;
        (m.synchronized ? tap : drill) = i;
      }
      ASSERT_LT(tap, canon.made.size()) << w.thread << " at " << w.x << "," << w.y << " is not tapped by G33.1";
      ASSERT_LT(drill, tap) << w.thread << " at " << w.x << "," << w.y << ": tapped before its drill";
      EXPECT_NEAR(canon.made[tap].pitch * unit, thread_pitch(w.thread), 2e-4) << w.thread;
      EXPECT_LT(canon.made[tap].bottom * unit, -12.0 + 1e-6) << w.thread << " tapped through";
    }
    EXPECT_GT(tapped, 0u);
    EXPECT_EQ(static_cast<std::size_t>(std::count_if(canon.made.begin(), canon.made.end(), [](const oracles::Made& m) { return m.synchronized; })),
              tapped);
    auto v = acodrill_run("verify " + t / "p.ngc" + " --holes " + shell_quote(drawing(c.drawing)) + " -q");
    EXPECT_EQ(v.code, 0) << v.out << v.err;
  }
  // A tap's K changed to another pitch (M3's 0.5 to 0.6): verify names the hole and both pitches.
  auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.ngc" + " --machine " + t / "encoder.json" +
                        " --origin drawing --iterations 5 -q");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string program = slurp(t / "p.ngc");
  const std::size_t k = program.find("K0.5000");
  ASSERT_NE(k, std::string::npos) << program;
  program.replace(k, 7, "K0.6000");
  testutil::spit(t / "wrong.ngc", program);
  auto v = acodrill_run("verify " + t / "wrong.ngc" + " --holes " + shell_quote(drawing("build_plate")) + " -q");
  EXPECT_EQ(v.code, 1);
  EXPECT_THAT(v.out + v.err, ::testing::HasSubstr("runs at 0.6 mm a turn where the M3's pitch is 0.5 mm"));
  // The program as another CAM's input: reordered in its own style it keeps
  // G33.1; for HAAS each rigid tap becomes G84 at F = K x S; verify compares
  // the pitch, and a K changed in the output is found.
  auto again = acodrill_run("plan " + t / "p.ngc" + " -o " + t / "q.ngc" + " -q");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(oracles::run_rs274(t / "q.ngc").made.size(), oracles::run_rs274(t / "p.ngc").made.size());
  EXPECT_NE(slurp(t / "q.ngc").find("G33.1"), std::string::npos);
  EXPECT_EQ(acodrill_run("verify " + t / "q.ngc" + " --holes " + t / "p.ngc" + " -q").code, 0);
  auto as_haas = acodrill_run("plan " + t / "p.ngc" + " --dialect haas -o " + t / "q.nc" + " -q");
  ASSERT_EQ(as_haas.code, 0) << as_haas.err;
  const std::string g84 = slurp(t / "q.nc");
  EXPECT_EQ(g84.find("G33.1"), std::string::npos);
  EXPECT_EQ(acodrill_run("verify " + t / "q.nc" + " --holes " + t / "p.ngc" + " -q").code, 0);
  std::smatch sm;
  ASSERT_TRUE(std::regex_search(g84, sm, std::regex(R"(S(\d+) M03\n(?:[^\n]*\n){1,3}G99 G84 [^\n]* F([0-9.]+))"))) << g84;
  EXPECT_NEAR(std::stod(sm[2]), 0.5 * std::stod(sm[1]), 0.05) << "F = K x S";
  std::string retapped = slurp(t / "q.ngc");
  retapped.replace(retapped.find("K0.5000"), 7, "K0.6000");
  testutil::spit(t / "q.ngc", retapped);
  auto off = acodrill_run("verify " + t / "q.ngc" + " --holes " + t / "p.ngc" + " -q");
  EXPECT_EQ(off.code, 1);
  EXPECT_THAT(off.out + off.err, ::testing::HasSubstr("tapped at 0.6 mm a turn where the input taps at 0.5"));
  // On HAAS the same machine's taps stay G84 (HAAS taps rigidly with it), at F = pitch x S.
  auto haas = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "h.nc" + " --machine " + t / "encoder.json" +
                           " --dialect haas --origin drawing --iterations 5 -q");
  ASSERT_EQ(haas.code, 0) << haas.err;
  EXPECT_EQ(slurp(t / "h.nc").find("G33.1"), std::string::npos);
  EXPECT_NE(slurp(t / "h.nc").find("G84"), std::string::npos);
}

// GRBL and Marlin cannot tap: the holes are drilled at the tap drill and the
// program ends with a pause that lists them; GRBL's own parser takes every
// line; counterbores are milled by the end mill's helix (rs274 reads them to
// size and depth), and without one the job is refused in one line.
TEST(features_test, grbl_and_marlin_drill_the_tap_drill_and_end_with_the_taps_to_make_by_hand) {
  testutil::TempDir t;
  for (const std::string dialect : {"grbl", "marlin"}) {
    SCOPED_TRACE(dialect);
    auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --dialect " + dialect +
                          " --iterations 10 --origin drawing --drills 2.5,3.4 --end-mill 3");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string program = slurp(t / "p.nc");
    EXPECT_EQ(program.find("G84"), std::string::npos);
    EXPECT_THAT(program, ::testing::HasSubstr("TAP M3 AT X"));
    EXPECT_THAT(program, ::testing::HasSubstr("TAP BY HAND"));
    EXPECT_THAT(program, ::testing::HasSubstr("3.000 MM END MILL"));
    EXPECT_THAT(r.err, ::testing::HasSubstr("cannot tap: the program ends with a pause that lists them"));
    if (dialect == "grbl") {
      EXPECT_EQ(oracles::grbl_refusal(program), "");
      // The counterbores, milled by the 3 mm end mill's helix to 6.5 mm, 3.0 deep (the callout's).
      const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
      std::size_t milled = 0;
      for (const oracles::Made& m : canon.made) {
        if (m.path_radius > 0) {
          ++milled;
          EXPECT_NEAR(2 * m.path_radius + 3.0, 6.5, 0.01);
          EXPECT_NEAR(m.bottom, -3.0, 1e-6);
        }
      }
      EXPECT_EQ(milled, 4u);
    }
    auto v = acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing("build_plate")) + " --drills 2.5,3.4 --end-mill 3 -q");
    EXPECT_EQ(v.code, 0) << v.out;
    // Without an end mill nothing can make the counterbores: one line, nothing written.
    std::filesystem::remove(t / "p.nc");
    auto refused = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --dialect " + dialect);
    EXPECT_EQ(refused.code, 2);
    EXPECT_EQ(testutil::count_lines(refused.err), 1) << refused.err;
    EXPECT_THAT(refused.err, ::testing::HasSubstr("GRBL and Marlin programs mill counterbores with the end mill: give --end-mill DIA"));
    EXPECT_FALSE(std::filesystem::exists(t / "p.nc"));
  }
}

// --spot: every drilled hole is spotted first, by one 90-degree spot drill
// (T1, before every drill), to a cone as wide as the smallest hole; the taps'
// and counterbores' places are not spotted again. Read back by rs274.
TEST(features_test, spot_spots_every_drilled_hole_first_with_one_tool) {
  testutil::TempDir t;
  for (const std::string dialect : {"haas", "linuxcnc", "grbl"}) {
    SCOPED_TRACE(dialect);
    const std::string mill = dialect == "grbl" ? " --drills 2.5,3.4 --end-mill 3" : "";  // GRBL mills the counterbores
    auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --spot --origin drawing --iterations 5 -q --dialect " + dialect + mill);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string program = slurp(t / "p.nc");
    EXPECT_THAT(program, ::testing::HasSubstr("T1 D=6.000 MM - 90 DEG SPOT DRILL - 6 HOLES"));
    const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
    const std::vector<Row> want = expected_rows(testutil::data("dxf-features/build_plate.features.csv"));
    ASSERT_EQ(want.size(), 6u);
    for (const Row& w : want) {
      std::vector<std::size_t> here;
      for (std::size_t i = 0; i < canon.made.size(); ++i) {
        if (std::fabs(canon.made[i].x - w.x) <= 0.0006 && std::fabs(canon.made[i].y - w.y) <= 0.0006) here.push_back(i);
      }
      ASSERT_GE(here.size(), 2u);
      // The first thing made here is the spot, as deep as the 2.5 mm tap drill's cone's radius.
      EXPECT_EQ(canon.made[here[0]].tool, 1);
      EXPECT_NEAR(canon.made[here[0]].bottom, -1.25, 0.001);
      for (std::size_t q = 1; q < here.size(); ++q) EXPECT_NE(canon.made[here[q]].tool, 1);
    }
    std::size_t spots = 0;
    for (const oracles::Made& m : canon.made) spots += m.tool == 1;
    EXPECT_EQ(spots, 6u);
    auto v = acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing("build_plate")) + " --spot -q" + mill);
    EXPECT_EQ(v.code, 0) << v.out;
  }
}

// A process table decides before the layer and the callout: the build
// plate without its callout gets its counterbores from a rule (3.0 mm deep,
// spotted first), its M3 taps left-hand from another; nothing is left
// undecided; rs274 reads every operation at its place, in order; holes
// --features names the rule; verify with the same table passes.
TEST(features_test, a_process_table_decides_and_gives_each_feature_its_operations) {
  testutil::TempDir t;
  testutil::spit(t / "shop.json", R"({"processes": [
  {"name": "M3 socket head", "kind": "undecided", "diameter_mm": [3.3, 3.5],
   "operations": ["spot", "drill", {"operation": "counterbore", "depth_mm": 3.0}]},
  {"thread": "M3", "operations": ["drill", {"operation": "tap", "hand": "left"}]}
]})");
  const std::string processes = " --processes " + t / "shop.json";
  auto shown = acodrill_run("holes " + shell_quote(drawing("build_plate_no_callout")) + " --features -q" + processes);
  ASSERT_EQ(shown.code, 0) << shown.err;
  EXPECT_EQ(shown.err, "");
  std::size_t by_rule = 0;
  for (std::size_t at = shown.out.find("counterbore,3.400000,6.500000"); at != std::string::npos; at = shown.out.find("counterbore,3.400000,6.500000", at + 1)) ++by_rule;
  EXPECT_EQ(by_rule, 4u) << shown.out;
  EXPECT_THAT(shown.out, ::testing::HasSubstr("process 1 (M3 socket head)"));
  for (const std::string dialect : {"haas", "linuxcnc"}) {
    SCOPED_TRACE(dialect);
    auto r = acodrill_run("plan " + shell_quote(drawing("build_plate_no_callout")) + " -o " + t / "p.nc" + " --origin drawing --iterations 5 --dialect " + dialect + processes);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.err, ::testing::Not(::testing::HasSubstr("not machined")));
    // The summary and the report count holes drilled and the operations at them apart.
    EXPECT_THAT(r.err, ::testing::HasSubstr("6 holes and 10 operations at them, 5 tools"));
    auto reported = acodrill_run("plan " + shell_quote(drawing("build_plate_no_callout")) + " -o " + t / "q.nc" + " --iterations 5 -q --report " +
                                 t / "r.json" + " --dialect " + dialect + processes);
    ASSERT_EQ(reported.code, 0) << reported.err;
    const nlohmann::json report = nlohmann::json::parse(slurp(t / "r.json"));
    EXPECT_EQ(report["holes"], 6);
    EXPECT_EQ(report["operations"], 10);
    std::vector<std::string> kinds;
    for (const auto& tool : report["tools"]) kinds.push_back(tool["kind"]);
    EXPECT_EQ(kinds, (std::vector<std::string>{"spot", "drill", "drill", "counterbore", "tap"}));
    const std::string program = slurp(t / "p.nc");
    EXPECT_THAT(program, ::testing::HasSubstr("M3 TAP LH"));
    EXPECT_THAT(program, ::testing::ContainsRegex("G74 X"));
    EXPECT_EQ(program.find("G84"), std::string::npos);
    EXPECT_EQ(program.find("NOT MADE"), std::string::npos);
    const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
    const std::map<int, double> tools = oracles::tool_diameters(program);
    for (const Row& w : expected_rows(testutil::data("dxf-features/build_plate_no_callout.features.csv"))) {
      std::vector<std::pair<double, double>> here;  // (tool's diameter, bottom) in the order made
      for (const oracles::Made& m : canon.made) {
        if (std::fabs(m.x - w.x) <= 0.0006 && std::fabs(m.y - w.y) <= 0.0006) here.push_back({tools.at(m.tool), m.bottom});
      }
      if (w.kind == "undecided") {
        ASSERT_EQ(here.size(), 3u) << w.x << "," << w.y;
        EXPECT_NEAR(here[0].first, 6.0, 1e-9) << "the spot drill first";
        EXPECT_NEAR(here[0].second, -0.5 * 3.4, 1e-9) << "a cone as wide as the smallest spotted hole (the taps' are not)";
        EXPECT_NEAR(here[1].first, 3.4, 1e-9);
        EXPECT_NEAR(here[2].first, 6.5, 1e-9);
        EXPECT_NEAR(here[2].second, -3.0, 1e-9) << "the rule's depth";
      } else {
        ASSERT_EQ(here.size(), 2u) << w.x << "," << w.y;
        EXPECT_NEAR(here[0].first, 2.5, 1e-9);
        EXPECT_NEAR(here[1].first, 3.0, 1e-9);
      }
    }
    auto v = acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing("build_plate_no_callout")) + " -q" + processes);
    EXPECT_EQ(v.code, 0) << v.out;
  }
}

// Inputs that draw no features (here CSV) are plain holes a rule selects by
// diameter: a 6 mm hole drilled 5.8 and reamed (G85) to 6, through; the other
// holes as before.
TEST(features_test, a_process_table_reams_plain_holes_of_any_input) {
  testutil::TempDir t;
  testutil::spit(t / "holes.csv", "x,y,diameter\n0,0,6\n40,0,6\n20,30,4.2\n");
  testutil::spit(t / "ream.json", R"({"processes": [{"diameter_mm": 6, "operations": ["drill", "ream"]}]})");
  auto r = acodrill_run("plan " + t / "holes.csv" + " -o " + t / "p.nc" + " --origin drawing --iterations 5 --processes " + t / "ream.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string program = slurp(t / "p.nc");
  EXPECT_THAT(program, ::testing::HasSubstr("6.000 MM REAMER"));
  EXPECT_THAT(program, ::testing::HasSubstr("5.800 MM DRILL"));
  EXPECT_THAT(program, ::testing::ContainsRegex("G85 X"));
  const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
  const std::map<int, double> tools = oracles::tool_diameters(program);
  std::map<double, int> made;  // by tool diameter
  for (const oracles::Made& m : canon.made) {
    ++made[tools.at(m.tool)];
    if (tools.at(m.tool) == 6.0) {
      EXPECT_NEAR(m.bottom, -(6.35 + 1.0), 1e-9) << "through and the reamer's lead";
    }
  }
  EXPECT_EQ(made, (std::map<double, int>{{4.2, 1}, {5.8, 2}, {6.0, 2}}));
  auto v = acodrill_run("verify " + t / "p.nc" + " --holes " + t / "holes.csv" + " -q --processes " + t / "ream.json");
  EXPECT_EQ(v.code, 0) << v.out;
}

// A process table it cannot make is one line naming the file and the rule's
// line, exit 2, nothing written.
TEST(features_test, a_bad_process_table_is_one_line_naming_its_line) {
  testutil::TempDir t;
  struct Bad {
    std::string rule, says;
  };
  for (const Bad& b : {Bad{R"({"operations": ["drill", "bore"]})", "process 2: operation 2: \"bore\" is no operation"},
                       Bad{R"({"operations": ["spot", "tap"]})", "process 2: \"operations\" must drill the hole"},
                       Bad{R"({"thread": "M9x3", "operations": ["drill"]})", "process 2: thread \"M9x3\" is no standard thread"},
                       Bad{R"({"operations": ["drill", "counterbore", "countersink"]})", "process 2: a hole is counterbored or countersunk, not both"},
                       Bad{R"({"diameter": 6, "operations": ["drill"]})", "process 2: unknown key \"diameter\""},
                       Bad{R"({"operations": ["drill", {"operation": "tap", "thread": "M6", "hand": "both"}]})", "process 2: operation 2: \"hand\" must be right or left"},
                       Bad{R"({"operations": ["drill", {"operation": "counterbore", "depth_mm": "deep"}]})", "process 2: operation 2: \"depth_mm\" must be a number"}}) {
    SCOPED_TRACE(b.rule);
    testutil::spit(t / "bad.json", "{\n  \"processes\": [\n    {\"kind\": \"tapped\", \"operations\": [\"drill\", \"tap\"]},\n    " + b.rule + "\n  ]\n}\n");
    auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --processes " + t / "bad.json");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr("acodrill: error: " + t / "bad.json" + ":4: " + b.says)) << r.err;
    EXPECT_FALSE(std::filesystem::exists(t / "p.nc"));
  }
  // A rule that makes a contradiction names the feature: a reamer no larger than its drill.
  testutil::spit(t / "ream.json", R"({"processes": [{"kind": "tapped", "operations": [{"operation": "drill", "diameter_mm": 3}, "ream"]}]})");
  auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --processes " + t / "ream.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("the drill D3 is not smaller than the reamer D2.459"));
}

// A tool table may hold the operations' tools: the tap and the counterbore
// come from it (its speed, the tap's feed its pitch a turn), in the
// operations' order whatever order the table lists them in; a tap of another
// pitch is no M3 tap, so the M3 holes get a generated one instead.
TEST(features_test, a_tool_table_makes_the_operations_its_tools_name) {
  testutil::TempDir t;
  testutil::spit(t / "tools.json", R"({"tools": [
    {"number": 7, "diameter_mm": 3.0, "operation": "tap", "pitch_mm": 0.5, "rpm": 400},
    {"number": 1, "diameter_mm": 2.5},
    {"number": 2, "diameter_mm": 3.4},
    {"number": 3, "diameter_mm": 6.5, "operation": "counterbore", "rpm": 500, "feed_mm_min": 40}]})");
  auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --iterations 5 -q --tools " + t / "tools.json");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string program = slurp(t / "p.nc");
  std::vector<std::string> order;
  static const std::regex change(R"(\nT(\d+) M06)");
  for (std::sregex_iterator it(program.begin(), program.end(), change), end; it != end; ++it) order.push_back((*it)[1]);
  EXPECT_EQ(order, (std::vector<std::string>{"1", "2", "3", "7"})) << program;
  EXPECT_EQ(speed_and_feed(program, 7), std::make_pair(400.0, 200.0));
  EXPECT_EQ(speed_and_feed(program, 3), std::make_pair(500.0, 40.0));
  EXPECT_THAT(program, ::testing::HasSubstr("(T7 D=3.000 MM - M3 TAP - 2 HOLES)"));
  auto v = acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing("build_plate")) + " -q");
  EXPECT_EQ(v.code, 0) << v.out;

  testutil::spit(t / "fine.json", R"({"tools": [{"number": 1, "diameter_mm": 2.5}, {"number": 2, "diameter_mm": 3.4},
    {"number": 5, "diameter_mm": 3.0, "operation": "tap", "pitch_mm": 0.35}]})");
  r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --iterations 5 -q --tools " + t / "fine.json");
  ASSERT_EQ(r.code, 0) << r.err;
  program = slurp(t / "p.nc");
  EXPECT_EQ(program.find("T5 M06"), std::string::npos) << "an M3x0.35 tap makes no M3 thread";
  EXPECT_THAT(program, ::testing::HasSubstr("M3 TAP - 2 HOLES)"));
  testutil::spit(t / "bad.json", R"({"tools": [{"number": 1, "diameter_mm": 2.5, "operation": "bore"}]})");
  r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --tools " + t / "bad.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("\"operation\" must be one of spot, drill, ream, countersink, counterbore, tap"));
}

// A CSV's and an XML map's feature columns (thread, counterbore_mm,
// counterbore_depth_mm, countersink_mm, countersink_angle_deg) make the same
// features a drawing does: rs274 reads each made at its place with its tool.
TEST(features_test, csv_and_xml_hole_lists_carry_features) {
  testutil::TempDir t;
  testutil::spit(t / "plate.csv",
                 "x,y,diameter,layer,thread,counterbore_mm,counterbore_depth_mm,countersink_mm\n"
                 "0,0,5,,M6,,,\n20,0,6.6,,,11,6.4,\n40,0,6.6,,,,,13\n60,0,4,,,,,\n");
  testutil::spit(t / "plate.xml",
                 "<holemap units=\"mm\">\n <hole x=\"0\" y=\"0\" diameter=\"5\" thread=\"M6\"/>\n"
                 " <hole x=\"20\" y=\"0\" diameter=\"6.6\" counterbore_mm=\"11\" counterbore_depth_mm=\"6.4\"/>\n"
                 " <hole x=\"40\" y=\"0\" diameter=\"6.6\" countersink_mm=\"13\"/>\n <hole x=\"60\" y=\"0\" diameter=\"4\"/>\n</holemap>\n");
  for (const std::string input : {"plate.csv", "plate.xml"}) {
    SCOPED_TRACE(input);
    auto r = acodrill_run("plan " + t / input + " -o " + t / "p.nc" + " --origin drawing --iterations 5 --thickness 10");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr("1 tapped (M6), 1 counterbored, 1 countersunk"));
    const std::string program = slurp(t / "p.nc");
    const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
    const std::map<int, double> tools = oracles::tool_diameters(program);
    std::multimap<double, std::pair<double, double>> made;  // x -> (tool, bottom)
    for (const oracles::Made& m : canon.made) made.insert({m.x, {tools.at(m.tool), m.bottom}});
    auto at = [&](double x) {
      std::vector<std::pair<double, double>> v;
      for (auto [it, end] = made.equal_range(x); it != end; ++it) v.push_back(it->second);
      return v;
    };
    ASSERT_EQ(at(0).size(), 2u);
    EXPECT_NEAR(at(0)[0].first, 5.0, 1e-9) << "M6's tap drill";
    EXPECT_NEAR(at(0)[1].first, 6.0, 1e-9) << "the M6 tap";
    ASSERT_EQ(at(20).size(), 2u);
    EXPECT_NEAR(at(20)[1].first, 11.0, 1e-9);
    EXPECT_NEAR(at(20)[1].second, -6.4, 1e-9);
    ASSERT_EQ(at(40).size(), 2u);
    EXPECT_NEAR(at(40)[1].first, 13.0, 1e-9);
    EXPECT_NEAR(at(40)[1].second, -6.5, 1e-9) << "90 degrees: as deep as its radius";
    EXPECT_EQ(at(60).size(), 1u);
  }
  testutil::spit(t / "bad.csv", "x,y,diameter,thread\n0,0,5,M9x3\n");
  auto bad = acodrill_run("plan " + t / "bad.csv" + " -o " + t / "p.nc");
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr(t / "bad.csv" + ":2: thread \"M9x3\" is no standard thread"));
}

// The setup sheet counts holes and the operations at them apart, and its map
// (and the route SVG) draws a counterbore as a ring and a tap as three
// quarters of one, over the drilled discs.
TEST(features_test, the_setup_sheet_and_the_route_draw_the_features) {
  testutil::TempDir t;
  auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --iterations 5 -q --setup-sheet " +
                        t / "sheet.html" + " --svg " + t / "route.svg");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string sheet = slurp(t / "sheet.html");
  EXPECT_THAT(sheet, ::testing::HasSubstr("6 and 6 operations at them / 4"));
  const std::string svg = slurp(t / "route.svg");
  auto count = [](const std::string& text, const std::regex& re) {
    return std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator());
  };
  // The group of the counterbores: unfilled, 4 circles; the taps': 2 arcs of 270 degrees.
  std::smatch bores;
  ASSERT_TRUE(std::regex_search(svg, bores, std::regex(R"(<g fill="none" stroke="[^"]+" stroke-width="1.5">\n((?:<circle[^\n]*\n)+)</g>)")));
  EXPECT_EQ(count(bores[1].str(), std::regex("<circle")), 4);
  EXPECT_EQ(count(svg, std::regex(R"(<path d="M[-0-9.]+ [-0-9.]+A[0-9.]+ [0-9.]+ 0 1 1 )")), 2);
}

// verify checks the order of each feature's operations: the same program
// with its taps moved before the drills makes every hole with the right tool
// and is still wrong, naming both lines.
TEST(features_test, verify_refuses_a_tap_made_before_its_drill) {
  testutil::TempDir t;
  auto r = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --iterations 5 -q");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string program = slurp(t / "p.nc");
  const std::size_t drills = program.find("(T1 2.500 MM DRILL, ");
  const std::size_t taps = program.find("(T4 M3 TAP, ");
  ASSERT_NE(drills, std::string::npos) << program;
  ASSERT_NE(taps, std::string::npos) << program;
  const std::size_t taps_end = program.find("M01\n", taps) + 4;
  const std::string tap_block = program.substr(taps, taps_end - taps);
  program.erase(taps, taps_end - taps);
  program.insert(drills, tap_block);
  testutil::spit(t / "taps_first.nc", program);
  auto v = acodrill_run("verify " + t / "taps_first.nc" + " --holes " + shell_quote(drawing("build_plate")) + " -q");
  EXPECT_EQ(v.code, 1) << v.out << v.err;
  EXPECT_THAT(v.out + v.err, ::testing::ContainsRegex(R"(hole \([0-9.]+, [0-9.]+\): the tap \(line [0-9]+\) comes before the drill \(line [0-9]+\))"));
  auto as_planned = acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing("build_plate")) + " -q");
  EXPECT_EQ(as_planned.code, 0) << as_planned.out;
}

// What contradicts is one line naming the feature, exit 2, nothing written:
// a counterbore deeper than the part.
TEST(features_test, a_counterbore_as_deep_as_the_part_is_refused_in_one_line) {
  testutil::TempDir t;
  auto r = acodrill_run("plan " + shell_quote(drawing("callouts")) + " -o " + t / "p.nc" + " --thickness 6.35");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
  EXPECT_THAT(r.err, ::testing::HasSubstr("counterbore D11 at X100.000 Y0.000 is 6.5 mm deep, as deep as the part or deeper"));
  EXPECT_FALSE(std::filesystem::exists(t / "p.nc"));
}

TEST(features_test, arcs_that_are_no_thread_leave_the_hole_as_drawn_and_say_so) {
  auto r = acodrill_run("holes " + shell_quote(drawing("arcs_not_threads")) + " --features");
  ASSERT_EQ(r.code, 0);
  // The 308 degree lobe is no thread arc at all; the other two are named.
  EXPECT_THAT(r.err, ::testing::HasSubstr("warning: 2 arc(s) of about three quarters of a turn around a hole"));
  EXPECT_THAT(r.err, ::testing::HasSubstr("match no standard thread"));
}

TEST(features_test, the_thread_tables_hold_together_and_match_what_drawings_show) {
  for (const formats::Thread& t : formats::standard_threads()) {
    EXPECT_LT(t.minor_mm(), t.tap_drill_mm) << t.name;
    EXPECT_LT(t.tap_drill_mm, t.major_mm) << t.name;
    EXPECT_GT(t.pitch_mm, 0) << t.name;
    // Drawn at its own tap drill, a thread is read as one of its major and tap drill.
    const formats::Thread* m = formats::match_thread(t.major_mm, t.tap_drill_mm, t.inch);
    ASSERT_NE(m, nullptr) << t.name;
    EXPECT_NEAR(m->major_mm, t.major_mm, 1e-9) << t.name << " read as " << m->name;
    EXPECT_NEAR(m->tap_drill_mm, t.tap_drill_mm, formats::tap_drill_allowance_mm(t.tap_drill_mm)) << t.name << " read as " << m->name;
    // Drawn at its minor diameter, as Fusion 360 draws it, rounded to the drawing's 3 decimals: itself,
    // but where two threads share the tap drill (#8-32 UNC and #8-36 UNF), the coarse one.
    const formats::Thread* at_minor = formats::match_thread(t.major_mm, std::round(t.minor_mm() * 1000) / 1000, t.inch);
    ASSERT_NE(at_minor, nullptr) << t.name;
    // #5-44 and #12-28 UNF drawn at their minor lie between #5-40's and #12-24's minor and tap drill.
    const bool inside_the_coarse = t.name == "#5-44 UNF" || t.name == "#12-28 UNF";
    if (at_minor->name != t.name && !inside_the_coarse) {
      EXPECT_NEAR(at_minor->tap_drill_mm, t.tap_drill_mm, 1e-9) << t.name << " drawn at its minor read as " << at_minor->name;
    }
  }
  auto name = [](double arc, double hole, bool inch) {
    const formats::Thread* t = formats::match_thread(arc, hole, inch);
    return t ? t->name : std::string("none");
  };
  EXPECT_EQ(name(3.0, 2.459, false), "M3");
  EXPECT_EQ(name(3.0, 2.5, false), "M3");
  EXPECT_EQ(name(10.0, 8.5, false), "M10");
  EXPECT_EQ(name(10.0, 8.8, false), "M10x1.25");
  EXPECT_EQ(name(10.0, 9.0, false), "M10x1");
  EXPECT_EQ(name(3.5, 2.9, false), "M3.5");
  EXPECT_EQ(name(3.505, 2.705, false), "#6-32 UNC");  // no metric thread has that hole: inch after metric
  EXPECT_EQ(name(6.35, 5.105, true), "1/4-20 UNC");
  EXPECT_EQ(name(6.35, 5.41, true), "1/4-28 UNF");
  EXPECT_EQ(name(10.0, 6.2, false), "none");   // a boss around a hole
  EXPECT_EQ(name(7.3, 5.0, false), "none");    // no standard major
  EXPECT_EQ(name(6.0, 3.0, false), "none");    // M6's arc around a hole far below its minor diameter
  EXPECT_EQ(name(6.0, 5.5, false), "none");    // over the tap drill: a clearance hole
  ASSERT_NE(formats::find_thread("M3x0.5"), nullptr);
  EXPECT_EQ(formats::find_thread("M3x0.5")->name, "M3");
  EXPECT_EQ(formats::find_thread("1/4-20")->name, "1/4-20 UNC");
  EXPECT_EQ(formats::find_thread("#10-32")->name, "#10-32 UNF");
  EXPECT_EQ(formats::find_thread("M10 x 1.25")->name, "M10x1.25");
  EXPECT_EQ(formats::find_thread("M7x3"), nullptr);
}

TEST(features_test, callouts_read_in_every_way_cads_write_them) {
  using formats::plain_callout;
  EXPECT_EQ(plain_callout("{\\Fgdt;n}3.4 THRU\\P{\\Fgdt;v}{\\Fgdt;n}6.5 {\\Fgdt;x}3.0", false), "DIA 3.4 THRU CBORE DIA 6.5 DEPTH 3.0");
  EXPECT_EQ(plain_callout("{\\fAIGDT|b0|i0|c0|p0;n}3.4 THRU\\P{\\fAIGDT|b0|i0|c0|p0;w} {\\fAIGDT|b0|i0|c0|p0;n}6.5 X 90%%d", false),
            "DIA 3.4 THRU CSK DIA 6.5 X 90 DEG");
  EXPECT_EQ(plain_callout("n6.6 THRU v n11 x 6.5", true), "DIA 6.6 THRU CBORE DIA 11 DEPTH 6.5");
  EXPECT_EQ(plain_callout("%%c5.5 THRU, C'BORE %%c10 X 5.4 DEEP", false), "DIA 5.5 THRU, C'BORE DIA 10 X 5.4 DEEP");
  EXPECT_EQ(plain_callout("\xE2\x8C\x80" "4.5 THRU \xE2\x8C\xB5 \xE2\x8C\x80" "9.0 X 90\xC2\xB0", false), "DIA 4.5 THRU CSK DIA 9.0 X 90 DEG");
  EXPECT_EQ(plain_callout("\\U+2300 13.5 \\U+2334 \\U+2300 20 \\U+21A7 12.6", false), "DIA 13.5 CBORE DIA 20 DEPTH 12.6");
  EXPECT_EQ(plain_callout("\\A1;\\H2.5;{\\C1;M3x0.5} - 6H", false), "M3X0.5 - 6H");
}

// A drawing with no concentric circle is read as before: the same holes, all plain.
TEST(features_test, drawings_without_features_are_read_as_before) {
  for (const std::string sample : {"plate70", "plate10", "pcb_mixed"}) {
    const std::string dxf = testutil::source_dir() + "/samples/" + sample + ".dxf";
    auto a = acodrill_run("holes " + shell_quote(dxf) + " -q");
    auto b = acodrill_run("holes " + shell_quote(dxf) + " -q --concentric separate");
    EXPECT_EQ(a.out, b.out) << sample;
    auto f = acodrill_run("holes " + shell_quote(dxf) + " --features -q");
    EXPECT_EQ(f.out.find(",undecided,"), std::string::npos);
    EXPECT_EQ(testutil::count_lines(f.out), testutil::count_lines(a.out)) << sample;
  }
}
