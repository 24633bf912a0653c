// IPC-2581 and ODB++ in (issue 86). The oracles: KiCad 9's own Excellon
// export of the same demo boards, plated and non-plated apart
// (tests/data/boards/make_boards.sh); an Altium ODB++ job listed by an
// independent reader of our own (tests/boards/odb_holes.py, its own ctest)
// and sized by Altium's board report; panels whose copies are computed here
// by hand; and bad input, one line each.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>
#include <vector>

#include "formats/archive.h"
#include "formats/error.h"
#include "formats/holes.h"
#include "test_util.h"

namespace {

using testutil::data;
using testutil::shell_quote;
using testutil::slurp;

formats::InputOptions drilled_slots() {
  formats::InputOptions o;
  o.slots.policy = formats::SlotPolicy::Drill;
  return o;
}

// Every hole of `got` matches one of `want` within `tolerance_mm` (position and diameter), and the counts agree.
void expect_same_holes(const aco::HoleSet& got, const aco::HoleSet& want, double tolerance_mm, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  std::vector<bool> used(want.size(), false);
  std::size_t unmatched = 0;
  for (const aco::Hole& g : got) {
    bool found = false;
    for (std::size_t k = 0; k < want.size() && !found; ++k) {
      if (used[k]) continue;
      const aco::Hole& w = want[k];
      if (std::fabs(g.center.x - w.center.x) <= tolerance_mm && std::fabs(g.center.y - w.center.y) <= tolerance_mm &&
          std::fabs(g.diameter - w.diameter) <= tolerance_mm) {
        used[k] = found = true;
      }
    }
    if (!found && ++unmatched <= 3) ADD_FAILURE() << what << ": no match for X" << g.center.x << " Y" << g.center.y << " D" << g.diameter;
  }
  EXPECT_EQ(unmatched, 0u) << what;
}

aco::HoleSet holes_of(const std::string& path, const formats::InputOptions& options = drilled_slots()) {
  return formats::parse_holes(path, slurp(path), options).holes;
}

struct Board {
  std::string name, ipc, odb;
  bool has_slots;
};

const Board kBoards[] = {
    {"pic_programmer", "pic_programmer.ipc2581.zip", "pic_programmer.odb.zip", false},
    {"ecc83-pp_v2", "ecc83-pp_v2.ipc2581.xml", "ecc83-pp_v2.odb.tgz", true},
    {"kit-dev-coldfire-xilinx_5213", "kit-dev-coldfire-xilinx_5213.ipc2581.zip", "kit-dev-coldfire-xilinx_5213.odb.tgz", true},
};

// The holes of IPC-2581 and ODB++ equal KiCad's Excellon export of the same
// board: plated to -PTH.drl, non-plated to -NPTH.drl, each a source of its
// own. Round holes within 1 µm. Slots are drilled as rows of holes: ODB++
// gives their ends exactly (within 1 µm), IPC-2581 only their outline, a
// polygon KiCad approximates within its 5 µm arc error: within 10 µm.
TEST(Boards, HolesEqualKiCadsOwnDrillFiles) {
  for (const Board& b : kBoards) {
    const std::string dir = data("boards/" + b.name + "/");
    const aco::HoleSet pth = holes_of(dir + b.name + "-PTH.drl");
    const aco::HoleSet npth = holes_of(dir + b.name + "-NPTH.drl");
    for (const std::string& file : {b.ipc, b.odb}) {
      const bool ipc = file == b.ipc;
      const std::vector<formats::LoadedHoles> sources = formats::parse_sources(dir + file, slurp(dir + file), drilled_slots());
      ASSERT_EQ(sources.size(), npth.empty() ? 1u : 2u) << file;
      EXPECT_EQ(sources.front().format, ipc ? formats::InputFormat::Ipc2581 : formats::InputFormat::Odb);
      const double tolerance = ipc && b.has_slots ? 0.010 : 0.001;
      expect_same_holes(sources[0].holes, pth, tolerance, file + " plated");
      EXPECT_EQ(sources[0].drill_function.rfind("Plated,1,", 0), 0u) << sources[0].drill_function;
      if (!npth.empty()) {
        expect_same_holes(sources[1].holes, npth, 0.001, file + " non-plated");
        EXPECT_EQ(sources[1].source_label, "non-plated");
        EXPECT_EQ(sources[1].drill_function.rfind("NonPlated,1,", 0), 0u) << sources[1].drill_function;
      }
      // Round holes alone (slots skipped) match within 1 µm, IPC-2581 too.
      formats::InputOptions skip;
      skip.slots.policy = formats::SlotPolicy::Skip;
      const formats::LoadedHoles all = formats::parse_holes(dir + file, slurp(dir + file), skip);
      aco::HoleSet want = holes_of(dir + b.name + "-PTH.drl", skip);
      for (const aco::Hole& h : holes_of(dir + b.name + "-NPTH.drl", skip)) want.push_back(h);
      expect_same_holes(all.holes, want, 0.001, file + " round holes");
      EXPECT_EQ(all.skipped.size(), b.has_slots ? (b.name == "ecc83-pp_v2" ? 9u : 3u) : 0u) << file;
    }
  }
}

TEST(Boards, TheSummarySaysStepLayersAndBoardSize) {
  const std::string dir = data("boards/pic_programmer/");
  const auto ipc = formats::parse_sources(dir + "pic_programmer.ipc2581.zip", slurp(dir + "pic_programmer.ipc2581.zip"), {});
  // KiCad's Edge.Cuts of the demo: 73.66..233.68 x 40.64..139.70 mm.
  EXPECT_EQ(ipc.front().description,
            "IPC-2581 rev C, step pic_programmer; drill layers top_layer_bottom_layer (251); board 160.020 x 99.060 mm");
  const auto odb = formats::parse_sources(dir + "pic_programmer.odb.zip", slurp(dir + "pic_programmer.odb.zip"), {});
  EXPECT_THAT(odb.front().description, ::testing::HasSubstr("ODB++, step PCB; drill layers"));
  EXPECT_THAT(odb.front().description, ::testing::HasSubstr("DRILL_NON-PLATED_TOP_LAYER-BOTTOM_LAYER (6)"));
  EXPECT_THAT(odb.front().description, ::testing::HasSubstr("board 160.020 x 99.060 mm"));
  // A source the filters empty is dropped; its count and the file's description stay.
  formats::InputOptions big;
  big.dxf.min_diameter_mm = 4.0;
  const auto only = formats::parse_sources(dir + "pic_programmer.odb.zip", slurp(dir + "pic_programmer.odb.zip"), big);
  ASSERT_EQ(only.size(), 1u);
  EXPECT_EQ(only[0].holes.size(), 6u);  // the 4.3 mm mounting holes, non-plated
  EXPECT_EQ(only[0].skipped_by_filter, 245u);
  EXPECT_EQ(only[0].source_label, "");
  EXPECT_EQ(only[0].drill_function, "NonPlated,1,2,NPTH,Drill");
  EXPECT_THAT(only[0].description, ::testing::HasSubstr("ODB++, step PCB"));
}

// The Altium job: its profile is the board Altium's own report sizes ("Board Size, 152.4mmx79.5mm").
TEST(Boards, AltiumJobFolderIsSizedAsAltiumsReportSays) {
  const std::string report = slurp(data("boards/altium-praxis/board-report-head.txt"));
  ASSERT_THAT(report, ::testing::HasSubstr("Board Size, 152.4mmx79.5mm"));
  testutil::TempDir t;
  auto r = testutil::acodrill_run("holes " + shell_quote(data("boards/altium-praxis/odb")) + " --format csv");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, ::testing::HasSubstr("639 holes from odb++"));
  EXPECT_THAT(r.err, ::testing::HasSubstr("board 152.400 x 79.500 mm"));
  EXPECT_THAT(r.err, ::testing::HasSubstr("4 feature(s)"));  // its four L records: slots, listed apart
}

// plan takes a board job as drill files: one program, plated then
// non-plated, and verify finds every hole drilled once with the right tool.
TEST(Boards, PlanAndVerifyAFolderATgzAndAZip) {
  testutil::TempDir t;
  for (const std::string& input : {data("boards/altium-praxis/odb"), data("boards/ecc83-pp_v2/ecc83-pp_v2.odb.tgz"),
                                   data("boards/pic_programmer/pic_programmer.ipc2581.zip")}) {
    const std::string program = t / "p.nc", report = t / "r.json";
    auto r = testutil::acodrill_run("plan " + shell_quote(input) + " -o " + shell_quote(program) + " --report " +
                                    shell_quote(report) + " --iterations 30 --machine pcb-drill");
    ASSERT_EQ(r.code, 0) << input << ": " << r.err;
    auto v = testutil::acodrill_run("verify " + shell_quote(program) + " --holes " + shell_quote(input));
    EXPECT_EQ(v.code, 0) << input << ": " << v.out << v.err;
    EXPECT_THAT(v.out, ::testing::HasSubstr("drilled once each with the right tool"));
  }
  // The PCB's two sources: the report lists them as two inputs, plated first.
  const std::string pic = data("boards/pic_programmer/pic_programmer.odb.zip");
  auto r = testutil::acodrill_run("plan " + shell_quote(pic) + " -o " + shell_quote(t / "p.nc") + " --report " +
                                  shell_quote(t / "r.json") + " --iterations 30");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string json = slurp(t / "r.json");
  // A board, as its drill files are: the same depth through 1.6 mm of PCB, the same speeds.
  const std::string drl = data("boards/pic_programmer/pic_programmer-PTH.drl"), npth = data("boards/pic_programmer/pic_programmer-NPTH.drl");
  auto e = testutil::acodrill_run("plan " + shell_quote(drl) + " " + shell_quote(npth) + " -o " + shell_quote(t / "e.nc") + " --iterations 30");
  ASSERT_EQ(e.code, 0) << e.err;
  auto cycle_words = [](const std::string& program) {
    std::vector<std::string> out;
    std::istringstream in(program);
    for (std::string line; std::getline(in, line);) {
      if (line.find(" G8") == std::string::npos && line.rfind("G8", 0) != 0) continue;
      std::string words;
      for (const char* w : {" Z", " R", " F", " Q"}) {
        const std::size_t at = line.find(w);
        if (at != std::string::npos) words += line.substr(at, line.find(' ', at + 1) - at);
      }
      out.push_back(words);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(cycle_words(slurp(t / "p.nc")), cycle_words(slurp(t / "e.nc")));
  EXPECT_THAT(json, ::testing::ContainsRegex("pic_programmer.odb.zip \\(plated\\)\"[^}]*\"holes\": *245"));
  EXPECT_THAT(json, ::testing::ContainsRegex("pic_programmer.odb.zip \\(non-plated\\)\"[^}]*\"holes\": *6"));
}

// A panel: step "pcb" (two holes) placed 2 x 3 by the panel step, its datum
// at (5, 5), every copy turned 90° (ODB++: clockwise; IPC-2581: counter-clockwise).
struct Copy {
  double x, y;
};
aco::HoleSet expected_panel(double turn_deg) {
  aco::HoleSet out;
  const double rad = turn_deg * 3.14159265358979323846 / 180.0;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (auto [px, py, d] : {std::tuple{10.0, 5.0, 1.0}, std::tuple{20.0, 15.0, 3.2}}) {
        const double lx = px - 5.0, ly = py - 5.0;  // from the board's datum
        aco::Hole h;
        h.center = {100.0 + i * 60.0 + lx * std::cos(rad) - ly * std::sin(rad), 50.0 + j * 40.0 + lx * std::sin(rad) + ly * std::cos(rad)};
        h.diameter = d;
        out.push_back(h);
      }
    }
  }
  return out;
}

std::string odb_panel_tar(const std::string& features) {
  const std::string matrix =
      "STEP {\n COL=1\n NAME=PCB\n}\nSTEP {\n COL=2\n NAME=PANEL\n}\n"
      "LAYER {\n ROW=1\n CONTEXT=BOARD\n TYPE=SIGNAL\n NAME=TOP\n}\n"
      "LAYER {\n ROW=2\n CONTEXT=BOARD\n TYPE=SIGNAL\n NAME=BOTTOM\n}\n"
      "LAYER {\n ROW=3\n CONTEXT=BOARD\n TYPE=DRILL\n NAME=DRILL\n START_NAME=TOP\n END_NAME=BOTTOM\n}\n";
  const std::string pcb_hdr = "UNITS=MM\nX_DATUM=5\nY_DATUM=5\n";
  const std::string panel_hdr =
      "UNITS=MM\nX_DATUM=0\nY_DATUM=0\nSTEP-REPEAT {\n NAME=PCB\n X=100\n Y=50\n DX=60\n DY=40\n NX=2\n NY=3\n ANGLE=270\n MIRROR=NO\n}\n";
  return formats::pack_tar({{"job/matrix/matrix", matrix},
                            {"job/steps/pcb/stephdr", pcb_hdr},
                            {"job/steps/panel/stephdr", panel_hdr},
                            {"job/steps/pcb/layers/drill/features", features}});
}

TEST(Boards, OdbPanelStepRepeatsItsBoard) {
  // ODB++ symbols: microns in a metric file.
  const std::string features = "UNITS=MM\n$0 r1000\n$1 r3200\n#\nP 10 5 0 P 0 0\nP 20 15 1 P 0 8 45.0 ;0=0\n";
  const std::string tar = odb_panel_tar(features);
  // ANGLE=270 clockwise is 90 counter-clockwise.
  const formats::LoadedHoles panel = formats::parse_holes("panel.tar", tar, {});
  expect_same_holes(panel.holes, expected_panel(90), 1e-9, "panel");
  // --step chooses the board alone; a step that is not there names those that are.
  formats::InputOptions o;
  o.step = "pcb";
  EXPECT_EQ(formats::parse_holes("panel.tar", tar, o).holes.size(), 2u);
  o.step = "nope";
  try {
    formats::parse_holes("panel.tar", tar, o);
    ADD_FAILURE() << "an unknown step was read";
  } catch (const formats::InputError& e) {
    EXPECT_THAT(e.where_what(), ::testing::HasSubstr("--step nope: no such step; the job's steps: PCB, PANEL"));
  }
  // The same job, gzipped: a .tgz.
  testutil::TempDir t;
  testutil::spit(t / "job.tar", tar);
  ASSERT_EQ(std::system(("gzip -n " + shell_quote(t / "job.tar")).c_str()), 0);
  expect_same_holes(holes_of(t / "job.tar.gz"), expected_panel(90), 1e-9, "panel.tgz");
  // An inch job: coordinates in inch, round symbols in mils.
  const std::string inch = "UNITS=INCH\n$0 r100\n#\nP 1 2 0 P 0 0\n";
  o.step = "pcb";
  const formats::LoadedHoles one = formats::parse_holes("inch.tar", odb_panel_tar(inch), o);
  ASSERT_EQ(one.holes.size(), 1u);
  EXPECT_NEAR(one.holes[0].center.x, 25.4, 1e-9);
  EXPECT_NEAR(one.holes[0].center.y, 50.8, 1e-9);
  EXPECT_NEAR(one.holes[0].diameter, 2.54, 1e-9);
}

std::string ipc_panel(const std::string& extra_layer, const std::string& board_holes) {
  return "<?xml version=\"1.0\"?>\n<IPC-2581 revision=\"B\" xmlns=\"http://webstds.ipc.org/2581\">\n"
         "<Ecad name=\"x\"><CadHeader units=\"MILLIMETER\"/><CadData>\n"
         "<Layer name=\"TOP\" layerFunction=\"CONDUCTOR\" side=\"TOP\"/>\n"
         "<Layer name=\"IN1\" layerFunction=\"CONDUCTOR\" side=\"INTERNAL\"/>\n"
         "<Layer name=\"BOT\" layerFunction=\"CONDUCTOR\" side=\"BOTTOM\"/>\n"
         "<Layer name=\"D\" layerFunction=\"DRILL\" side=\"ALL\"><Span fromLayer=\"TOP\" toLayer=\"BOT\"/></Layer>\n" +
         extra_layer +
         "<Step name=\"board\" type=\"BOARD\"><Datum x=\"5\" y=\"5\"/>\n<LayerFeature layerRef=\"D\">\n" + board_holes +
         "</LayerFeature></Step>\n"
         "<Step name=\"panel\" type=\"PANEL\"><Datum x=\"0\" y=\"0\"/>\n"
         "<StepRepeat stepRef=\"board\" x=\"100\" y=\"50\" nx=\"2\" ny=\"3\" dx=\"60\" dy=\"40\" angle=\"90\" mirror=\"false\"/>\n"
         "</Step>\n</CadData></Ecad>\n</IPC-2581>\n";
}

TEST(Boards, Ipc2581PanelStepRepeatsItsBoard) {
  const std::string holes =
      "<Set><Hole name=\"H1\" diameter=\"1\" platingStatus=\"PLATED\" x=\"10\" y=\"5\"/></Set>\n"
      "<Set><Hole name=\"H2\" diameter=\"3.2\" platingStatus=\"NONPLATED\" x=\"20\" y=\"15\"/></Set>\n";
  const std::string xml = ipc_panel("", holes);
  expect_same_holes(formats::parse_holes("p.xml", xml, {}).holes, expected_panel(90), 1e-9, "panel");
  // Windows tools start their XML with a byte order mark.
  expect_same_holes(formats::parse_holes("bom.xml", "\xEF\xBB\xBF" + xml, {}).holes, expected_panel(90), 1e-9, "with a BOM");
  const auto sources = formats::parse_sources("p.xml", xml, {});
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[0].holes.size(), 6u);  // H1 in each copy, plated
  EXPECT_EQ(sources[1].holes.size(), 6u);
  EXPECT_EQ(sources[1].drill_function, "NonPlated,1,3,NPTH,Drill");
  // A blind span is a source of its own, named in a warning, not merged with the through-holes.
  const std::string blind = ipc_panel("<Layer name=\"B\" layerFunction=\"DRILL\" side=\"TOP\"><Span fromLayer=\"TOP\" toLayer=\"IN1\"/></Layer>\n",
                                      holes + "</LayerFeature><LayerFeature layerRef=\"B\"><Set><Hole name=\"V\" diameter=\"0.2\" x=\"7\" y=\"7\"/></Set>\n");
  formats::InputOptions o;
  o.step = "board";
  const auto three = formats::parse_sources("b.xml", blind, o);
  ASSERT_EQ(three.size(), 3u);
  EXPECT_EQ(three[2].source_label, "plated, blind 1-2");
  EXPECT_EQ(three[2].drill_function, "Plated,1,2,Blind,Drill");
  ASSERT_EQ(three[0].warnings.size(), 1u);
  EXPECT_THAT(three[0].warnings[0].message, ::testing::HasSubstr("drill layer B spans conductor layers 1-2 of 3"));
  // A back-drill layer: not plated, a source of its own, named.
  const std::string back = ipc_panel("<Layer name=\"BD\" layerFunction=\"BACKDRILL\" side=\"BOTTOM\"/>\n",
                                     holes + "</LayerFeature><LayerFeature layerRef=\"BD\"><Set><Hole name=\"V\" diameter=\"0.5\" x=\"7\" y=\"7\"/></Set>\n");
  const auto backs = formats::parse_sources("bd.xml", back, o);
  ASSERT_EQ(backs.size(), 3u);
  EXPECT_EQ(backs[2].source_label, "non-plated, back-drill 1-3");
  EXPECT_EQ(backs[2].drill_function, "NonPlated,1,3,Blind,Drill");
  ASSERT_EQ(backs[0].warnings.size(), 1u);
  EXPECT_THAT(backs[0].warnings[0].message, ::testing::HasSubstr("drill layer BD is a back-drill: its holes are a source of their own"));
  // Inch, and an oval slot turned by its Xform.
  std::string inch = ipc_panel("", "<Set><SlotCavity name=\"S\" platingStatus=\"PLATED\"><Location x=\"1\" y=\"1\"/>"
                                   "<Xform rotation=\"90\"/><Oval width=\"0.2\" height=\"0.1\"/></SlotCavity></Set>\n");
  inch.replace(inch.find("MILLIMETER"), 10, "INCH");
  formats::InputOptions s;
  s.step = "board";
  s.slots.policy = formats::SlotPolicy::Skip;
  const formats::LoadedHoles slot = formats::parse_holes("s.xml", inch, s);
  ASSERT_EQ(slot.skipped.size(), 1u);
  EXPECT_THAT(slot.skipped[0].message, ::testing::HasSubstr("slot 2.540 mm wide from X25.400 Y24.130 to X25.400 Y26.670 mm"));
}

// Bad input: one line naming the file (and the entry and line), exit 2, nothing written.
TEST(Boards, BadInputIsOneLineAndNothingIsWritten) {
  testutil::TempDir t;
  const std::string good_ipc = slurp(data("boards/ecc83-pp_v2/ecc83-pp_v2.ipc2581.xml"));
  const std::string features = "UNITS=MM\n$0 r1000\n#\nP 10 5 0 P 0 0\nP 11 5 7 P 0 0\n";
  struct Case {
    std::string name, bytes, want;
  };
  const std::vector<Case> cases = {
      {"cut.xml", good_ipc.substr(0, good_ipc.size() / 2), "cut.xml:"},
      {"noecad.xml", "<IPC-2581 revision=\"C\"><Content/></IPC-2581>", "noecad.xml:1: IPC-2581 without <Ecad><CadData>"},
      {"nodrill.xml", "<IPC-2581><Ecad><CadHeader units=\"MILLIMETER\"/><CadData><Layer name=\"T\" layerFunction=\"CONDUCTOR\"/>"
                      "<Step name=\"s\"/></CadData></Ecad></IPC-2581>",
       "nodrill.xml:1: no drill layer"},
      {"badnum.xml", ipc_panel("", "<Set><Hole diameter=\"wide\" x=\"1\" y=\"1\"/></Set>"), "badnum.xml:10: diameter=\"wide\" is not a number"},
      {"nomatrix.tar", formats::pack_tar({{"job/steps/pcb/stephdr", "UNITS=MM\n"}}),
       "nomatrix.tar: an archive with neither an ODB++ job (no matrix/matrix) nor one IPC-2581 file; it holds job/steps/pcb/stephdr"},
      {"symbol.tar", odb_panel_tar(features), "symbol.tar:job/steps/pcb/layers/drill/features:5: symbol 7 is not defined"},
      {"cut.tgz", slurp(data("boards/ecc83-pp_v2/ecc83-pp_v2.odb.tgz")).substr(0, 20000), "cut.tgz: the compressed data ends early"},
      {"cut.zip", slurp(data("boards/pic_programmer/pic_programmer.odb.zip")).substr(0, 20000), "cut.zip: a zip archive without its directory"},
      {"empty.zip", std::string("PK\5\6", 4) + std::string(18, '\0'), "empty.zip: an archive with neither an ODB++ job (no matrix/matrix) nor one IPC-2581 file (it is empty)"},
  };
  for (const Case& c : cases) {
    testutil::spit(t / c.name, c.bytes);
    auto r = testutil::acodrill_run("plan " + shell_quote(t / c.name) + " -o " + shell_quote(t / "out.nc"));
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr("acodrill: error: " + t / c.want)) << c.name;
    EXPECT_FALSE(std::filesystem::exists(t / "out.nc")) << c.name;
  }
  // A folder that is no ODB++ job, and a job of two steps with no panel.
  std::filesystem::create_directories(t / "plain");
  auto r = testutil::acodrill_run("plan " + shell_quote(t / "plain") + " -o " + shell_quote(t / "out.nc"));
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("is a directory, not an ODB++ job folder (it has no matrix/matrix)"));
  std::string two = ipc_panel("", "<Set><Hole diameter=\"1\" x=\"1\" y=\"1\"/></Set>");
  two.replace(two.find("<StepRepeat"), two.find("/>", two.find("<StepRepeat")) + 2 - two.find("<StepRepeat"), "");
  testutil::spit(t / "two.xml", two);
  r = testutil::acodrill_run("holes " + shell_quote(t / "two.xml") + " --format csv");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("the job has 2 steps (board, panel); say which to drill with --step NAME"));
  r = testutil::acodrill_run("holes " + shell_quote(t / "two.xml") + " --format csv --step board");
  EXPECT_EQ(r.code, 0) << r.err;
}

// The folder, its .tgz and its .zip are one job: the same holes in the same order.
TEST(Boards, FolderTarAndArchivesReadAlike) {
  testutil::TempDir t;
  const std::string folder = data("boards/altium-praxis/odb");
  ASSERT_EQ(std::system(("cd " + shell_quote(folder) + "/.. && tar czf " + shell_quote(t / "job.tgz") + " odb && " +
                         "zip -qr " + shell_quote(t / "job.zip") + " odb")
                            .c_str()),
            0);
  const auto a = testutil::acodrill_run("holes " + shell_quote(folder) + " --format csv");
  const auto b = testutil::acodrill_run("holes " + shell_quote(t / "job.tgz") + " --format csv");
  const auto c = testutil::acodrill_run("holes " + shell_quote(t / "job.zip") + " --format csv");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(a.out, c.out);
  EXPECT_GT(std::count(a.out.begin(), a.out.end(), '\n'), 600);
}

}  // namespace
