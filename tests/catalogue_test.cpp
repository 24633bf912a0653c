// The catalogue of bad input: malformed files of every format, impossible
// numbers, explosive blocks, unreadable paths, output over the input, invalid
// option values. Each must give exit 2, exactly one stderr line
// "acodrill: error: ...", no output file, an existing output untouched, and
// finish within a couple of seconds. Then the numeric edge cases that must work.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <chrono>
#include <filesystem>

#include "gcode/interpreter.h"
#include "test_util.h"

using testutil::acodrill_run;
using testutil::shell_quote;
using testutil::slurp;
using testutil::spit;
using testutil::TempDir;

namespace {

struct BadCase {
  std::string name;
  std::string file;       // input file name in the temp dir ("" = none written)
  std::string content;    // its content
  std::string args;       // after "acodrill"; {in} = the input path, {out} = the output path, {dir} = temp dir
  std::string expect;     // a substring of the error line
};

// gtest prints a parameter with this; without it, the test names carry a byte dump.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

std::string dxf(const std::string& entities, const std::string& blocks = "") {
  std::string s = "0\nSECTION\n2\nHEADER\n0\nENDSEC\n";
  if (!blocks.empty()) s += "0\nSECTION\n2\nBLOCKS\n" + blocks + "0\nENDSEC\n";
  return s + "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}
const std::string kCircle = "0\nCIRCLE\n8\n0\n10\n1\n20\n1\n30\n0\n40\n1\n";
std::string block(const std::string& name, const std::string& body) {
  return "0\nBLOCK\n8\n0\n2\n" + name + "\n70\n0\n10\n0\n20\n0\n30\n0\n" + body + "0\nENDBLK\n";
}
std::string insert(const std::string& name, const std::string& extra = "") {
  return "0\nINSERT\n8\n0\n2\n" + name + "\n10\n0\n20\n0\n30\n0\n" + extra;
}
const std::string kGoodCsv = "x,y,d\n1,1,3\n5,5,3\n";

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

std::vector<BadCase> catalogue() {
  const std::string plan = "plan {in} -o {out}";
  std::string utf16 = "\xFF\xFE";
  for (char c : dxf(kCircle)) utf16 += std::string(1, c) + '\0';
  std::string garbage(2 << 20, '\0');
  std::uint64_t x = 7;
  for (char& c : garbage) c = static_cast<char>((x = x * 6364136223846793005ULL + 1) >> 56);
  std::string deep;
  for (int i = 0; i < 2000; ++i) deep += block("B" + std::to_string(i), insert("B" + std::to_string(i + 1)));
  deep += block("B2000", kCircle);
  return {
      // DXF
      {"dxf_empty", "a.dxf", "", plan, "a.dxf: empty file"},
      {"dxf_not_a_dxf", "a.dxf", "hello\nworld\n", plan, "a.dxf:1: invalid group code"},
      {"dxf_truncated_mid_entity", "a.dxf", "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n10\n1\n20\n", plan, "a.dxf:9: file ends after group code 20"},
      {"dxf_truncated_no_endsec", "a.dxf", "0\nSECTION\n2\nENTITIES\n" + kCircle, plan, "a.dxf:1: file ends inside the ENTITIES section"},
      {"dxf_non_integer_code", "a.dxf", "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n1O\n1\n", plan, "a.dxf:7: invalid group code \"1O\""},
      {"dxf_non_numeric", "a.dxf", dxf("0\nCIRCLE\n10\none\n20\n1\n40\n1\n"), plan, "a.dxf:14: group code 10: \"one\" is not a number"},
      {"dxf_nan", "a.dxf", dxf("0\nCIRCLE\n10\nnan\n20\n1\n40\n1\n"), plan, "not a finite number"},
      {"dxf_inf", "a.dxf", dxf("0\nCIRCLE\n10\n1\n20\n1\n40\ninf\n"), plan, "not a finite number"},
      {"dxf_huge_exponent", "a.dxf", dxf("0\nCIRCLE\n10\n1e400\n20\n1\n40\n1\n"), plan, "group code 10"},
      {"dxf_zero_radius", "a.dxf", dxf("0\nCIRCLE\n10\n1\n20\n1\n40\n0\n"), plan, "radius must be positive"},
      {"dxf_negative_radius", "a.dxf", dxf("0\nCIRCLE\n10\n1\n20\n1\n40\n-2\n"), plan, "radius must be positive"},
      {"dxf_missing_block", "a.dxf", dxf(insert("NOPE")), plan, "undefined block \"NOPE\""},
      {"dxf_self_reference", "a.dxf", dxf(insert("S"), block("S", insert("S"))), plan, "\"S\" inserts itself"},
      {"dxf_cycle", "a.dxf", dxf(insert("A"), block("A", insert("B")) + block("B", insert("A"))), plan, "cyclic"},
      {"dxf_nesting_thousands_deep", "a.dxf", dxf(insert("B0"), deep), plan, "nested more than"},
      {"dxf_array_over_hole_limit", "a.dxf", dxf(insert("C", "70\n2000\n71\n2000\n44\n1\n45\n1\n"), block("C", kCircle)),
       plan + " --max-holes 100000", "hole limit"},
      {"dxf_explosive_empty_blocks", "a.dxf",
       dxf(insert("X", "70\n1000\n71\n1000\n"), block("E", "") + block("X", insert("E", "70\n1000\n71\n1000\n"))), plan,
       "expansion limit"},
      {"dxf_bad_array_count", "a.dxf", dxf(insert("C", "70\n0\n"), block("C", kCircle)), plan, "must be at least 1 x 1"},
      {"dxf_zero_extrusion", "a.dxf", dxf("0\nCIRCLE\n10\n1\n20\n1\n40\n1\n210\n0\n220\n0\n230\n0\n"), plan, "zero vector"},
      {"dxf_utf16", "a.dxf", utf16, plan, "UTF-16"},
      {"dxf_binary_garbage", "a.dxf", garbage, plan, "a.dxf:"},
      {"dxf_truncated_binary", "a.dxf", std::string("AutoCAD Binary DXF\r\n\x1a\0", 22) + std::string("\0\0SECTION\0\x02\0ENT", 15),
       plan, "binary DXF ends"},
      {"dxf_no_holes", "a.dxf", dxf("0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n"), plan, "no holes to drill"},
      // Excellon
      {"excellon_hit_before_tool", "a.drl", "M48\nINCH,TZ\nT1C0.02\n%\nX1000Y1000\nM30\n", plan, "a.drl:5: drill hit before any tool"},
      {"excellon_undefined_tool", "a.drl", "M48\nINCH,TZ\nT1C0.02\n%\nT7\nX1000Y1000\nM30\n", plan, "a.drl:5: tool T7 is not defined"},
      {"excellon_garbage_line", "a.drl", "M48\nINCH,TZ\nT1C0.02\n%\nT1\n@@@@\nM30\n", plan, "a.drl:6:"},
      {"excellon_negative_diameter", "a.drl", "M48\nINCH,TZ\nT1C-0.02\n%\nT1\nX1Y1\nM30\n", plan, "a.drl:3: tool T1 has a negative diameter"},
      {"excellon_bad_coordinate", "a.drl", "M48\nINCH,TZ\nT1C0.02\n%\nT1\nX12.3.4Y1\nM30\n", plan, "a.drl:6:"},
      // Gerber (issue 16): drawings, maps and routes are refused, never drilled.
      {"gerber_drill_drawing", "a.drd", "G04 drill drawing*\n%FSLAX24Y24*%\n%MOIN*%\n%ADD10C,0.0300*%\nD10*\nX1000Y1000D02*\nX2000Y1000D01*\nM02*\n", plan,
       "a.drd:7: this Gerber draws 1 stroke(s) and 0 region edge(s): it does not look like drill data"},
      {"gerber_drill_map", "a.gbr", "%TF.FileFunction,Drillmap*%\n%FSLAX24Y24*%\n%MOIN*%\nM02*\n", plan, "a.gbr:1: a drill map"},
      {"gerber_route", "a.gbr", "%TF.FileFunction,NonPlated,1,2,NPTH,Route*%\n%FSLAX24Y24*%\nM02*\n", plan, "a.gbr:1: a route file"},
      {"gerber_rs274d_without_apertures", "a.gbr", "G54D10*\nX010000Y020000D03*\nM02*\n", plan, "a.gbr:1: aperture D10 is not defined (an RS-274D file needs its aperture list: --apertures FILE)"},
      {"gerber_bad_aperture_list", "a.gbr", "G54D10*\nX010000Y020000D03*\nM02*\n", plan + " --apertures {dir}/tools.json", "tools.json:1: expected \"D<code> <shape> <size>"},
      // XML
      {"xml_malformed", "a.xml", "<holemap><hole x=\"1\" y=\"2\"></holemap>\n", plan, "a.xml:1: XML"},
      {"xml_wrong_root", "a.xml", "<drawing/>\n", plan, "expected a <holemap> root"},
      {"xml_bad_number", "a.xml", "<holemap>\n<hole x=\"abc\" y=\"2\"/>\n</holemap>\n", plan, "a.xml:2: x=\"abc\" is not a number"},
      {"xml_bad_units", "a.xml", "<holemap units=\"furlong\"><hole x=\"1\" y=\"2\"/></holemap>\n", plan, "units must be"},
      // CSV
      {"csv_garbage", "a.csv", "x,y,d\n1,2,3\nfoo,bar\n", plan, "a.csv:3: expected x,y"},
      {"csv_negative_diameter", "a.csv", "1,2,-3\n", plan, "a.csv:1: negative diameter"},
      {"csv_nan", "a.csv", "1,nan,3\n", plan, "a.csv:1:"},
      {"csv_binary", "a.csv", std::string("1,2,3\n\0\0\0\x01", 10), plan, "binary data"},
      // Issue 84: files opened by mistake say what they are, and what acodrill reads.
      {"png_named_drl", "a.drl", std::string("\x89PNG\r\n\x1A\n\0\0\0\rIHDR", 16), plan,
       "a.drl: a PNG image, not a hole file: acodrill reads DXF, Excellon, Gerber, IPC-2581, ODB++, another CAM's G-code"},
      {"dwg_drawing", "a.dwg", std::string("AC1032\0\0\0\0", 10), plan, "a.dwg: an AutoCAD DWG drawing (save it as DXF)"},
      {"text_named_drl", "a.drl", "hello world\nthis is no drill file\n", plan,
       "a.drl:1: unexpected \"hello world\": not a hole file acodrill recognises (acodrill reads DXF, Excellon, Gerber"},
      // TSPLIB
      {"tsplib_no_coords", "a.tsp", "NAME : a\nTYPE : TSP\nDIMENSION : 3\nEDGE_WEIGHT_TYPE : EUC_2D\nEOF\n", "tsp {in}", "no NODE_COORD_SECTION"},
      {"tsplib_wrong_dimension", "a.tsp", "NAME : a\nDIMENSION : 3\nNODE_COORD_SECTION\n1 0 0\n2 1 1\nEOF\n", "tsp {in}", "DIMENSION is 3"},
      {"tsplib_bad_weight_type", "a.tsp", "NAME : a\nEDGE_WEIGHT_TYPE : GEO\nNODE_COORD_SECTION\n1 0 0\nEOF\n", "tsp {in}", "a.tsp:2: EDGE_WEIGHT_TYPE GEO"},
      {"tsplib_bad_node", "a.tsp", "NAME : a\nNODE_COORD_SECTION\n1 0 zero\nEOF\n", "tsp {in}", "a.tsp:3: expected \"index x y\""},
      // G-code for verify
      {"verify_unclosed_comment", "a.nc", "G0 X1 (oops\n", "verify {in}", "a.nc:1: unclosed comment"},
      {"verify_cycle_without_depth", "a.nc", "G0 X0 Y0 Z5\nG81 X1 Y1 R1 F10\n", "verify {in}", "a.nc:2: canned cycle without a depth"},
      {"verify_bad_word", "a.nc", "G0 X1 &5\n", "verify {in}", "a.nc:1: unexpected character"},
      {"verify_parameter", "a.nc", "G0 X1 #5\n", "verify {in}", "a.nc:1: parameters and expressions"},
      // Issue 14: a program that does more than drill is refused at its first such line, never reordered.
      {"program_milling_move", "a.nc", "G21 G90\nG0 Z5\nG0 X1 Y1\nG1 Z-1 F100\nG1 X5 Y1\nG0 Z5\nM30\n", "plan {in} -o {out}",
       "a.nc:5: G1 moves in X/Y at Z-1.000, at or below the top of the part: a cutting move"},
      // Issue 23: G1 travel is travel only above the part; a program that ends before its holes says where.
      {"program_g1_at_top", "a.nc", "G21 G90\nG0 Z5\nG0 X1 Y1\nG1 Z-1 F100\nG1 Z0\nG1 X5 Y1\nM30\n", "plan {in} -o {out}",
       "a.nc:6: G1 moves in X/Y at Z0.000, at or below the top of the part"},
      {"program_ends_before_its_holes", "a.nc", "G21 G90\nG0 Z5\nM2\nG0 X1 Y1\nG1 Z-1 F100\nG0 Z5\n", "plan {in} -o {out}",
       "a.nc:3: no holes to drill before the program ends here (M2); 3 line(s) of code after it are not read"},
      {"program_tapping_for_grbl", "a.nc", "G21 G90\nT1 M6\nS500 M3\nG0 X1 Y1 Z5\nG84 R1 Z-5 F500\nG80\nM30\n",
       "plan {in} -o {out} --dialect grbl", "a.nc:5: G84 (tapping) cannot be written as moves"},
      {"unknown_machine_class", "a.csv", kGoodCsv, "plan {in} -o {out} --machine bridgeport", "no machine class \"bridgeport\""},
      {"program_arc", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nG80\nG2 X5 Y1 I2 J0\nM30\n", "plan {in} -o {out}", "a.nc:5: an arc (G2)"},
      {"program_probe", "a.nc", "G21\nG38.2 Z-10 F50\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nM30\n", "plan {in} -o {out}", "a.nc:2: probing (G38.2)"},
      {"program_subprogram", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nM98 P100\nM30\n", "plan {in} -o {out}", "a.nc:4: a subprogram call (M98)"},
      {"program_o_call", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\no100 call\nM30\n", "plan {in} -o {out}", "a.nc:4: a subroutine or flow control"},
      {"program_other_axis", "a.nc", "G21\nG0 X1 Y1 Z5\nG0 A90\nG81 R1 Z-1 F100\nM30\n", "plan {in} -o {out}", "a.nc:3: the A axis"},
      {"program_g92", "a.nc", "G21\nG92 X0 Y0\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nM30\n", "plan {in} -o {out}", "a.nc:2: G92 changes the coordinate system"},
      {"program_units_changed", "a.nc", "G20 G90\nG0 X1 Y1 Z0.2\nG81 R0.1 Z-0.1 F10\nG80\nG21\nG0 X30 Y30 Z5\nG81 R1 Z-3 F100\nG80\nM30\n",
       "plan {in} -o {out}", "a.nc:7: a hole in mm after holes in inch"},
      {"program_plane", "a.nc", "G21 G18\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nM30\n", "plan {in} -o {out}", "a.nc:1: another plane (G18)"},
      {"program_repeats", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 X2 R1 Z-2 L5 F100\nM30\n", "plan {in} -o {out}", "a.nc:3: L5 in absolute mode (G90) drills one place 5 times"},
      {"program_no_holes", "a.nc", "G21\nG0 X1 Y1 Z5\nG0 Z1\nM30\n", "plan {in} -o {out}", "no holes"},
      {"program_origin", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nM30\n", "plan {in} -o {out} --origin center", "--origin: a program's coordinates stay"},
      {"program_keep_style_units", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nM30\n", "plan {in} -o {out} --keep-style --units inch", "--keep-style keeps the input's units"},
      {"keep_style_on_a_hole_file", "a.csv", kGoodCsv, "plan {in} -o {out} --keep-style", "--keep-style and --min-spacing apply to a drilling program"},
      // Issue 83: milling kept as written only in the program's own style, and only a program has it.
      {"keep_milling_for_another_dialect", "a.nc", "G21\nG0 X1 Y1 Z5\nG81 R1 Z-1 F100\nG80\nG1 Z-1 F100\nG1 X5\nM30\n",
       "plan {in} -o {out} --keep-milling --dialect grbl", "--keep-milling writes the program in its own style"},
      {"keep_milling_on_a_hole_file", "a.csv", kGoodCsv, "plan {in} -o {out} --keep-milling", "--keep-milling applies to a drilling program input"},
      // Paths and outputs
      {"missing_input", "", "", "plan {dir}/missing.dxf -o {out}", "missing.dxf: cannot read"},
      {"directory_as_input", "", "", "plan {dir} -o {out}", "is a directory"},
      // A file that opens but cannot be read, even by root (CI runs as root).
      {"unreadable_input", "", "", "plan /proc/self/mem -o {out}", "/proc/self/mem: read error"},
      {"output_over_input", "a.csv", kGoodCsv, "plan {in} -o {in}", "output would overwrite the input"},
      {"report_over_input", "a.csv", kGoodCsv, "plan {in} -o {out} --report {in}", "output would overwrite the input"},
      {"output_in_missing_directory", "a.csv", kGoodCsv, "plan {in} -o {dir}/no/such/dir/out.nc", "cannot write"},
      // Options
      {"rho_out_of_range", "a.csv", kGoodCsv, plan + " --rho 1.5", "--rho"},
      {"alpha_negative", "a.csv", kGoodCsv, plan + " --alpha -1", "--alpha"},
      {"ants_zero", "a.csv", kGoodCsv, plan + " --ants 0", "--ants"},
      {"threads_zero", "a.csv", kGoodCsv, plan + " --threads 0", "--threads"},
      {"threads_not_a_number", "a.csv", kGoodCsv, plan + " --threads many", "--threads"},
      {"time_limit_negative", "a.csv", kGoodCsv, plan + " --time-limit -3", "--time-limit"},
      {"unknown_algorithm", "a.csv", kGoodCsv, plan + " --algorithm genetic", "--algorithm"},
      {"unknown_local_search", "a.csv", kGoodCsv, plan + " --local-search lk", "--local-search"},
      {"unknown_dialect", "a.csv", kGoodCsv, plan + " --dialect heidenhain", "--dialect"},
      {"unknown_units", "a.csv", kGoodCsv, plan + " --units furlong", "--units"},
      {"unknown_input_units", "a.csv", kGoodCsv, plan + " --input-units cubits", "--input-units"},
      {"unknown_material", "a.csv", kGoodCsv, plan + " --material cheese", "--material"},
      {"thickness_zero", "a.csv", kGoodCsv, plan + " --thickness 0", "--thickness"},
      {"resume_beyond_the_end", "a.csv", kGoodCsv, plan + " --resume-from 3", "--resume-from 3 is outside 1..2"},
      {"unknown_option", "a.csv", kGoodCsv, plan + " --frobnicate", "frobnicate"},
      {"unknown_command", "", "", "drill", "unknown command \"drill\""},
      {"missing_output_option", "a.csv", kGoodCsv, "plan {in}", "--output"},
      {"bad_tool_table", "a.csv", kGoodCsv, plan + " --tools {dir}/tools.json", "tools.json:2: invalid JSON"},
      {"hole_no_tool_fits", "a.csv", "x,y,d\n1,1,3\n5,5,4\n", plan + " --tools {dir}/tools_ok.json", "1 hole(s) fit no tool"},
      {"part_larger_than_travel", "a.csv", "x,y,d\n1,1,3\n5000,5,3\n", plan,
       "the holes span 5002.000 x 7.000 mm (tool edges included) but the machine travels 762.000 x 406.000 mm"},
      {"part_fits_only_turned", "a.csv", "x,y,d\n0,0,2\n0,600,2\n", plan, "turned by 90 degrees the part would fit"},
      {"outside_travel_at_work_offset", "a.csv", "x,y,d\n0,0,2\n100,100,2\n", plan + " --machine {dir}/offset.json",
       "the holes reach machine X 699.000..801.000"},
      // Issue 16: holes without a diameter never become a "0.000 MM DRILL".
      {"csv_rows_without_diameter", "a.csv", "x,y\n1,1\n5,5\n", plan, "a.csv:2: hole without a diameter"},
      {"csv_row_shorter_than_its_header", "a.csv", "x,y,d\n1,1,3\n5,5\n", plan, "a.csv:3: the row has 2 fields but the header names 3"},
      {"tsplib_nodes_planned_without_diameter", "a.tsp", "NAME : a\nTYPE : TSP\nDIMENSION : 2\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 5 5\nEOF\n",
       plan, "a.tsp:6: hole without a diameter"},
      {"excellon_hit_after_undefined_t0", "a.drl", "M48\nMETRIC\nT1C0.6\n%\nT0\nX1.0Y1.0\nM30\n", plan, "a.drl:6: drill hit with no tool loaded (T0)"},
      {"unknown_origin", "a.csv", kGoodCsv, plan + " --origin bottom", "--origin must be"},
      {"origin_point_not_a_number", "a.csv", kGoodCsv, plan + " --origin 1,abc", "--origin must be"},
      {"bad_machine_profile", "a.csv", kGoodCsv, plan + " --machine {dir}/tools_ok.json", "a machine profile is a JSON object"},
  };
}

}  // namespace

class CatalogueTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(CatalogueTest, exit_2_one_line_no_output_and_existing_output_untouched) {
  const BadCase& c = GetParam();
  TempDir t;
  spit(t / "tools.json", "{ \"tools\": [ 1, 2, \n");
  spit(t / "offset.json", "{\"work_offset_x_mm\": 700, \"work_offset_y_mm\": 10}");
  spit(t / "tools_ok.json", "[ {\"number\": 1, \"diameter_mm\": 3} ]\n");
  const std::string in = c.file.empty() ? "" : t / c.file;
  if (!c.file.empty()) spit(in, c.content);
  const std::string& args = c.args;
  // Run twice: once with no output file, once over an existing one.
  for (bool existing : {false, true}) {
    const std::string out = t / "out.nc";
    std::filesystem::remove(out);
    if (existing) spit(out, "OLD PROGRAM\n");
    std::string line = replace_all(replace_all(replace_all(args, "{in}", shell_quote(in)), "{out}", shell_quote(out)),
                                   "{dir}", shell_quote(t.path()));
    const auto t0 = std::chrono::steady_clock::now();
    auto r = acodrill_run(line);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.code, 2) << c.name << "\n" << r.err;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << c.name << "\n" << r.err;
    EXPECT_THAT(r.err, ::testing::StartsWith("acodrill: error: ")) << c.name;
    EXPECT_THAT(r.err, ::testing::HasSubstr(c.expect)) << c.name;
    EXPECT_EQ(r.out, "") << c.name << ": nothing on stdout";
    EXPECT_LT(seconds, 5.0) << c.name;
    if (existing) {
      EXPECT_EQ(slurp(out), "OLD PROGRAM\n") << c.name;
    } else {
      EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
    }
    if (!c.file.empty() && c.expect.find("overwrite") != std::string::npos) {
      EXPECT_EQ(slurp(in), c.content);
    }
  }
  for (const auto& e : std::filesystem::recursive_directory_iterator(t.path())) {
    EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos) << c.name << ": temporary file left: " << e.path();
  }
}

INSTANTIATE_TEST_SUITE_P(bad_input, CatalogueTest, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<BadCase>& p) { return p.param.name; });

TEST(catalogue_test, has_at_least_forty_cases) { EXPECT_GE(catalogue().size(), 40u); }

TEST(catalogue_test, a_full_disk_fails_cleanly_and_keeps_the_old_program) {
  TempDir t;
  const std::string disk = t / "disk";
  std::filesystem::create_directory(disk);
  // A tiny tmpfs where the machine allows mounting; without it the test says so and stops.
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
  struct Unmount {
    std::string path;
    ~Unmount() { ::umount(path.c_str()); }
  } unmount{disk};
  spit(disk + "/old.nc", "OLD PROGRAM\n");
  // A program far larger than 64 KiB: 5000 holes.
  std::string csv = "x,y,d\n";
  for (int i = 0; i < 5000; ++i) csv += std::to_string(i % 100) + "," + std::to_string(i / 100) + ",1\n";
  spit(t / "big.csv", csv);
  auto r = acodrill_run("plan " + shell_quote(t / "big.csv") + " -o " + shell_quote(disk + "/old.nc") + " --iterations 1");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
  EXPECT_THAT(r.err, ::testing::HasSubstr("No space left on device"));
  EXPECT_EQ(slurp(disk + "/old.nc"), "OLD PROGRAM\n");
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(disk)) files += e.is_regular_file();
  EXPECT_EQ(files, 1u) << "the temporary file is removed";
}

// --- Numeric edge cases: all must plan, and verify must agree ------------------

TEST(catalogue_test, numeric_edge_cases_plan_and_verify) {
  TempDir t;
  std::string collinear = "x,y,d\n", cluster = "x,y,d\n", far = "x,y,d\n", close = "x,y,d\n";
  for (int i = 0; i < 50; ++i) {
    collinear += std::to_string((i * 37) % 50) + ",0,1\n";
    cluster += "3,3," + std::to_string(1 + i) + "\n";  // one point, 50 concentric diameters
    far += std::to_string(1e9 + i) + ",1000000000,1\n";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.7f,1,1\n", 1.0 + i * 2e-6);  // 2e-6 mm apart: distinct holes
    close += buf;
  }
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"one.csv", "x,y,d\n10,10,3\n"}, {"two.csv", "x,y,d\n10,10,3\n20,20,3\n"}, {"collinear.csv", collinear},
      {"cluster.csv", cluster}, {"far.csv", far}, {"close.csv", close}};
  const std::string huge_machine = t / "huge.json";
  spit(huge_machine, "{\"x_min_mm\": -1e12, \"x_max_mm\": 1e12, \"y_min_mm\": -1e12, \"y_max_mm\": 1e12}");
  for (const auto& [name, text] : cases) {
    spit(t / name, text);
    auto r = acodrill_run("plan " + shell_quote(t / name) + " -o " + shell_quote(t / "p.nc") + " -q --machine " +
                          shell_quote(huge_machine));
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    auto v = acodrill_run("verify " + shell_quote(t / "p.nc") + " --holes " + shell_quote(t / name) + " -q");
    if (name != "close.csv") {
      EXPECT_EQ(v.code, 0) << name << ": " << v.out << r.err;
    } else {
      // Holes 1e-7 mm apart print to the same 0.001 mm: the program drills
      // them all; verify sees several at one printed position and says so.
      EXPECT_EQ(gcode::interpret(slurp(t / "p.nc")).holes.size(), 50u);
    }
  }
}
