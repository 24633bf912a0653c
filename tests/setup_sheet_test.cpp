// The setup sheet (issue 13) as the operator sees it: printed by a real
// browser (Debian's chromium, headless) to PDF, its text read by pdftotext and
// checked against the plan's own report. Skips only where chromium cannot start.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "gcode/program.h"
#include "test_util.h"

namespace {

using testutil::acodrill_run;
using testutil::shell_quote;
using testutil::slurp;

// Prints `html` to `pdf` with headless chromium; false when the browser cannot start here.
bool print_to_pdf(const std::string& html, const std::string& pdf, const testutil::TempDir& t) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0) return false;
  // The flags keep chromium off the (closed) network and out of the user's profile.
  auto r = testutil::run("timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                         "--disable-background-networking --disable-component-update --disable-sync "
                         "--no-pdf-header-footer --user-data-dir=" + shell_quote(t / "profile") +
                         " --print-to-pdf=" + shell_quote(pdf) + " " + shell_quote("file://" + html));
  return r.code == 0 && std::filesystem::exists(pdf) && std::filesystem::file_size(pdf) > 1000;
}

std::string squeeze(const std::string& s) {
  // pdftotext breaks lines and columns where the layout does; compare words.
  std::string out;
  for (char c : s) {
    const bool blank = c == ' ' || c == '\n' || c == '\t' || c == '\f';
    if (blank) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

void check_sheet(const std::string& input, const std::string& extra) {
  testutil::TempDir t;
  const std::string html = t / "sheet.html";
  auto r = acodrill_run("plan " + shell_quote(input) + " -o " + shell_quote(t / "p.nc") + " --report " +
                        shell_quote(t / "r.json") + " --setup-sheet " + shell_quote(html) + " -q --iterations 20" + extra);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = slurp(html);
  // Self-contained: no scripts, nothing fetched.
  EXPECT_THAT(page, ::testing::StartsWith("<!DOCTYPE html>"));
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("src="), std::string::npos);
  EXPECT_EQ(page.find("href="), std::string::npos);
  EXPECT_THAT(page, ::testing::HasSubstr("<svg"));
  // Reproducible: the same plan gives the same page.
  auto again = acodrill_run("plan " + shell_quote(input) + " -o " + shell_quote(t / "q.nc") + " --setup-sheet " +
                            shell_quote(t / "again.html") + " -q --iterations 20" + extra);
  ASSERT_EQ(again.code, 0);
  std::string second = slurp(t / "again.html");
  const std::string a = t / "p.nc", b = t / "q.nc";
  second.replace(second.find(b), b.size(), a);  // only the program's name differs
  EXPECT_EQ(page, second);

  const std::string pdf = t / "sheet.pdf";
  if (!print_to_pdf(html, pdf, t)) GTEST_SKIP() << "chromium cannot start here";
  auto text_run = testutil::run("pdftotext -layout " + shell_quote(pdf) + " -");
  ASSERT_EQ(text_run.code, 0) << "pdftotext: " << text_run.err;
  const std::string text = squeeze(text_run.out);
  const auto report = nlohmann::json::parse(slurp(t / "r.json"));
  auto f = [](double v, int d) { return gcode::format_number(v, d); };
  EXPECT_THAT(text, ::testing::HasSubstr("Setup sheet"));
  EXPECT_THAT(text, ::testing::HasSubstr("LOWER-LEFT OF HOLES"));
  const auto& zero = report["origin"]["zero_in_input_mm"];
  EXPECT_THAT(text, ::testing::HasSubstr("drawing X" + f(zero["x"].get<double>(), 3) + " Y" + f(zero["y"].get<double>(), 3)));
  const auto& ext = report["extent_mm"];
  EXPECT_THAT(text, ::testing::HasSubstr("X" + f(ext["x_min"].get<double>(), 3) + ".." + f(ext["x_max"].get<double>(), 3) +
                                         " Y" + f(ext["y_min"].get<double>(), 3) + ".." + f(ext["y_max"].get<double>(), 3)));
  EXPECT_THAT(text, ::testing::HasSubstr("Total estimated time: " +
                                         f(report["machining_time_s"]["optimized"].get<double>() / 60.0, 2) + " min"));
  EXPECT_THAT(text, ::testing::HasSubstr(f(report["travel_mm"]["input_order"].get<double>(), 3)));
  EXPECT_THAT(text, ::testing::HasSubstr(f(report["travel_mm"]["optimized"].get<double>(), 3)));
  // One row per tool: number, diameter, cycle, depth and hole count, in that order.
  for (const auto& tool : report["tools"]) {
    const std::string row = "T" + std::to_string(tool["tool"].get<int>());
    EXPECT_THAT(text, ::testing::ContainsRegex(row + " .*" + f(tool["diameter_mm"].get<double>(), 3) + " " +
                                               tool["cycle"].get<std::string>() + " " +
                                               f(tool["depth_mm"].get<double>(), 3)))
        << row;
    EXPECT_THAT(text, ::testing::HasSubstr(" " + std::to_string(tool["spindle_rpm"].get<int>()) + " " +
                                           std::to_string(tool["holes"].get<int>()) + " "))
        << row;
  }
}

}  // namespace

TEST(setup_sheet_test, plate70_prints_with_its_plan) {
  check_sheet(testutil::source_dir() + "/samples/plate70.dxf", "");
}

TEST(setup_sheet_test, multi_tool_excellon_job_prints_every_tool) {
  check_sheet(testutil::data("kicad/StickHub-mm-decimal.drl"), "");
}
