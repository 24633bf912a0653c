// The DXF reader against files written by ezdxf and real CAD exports (each
// with the holes ezdxf finds), and stage by stage on small inline DXF strings.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "dxf/reader.h"
#include "test_util.h"

using testutil::data;

namespace {

// Holes as a multiset within 1e-6 mm; returns what does not match.
std::string compare_sets(const aco::HoleSet& got, const aco::HoleSet& want) {
  std::vector<char> used(got.size(), 0);
  std::string problems;
  for (const aco::Hole& w : want) {
    bool found = false;
    for (std::size_t i = 0; i < got.size(); ++i) {
      if (!used[i] && std::fabs(got[i].center.x - w.center.x) <= 1e-6 && std::fabs(got[i].center.y - w.center.y) <= 1e-6 &&
          std::fabs(got[i].diameter - w.diameter) <= 1e-6) {
        used[i] = 1;
        found = true;
        break;
      }
    }
    if (!found) problems += " missing(" + std::to_string(w.center.x) + "," + std::to_string(w.center.y) + ")";
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!used[i]) problems += " extra(" + std::to_string(got[i].center.x) + "," + std::to_string(got[i].center.y) + ")";
  }
  return problems;
}

std::vector<std::string> fixtures(const std::string& folder) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(data(folder))) {
    if (e.path().extension() == ".dxf") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A minimal R12-style DXF around the given ENTITIES body (and optional BLOCKS body).
std::string dxf_doc(const std::string& entities, const std::string& blocks = "", const std::string& header = "") {
  std::string s = "0\nSECTION\n2\nHEADER\n" + header + "0\nENDSEC\n";
  if (!blocks.empty()) s += "0\nSECTION\n2\nBLOCKS\n" + blocks + "0\nENDSEC\n";
  s += "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
  return s;
}

std::string circle(double x, double y, double r, const std::string& extra = "", const std::string& layer = "0") {
  return "0\nCIRCLE\n8\n" + layer + "\n10\n" + std::to_string(x) + "\n20\n" + std::to_string(y) + "\n30\n0.0\n40\n" +
         std::to_string(r) + "\n" + extra;
}

std::string insert(const std::string& block, double x, double y, const std::string& extra = "") {
  return "0\nINSERT\n8\n0\n2\n" + block + "\n10\n" + std::to_string(x) + "\n20\n" + std::to_string(y) + "\n30\n0.0\n" + extra;
}

std::string block(const std::string& name, const std::string& body, double bx = 0, double by = 0) {
  return "0\nBLOCK\n8\n0\n2\n" + name + "\n70\n0\n10\n" + std::to_string(bx) + "\n20\n" + std::to_string(by) +
         "\n30\n0.0\n3\n" + name + "\n" + body + "0\nENDBLK\n8\n0\n";
}

dxf::ReadResult read(const std::string& text, dxf::ReadOptions o = {}) { return dxf::read_holes(text, o); }

// The error a bad input gives: its line and message.
std::pair<std::uint32_t, std::string> error_of(const std::string& text, dxf::ReadOptions o = {}) {
  try {
    dxf::read_holes(text, o);
  } catch (const dxf::ReadError& e) {
    return {e.line(), e.what()};
  }
  return {0, "no error"};
}

}  // namespace

class FixtureTest : public ::testing::TestWithParam<std::string> {};

TEST_P(FixtureTest, gives_exactly_the_holes_ezdxf_finds) {
  const std::string path = GetParam();
  const std::string expected_path = path.substr(0, path.size() - 4) + ".holes.csv";
  aco::HoleSet want = testutil::read_holes_csv(testutil::slurp(expected_path));
  dxf::ReadResult r = dxf::read_holes(testutil::slurp(path));
  EXPECT_EQ(r.holes.size(), want.size()) << " in " << path;
  EXPECT_EQ(compare_sets(r.holes, want), "") << " in " << path;
}

std::string fixture_name(const ::testing::TestParamInfo<std::string>& param) {
  return std::filesystem::path(param.param).stem().string();
}
INSTANTIATE_TEST_SUITE_P(ezdxf_written, FixtureTest, ::testing::ValuesIn(fixtures("dxf")), fixture_name);
INSTANTIATE_TEST_SUITE_P(real_exports, FixtureTest, ::testing::ValuesIn(fixtures("real-dxf")), fixture_name);
// One ezdxf-written file per reader feature, the holes computed by ezdxf (tests/data/make_dxf_cases.py).
INSTANTIATE_TEST_SUITE_P(ezdxf_feature_cases, FixtureTest, ::testing::ValuesIn(fixtures("dxf-cases")), fixture_name);

TEST(dxf_reader_test, samples_give_their_hole_lists) {
  for (const auto& e : std::filesystem::directory_iterator(testutil::source_dir() + "/samples")) {
    if (e.path().extension() != ".dxf") continue;
    std::string p = e.path().string();
    aco::HoleSet want = testutil::read_holes_csv(testutil::slurp(p.substr(0, p.size() - 4) + ".holes.csv"));
    dxf::ReadResult r = dxf::read_holes(testutil::slurp(p));
    EXPECT_EQ(compare_sets(r.holes, want), "") << " in sample " << p;
  }
}

// --- Tags -----------------------------------------------------------------

TEST(dxf_reader_test, reads_crlf_padded_codes_comments_and_trailing_spaces) {
  std::string text = "999\r\nwritten by hand\r\n  0\r\nSECTION\r\n  2\r\nENTITIES\r\n  0\r\nCIRCLE  \r\n  8\r\nL1\r\n 10\r\n"
                     "5.0\r\n 20\r\n6.0\r\n 40\r\n1.5  \r\n  0\r\nENDSEC\r\n  0\r\nEOF\r\n";
  auto r = read(text);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(r.holes[0].center.x, 5.0);
  EXPECT_DOUBLE_EQ(r.holes[0].center.y, 6.0);
  EXPECT_DOUBLE_EQ(r.holes[0].diameter, 3.0);
  EXPECT_EQ(r.holes[0].layer, "L1");
  EXPECT_EQ(r.holes[0].source_line, 7u);
}

TEST(dxf_reader_test, integer_written_as_float_is_a_warning) {
  auto r = read(dxf_doc(circle(1, 1, 1)), {});
  std::string header = "9\n$INSUNITS\n70\n1.0\n";
  auto r2 = read(dxf_doc(circle(1, 1, 1), "", header));
  ASSERT_EQ(r2.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(r2.holes[0].center.x, 25.4);
  EXPECT_THAT(r2.diagnostics.front().message, ::testing::HasSubstr("written as a float"));
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(dxf_reader_test, missing_eof_after_complete_entities_is_a_warning) {
  std::string text = dxf_doc(circle(1, 2, 0.5));
  text = text.substr(0, text.rfind("0\nEOF"));
  auto r = read(text);
  ASSERT_EQ(r.holes.size(), 1u);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_THAT(r.diagnostics.back().message, ::testing::HasSubstr("no EOF"));
}

// --- Entities and blocks ---------------------------------------------------

TEST(dxf_reader_test, paper_space_circles_are_not_holes) {
  auto r = read(dxf_doc(circle(1, 1, 1) + circle(5, 5, 1, "67\n1\n")));
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(r.holes[0].center.x, 1.0);
}

TEST(dxf_reader_test, block_definitions_nothing_inserts_are_not_holes) {
  auto r = read(dxf_doc(circle(1, 1, 1), block("UNUSED", circle(9, 9, 1))));
  EXPECT_EQ(r.holes.size(), 1u);
}

TEST(dxf_reader_test, insert_applies_base_point_scale_rotation_and_mirror) {
  // Block with base (1,0) and a circle at (2,0) r=0.5; inserted at (10,10), scale 2, rotated 90°:
  // (2,0)-(1,0) = (1,0) → *2 = (2,0) → rot 90 = (0,2) → + (10,10) = (10,12); r = 1.
  auto r = read(dxf_doc(insert("B", 10, 10, "41\n2\n42\n2\n43\n2\n50\n90\n"), block("B", circle(2, 0, 0.5), 1, 0)));
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_NEAR(r.holes[0].center.x, 10.0, 1e-9);
  EXPECT_NEAR(r.holes[0].center.y, 12.0, 1e-9);
  EXPECT_NEAR(r.holes[0].diameter, 2.0, 1e-9);
  // Mirror in X (scale -1, 1): the circle at (2,0) lands at (10 - 1, 10).
  auto m = read(dxf_doc(insert("B", 10, 10, "41\n-1\n42\n1\n"), block("B", circle(2, 0, 0.5), 1, 0)));
  ASSERT_EQ(m.holes.size(), 1u);
  EXPECT_NEAR(m.holes[0].center.x, 9.0, 1e-9);
  EXPECT_NEAR(m.holes[0].diameter, 1.0, 1e-9);
}

TEST(dxf_reader_test, zero_z_scale_as_librecad_writes_it_is_harmless) {
  auto r = read(dxf_doc(insert("B", 5, 5, "41\n1\n42\n1\n43\n0\n"), block("B", circle(1, 1, 0.5))));
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_NEAR(r.holes[0].center.x, 6.0, 1e-9);
}

TEST(dxf_reader_test, minsert_rows_and_columns) {
  auto r = read(dxf_doc(insert("B", 0, 0, "70\n3\n71\n2\n44\n10\n45\n5\n"), block("B", circle(0, 0, 0.5))));
  ASSERT_EQ(r.holes.size(), 6u);
  EXPECT_NEAR(r.holes[5].center.x, 20.0, 1e-9);
  EXPECT_NEAR(r.holes[5].center.y, 5.0, 1e-9);
}

TEST(dxf_reader_test, nested_blocks) {
  std::string blocks = block("INNER", circle(1, 0, 0.25)) + block("OUTER", insert("INNER", 0, 0) + insert("INNER", 0, 10));
  auto r = read(dxf_doc(insert("OUTER", 100, 0, "50\n180\n"), blocks));
  ASSERT_EQ(r.holes.size(), 2u);
  EXPECT_NEAR(r.holes[0].center.x, 99.0, 1e-9);
  EXPECT_NEAR(r.holes[1].center.y, -10.0, 1e-9);
}

TEST(dxf_reader_test, non_uniform_scale_makes_an_ellipse_which_is_skipped_with_a_warning) {
  auto r = read(dxf_doc(insert("B", 0, 0, "41\n2\n42\n1\n"), block("B", circle(0, 0, 1))));
  EXPECT_TRUE(r.holes.empty());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_THAT(r.diagnostics[0].message, ::testing::HasSubstr("ellipse"));
}

TEST(dxf_reader_test, extrusion_0_0_minus1_mirrors_x_and_tiny_normals_are_handled) {
  auto r = read(dxf_doc(circle(10, 20, 1, "210\n0\n220\n0\n230\n-1\n") +
                        circle(10, 20, 1, "210\n2.6e-24\n220\n1.7e-20\n230\n-1\n")));
  ASSERT_EQ(r.holes.size(), 1u) << "the two are the same hole";
  EXPECT_NEAR(r.holes[0].center.x, -10.0, 1e-9);
  EXPECT_NEAR(r.holes[0].center.y, 20.0, 1e-9);
  EXPECT_EQ(r.duplicates_removed, 1u);
}

TEST(dxf_reader_test, tilted_circle_is_skipped) {
  auto r = read(dxf_doc(circle(0, 0, 1, "210\n1\n220\n0\n230\n0\n")));
  EXPECT_TRUE(r.holes.empty());
}

TEST(dxf_reader_test, units_from_insunits_and_default) {
  auto cm = read(dxf_doc(circle(1, 1, 1), "", "9\n$INSUNITS\n70\n5\n"));
  EXPECT_DOUBLE_EQ(cm.holes[0].center.x, 10.0);
  dxf::ReadOptions inch;
  inch.default_unit_mm = 25.4;
  auto unitless = read(dxf_doc(circle(1, 1, 1), "", "9\n$INSUNITS\n70\n0\n"), inch);
  EXPECT_DOUBLE_EQ(unitless.holes[0].center.x, 25.4);
  auto mm = read(dxf_doc(circle(1, 1, 1), "", "9\n$INSUNITS\n70\n4\n"), inch);
  EXPECT_DOUBLE_EQ(mm.holes[0].center.x, 1.0) << "$INSUNITS wins over --input-units";
}

TEST(dxf_reader_test, layer_and_diameter_filters) {
  std::string body = circle(0, 0, 0.5, "", "DRILL_1") + circle(1, 0, 1.0, "", "drill_2") + circle(2, 0, 2.0, "", "MILL");
  dxf::ReadOptions o;
  o.layers = {"DRILL*"};
  EXPECT_EQ(read(dxf_doc(body), o).holes.size(), 2u);
  o.layers.clear();
  o.min_diameter_mm = 1.5;
  o.max_diameter_mm = 2.5;
  auto r = read(dxf_doc(body), o);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(r.holes[0].diameter, 2.0);
}

TEST(dxf_reader_test, duplicates_dropped_concentric_kept) {
  auto r = read(dxf_doc(circle(1, 1, 1) + circle(1, 1, 1) + circle(1.0000000001, 1, 1) + circle(1, 1, 2)));
  EXPECT_EQ(r.holes.size(), 2u);
  EXPECT_EQ(r.duplicates_removed, 2u);
}

TEST(dxf_reader_test, wildcards) {
  EXPECT_TRUE(dxf::wildcard_match("DR*", "drill"));
  EXPECT_TRUE(dxf::wildcard_match("*", ""));
  EXPECT_TRUE(dxf::wildcard_match("H?LE*S", "HOLES"));
  EXPECT_FALSE(dxf::wildcard_match("H?LE", "HOLES"));
  EXPECT_FALSE(dxf::wildcard_match("*X", "HOLES"));
}

// --- Bad input: one error with a line, never a crash or a hang --------------

TEST(dxf_reader_bad_input, empty_file) {
  EXPECT_THAT(error_of("").second, ::testing::HasSubstr("empty"));
}

TEST(dxf_reader_bad_input, not_a_dxf) {
  auto [line, what] = error_of("hello world\nthis is text\n");
  EXPECT_EQ(line, 1u);
  EXPECT_THAT(what, ::testing::HasSubstr("invalid group code"));
}

TEST(dxf_reader_bad_input, truncated_mid_entity) {
  std::string text = dxf_doc(circle(1, 1, 1) + circle(2, 2, 1));
  text = text.substr(0, text.find("40\n1.000000", text.find("2.000000")));
  auto [line, what] = error_of(text);
  EXPECT_GT(line, 0u);
  EXPECT_THAT(what, ::testing::AnyOf(::testing::HasSubstr("truncated"), ::testing::HasSubstr("radius")));
  auto [line2, what2] = error_of("0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n");
  EXPECT_EQ(line2, 7u);
  EXPECT_THAT(what2, ::testing::HasSubstr("no value"));
}

TEST(dxf_reader_bad_input, non_integer_group_code_names_its_line) {
  auto [line, what] = error_of("0\nSECTION\n2\nENTITIES\nX1\nCIRCLE\n");
  EXPECT_EQ(line, 5u);
  EXPECT_THAT(what, ::testing::HasSubstr("invalid group code \"X1\""));
}

TEST(dxf_reader_bad_input, non_numeric_nan_and_inf) {
  for (const char* bad : {"abc", "nan", "inf", "-inf", "1e999", "1.2.3"}) {
    auto [line, what] = error_of(dxf_doc("0\nCIRCLE\n8\n0\n10\n" + std::string(bad) + "\n20\n0\n40\n1\n"));
    EXPECT_EQ(line, 16u) << bad << ": the line of the bad value";
    EXPECT_THAT(what, ::testing::HasSubstr("number")) << bad;
  }
}

TEST(dxf_reader_bad_input, zero_or_negative_radius) {
  EXPECT_THAT(error_of(dxf_doc(circle(0, 0, 0))).second, ::testing::HasSubstr("radius must be positive"));
  EXPECT_THAT(error_of(dxf_doc(circle(0, 0, -1))).second, ::testing::HasSubstr("radius must be positive"));
}

TEST(dxf_reader_bad_input, insert_of_missing_block) {
  auto [line, what] = error_of(dxf_doc(insert("NOPE", 0, 0)));
  EXPECT_GT(line, 0u);
  EXPECT_THAT(what, ::testing::HasSubstr("undefined block \"NOPE\""));
}

TEST(dxf_reader_bad_input, self_and_cyclic_references_name_the_block) {
  EXPECT_THAT(error_of(dxf_doc(insert("SELF", 0, 0), block("SELF", insert("SELF", 1, 1)))).second,
              ::testing::HasSubstr("\"SELF\" inserts itself"));
  std::string blocks = block("A", insert("B", 0, 0)) + block("B", insert("A", 0, 0));
  EXPECT_THAT(error_of(dxf_doc(insert("A", 0, 0), blocks)).second, ::testing::HasSubstr("cyclic"));
}

TEST(dxf_reader_bad_input, nesting_thousands_deep) {
  std::string blocks;
  for (int i = 0; i < 3000; ++i) blocks += block("B" + std::to_string(i), insert("B" + std::to_string(i + 1), 0, 0));
  blocks += block("B3000", circle(0, 0, 1));
  auto [line, what] = error_of(dxf_doc(insert("B0", 0, 0), blocks));
  EXPECT_GT(line, 0u);
  EXPECT_THAT(what, ::testing::HasSubstr("nested more than"));
}

TEST(dxf_reader_bad_input, array_over_the_hole_limit) {
  dxf::ReadOptions o;
  o.max_holes = 1000;
  auto [line, what] = error_of(dxf_doc(insert("B", 0, 0, "70\n100\n71\n100\n44\n1\n45\n1\n"), block("B", circle(0, 0, 0.1))), o);
  EXPECT_THAT(what, ::testing::HasSubstr("more than 1000 holes (the hole limit, --max-holes)"));
  // A front end without --max-holes (the page) names its limit its own way.
  o.max_holes_named = "the most this page plans";
  EXPECT_THAT(error_of(dxf_doc(insert("B", 0, 0, "70\n100\n71\n100\n44\n1\n45\n1\n"), block("B", circle(0, 0, 0.1))), o).second,
              ::testing::HasSubstr("more than 1000 holes (the most this page plans)"));
  // An explosive array of empty blocks makes no holes but must not hang either.
  std::string blocks = block("E", "") + block("X", insert("E", 0, 0, "70\n30000\n71\n30000\n"));
  auto [l2, w2] = error_of(dxf_doc(insert("X", 0, 0, "70\n100\n71\n100\n"), blocks));
  EXPECT_THAT(w2, ::testing::HasSubstr("expansion limit"));
}

TEST(dxf_reader_bad_input, utf16_file) {
  std::string text = "\xFF\xFE";
  for (char c : dxf_doc(circle(0, 0, 1))) {
    text += c;
    text += '\0';
  }
  auto [line, what] = error_of(text);
  EXPECT_THAT(what, ::testing::HasSubstr("UTF-16"));
  std::string no_bom;
  for (char c : dxf_doc(circle(0, 0, 1))) {
    no_bom += c;
    no_bom += '\0';
  }
  EXPECT_THAT(error_of(no_bom).second, ::testing::HasSubstr("UTF-16"));
}

TEST(dxf_reader_bad_input, megabytes_of_binary_garbage) {
  std::string garbage(4 << 20, '\0');
  std::uint64_t x = 12345;
  for (char& c : garbage) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    c = static_cast<char>(x >> 56);
  }
  auto [line, what] = error_of(garbage);
  EXPECT_NE(what, "no error");
  garbage[0] = '0';  // text-looking start, binary later
  EXPECT_NE(error_of(garbage).second, "no error");
}

TEST(dxf_reader_bad_input, truncated_binary_dxf) {
  std::string bin = testutil::slurp(data("dxf/r2010_binary.dxf"));
  auto [line, what] = error_of(bin.substr(0, bin.size() / 2));
  EXPECT_NE(what, "no error");
}

// Issue 71: holes drawn without a CIRCLE (tests/data/make_round_contours.py:
// each file as a CAD writes it, with the holes ezdxf's own geometry and a
// numpy circle fit find). Without --round-contours only the CIRCLEs are
// holes and the round contours are named in a warning; with it, exactly the
// round contours are added, at ezdxf's fitted centre within 1 µm.
class RoundContourTest : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundContourTest, reads_exactly_the_round_contours_when_asked_and_names_them_when_not) {
  const std::string path = GetParam();
  const std::string stem = path.substr(0, path.size() - 4);
  const aco::HoleSet circles = testutil::read_holes_csv(testutil::slurp(stem + ".holes.csv"));
  const aco::HoleSet round = testutil::read_holes_csv(testutil::slurp(stem + ".round.csv"));
  const std::string text = testutil::slurp(path);
  dxf::ReadResult plain = dxf::read_holes(text);
  EXPECT_EQ(compare_sets(plain.holes, circles), "");
  EXPECT_EQ(plain.round_contours, round.size() - circles.size());
  const bool named = std::any_of(plain.diagnostics.begin(), plain.diagnostics.end(), [](const dxf::Diagnostic& d) {
    return d.message.find("--round-contours reads them as holes") != std::string::npos;
  });
  EXPECT_EQ(named, round.size() > circles.size()) << "told exactly when there are some";
  dxf::ReadOptions o;
  o.round_contours = true;
  dxf::ReadResult r = dxf::read_holes(text, o);
  ASSERT_EQ(r.holes.size(), round.size());
  EXPECT_EQ(r.round_contour_holes, round.size() - circles.size());
  std::vector<char> used(r.holes.size(), 0);
  for (const aco::Hole& w : round) {
    bool found = false;
    for (std::size_t i = 0; i < r.holes.size() && !found; ++i) {
      if (used[i] || aco::euclidean(r.holes[i].center, w.center) > 1e-6) continue;
      used[i] = 1;
      found = true;
      EXPECT_NEAR(r.holes[i].diameter, w.diameter, 1e-3) << w.center.x << "," << w.center.y;
      EXPECT_EQ(r.holes[i].layer, w.layer);
    }
    EXPECT_TRUE(found) << "no hole within 1 um of (" << w.center.x << ", " << w.center.y << ") in " << path;
  }
}

INSTANTIATE_TEST_SUITE_P(ezdxf_written, RoundContourTest, ::testing::ValuesIn(fixtures("dxf-contours")), fixture_name);

TEST(dxf_reader_test, round_contours_add_nothing_to_drawings_without_them) {
  // Every other fixture, real exports included (a SolidWorks panel drawn in
  // ARCs and LINEs: rounded corners and slots, no hole), reads the same.
  dxf::ReadOptions o;
  o.round_contours = true;
  for (const std::string folder : {"dxf", "real-dxf", "dxf-cases"}) {
    for (const std::string& path : fixtures(folder)) {
      const std::string text = testutil::slurp(path);
      dxf::ReadResult plain = dxf::read_holes(text), with = dxf::read_holes(text, o);
      EXPECT_EQ(compare_sets(with.holes, plain.holes), "") << path;
      EXPECT_EQ(with.round_contours, 0u) << path;
    }
  }
}

TEST(dxf_reader_test, round_contours_follow_the_layer_filter_and_their_tolerance) {
  const std::string text = testutil::slurp(data("dxf-contours/inkscape_r12_line_polygons.dxf"));
  dxf::ReadOptions o;
  o.round_contours = true;
  o.layers = {"OUTLINE"};
  EXPECT_EQ(dxf::read_holes(text, o).holes.size(), 0u);
  o.layers = {"hol*"};
  EXPECT_EQ(dxf::read_holes(text, o).holes.size(), 4u);
  // An octagon is 7.6 % off its circle: a hole only with the tolerance raised to 10 %.
  const std::string octagons = testutil::slurp(data("dxf-contours/openscad_lwpolyline_polygons.dxf"));
  dxf::ReadOptions loose;
  loose.round_contours = true;
  EXPECT_EQ(dxf::read_holes(octagons, loose).holes.size(), 2u);
  loose.round_tolerance = 0.10;
  EXPECT_EQ(dxf::read_holes(octagons, loose).holes.size(), 3u) << "the square stays no hole";
}

TEST(dxf_reader_test, a_header_in_inch_on_a_drawing_in_mm_is_named_and_can_be_overridden) {
  const std::string text = testutil::slurp(data("dxf-contours/onshape_inch_header_mm_drawing.dxf"));
  dxf::ReadResult r = dxf::read_holes(text);
  ASSERT_EQ(r.holes.size(), 8u);
  EXPECT_NEAR(r.holes[0].diameter, 5.2 * 25.4, 1e-9);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_THAT(r.diagnostics[0].message, ::testing::HasSubstr("$INSUNITS 1"));
  EXPECT_THAT(r.diagnostics[0].message, ::testing::HasSubstr("--dxf-units mm"));
  dxf::ReadOptions o;
  o.units_override_mm = 1.0;
  dxf::ReadResult mm = dxf::read_holes(text, o);
  EXPECT_NEAR(mm.holes[0].diameter, 5.2, 1e-9);
  EXPECT_TRUE(mm.diagnostics.empty());
  // A drawing in mm with big holes is not suspect: mm is no unit to blow it up.
  EXPECT_TRUE(dxf::read_holes(dxf_doc(circle(0, 0, 40) + circle(200, 0, 40), "", "9\n$INSUNITS\n70\n4\n")).diagnostics.empty());
}
