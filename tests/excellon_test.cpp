// Excellon in and out: real drill files from Eagle, KiCad, Altium, OrCAD,
// gEDA, Mentor and others (hits cross-checked against gerbv), the dialect
// corners one by one, bad input, and round trips through our reader and gerbv.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <cstdio>

#include "app/errors.h"
#include "formats/readers.h"
#include "formats/writers.h"
#include "app/inputs.h"
#include "test_util.h"

using testutil::data;
using testutil::shell_quote;
using testutil::slurp;
using testutil::spit;

namespace {

struct Hit {
  double x, y, d;
};

std::vector<Hit> hits_csv(const std::string& text) {
  std::vector<Hit> out;
  for (const aco::Hole& h : testutil::read_holes_csv(text)) out.push_back({h.center.x, h.center.y, h.diameter});
  return out;
}

// Same set of (x, y, d) within tol; returns a description of the difference.
std::string diff(std::vector<Hit> got, std::vector<Hit> want, double tol, double dtol) {
  std::string problems;
  std::vector<char> used(got.size(), 0);
  for (const Hit& w : want) {
    bool found = false;
    for (std::size_t i = 0; i < got.size() && !found; ++i) {
      if (std::fabs(got[i].x - w.x) <= tol && std::fabs(got[i].y - w.y) <= tol && std::fabs(got[i].d - w.d) <= dtol) {
        used[i] = 1;  // duplicates in `want` may match one hit: `holes` drops exact duplicates
        found = true;
      }
    }
    if (!found) problems += " missing(" + std::to_string(w.x) + "," + std::to_string(w.y) + ")";
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!used[i]) problems += " extra(" + std::to_string(got[i].x) + "," + std::to_string(got[i].y) + ")";
  }
  return problems;
}

app::LoadedHoles parse(const std::string& text, app::InputOptions o = {}) {
  return formats::parse_excellon("t.drl", text, o);
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const app::UserError& e) {
    return e.where_what();
  }
  return "no error";
}

// The hits alone: slots (G85, routed ovals) skipped, as the oracles list hits.
app::InputOptions hits_only() {
  app::InputOptions o;
  o.slots.policy = formats::SlotPolicy::Skip;
  return o;
}

std::vector<std::string> fixtures() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(data("real-excellon"))) {
    if (std::filesystem::exists(e.path().string() + ".hits.csv")) out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

class ExcellonFixture : public ::testing::TestWithParam<std::string> {};

TEST_P(ExcellonFixture, every_hit_with_its_tool_diameter) {
  const std::string path = GetParam();
  app::LoadedHoles got = app::load_holes(path, hits_only());
  EXPECT_EQ(got.format, app::InputFormat::Excellon) << "chosen by content";
  std::vector<Hit> want = hits_csv(slurp(path + ".hits.csv"));
  std::vector<Hit> mine;
  for (const auto& h : got.holes) mine.push_back({h.center.x, h.center.y, h.diameter});
  EXPECT_EQ(diff(mine, want, 1e-6, 1e-6), "") << path;
  // Every hit is there: distinct positions count the same.
  std::set<std::pair<long long, long long>> distinct;
  for (const Hit& w : want) distinct.insert({std::llround(w.x * 1e5), std::llround(w.y * 1e5)});
  EXPECT_EQ(got.holes.size(), distinct.size()) << path;
}

std::string fixture_name(const ::testing::TestParamInfo<std::string>& param) {
  std::string s = std::filesystem::path(param.param).filename().string();
  for (char& c : s) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}
INSTANTIATE_TEST_SUITE_P(real_files, ExcellonFixture, ::testing::ValuesIn(fixtures()), fixture_name);

TEST(excellon_test, gerber_form_drill_data_is_refused_with_one_line) {
  auto r = testutil::acodrill_run("holes " + shell_quote(data("real-excellon/orcad_rs232_GERBER_FORMAT_drill.drd")) +
                                  " --format csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(testutil::count_lines(r.err), 1);
  EXPECT_THAT(r.err, ::testing::HasSubstr("Gerber"));
}

TEST(excellon_test, zero_suppression_and_formats) {
  // TZ (leading zeros dropped): digits count from the right.
  auto tz = parse("M48\nINCH,TZ\nT1C0.02\n%\nT1\nX1875Y350\nM30\n");
  ASSERT_EQ(tz.holes.size(), 1u);
  EXPECT_NEAR(tz.holes[0].center.x, 0.1875 * 25.4, 1e-9);
  EXPECT_NEAR(tz.holes[0].center.y, 0.035 * 25.4, 1e-9);
  // LZ (trailing zeros dropped): digits count from the left, 2:4 → "03185" = 03.185.
  auto lz = parse("M48\nINCH,LZ\nT1C0.02\n%\nT1\nX03185Y2\nM30\n");
  EXPECT_NEAR(lz.holes[0].center.x, 3.185 * 25.4, 1e-9);
  EXPECT_NEAR(lz.holes[0].center.y, 20.0 * 25.4, 1e-9);
  // METRIC with a 000.000 template and LZ.
  auto m = parse("M48\nMETRIC,LZ,000.000\nT1C0.8\n%\nT1\nX0125Y001\nM30\n");
  EXPECT_NEAR(m.holes[0].center.x, 12.5, 1e-9);
  EXPECT_NEAR(m.holes[0].center.y, 1.0, 1e-9);
  // Explicit decimals, a KiCad FORMAT comment (the last statement wins).
  auto k = parse("M48\n;FORMAT={3:3/ absolute / metric / decimal}\nMETRIC\nT1C0.8\n%\nT1\nX1.5Y-2.25\nM30\n");
  EXPECT_NEAR(k.holes[0].center.x, 1.5, 1e-9);
  EXPECT_NEAR(k.holes[0].center.y, -2.25, 1e-9);
  auto f = parse("M48\n;FILE_FORMAT=2:4\n;FILE_FORMAT=3:3\nMETRIC,TZ\nT1C1\n%\nT1\nX1500Y2\nM30\n");
  EXPECT_NEAR(f.holes[0].center.x, 1.5, 1e-9);
}

TEST(excellon_test, modal_incremental_offsets_and_repeats) {
  auto r = parse("M48\nMETRIC,TZ\nT1C1.0\nT2C1.0\n%\nT1\nX10000Y20000\nY30000\nG91\nX1000\nG90\nG93X100000Y0\nX0Y0\n"
                 "T2\nX0Y0\nR3X1000Y0\nM30\n");
  ASSERT_EQ(r.holes.size(), 8u);
  EXPECT_NEAR(r.holes[1].center.y, 30.0, 1e-9);  // modal X
  EXPECT_NEAR(r.holes[2].center.x, 11.0, 1e-9);  // incremental
  EXPECT_NEAR(r.holes[3].center.x, 100.0, 1e-9) << "G93 moves the zero point";
  EXPECT_EQ(r.holes[4].layer, "T2") << "equal diameters on two tools stay two tools";
  EXPECT_NEAR(r.holes[7].center.x, 103.0, 1e-9) << "R3: three more hits, 1 mm apart";
}

// Issue 25: a step-and-repeat panel (Excellon CNC-7: M25 begins a pattern,
// M01 ends it, each M02 X Y drills it again moved by X Y from the previous
// copy, M08 ends) is read as the copies it makes, tools and slots included.
TEST(excellon_test, step_and_repeat_is_read_as_its_copies) {
  auto r = parse("M48\nMETRIC,TZ\nT1C0.800\nT2C1.000\n%\nG05\nT1\nM25\nX10.000Y10.000\nX20.000Y10.000\nT2\nX15.000Y20.000\n"
                 "G85X15.000Y25.000\nM01\nM02X50.000Y0\nM02X50.000Y0\nM02X0Y40.000\nM08\nT1\nX1.0Y1.0\nM30\n");
  ASSERT_EQ(r.holes.size(), 3u * 4 + 1);
  ASSERT_EQ(r.slots.size(), 4u) << "the pattern's slot in every copy";
  const double expect[][3] = {{10, 10, 0.8}, {20, 10, 0.8}, {15, 20, 1.0}, {60, 10, 0.8},  {70, 10, 0.8},   {65, 20, 1.0}, {110, 10, 0.8},
                              {120, 10, 0.8}, {115, 20, 1.0}, {110, 50, 0.8}, {120, 50, 0.8}, {115, 60, 1.0}, {1, 1, 0.8}};
  for (std::size_t i = 0; i < r.holes.size(); ++i) {
    EXPECT_NEAR(r.holes[i].center.x, expect[i][0], 1e-9) << i;
    EXPECT_NEAR(r.holes[i].center.y, expect[i][1], 1e-9) << i;
    EXPECT_NEAR(r.holes[i].diameter, expect[i][2], 1e-9) << i;
  }
  EXPECT_NEAR(r.slots[3].to.y, 65.0, 1e-9);
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nT1\nM25\nX1Y1\nM01\nM02X1Y0M80\nM30\n"), ::testing::HasSubstr("t.drl:9: a swapped or mirrored"));
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nT1\nX1Y1\nM02X1Y0\nM30\n"), ::testing::HasSubstr("t.drl:7: M02 repeats a pattern"));
}

TEST(excellon_test, units_before_the_header_and_no_header_at_all) {
  auto m71 = parse("M71\nM48\nT1C0.5\n%\nT1\nX1000Y1000\nM30\n");
  EXPECT_NEAR(m71.holes[0].center.x, 1.0, 1e-9);
  EXPECT_NEAR(m71.holes[0].diameter, 0.5, 1e-9);
  auto orcad = parse("%\nT1C0.028F200S100\nX002250Y002300\nM30\n");
  ASSERT_EQ(orcad.holes.size(), 1u);
  EXPECT_NEAR(orcad.holes[0].diameter, 0.7112, 1e-9);
  EXPECT_TRUE(formats::looks_like_excellon("%\nT1C0.028F200S100\nX002250Y002300\n"));
}

TEST(excellon_test, slots_and_routes_are_read_as_slots_or_named_as_not_drilled) {
  // A G85 canned slot, a routed oval (plunge, one straight move, retract: how
  // KiCad writes oval pads), a routed oval cut back and forth (Mentor), a
  // routed corner (routing, not drilling), then a hit.
  auto r = parse("M48\nINCH,TZ\nT1C0.5\n%\nT1\nX0Y0G85X5000Y0\nG00X1000Y1000\nM15\nG01X2000\nM16\nG05\n"
                 "G00X1000Y3000\nM15\nG01Y2500\nY3500\nM17\nG00X0Y0\nM15\nG01X1000\nY1000\nM16\nG05\nX3000Y3000\nM30\n");
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_NEAR(r.holes[0].center.x, 0.3 * 25.4, 1e-9);
  ASSERT_EQ(r.slots.size(), 3u);
  const double in = 25.4;
  EXPECT_NEAR(r.slots[0].from.x, 0.0, 1e-9);
  EXPECT_NEAR(r.slots[0].to.x, 0.5 * in, 1e-9);
  EXPECT_NEAR(r.slots[0].width_mm, 0.5 * in, 1e-9);
  EXPECT_EQ(r.slots[0].source_line, 6u);
  EXPECT_NEAR(r.slots[1].from.x, 0.1 * in, 1e-9);
  EXPECT_NEAR(r.slots[1].to.x, 0.2 * in, 1e-9);
  EXPECT_NEAR(r.slots[1].to.y, 0.1 * in, 1e-9);
  EXPECT_EQ(r.slots[1].source_line, 8u);
  EXPECT_NEAR(std::min(r.slots[2].from.y, r.slots[2].to.y), 0.25 * in, 1e-9);
  EXPECT_NEAR(std::max(r.slots[2].from.y, r.slots[2].to.y), 0.35 * in, 1e-9);
  ASSERT_EQ(r.skipped.size(), 1u);
  EXPECT_EQ(r.skipped[0].line, 18u);
  EXPECT_THAT(r.skipped[0].message, ::testing::HasSubstr("routed path of 2 moves"));
}

TEST(excellon_test, drilled_slots_are_rows_of_holes_ends_first_then_midpoints) {
  const std::string text = "M48\nMETRIC\nT1C1.0\n%\nT1\nX0.0Y0.0G85X2.0Y0.0\nX10.0Y10.0\nM30\n";
  app::InputOptions o;  // the default: drill, pitch a quarter of the width
  app::LoadedHoles in = formats::parse_holes("t.drl", text, o);
  EXPECT_EQ(in.slots_drilled, 1u);
  ASSERT_EQ(in.slot_holes, 9u);  // 2 mm at 0.25 mm: 9 holes
  ASSERT_EQ(in.holes.size(), 10u);
  std::vector<double> xs;
  for (const aco::Hole& h : in.holes) {
    if (h.chain == 0) continue;
    EXPECT_DOUBLE_EQ(h.diameter, 1.0);
    EXPECT_DOUBLE_EQ(h.center.y, 0.0);
    EXPECT_EQ(h.source_line, 6u);
    xs.push_back(h.center.x);
  }
  ASSERT_EQ(xs.size(), 9u);
  EXPECT_DOUBLE_EQ(xs[0], 0.0);
  EXPECT_DOUBLE_EQ(xs[1], 2.0);
  // Every later hole lies midway between two holes already drilled.
  for (std::size_t i = 2; i < xs.size(); ++i) {
    double left = -1e9, right = 1e9;
    for (std::size_t j = 0; j < i; ++j) {
      if (xs[j] < xs[i]) left = std::max(left, xs[j]);
      if (xs[j] > xs[i]) right = std::min(right, xs[j]);
    }
    EXPECT_NEAR(xs[i] - left, right - xs[i], 1e-9) << "hole " << i;
  }
  // --slots skip: no holes, the slot named.
  o.slots.policy = formats::SlotPolicy::Skip;
  app::LoadedHoles skipped = formats::parse_holes("t.drl", text, o);
  EXPECT_EQ(skipped.holes.size(), 1u);
  ASSERT_EQ(skipped.skipped.size(), 1u);
  EXPECT_EQ(skipped.skipped[0].line, 6u);
  EXPECT_THAT(skipped.skipped[0].message, ::testing::HasSubstr("slot 1.000 mm wide from X0.000 Y0.000 to X2.000 Y0.000 mm"));
  // A pitch of the user's.
  o.slots = {formats::SlotPolicy::Drill, 1.0};
  EXPECT_EQ(formats::parse_holes("t.drl", text, o).slot_holes, 3u);
}

TEST(excellon_test, bad_input_names_file_and_line) {
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nX100Y100\nM30\n"), ::testing::HasSubstr("t.drl:5: drill hit before any tool"));
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nT2\nX100Y100\nM30\n"), ::testing::HasSubstr("t.drl:5: tool T2 is not defined"));
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nT1\nhello world\nM30\n"), ::testing::HasSubstr("t.drl:6: unexpected"));
  EXPECT_THAT(error_of("M48\nINCH\nT1C-0.5\n%\nT1\nX1Y1\nM30\n"), ::testing::HasSubstr("t.drl:3: tool T1 has a negative diameter"));
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nT1\nX12a4Y1\nM30\n"), ::testing::HasSubstr("t.drl:6:"));
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.5\n%\nT1\nX1\x01Y1\nM30\n"), ::testing::HasSubstr("control character"));
}

TEST(excellon_test, what_we_write_reads_back_to_the_same_holes_in_our_reader_and_gerbv) {
  testutil::TempDir t;
  for (const char* input : {"real-excellon/eagle_arduino_uno_inch_tz.drd", "real-excellon/unknown_m71_g93_tzsupp.exc",
                            "real-excellon/altium_pic18f14k50_inch_lz_pth_npth.txt"}) {
    const std::string in = data(input);
    auto r = testutil::acodrill_run("plan " + shell_quote(in) + " -o " + shell_quote(t / "p.nc") + " --excellon " +
                                    shell_quote(t / "out.drl") + " -q --iterations 20");
    ASSERT_EQ(r.code, 0) << r.err;
    std::vector<Hit> original;
    for (const auto& h : app::load_holes(in, {}).holes) original.push_back({h.center.x, h.center.y, h.diameter});
    std::vector<Hit> ours;
    for (const auto& h : app::load_holes(t / "out.drl", {}).holes) ours.push_back({h.center.x, h.center.y, h.diameter});
    EXPECT_EQ(ours.size(), original.size()) << input;
    EXPECT_EQ(diff(ours, original, 0.0006, 0.0006), "") << input;

    // gerbv (Debian) reads our file and writes it again in its own Excellon; we read that.
    ASSERT_EQ(std::system("command -v gerbv >/dev/null"), 0) << "gerbv missing: scripts/test installs it";
    auto g = testutil::run("gerbv -x drill -o " + shell_quote(t / "gerbv.drl") + " " + shell_quote(t / "out.drl"));
    ASSERT_EQ(g.code, 0) << g.err;
    std::vector<Hit> theirs;
    for (const auto& h : app::load_holes(t / "gerbv.drl", {}).holes) theirs.push_back({h.center.x, h.center.y, h.diameter});
    EXPECT_EQ(theirs.size(), original.size()) << input;
    // gerbv writes inch 2:4 and 3-decimal diameters: 2.54 µm and 12.7 µm steps.
    EXPECT_EQ(diff(theirs, original, 0.0026, 0.0128), "") << input;
  }
}

TEST(excellon_test, kicad_writer_on_real_boards_gives_the_boards_holes) {
  // tests/data/kicad: written by KiCad 6's EXCELLON_WRITER from its demo boards
  // (tests/kicad/export_kicad_drills.py), with each board's own hole list.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(data("kicad"))) {
    if (e.path().extension() != ".drl") continue;
    const std::string name = e.path().filename().string();
    const std::string board = name.substr(0, name.find(name.find("-inch-") != std::string::npos ? "-inch-" : "-mm-"));
    std::vector<Hit> want = hits_csv(slurp(data("kicad/" + board + ".holes.csv")));
    std::vector<Hit> got;
    const app::LoadedHoles in = app::load_holes(e.path().string(), hits_only());
    for (const auto& h : in.holes) got.push_back({h.center.x, h.center.y, h.diameter});
    const bool inch = name.find("-inch-") != std::string::npos;
    // Positions within half the file's last digit; diameters as KiCad rounds them in inch.
    EXPECT_EQ(diff(got, want, inch ? 0.0026 : 0.0006, 0.013), "") << name;
    EXPECT_EQ(got.size(), want.size()) << name;
    ++files;
  }
  EXPECT_GE(files, 16);
}

// Issue 16: a header that defines T0 makes T0 a tool (gerbv and the EDA tool
// that wrote it read these hits); only an undefined T0 unloads the spindle.
TEST(excellon_test, a_tool_zero_defined_in_the_header_drills) {
  auto in = parse("M48\nMETRIC\nT0C0.006\nT1C0.8\n%\nT0\nX1.0Y2.0\nX3.0Y4.0\nT1\nX5.0Y6.0\nT0\nM30\n");
  ASSERT_EQ(in.holes.size(), 3u);
  EXPECT_DOUBLE_EQ(in.holes[0].diameter, 0.006);
  EXPECT_EQ(in.holes[0].layer, "T0");
  EXPECT_DOUBLE_EQ(in.holes[1].center.y, 4.0);
  EXPECT_DOUBLE_EQ(in.holes[2].diameter, 0.8);
  EXPECT_EQ(error_of("M48\nMETRIC\nT1C0.8\n%\nT1\nX5.0Y6.0\nT0\nX1.0Y1.0\nM30\n"),
            "t.drl:8: drill hit with no tool loaded (T0)");
}

// The contract: `acodrill holes` prints every hit of an Excellon file — slots
// are listed only when asked (--slots drill), so the rows are the file's hits.
TEST(excellon_test, the_holes_command_lists_the_hits_and_drills_slots_only_when_asked) {
  for (const char* name : {"handmade_g85_slot.drl", "mentor_jj1_metric_tz_route.drl"}) {
    const std::string path = data(std::string("real-excellon/") + name);
    auto r = testutil::acodrill_run("holes " + shell_quote(path) + " -q");
    ASSERT_EQ(r.code, 0) << r.err;
    std::set<std::pair<long long, long long>> distinct;
    for (const Hit& w : hits_csv(slurp(path + ".hits.csv"))) distinct.insert({std::llround(w.x * 1e5), std::llround(w.y * 1e5)});
    EXPECT_EQ(testutil::count_lines(r.out) - 1, static_cast<int>(distinct.size())) << name;
    auto drilled = testutil::acodrill_run("holes " + shell_quote(path) + " -q --slots drill");
    ASSERT_EQ(drilled.code, 0);
    EXPECT_GT(testutil::count_lines(drilled.out), testutil::count_lines(r.out)) << name << ": its slots as rows of holes";
  }
}

// Issue 70: drill files that do not state their format, read right or refused.
TEST(excellon_test, units_and_zeros_on_one_line_are_both_read) {
  // Upverter: "M71,TZ" (mm, trailing zeros kept), "M72,LZ" (inch, leading zeros kept).
  auto m71 = parse("M48\nM71,TZ\nT1C0.8\n%\nT1\nX10000Y2500\nM30\n");
  ASSERT_EQ(m71.holes.size(), 1u);
  EXPECT_NEAR(m71.holes[0].center.x, 10.0, 1e-9);
  EXPECT_NEAR(m71.holes[0].center.y, 2.5, 1e-9);
  EXPECT_NEAR(m71.holes[0].diameter, 0.8, 1e-9) << "not 25.4 times too large";
  auto m72 = parse("M48\nM72,LZ\nT1C0.02\n%\nT1\nX015Y0165\nM30\n");
  EXPECT_NEAR(m72.holes[0].center.x, 1.5 * 25.4, 1e-9);
  EXPECT_NEAR(m72.holes[0].center.y, 1.65 * 25.4, 1e-9);
  EXPECT_TRUE(m72.assumptions.size() == 1u && m72.assumptions[0].find("format: 2:4") == 0) << "only the digits were assumed";
}

TEST(excellon_test, numbers_with_leading_zeros_and_varying_length_keep_their_leading_zeros) {
  // PADS without a header: inch, 2:4, trailing zeros dropped.
  auto pads = parse("%\nT1C.035F197S55\nX015Y012\nX021Y0165\nX0305Y01\nM30\n");
  ASSERT_EQ(pads.holes.size(), 3u);
  EXPECT_NEAR(pads.holes[0].center.x, 38.1, 1e-9);
  EXPECT_NEAR(pads.holes[0].center.y, 30.48, 1e-9);
  EXPECT_NEAR(pads.holes[1].center.y, 1.65 * 25.4, 1e-9);
  EXPECT_THAT(pads.assumptions, ::testing::Contains(::testing::HasSubstr("leading zeros kept (the numbers' shapes say so)")));
  EXPECT_THAT(pads.assumptions, ::testing::Contains(::testing::HasSubstr("units: inch")));
  // Leading zeros dropped, trailing kept: the other way.
  auto tz = parse("%\nT1C.035\nX15000Y12000\nX2100Y16500\nM30\n");
  EXPECT_NEAR(tz.holes[1].center.x, 0.21 * 25.4, 1e-9);
}

TEST(excellon_test, allegro_tool_sizes_from_comments_and_the_format_from_nc_param) {
  // Counted per tool against the file's own "Quantity = N" comments.
  for (const std::string name : {"allegro/ncdrill-1-4.drl", "allegro-2/MinnowMax_RevA1_NCDRILL.drl"}) {
    const std::string path = data("real-excellon/" + name);
    app::LoadedHoles got = app::load_holes(path, hits_only());
    EXPECT_TRUE(got.assumptions.empty()) << name << ": nc_param.txt says it all";
    std::map<std::string, std::size_t> per_tool;
    for (const auto& h : got.holes) ++per_tool[h.layer];
    const std::string text = slurp(path);
    std::size_t comments = 0;
    for (std::size_t at = text.find(";T"); at != std::string::npos; at = text.find(";T", at + 1)) {
      const std::string line = text.substr(at, text.find('\n', at) - at);
      const int tool = std::stoi(line.substr(2));
      const std::size_t quantity = std::stoul(line.substr(line.find("Quantity = ") + 11));
      EXPECT_EQ(per_tool["T" + std::to_string(tool)], quantity) << name << " T" << tool;
      ++comments;
    }
    EXPECT_GT(comments, 5u);
  }
  // Without its nc_param.txt the format is nowhere: refused, saying so.
  testutil::TempDir t;
  std::filesystem::copy_file(data("real-excellon/allegro/ncdrill-1-4.drl"), t / "ncdrill.drl");
  try {
    app::load_holes(t / "ncdrill.drl", hits_only());
    ADD_FAILURE() << "read without its format";
  } catch (const app::UserError& e) {
    EXPECT_THAT(e.where_what(), ::testing::HasSubstr("without its nc_param.txt beside it"));
  }
  // The format stated outright reads it too.
  app::InputOptions o = hits_only();
  o.excellon_format = formats::InputOptions::ExcellonFormat{false, 2, 4, true};
  EXPECT_EQ(app::load_holes(t / "ncdrill.drl", o).holes.size(), 287u);
}

TEST(excellon_test, holes_that_make_no_sense_as_read_are_refused_naming_the_option) {
  // Inch assumed for a file written in mm: 38 m wide.
  EXPECT_THAT(error_of("M48\nT1C0.8\n%\nT1\nX10.0Y20.0\nX1500.0Y2500.0\nM30\n"),
              ::testing::AllOf(::testing::HasSubstr("t.drl: the 2 holes as read span"), ::testing::HasSubstr("units: inch"),
                               ::testing::HasSubstr("--excellon-format")));
  // One-digit numbers read with trailing zeros kept: all within a millimetre.
  EXPECT_THAT(error_of("M48\nINCH\nT1C0.02\n%\nT1\nX1Y1\nX2Y1\nX3Y2\nM30\n"),
              ::testing::HasSubstr("the 3 holes as read lie within"));
  app::InputOptions lz;
  lz.excellon_format = formats::InputOptions::ExcellonFormat{false, 2, 4, true};
  auto read = parse("M48\nINCH\nT1C0.02\n%\nT1\nX1Y1\nX2Y1\nX3Y2\nM30\n", lz);
  EXPECT_NEAR(read.holes[2].center.x, 30 * 25.4, 1e-9) << "--excellon-format wins";
  // A file that states its format is taken at its word.
  EXPECT_EQ(parse("M48\nINCH,TZ\n;FILE_FORMAT=2:4\nT1C0.02\n%\nT1\nX1Y1\nX2Y1\nM30\n").holes.size(), 2u);
}

TEST(excellon_test, header_lines_acodrill_does_not_know_are_named) {
  auto r = parse("M48\nINCH,TZ\nFMAT,2\nFROBNICATE,7\nT1C0.02\n%\nT1\nX1000Y1000\nX20000Y1000\nM30\n");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].line, 4u);
  EXPECT_THAT(r.warnings[0].message, ::testing::HasSubstr("FROBNICATE,7"));
  testutil::TempDir t;
  spit(t / "a.drl", "M48\nINCH,TZ\nFROBNICATE,7\nT1C0.02\n%\nT1\nX1000Y1000\nX20000Y1000\nM30\n");
  auto bad = testutil::acodrill_run("holes " + (t / "a.drl") + " --excellon-format inch,2:4");
  EXPECT_EQ(bad.code, 2);
  EXPECT_THAT(bad.err, ::testing::HasSubstr("--excellon-format must be UNITS,I:D,ZEROS"));
  auto ok = testutil::acodrill_run("plan " + (t / "a.drl") + " -o " + (t / "a.nc") + " --report " + (t / "r.json"));
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_THAT(ok.err, ::testing::HasSubstr("warning: 3: header line \"FROBNICATE,7\""));
  EXPECT_THAT(slurp(t / "r.json"), ::testing::HasSubstr("\"input_assumptions\""));
}

// Issue 70: jaseg/gerbonara's corpus, drill files from sixteen EDA tools
// (tests/data/gerbonara-drill/README.md): each read as an independent reader
// reads it — gerbv where it reads the file right, else make_hits.py's
// listing from the format the file states — or refused with one line.
namespace {

struct CorpusFile {
  std::string path;
  enum Oracle { Gerbv, Listing, RoutesOnly, Refused } oracle;
  std::string refusal;  // Refused: what the one line says
};

std::vector<Hit> gerbv_hits(const std::string& path) {
  testutil::TempDir t;
  auto r = testutil::run("gerbv -x drill -o " + (t / "out.drl") + " " + shell_quote(path));
  EXPECT_EQ(r.code, 0) << r.err;
  // gerbv writes INCH,TZ with four decimals: digits / 10^4 inch.
  std::map<int, double> tools;
  int tool = -1;
  std::vector<Hit> hits;
  std::istringstream in(slurp(t / "out.drl"));
  for (std::string l; std::getline(in, l);) {
    int n = 0;
    double d = 0;
    long long x = 0, y = 0;
    char c = 0;
    if (std::sscanf(l.c_str(), "T%dC%lf", &n, &d) == 2) tools[n] = d * 25.4;
    else if (std::sscanf(l.c_str(), "T%d%c", &n, &c) == 1) tool = n;
    else if (std::sscanf(l.c_str(), "X%lldY%lld%c", &x, &y, &c) == 2) hits.push_back({x * 25.4e-4, y * 25.4e-4, tools[tool]});
  }
  return hits;
}

}  // namespace

TEST(excellon_test, every_drill_file_of_sixteen_eda_tools_is_read_right_or_refused) {
  const std::vector<CorpusFile> corpus = {
      {"Target3001/IRNASIoTbank1.2.Drill", CorpusFile::Gerbv, ""},
      {"altium-composite-drill/NC Drill/LimeSDR-QPCIe_1v2-RoundHoles.TXT", CorpusFile::Listing, ""},
      {"altium-composite-drill/NC Drill/LimeSDR-QPCIe_1v2-SlotHoles.TXT", CorpusFile::RoutesOnly, ""},
      {"altium-old-composite-drill.txt", CorpusFile::Gerbv, ""},
      {"diptrace/keyboard.drl", CorpusFile::Gerbv, ""},
      {"diptrace/mainboard.drl", CorpusFile::Gerbv, ""},
      {"diptrace/panel.drl", CorpusFile::Gerbv, ""},
      {"eagle-newer/drills.xln", CorpusFile::Gerbv, ""},
      {"easyeda/Gerber_Drill_NPTH.DRL", CorpusFile::Listing, ""},
      {"easyeda/Gerber_Drill_PTH.DRL", CorpusFile::Listing, ""},
      {"fritzing/combined.txt", CorpusFile::Gerbv, ""},
      {"geda/controller.plated-drill.cnc", CorpusFile::Gerbv, ""},
      {"geda/controller.unplated-drill.cnc", CorpusFile::Gerbv, ""},
      {"geda/driver.plated-drill.cnc", CorpusFile::Gerbv, ""},
      {"geda/driver.unplated-drill.cnc", CorpusFile::Gerbv, ""},
      {"kicad-older/chibi_2024.drl", CorpusFile::Gerbv, ""},
      {"kicad-x2-tests/x2ap/Flashpads-PTH.drl", CorpusFile::Gerbv, ""},
      {"kicad-x2-tests/x2ap/Flashpads-NPTH.drl", CorpusFile::Gerbv, ""},
      {"kicad-x2-tests/nox2noap/Flashpads-PTH.drl", CorpusFile::Gerbv, ""},
      {"ncdrill.DRD", CorpusFile::Gerbv, ""},
      {"orcad/arena_12-12_v6_L1-L6.drl", CorpusFile::Listing, ""},
      {"p-cad/ZXINET.DRL", CorpusFile::Gerbv, ""},
      {"pcb-rnd/power-art.xln", CorpusFile::Gerbv, ""},
      {"siemens-2/NCDrill/ContourPlated.ncd", CorpusFile::RoutesOnly, ""},
      {"siemens-2/NCDrill/ThruHoleNonPlated.ncd", CorpusFile::Gerbv, ""},
      {"siemens-2/NCDrill/ThruHolePlated.ncd", CorpusFile::Gerbv, ""},
      {"siemens/80101_0125_F200_ContourPlated.ncd", CorpusFile::RoutesOnly, ""},
      {"siemens/80101_0125_F200_ThruHoleNonPlated.ncd", CorpusFile::Gerbv, ""},
      {"siemens/80101_0125_F200_ThruHolePlated.ncd", CorpusFile::Gerbv, ""},
      {"upverter/design_export.drl", CorpusFile::Gerbv, ""},
      {"upverter/design_export.xln", CorpusFile::Gerbv, ""},  // Gerber drill data, chosen by content
      {"zuken-emulated/Drill/8seg_Driver__routed_Drill_thru_nplt.fdr", CorpusFile::Refused,
       "holes as read lie within 0.899 mm: the units or the zeros are likely wrong"},
      {"test_syntax_error.exc", CorpusFile::Refused, "test_syntax_error.exc:12: tool T99 is not defined"},
  };
  for (const CorpusFile& c : corpus) {
    SCOPED_TRACE(c.path);
    const std::string path = data("gerbonara-drill/" + c.path);
    if (c.oracle == CorpusFile::Refused) {
      auto r = testutil::acodrill_run("holes " + shell_quote(path));
      EXPECT_EQ(r.code, 2);
      EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
      EXPECT_THAT(r.err, ::testing::HasSubstr(c.refusal));
      continue;
    }
    app::LoadedHoles got = app::load_holes(path, hits_only());
    std::vector<Hit> mine;
    for (const auto& h : got.holes) mine.push_back({h.center.x, h.center.y, h.diameter});
    if (c.oracle == CorpusFile::RoutesOnly) {
      EXPECT_TRUE(mine.empty());
      EXPECT_FALSE(got.skipped.empty()) << "its slots and routes are named";
    } else if (c.oracle == CorpusFile::Listing) {
      EXPECT_EQ(diff(mine, hits_csv(slurp(path + ".hits.csv")), 1e-6, 1e-6), "");
    } else {
      // gerbv prints positions to a tenth of a thou (2.54 µm), tool sizes to a thou (25.4 µm).
      const std::vector<Hit> want = gerbv_hits(path);
      EXPECT_EQ(diff(mine, want, 0.0026, 0.0128), "");
      std::set<std::pair<long long, long long>> distinct;
      for (const Hit& w : want) distinct.insert({std::llround(w.x * 1e3), std::llround(w.y * 1e3)});
      EXPECT_EQ(mine.size(), distinct.size());
    }
  }
}
