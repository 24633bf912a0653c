// Issue 82: holes as a machinist draws them. Drawings written by ezdxf
// (tests/data/make_feature_cases.py) with the features each holds, computed
// there from ezdxf's own entities and an independent thread table; programs
// read back by LinuxCNC's rs274.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
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
                        " --iterations 5 -q");
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

// The build plate: the program drills 3.4 at the four counterbored
// places and 2.5 (M3's tap drill) at the two tapped ones, nothing at 6.5 or
// 2.459, as LinuxCNC's interpreter reads it; the header and the summary say
// what it does not make. --concentric separate drills every circle through.
TEST(features_test, the_build_plate_drills_each_hole_once_at_its_drill_and_never_the_counterbore) {
  testutil::TempDir t;
  for (const std::string name : {"build_plate", "build_plate_no_callout", "m6_tapped_and_counterbored"}) {
    const std::vector<Row> want = expected_rows(testutil::data("dxf-features/" + name + ".features.csv"));
    auto r = acodrill_run("plan " + shell_quote(drawing(name)) + " -o " + t / "p.nc" +
                          " --dialect linuxcnc --origin drawing --iterations 20");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string program = slurp(t / "p.nc");
    const oracles::Canon canon = oracles::run_rs274(t / "p.nc");
    const std::map<int, double> tools = oracles::tool_diameters(program);
    ASSERT_EQ(canon.made.size(), want.size()) << name;
    for (const Row& w : want) {
      const auto m = std::find_if(canon.made.begin(), canon.made.end(), [&](const oracles::Made& k) {
        return std::fabs(k.x - w.x) <= 0.0006 && std::fabs(k.y - w.y) <= 0.0006;
      });
      ASSERT_NE(m, canon.made.end()) << name << ": nothing made at " << w.x << "," << w.y;
      EXPECT_NEAR(tools.at(m->tool), w.drill, 1e-3) << name << " at " << w.x << "," << w.y;
      EXPECT_EQ(m->path_radius, 0.0) << "drilled, not milled";
    }
    // What the program does not make is said where the operator reads it.
    std::size_t said = 0;
    for (std::size_t at = program.find("(NOT MADE: "); at != std::string::npos; at = program.find("(NOT MADE: ", at + 1)) ++said;
    std::size_t not_plain = 0;
    for (const Row& w : want) not_plain += w.kind != "plain";
    EXPECT_EQ(said, not_plain) << program;
    EXPECT_EQ(acodrill_run("verify " + t / "p.nc" + " --holes " + shell_quote(drawing(name)) + " -q").code, 0) << name;
  }
  auto with_callout = acodrill_run("plan " + shell_quote(drawing("build_plate")) + " -o " + t / "p.nc" + " --iterations 5");
  EXPECT_THAT(with_callout.err, ::testing::HasSubstr("hole features: 2 tapped (M3), 4 counterbored"));
  EXPECT_THAT(with_callout.err, ::testing::HasSubstr("warning: 2 tapped hole(s) (M3 x2) drilled at the tap drill (M3 2.5 mm)"));
  auto without = acodrill_run("plan " + shell_quote(drawing("build_plate_no_callout")) + " -o " + t / "p.nc" + " --iterations 5");
  EXPECT_EQ(without.code, 0);
  EXPECT_THAT(without.err, ::testing::HasSubstr("warning: 4 circle(s) around a smaller hole (D6.5 x4) not machined"));
  auto separate = acodrill_run("holes " + shell_quote(drawing("build_plate")) + " --concentric separate -q");
  EXPECT_EQ(testutil::read_holes_csv(separate.out).size(), 10u) << "every circle, as before issue 82";
  auto bad = acodrill_run("holes " + shell_quote(drawing("build_plate")) + " --concentric sometimes");
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr("--concentric must be features or separate"));
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
