// Gerber drill data in (issue 16): real X2 drill files from Ucamco, Proteus and
// KiCad 6's own GERBER_WRITER, each with the holes an independent reader finds
// (tests/data/real-gerber/README.md); KiCad's boards' own pad and via lists as
// a second oracle; traps that are not drill data; RS-274D with an aperture
// list; each RS-274X feature on a small file; and what we write, read back by
// our reader and by gerbv.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "app/errors.h"
#include "app/inputs.h"
#include "formats/readers.h"
#include "test_util.h"

namespace {

using testutil::data;
using testutil::shell_quote;
using testutil::slurp;

struct Row {
  double x, y, d;
};

// x_mm,y_mm,diameter_mm rows of a CSV with a header; duplicates dropped, as `holes` drops them.
std::vector<Row> rows(const std::string& path) {
  std::vector<Row> out;
  std::set<std::tuple<long long, long long, long long>> seen;
  std::istringstream in(slurp(path));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    Row r{};
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &r.x, &r.y, &r.d) != 3) continue;
    if (seen.insert({std::llround(r.x * 1e5), std::llround(r.y * 1e5), std::llround(r.d * 1e5)}).second) out.push_back(r);
  }
  return out;
}

// "" when `got` and `want` hold the same holes (any order), else what differs.
std::string diff(const aco::HoleSet& got, const std::vector<Row>& want, double tol, double d_tol = -1) {
  if (d_tol < 0) d_tol = tol;
  std::string problems;
  std::vector<char> used(got.size(), 0);
  for (const Row& w : want) {
    bool found = false;
    for (std::size_t i = 0; i < got.size() && !found; ++i) {
      if (!used[i] && std::fabs(got[i].center.x - w.x) <= tol && std::fabs(got[i].center.y - w.y) <= tol &&
          std::fabs(got[i].diameter - w.d) <= d_tol) {
        used[i] = 1;
        found = true;
      }
    }
    if (!found) problems += " missing(" + std::to_string(w.x) + "," + std::to_string(w.y) + " D" + std::to_string(w.d) + ")";
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!used[i]) problems += " extra(" + std::to_string(got[i].center.x) + "," + std::to_string(got[i].center.y) + ")";
  }
  return problems;
}

app::InputOptions round_holes_only() {
  app::InputOptions o;
  o.slots.policy = formats::SlotPolicy::Skip;
  return o;
}

app::LoadedHoles parse(const std::string& text, app::InputOptions o = round_holes_only()) {
  return formats::parse_holes("t.gbr", text, o);
}

std::string error_of(const std::string& text, app::InputOptions o = round_holes_only()) {
  try {
    parse(text, o);
  } catch (const app::UserError& e) {
    return e.where_what();
  }
  return "no error";
}

std::vector<std::string> drill_files() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(data("real-gerber"))) {
    const std::string p = e.path().string();
    if (p.find("/traps/") != std::string::npos || p.find("drl_map") != std::string::npos) continue;
    if (std::filesystem::exists(p + ".holes.csv")) out.push_back(p);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> traps() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(data("real-gerber"))) {
    const std::string p = e.path().string();
    const bool map = p.find("drl_map.gbr") != std::string::npos && p.size() > 4 && p.substr(p.size() - 4) == ".gbr";
    if ((p.find("/traps/") != std::string::npos && e.is_regular_file()) || map) out.push_back(p);
  }
  out.push_back(data("real-excellon/orcad_rs232_GERBER_FORMAT_drill.drd"));  // a drill drawing in Gerber form
  std::sort(out.begin(), out.end());
  return out;
}

std::string name_of(const ::testing::TestParamInfo<std::string>& param) {
  std::string s = std::filesystem::path(param.param).filename().string();
  for (char& c : s) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

}  // namespace

class GerberFixture : public ::testing::TestWithParam<std::string> {};

TEST_P(GerberFixture, every_round_flash_is_a_hole_of_its_diameter) {
  const std::string path = GetParam();
  app::LoadedHoles got = app::load_holes(path, round_holes_only());
  EXPECT_EQ(got.format, app::InputFormat::Gerber) << "chosen by content";
  const std::vector<Row> want = rows(path + ".holes.csv");
  EXPECT_EQ(got.holes.size(), want.size()) << path;
  EXPECT_EQ(diff(got.holes, want, 1e-6), "") << path;
  EXPECT_THAT(got.drill_function, ::testing::AnyOf(::testing::StartsWith("Plated"), ::testing::StartsWith("NonPlated")));
  // Flashes of non-round apertures are slots, as the independent reader lists them.
  const std::string other = slurp(path + ".other.csv");
  EXPECT_EQ(got.slots.size(), static_cast<std::size_t>(testutil::count_lines(other) - 1)) << path;
}
INSTANTIATE_TEST_SUITE_P(real_files, GerberFixture, ::testing::ValuesIn(drill_files()), name_of);

class GerberTrap : public ::testing::TestWithParam<std::string> {};

TEST_P(GerberTrap, is_refused_in_one_line_and_never_drilled) {
  testutil::TempDir t;
  auto r = testutil::acodrill_run("plan " + shell_quote(GetParam()) + " -o " + shell_quote(t / "p.nc"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
  EXPECT_THAT(r.err, ::testing::MatchesRegex("acodrill: error: .*:[0-9]+: .*(does not look like drill data|a drill map|a route file).*\n"));
  EXPECT_FALSE(std::filesystem::exists(t / "p.nc"));
}
INSTANTIATE_TEST_SUITE_P(real_files, GerberTrap, ::testing::ValuesIn(traps()), name_of);

// KiCad's own list of the boards' pads and vias (pcbnew), a second oracle:
// round drills are the PTH and NPTH files' holes, oval drills their slots.
TEST(gerber_test, kicad_x2_drill_files_give_the_boards_own_pads_and_vias) {
  int boards = 0;
  for (const char* board : {"ecc83-pp_v2", "flat_hierarchy", "pic_programmer"}) {
    const std::string dir = data(std::string("real-gerber/kicad/") + board);
    aco::HoleSet holes;
    std::vector<formats::Slot> slots;
    for (const char* kind : {"PTH", "NPTH"}) {
      app::LoadedHoles in = app::load_holes(dir + "/x2_mm46/" + board + "-" + kind + "-drl.gbr", round_holes_only());
      holes.insert(holes.end(), in.holes.begin(), in.holes.end());
      slots.insert(slots.end(), in.slots.begin(), in.slots.end());
    }
    std::istringstream csv(slurp(dir + "/holes.csv"));
    std::string line;
    std::getline(csv, line);  // kind,ref,pad,x_mm,y_mm,y_gerber_mm,drill_x_mm,drill_y_mm,shape,plated
    std::vector<Row> round;
    std::size_t ovals = 0;
    while (std::getline(csv, line)) {
      std::vector<std::string> f;
      std::stringstream ss(line);
      for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
      ASSERT_GE(f.size(), 9u) << line;
      const double x = std::stod(f[3]), y = std::stod(f[5]), dx = std::stod(f[6]), dy = std::stod(f[7]);
      if (f[8] == "round") {
        round.push_back({x, y, dx});
        continue;
      }
      ++ovals;
      // An oval drill dx x dy: a slot as wide as the smaller side, centred on the pad.
      bool found = false;
      for (const formats::Slot& s : slots) {
        const double cx = (s.from.x + s.to.x) / 2, cy = (s.from.y + s.to.y) / 2;
        const double length = aco::euclidean(s.from, s.to) + s.width_mm;
        found = found || (std::fabs(cx - x) < 1e-3 && std::fabs(cy - y) < 1e-3 &&
                          std::fabs(s.width_mm - std::min(dx, dy)) < 2e-3 && std::fabs(length - std::max(dx, dy)) < 2e-3);
      }
      EXPECT_TRUE(found) << board << ": oval drill at (" << x << ", " << y << ")";
    }
    EXPECT_EQ(slots.size(), ovals) << board;
    EXPECT_EQ(diff(holes, round, 1e-3), "") << board;
    ++boards;
  }
  EXPECT_EQ(boards, 3);
}

TEST(gerber_test, rs274x_features_one_by_one) {
  const std::string head = "%FSLAX24Y24*%\n%MOIN*%\n%ADD10C,0.0320*%\n";
  // One axis at a time, a bare D03 after a move, G54 before a select.
  auto a = parse(head + "G54D10*\nX10000Y20000D03*\nX15000D03*\nY5000D02*\nD03*\nM02*\n");
  ASSERT_EQ(a.holes.size(), 3u);
  EXPECT_NEAR(a.holes[1].center.x, 1.5 * 25.4, 1e-9);
  EXPECT_NEAR(a.holes[1].center.y, 2.0 * 25.4, 1e-9);
  EXPECT_NEAR(a.holes[2].center.y, 0.5 * 25.4, 1e-9);
  EXPECT_NEAR(a.holes[0].diameter, 0.032 * 25.4, 1e-9);
  EXPECT_EQ(a.holes[2].source_line, 8u);
  // Millimetres (G71), incremental (G91), trailing zeros omitted.
  auto b = parse("%FSTAX33Y33*%\nG71*\n%ADD11C,0.8*%\nD11*\nG91*\nX1Y2D03*\nX1D03*\nM02*\n");
  ASSERT_EQ(b.holes.size(), 2u);
  EXPECT_NEAR(b.holes[0].center.x, 100.0, 1e-9);
  EXPECT_NEAR(b.holes[0].center.y, 200.0, 1e-9);
  EXPECT_NEAR(b.holes[1].center.x, 200.0, 1e-9);
  // Step and repeat: 3 x 2 copies.
  auto c = parse("%FSLAX35Y35*%%MOMM*%%ADD10C,1.0*%D10*%SRX3Y2I10.0J20.0*%X0Y0D03*%SR*%M02*");
  ASSERT_EQ(c.holes.size(), 6u);
  EXPECT_NEAR(c.holes[5].center.x, 20.0, 1e-9);
  EXPECT_NEAR(c.holes[5].center.y, 20.0, 1e-9);
  // %TO object attributes and comments are not D codes; an aperture macro of one circle is a hole.
  auto d = parse("%FSLAX35Y35*%%MOMM*%%AMDOT*1,1,$1,0,0*%%ADD10DOT,0.6*%%TO.C,R1*%G04 D03 in a comment*\nD10*X100000Y0D03*%TD*%M02*");
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_NEAR(d.holes[0].diameter, 0.6, 1e-9);
  // Obround and rectangle flashes are slots along their longer side.
  auto e = parse("%FSLAX35Y35*%%MOMM*%%ADD10O,3.0X1.0*%%ADD11R,1.0X2.0*%D10*X0Y0D03*D11*X1000000Y0D03*M02*");
  ASSERT_EQ(e.slots.size(), 2u);
  EXPECT_NEAR(e.slots[0].from.x, -1.0, 1e-9);
  EXPECT_NEAR(e.slots[0].to.x, 1.0, 1e-9);
  EXPECT_NEAR(e.slots[0].width_mm, 1.0, 1e-9);
  EXPECT_NEAR(e.slots[1].from.y, -0.5, 1e-9);
  EXPECT_NEAR(e.slots[1].to.x, 10.0, 1e-9);
}

TEST(gerber_test, what_cannot_be_drilled_is_refused_with_its_line) {
  const std::string head = "%FSLAX35Y35*%\n%MOMM*%\n%ADD10C,1.0*%\n";
  EXPECT_EQ(error_of(head + "D10*\nX0Y0D02*\nX100000Y0D01*\nM02*\n"),
            "t.gbr:6: this Gerber draws 1 stroke(s) and 0 region edge(s): it does not look like drill data (a copper, "
            "drawing, map or route layer); acodrill drills flashed apertures only and never guesses holes from pads");
  EXPECT_THAT(error_of(head + "G36*\nX0Y0D02*\nX100000Y0D01*\nY100000D01*\nG37*\nM02*\n"), ::testing::HasSubstr("t.gbr:6: this Gerber draws 0 stroke(s) and 2 region edge(s)"));
  EXPECT_THAT(error_of(head + "%LPC*%\nD10*\nX0Y0D03*\nM02*\n"), ::testing::HasSubstr("t.gbr:6: a flash of clear polarity"));
  EXPECT_THAT(error_of(head + "%ADD11P,1.0X6*%\nD11*\nX0Y0D03*\nM02*\n"), ::testing::HasSubstr("t.gbr:6: polygon aperture D11"));
  EXPECT_THAT(error_of(head + "%AMTHERMAL*7,0,0,0.8,0.6,0.1,0*%\n%ADD12THERMAL*%\nD12*\nX0Y0D03*\nM02*\n"),
              ::testing::HasSubstr("t.gbr:7: aperture macro THERMAL is flashed but draws neither a circle nor a slot"));
  EXPECT_THAT(error_of(head + "D13*\nX0Y0D03*\nM02*\n"), ::testing::HasSubstr("t.gbr:4: aperture D13 is not defined"));
  EXPECT_THAT(error_of("%TF.FileFunction,Copper,L1,Top*%\n" + head + "M02*\n"), ::testing::HasSubstr("t.gbr:1: %TF.FileFunction,Copper,L1,Top: this layer is not drill data"));
  EXPECT_THAT(error_of(head + "D10*\nX0Y0D03*\nX12a4D03*\n"), ::testing::HasSubstr("t.gbr:6:"));
  EXPECT_THAT(error_of(head + "%ADD10C,1.0\n"), ::testing::HasSubstr("file ends inside a %...% block"));
}

// RS-274D: no apertures in the file; they come from a list (--apertures).
TEST(gerber_test, rs274d_reads_its_apertures_from_a_list_in_the_common_layouts) {
  const std::string file = "G54D10*\nX010000Y020000D03*\nD11*\nX030000Y020000D03*\nD12*\nX050000Y010000D03*\nM02*\n";
  EXPECT_THAT(error_of(file), ::testing::HasSubstr("t.gbr:1: aperture D10 is not defined (an RS-274D file needs its aperture list: --apertures FILE)"));
  for (const std::string& list : {std::string("D10 C 0.032\nD11 C 0.040\nD12 R 0.060 0.030\n"),
                                 std::string("# wheel\nD10,C,0.032\nD11,ROUND,40MIL\nD12,RECT,60,30,MILS\n"),
                                 std::string("UNITS MILS\nD10 CIRCLE 32\n11 ROUND 40 drill\nD12 OBLONG 60 30\n"),
                                 std::string("UNITS MM\nD10 C 0.8128\nD11 C 1.016MM\nD12 O 1.524 0.762\n"),
                                 std::string("%ADD10C,0.032*%\n%ADD11C,0.040*%\n%ADD12O,0.060X0.030*%\n")}) {
    app::InputOptions o = round_holes_only();
    o.aperture_list = list;
    o.aperture_list_path = "wheel.txt";
    app::LoadedHoles in = parse(file, o);
    ASSERT_EQ(in.holes.size(), 2u) << list;
    EXPECT_NEAR(in.holes[0].center.x, 1.0 * 25.4, 1e-9) << "2.4 inch, leading zeros omitted: " << list;
    EXPECT_NEAR(in.holes[0].diameter, 0.032 * 25.4, 1e-6) << list;
    EXPECT_NEAR(in.holes[1].diameter, 0.040 * 25.4, 1e-6) << list;
    ASSERT_EQ(in.slots.size(), 1u) << list;
    EXPECT_NEAR(in.slots[0].width_mm, 0.030 * 25.4, 1e-6) << list;
  }
  // The README's example list, as printed there.
  const std::string readme = slurp(testutil::source_dir() + "/README.md");
  const auto begin = readme.find("D10 C 0.032            #");
  ASSERT_NE(begin, std::string::npos);
  app::InputOptions documented = round_holes_only();
  documented.aperture_list = readme.substr(begin, readme.find("```", begin) - begin);
  app::LoadedHoles doc = parse("G54D10*\nX010000Y020000D03*\nD11*\nX020000Y020000D03*\nD13*\nX030000Y020000D03*\nD12*\nX040000Y020000D03*\nM02*\n", documented);
  ASSERT_EQ(doc.holes.size(), 3u);
  EXPECT_NEAR(doc.holes[1].diameter, 0.040 * 25.4, 1e-6);
  EXPECT_NEAR(doc.holes[2].diameter, 0.031 * 25.4, 1e-6);
  ASSERT_EQ(doc.slots.size(), 1u);
  EXPECT_NEAR(doc.slots[0].width_mm, 0.030 * 25.4, 1e-6);

  app::InputOptions bad = round_holes_only();
  bad.aperture_list = "D10 C 0.032\nD11 hexagon 3\n";
  bad.aperture_list_path = "wheel.txt";
  EXPECT_THAT(error_of(file, bad), ::testing::HasSubstr("wheel.txt:2: aperture shape \"HEXAGON\""));
}

TEST(gerber_test, what_we_write_reads_back_to_the_same_holes_in_our_reader_and_gerbv) {
  ASSERT_EQ(std::system("command -v gerbv >/dev/null"), 0) << "gerbv missing: scripts/test installs it";
  testutil::TempDir t;
  for (const char* input : {"real-gerber/ucamco_ex2_Plated_1-10_PTH_Drill.gbr", "real-gerber/kicad/ecc83-pp_v2/x2_mm46/ecc83-pp_v2-PTH-drl.gbr",
                            "real-excellon/eagle_arduino_uno_inch_tz.drd"}) {
    const std::string in = data(input);
    auto r = testutil::acodrill_run("plan " + shell_quote(in) + " -o " + shell_quote(t / "p.nc") + " --gerber " +
                                    shell_quote(t / "out.gbr") + " -q --iterations 20");
    ASSERT_EQ(r.code, 0) << r.err;
    // The same holes, slots drilled as rows of holes, in the input's coordinates.
    const aco::HoleSet original = app::load_holes(in, {}).holes;
    std::vector<Row> want;
    for (const aco::Hole& h : original) want.push_back({h.center.x, h.center.y, h.diameter});
    const app::LoadedHoles ours = app::load_holes(t / "out.gbr", {});
    EXPECT_EQ(ours.holes.size(), original.size()) << input;
    // Diameters are the tools' (the generated table rounds them to 1 um).
    EXPECT_EQ(diff(ours.holes, want, 1e-6, 0.0006), "") << input;
    // gerbv reads it and writes it again (inch 3.6, sizes to 4 decimals of an inch); we read that.
    auto g = testutil::run("gerbv -x rs274x -o " + shell_quote(t / "gerbv.gbr") + " " + shell_quote(t / "out.gbr"));
    ASSERT_EQ(g.code, 0) << g.err;
    const app::LoadedHoles theirs = app::load_holes(t / "gerbv.gbr", {});
    EXPECT_EQ(theirs.holes.size(), original.size()) << input;
    // Positions to 1e-6 inch, diameters to 1e-4 inch: gerbv's own precision.
    EXPECT_EQ(diff(theirs.holes, want, 0.00003, 0.0006 + 0.0013), "") << input;
  }
}
