// The job as one call (issue 64): the library plans what `acodrill plan`
// plans, byte for byte, from bytes in memory; it reports progress, obeys a
// stop, runs in slices to the same result, and says a bad input in one line.
#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <nlohmann/json.hpp>

#include "gcode/interpreter.h"
#include "job/plan.h"
#include "job/verify.h"
#include "test_util.h"

namespace {

using testutil::data;
using testutil::slurp;

std::string sample(const std::string& name) { return testutil::source_dir() + "/samples/" + name; }

// The report without what depends on the clock (the solver's wall and busy times).
nlohmann::json steady_report(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text);
  j["solver"].erase("wall_s");
  j["solver"].erase("thread_busy_s");
  return j;
}

// The convergence rows without their times.
std::string steady_convergence(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, out;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) f.push_back(cell);
    if (f.size() == 4) out += f[0] + "," + f[1] + "," + f[3] + "\n";
  }
  return out;
}

struct Case {
  const char* name;
  std::vector<std::string> inputs;  // paths
  std::string options;              // as acodrill plan takes them
  job::PlanSettings settings;       // the same, as the library takes them
};

std::vector<Case> cases() {
  std::vector<Case> out;
  {
    Case c{"plate70", {sample("plate70.dxf")}, "--seed 3 --iterations 40", {}};
    c.settings.solver.seed = 3;
    c.settings.solver.iterations = 40;
    out.push_back(c);
  }
  {
    // A KiCad drill file on the router, with the drills owned and an end mill for the rest.
    Case c{"video owned drills and end mill",
           {data("kicad/video-mm-decimal.drl")},
           "--machine router --drills 0.4,0.6,0.8 --end-mill 0.5 --seed 5 --iterations 30",
           {}};
    c.settings.machine = "router";
    c.settings.bench.drills = "0.4,0.6,0.8";
    c.settings.bench.end_mill_mm = 0.5;
    c.settings.solver.seed = 5;
    c.settings.solver.iterations = 30;
    out.push_back(c);
  }
  {
    Case c{"panel of six, back side", {data("kicad/pic_programmer-inch-decimal.drl")},
           "--panel 3x2 --pitch 120,90 --side back --alignment-pins 3 --origin center --dialect fanuc --units inch "
           "--seed 2 --iterations 25",
           {}};
    c.settings.panel = "3x2";
    c.settings.pitch = "120,90";
    c.settings.bench.side = "back";
    c.settings.bench.alignment_pins_mm = 3.0;
    c.settings.origin = "center";
    c.settings.dialect = "fanuc";
    c.settings.units = "inch";
    c.settings.solver.seed = 2;
    c.settings.solver.iterations = 25;
    out.push_back(c);
  }
  return out;
}

std::vector<job::InputFile> files_of(const std::vector<std::string>& paths) {
  std::vector<job::InputFile> files;
  for (const std::string& p : paths) files.push_back({p, slurp(p), ""});
  return files;
}

}  // namespace

TEST(job_test, the_library_call_writes_what_acodrill_plan_writes) {
  for (Case c : cases()) {
    SCOPED_TRACE(c.name);
    testutil::TempDir t;
    std::string inputs;
    for (const std::string& p : c.inputs) inputs += testutil::shell_quote(p) + " ";
    const auto cli = testutil::acodrill_run(
        "plan " + inputs + c.options + " -q -o " + t / "p.nc" + " --report " + t / "r.json" + " --svg " + t / "r.svg" +
        " --svg-compare " + t / "c.svg" + " --setup-sheet " + t / "s.html" + " --excellon " + t / "o.drl" + " --gerber " +
        t / "o.gbr" + " --convergence " + t / "conv.csv");
    ASSERT_EQ(cli.code, 0) << cli.err;
    c.settings.program_name = t / "p.nc";
    c.settings.wanted = job::Wanted::all();
    for (int threads : {1, 2}) {
      c.settings.solver.threads = threads;
      const job::Result r = job::plan(files_of(c.inputs), c.settings);
      ASSERT_EQ(r.exit_code, 0) << r.error;
      EXPECT_FALSE(r.stopped);
      EXPECT_EQ(r.files.program, slurp(t / "p.nc"));
      EXPECT_EQ(r.files.route_svg, slurp(t / "r.svg"));
      EXPECT_EQ(r.files.compare_svg, slurp(t / "c.svg"));
      EXPECT_EQ(r.files.setup_sheet, slurp(t / "s.html"));
      EXPECT_EQ(r.files.excellon, slurp(t / "o.drl"));
      EXPECT_EQ(r.files.gerber, slurp(t / "o.gbr"));
      nlohmann::json report = steady_report(r.files.report);
      nlohmann::json expected = steady_report(slurp(t / "r.json"));
      // The report names the threads it ran on; the routes are the same on any number.
      report["solver"].erase("threads");
      expected["solver"].erase("threads");
      EXPECT_EQ(report, expected);
      EXPECT_EQ(steady_convergence(r.files.convergence), steady_convergence(slurp(t / "conv.csv")));
      // The summary as values: the plan's own figures, and the report's.
      EXPECT_EQ(r.holes.size(), nlohmann::json::parse(r.files.report)["holes"].get<std::size_t>());
      EXPECT_LT(r.plan.optimized.travel_mm, r.plan.input_order.travel_mm);
      EXPECT_NEAR(r.plan.optimized.split.total(), r.plan.optimized.time_s, 1e-6);
    }
  }
}

TEST(job_test, progress_sees_the_routes_improve_and_a_stop_keeps_a_valid_program) {
  job::PlanSettings settings;
  settings.solver.iterations = 100000;  // only the stop ends it
  settings.solver.seed = 4;
  settings.machine = "router";
  const std::vector<job::InputFile> files = files_of({data("kicad/video-mm-decimal.drl")});
  std::atomic<bool> stop{false};
  std::vector<job::Progress> seen;
  const job::Result r = job::plan(files, settings, [&](const job::Progress& p) {
    seen.push_back(p);
    if (seen.size() == 30) stop.store(true);
  }, &stop);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_TRUE(r.stopped);
  ASSERT_GE(seen.size(), 30u);
  // Within a tool the best only gets shorter; at least one call says it did.
  bool improved = false;
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_GE(seen[i].elapsed_s, seen[i - 1].elapsed_s);
    if (seen[i].tool != seen[i - 1].tool) continue;
    EXPECT_LE(seen[i].best_length, seen[i - 1].best_length + 1e-9);
    if (seen[i].improved && seen[i].best_length < seen[i - 1].best_length) improved = true;
    EXPECT_GT(seen[i].tools, seen[i].tool);
    // At least every 200 ms (here an iteration takes milliseconds; the bound leaves room for a loaded machine).
    EXPECT_LT(seen[i].elapsed_s - seen[i - 1].elapsed_s, 0.5);
    EXPECT_GT(seen[i].holes, 0u);
  }
  EXPECT_TRUE(improved);
  // Every hole drilled once with the right tool, read back as verify reads it.
  const gcode::Interpretation run = gcode::interpret(r.files.program);
  EXPECT_EQ(run.holes.size(), r.holes.size());
  EXPECT_TRUE(job::check_drilled(run, r.holes).empty());
  // A whole program, to its end (GRBL's M2).
  EXPECT_NE(r.files.program.find("\nM2"), std::string::npos);
}

TEST(job_test, a_job_in_slices_is_the_job_in_one_call) {
  for (Case c : cases()) {
    SCOPED_TRACE(c.name);
    c.settings.wanted.report = true;
    const job::Result whole = job::plan(files_of(c.inputs), c.settings);
    ASSERT_EQ(whole.exit_code, 0) << whole.error;
    job::PlanJob sliced(files_of(c.inputs), c.settings);
    int slices = 0;
    while (!sliced.advance(7)) ++slices;
    const job::Result r = sliced.finish();
    EXPECT_GT(slices, 2);
    EXPECT_EQ(r.files.program, whole.files.program);
    EXPECT_EQ(steady_report(r.files.report), steady_report(whole.files.report));
    // Ended early, it keeps the best so far: still every hole.
    job::PlanJob early(files_of(c.inputs), c.settings);
    EXPECT_FALSE(early.advance(3));
    const job::Result e = early.finish();
    ASSERT_EQ(e.exit_code, 0) << e.error;
    EXPECT_TRUE(e.stopped);
    EXPECT_EQ(gcode::interpret(e.files.program).holes.size(), whole.holes.size());
  }
}

// Issue 84: the page's time limit covers the outputs. The colony is
// budgeted what is left after the work around it; with no time for it, each
// tool's holes stay in their first (nearest-neighbour) route, and the job
// still says "done", not "stopped".
TEST(job_test, a_time_limit_that_covers_the_outputs_leaves_the_colony_out_when_there_is_no_time_for_it) {
  job::PlanSettings settings;
  settings.solver.seed = 3;
  settings.solver.time_limit_s = 1e-6;
  settings.solver.time_limit_covers_outputs = true;
  settings.wanted.report = true;
  const job::Result r = job::plan(files_of({sample("plate70.dxf")}), settings);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_FALSE(r.stopped);
  EXPECT_TRUE(r.no_time_for_colony);
  EXPECT_EQ(r.plan.iterations, 0);
  ASSERT_FALSE(r.plan.groups.empty());
  for (const planning::ToolGroup& g : r.plan.groups) {
    EXPECT_EQ(g.solution.stop_reason, "time limit");
    EXPECT_EQ(g.optimized.size(), g.input_order.size());
  }
  // The nearest-neighbour route itself: no local search, no iteration.
  EXPECT_EQ(r.plan.optimized.travel_mm, r.plan.nearest_neighbor.travel_mm);
  EXPECT_LT(r.plan.optimized.travel_mm, r.plan.input_order.travel_mm);
  const gcode::Interpretation run = gcode::interpret(r.files.program);
  EXPECT_EQ(run.holes.size(), r.holes.size());
  EXPECT_TRUE(job::check_drilled(run, r.holes).empty());
  EXPECT_EQ(nlohmann::json::parse(r.files.report)["tools"][0]["stop_reason"], "time limit");

  // A limit the iterations end first: the budget changes nothing, and the
  // input order counted before the routing is the one counted after it.
  job::PlanSettings plain;
  plain.solver.seed = 3;
  plain.solver.iterations = 40;
  plain.wanted.report = true;
  job::PlanSettings budgeted = plain;
  budgeted.solver.time_limit_s = 600;
  budgeted.solver.time_limit_covers_outputs = true;
  const job::Result a = job::plan(files_of({sample("plate70.dxf")}), plain);
  const job::Result b = job::plan(files_of({sample("plate70.dxf")}), budgeted);
  ASSERT_EQ(b.exit_code, 0) << b.error;
  EXPECT_FALSE(b.no_time_for_colony);
  EXPECT_EQ(b.files.program, a.files.program);
  EXPECT_EQ(b.plan.input_order.time_s, a.plan.input_order.time_s);
  EXPECT_EQ(b.plan.input_order.travel_mm, a.plan.input_order.travel_mm);
}

TEST(job_test, a_bad_input_or_setting_is_one_line_and_nothing_else) {
  job::PlanSettings settings;
  job::Result r = job::plan({{"bad.csv", "x,y,diameter\n1,2,3\n4,five,3\n", ""}}, settings);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.error.find("bad.csv:3"), std::string::npos) << r.error;
  EXPECT_EQ(r.error.find('\n'), std::string::npos);
  EXPECT_TRUE(r.files.program.empty());
  settings.dialect = "heidenhain";
  r = job::plan(files_of({sample("plate10.dxf")}), settings);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.error, "--dialect must be haas, fanuc, linuxcnc, grbl or marlin (got \"heidenhain\")");
  settings.dialect.clear();
  r = job::plan({}, settings);
  EXPECT_EQ(r.exit_code, 2);
  // The same settings then plan a good input: nothing is left over from a failure.
  r = job::plan(files_of({sample("plate10.dxf")}), settings);
  EXPECT_EQ(r.exit_code, 0) << r.error;
  EXPECT_EQ(gcode::interpret(r.files.program).holes.size(), 10u);
  // A fault of acodrill's own: exit 3, no program.
  settings.break_writer_for_test = true;
  r = job::plan(files_of({sample("plate10.dxf")}), settings);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(r.files.program.empty());
}
