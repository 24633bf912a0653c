// acobench as the contract describes it: the grid, the columns, the summary,
// the charts, and the thesis preset end to end.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "formats/readers.h"
#include "test_util.h"

using testutil::shell_quote;
using testutil::slurp;

namespace {

std::string acobench() { return shell_quote(std::string(ACO_BUILD_DIR) + "/bin/acobench"); }

std::vector<std::vector<std::string>> csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(cell);
    if (!line.empty() && line.back() == ',') row.push_back("");
    rows.push_back(row);
  }
  return rows;
}

int column(const std::vector<std::string>& header, const std::string& name) {
  auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

}  // namespace

TEST(bench_test, grid_rows_summary_and_charts) {
  testutil::TempDir t;
  const std::string d198 = testutil::data("tsplib/d198.tsp");
  const std::string plate = testutil::source_dir() + "/samples/plate27.dxf";
  auto r = testutil::run(acobench() + " --instances " + shell_quote(d198 + "," + plate) +
                         " --algorithm acs,as,nn --iterations 5 --threads 1,2 --seeds 2 --time-limit 0.02,0.05 --out " +
                         shell_quote(t / "runs.csv") + " --summary " + shell_quote(t / "summary.csv") + " --plots " +
                         shell_quote(t / "plots"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto runs = csv(slurp(t / "runs.csv"));
  // 2 instances x 3 algorithms x 2 time limits x 2 threads x 2 seeds.
  ASSERT_EQ(runs.size(), 1u + 2 * 3 * 2 * 2 * 2);
  const auto& h = runs[0];
  for (const char* name : {"instance", "n", "algorithm", "alpha", "beta", "rho", "ants", "iterations", "threads", "seed",
                           "length", "gap_pct", "wall_s", "iterations_done", "time_to_1pct_s", "busy_s"}) {
    EXPECT_GE(column(h, name), 0) << name;
  }
  int gaps = 0, empty_gaps = 0;
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const auto& row = runs[i];
    const std::string gap = row[column(h, "gap_pct")];
    if (row[column(h, "instance")] == "d198") {
      ASSERT_FALSE(gap.empty());
      EXPECT_GE(std::stod(gap), 0.0) << "never below the proven optimum";
      ++gaps;
    } else {
      EXPECT_TRUE(gap.empty()) << "no optimum is known for a plate";
      ++empty_gaps;
    }
    EXPECT_GT(std::stod(row[column(h, "length")]), 0.0);
  }
  EXPECT_EQ(gaps, 24);
  EXPECT_EQ(empty_gaps, 24);
  auto summary = csv(slurp(t / "summary.csv"));
  ASSERT_EQ(summary.size(), 1u + 2 * 3 * 2 * 2);
  const auto& sh = summary[0];
  for (const char* name : {"length_median", "length_mean", "length_sd", "length_min", "wall_median_s", "wall_mean_s",
                           "wall_sd_s", "wall_min_s", "speedup", "efficiency"}) {
    EXPECT_GE(column(sh, name), 0) << name;
  }
  for (std::size_t i = 1; i < summary.size(); ++i) {
    if (summary[i][column(sh, "threads")] == "1" && summary[i][column(sh, "algorithm")] != "nn") {
      EXPECT_EQ(summary[i][column(sh, "speedup")], "1.0000");
    }
  }
  for (const char* chart : {"speedup.svg", "convergence.svg", "gap_vs_time.svg"}) {
    const std::string path = t / ("plots/" + std::string(chart));
    ASSERT_TRUE(std::filesystem::exists(path)) << chart;
    EXPECT_EQ(testutil::run("rsvg-convert " + shell_quote(path) + " -o " + shell_quote(t / "c.png")).code, 0) << chart;
  }
}

TEST(bench_test, first_seed_runs_the_same_runs_as_those_seeds_of_a_longer_grid) {
  testutil::TempDir t;
  const std::string d198 = shell_quote(testutil::data("tsplib/d198.tsp"));
  // One focused iteration: d198's optimum is found by every seed in three.
  const std::string runs = " --algorithm focused --iterations 1 --threads 1";
  auto all = testutil::run(acobench() + " --instances " + d198 + runs + " --seeds 3 --out " +
                           shell_quote(t / "all.csv"));
  ASSERT_EQ(all.code, 0) << all.err;
  auto part = testutil::run(acobench() + " --instances " + d198 + runs + " --first-seed 2 --seeds 2 --out " +
                            shell_quote(t / "part.csv"));
  ASSERT_EQ(part.code, 0) << part.err;
  auto a = csv(slurp(t / "all.csv")), p = csv(slurp(t / "part.csv"));
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(p.size(), 3u);
  const int seed = column(a[0], "seed"), length = column(a[0], "length");
  for (std::size_t i = 1; i < p.size(); ++i) {
    EXPECT_EQ(p[i][seed], std::to_string(i + 1));
    EXPECT_EQ(p[i][length], a[i + 1][length]) << "seed " << p[i][seed];
  }
  EXPECT_NE(a[1][length], a[2][length]) << "seeds that give the same route would not tell the seeds apart";
}

TEST(bench_test, thesis_preset_prints_tables_4_1_to_4_15_beside_the_published_times) {
  testutil::TempDir t;
  // As the contract writes it: no --out needed with a preset.
  auto r = testutil::run("cd " + shell_quote(t.path()) + " && " + acobench() + " --preset thesis --quick");
  ASSERT_EQ(r.code, 0) << r.err;
  for (int table = 1; table <= 15; ++table) {
    EXPECT_THAT(r.out, ::testing::HasSubstr("Table 4." + std::to_string(table) + ":")) << table;
  }
  EXPECT_THAT(r.out, ::testing::HasSubstr("| 1 | ")) << "one processor row";
  EXPECT_THAT(r.out, ::testing::HasSubstr("| 39858 |")) << "the thesis's own time for experiment 5, set A, 1 processor";
  EXPECT_THAT(r.out, ::testing::HasSubstr("focused vs best as"));
}

TEST(bench_test, bad_grid_values_are_usage_errors) {
  testutil::TempDir t;
  for (const std::string& args : {"--instances /nonexistent.tsp --out " + shell_quote(t / "r.csv"),
                                 "--instances " + shell_quote(testutil::data("tsplib/d198.tsp")) + " --rho 2 --out " +
                                     shell_quote(t / "r.csv"),
                                 "--instances " + shell_quote(testutil::data("tsplib/d198.tsp")) +
                                     " --algorithm zzz --out " + shell_quote(t / "r.csv"),
                                 "--instances " + shell_quote(testutil::data("tsplib/d198.tsp")),
                                 std::string("--out")}) {
    auto r = testutil::run(acobench() + " " + args);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(t / "r.csv"));
  }
}

TEST(bench_test, make_tiled_lays_copies_of_the_board_side_by_side_with_the_gap_between) {
  testutil::TempDir t;
  // A board away from the origin, with fractions, in pla7397's metric.
  testutil::spit(t / "board.tsp",
                 "NAME : board\nTYPE : TSP\nDIMENSION : 5\nEDGE_WEIGHT_TYPE : CEIL_2D\nNODE_COORD_SECTION\n"
                 "1 10.5 20\n2 30 25.25\n3 12 40\n4 29.75 39\n5 20 30\nEOF\n");
  auto r = testutil::run("python3 " + shell_quote(testutil::source_dir() + "/bench/make_tiled.py") + " " +
                         shell_quote(t / "board.tsp") + " " + shell_quote(t / "panel.tsp") + " 3 2 100");
  ASSERT_EQ(r.code, 0) << r.err;
  // Both read by the project's own TSPLIB reader, which checks DIMENSION against the nodes.
  const formats::LoadedHoles board = formats::parse_tsplib(t / "board.tsp", slurp(t / "board.tsp"));
  const formats::LoadedHoles panel = formats::parse_tsplib(t / "panel.tsp", slurp(t / "panel.tsp"));
  const auto& b = board.holes;
  const auto& p = panel.holes;
  ASSERT_EQ(b.size(), 5u);
  ASSERT_EQ(p.size(), 6 * b.size());
  EXPECT_EQ(formats::tsplib_metric(panel), aco::Metric::TsplibCeil2d);
  // Copy (i, j) is the board moved to the origin, then i board widths plus
  // gaps right and j heights plus gaps up: the board is 19.5 x 20.
  std::size_t k = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 2; ++j) {
      for (const aco::Hole& h : b) {
        EXPECT_NEAR(p[k].center.x, h.center.x - 10.5 + i * (19.5 + 100), 1e-9) << k;
        EXPECT_NEAR(p[k].center.y, h.center.y - 20 + j * (20 + 100), 1e-9) << k;
        ++k;
      }
    }
  }
  // The solver reads it as one instance.
  auto solved = testutil::acodrill_run("tsp " + shell_quote(t / "panel.tsp") + " --iterations 2 -q");
  ASSERT_EQ(solved.code, 0) << solved.err;
  EXPECT_THAT(solved.out, ::testing::StartsWith("length "));
}

// Issue 48: sweeps split into shards for a cluster.
namespace {

// The rows of a runs or summary CSV without the columns that hold times (and
// the shard that ran a row, which the merge clears).
std::vector<std::vector<std::string>> without_times(const std::string& text) {
  auto rows = csv(text);
  std::vector<int> drop;
  for (const char* name : {"wall_s", "time_to_1pct_s", "busy_s", "trace", "wall_median_s", "wall_mean_s", "wall_sd_s",
                           "wall_min_s", "speedup", "efficiency"}) {
    const int k = column(rows.at(0), name);
    if (k >= 0) drop.push_back(k);
  }
  std::sort(drop.rbegin(), drop.rend());
  for (auto& row : rows) {
    for (int k : drop) {
      if (k < static_cast<int>(row.size())) row.erase(row.begin() + k);
    }
  }
  return rows;
}

const std::string kSweep = " --algorithm focused,nn2opt --alpha 1,2 --beta 3,5 --seeds 2 --iterations 3 --threads 1";

std::string sweep_instances() {
  return " --instances " + shell_quote(testutil::data("tsplib/d198.tsp") + "," + testutil::source_dir() + "/samples/plate10.dxf");
}

}  // namespace

TEST(bench_test, shards_merged_give_the_rows_and_summary_of_one_process_whatever_n) {
  testutil::TempDir t;
  auto one = testutil::run(acobench() + sweep_instances() + kSweep + " --out " + shell_quote(t / "one.csv") + " --summary " +
                           shell_quote(t / "one-summary.csv"));
  ASSERT_EQ(one.code, 0) << one.err;
  const auto one_rows = without_times(slurp(t / "one.csv"));
  ASSERT_EQ(one_rows.size(), 1u + 2 * 2 * (2 * 2) * 2) << "2 instances x 2 algorithms x 2x2 alpha-beta cells x 2 seeds";
  const int tour = column(one_rows[0], "tour_hash");
  ASSERT_GE(tour, 0);
  EXPECT_NE(one_rows[1][tour], one_rows[2][tour]) << "seeds 1 and 2 of a cell: different tours";
  for (int n : {1, 3, 7}) {
    std::string parts;
    for (int k = n - 1; k >= 0; --k) {  // any order
      const std::string part = t / ("part-" + std::to_string(k) + ".csv");
      auto r = testutil::run(acobench() + sweep_instances() + kSweep + " --shard " + std::to_string(k) + "/" +
                             std::to_string(n) + " --out " + shell_quote(part));
      ASSERT_EQ(r.code, 0) << r.err;
      parts += " " + shell_quote(part);
    }
    auto m = testutil::run(acobench() + " merge" + parts + " --out " + shell_quote(t / "all.csv") + " --summary " +
                           shell_quote(t / "all-summary.csv") + " --plots " + shell_quote(t / "plots"));
    ASSERT_EQ(m.code, 0) << m.err;
    EXPECT_EQ(without_times(slurp(t / "all.csv")), one_rows) << n << " shards";
    EXPECT_EQ(without_times(slurp(t / "all-summary.csv")), without_times(slurp(t / "one-summary.csv"))) << n << " shards";
    EXPECT_TRUE(std::filesystem::exists(t / "plots/convergence.svg"));
    for (int k = 0; k < n; ++k) std::filesystem::remove(t / ("part-" + std::to_string(k) + ".csv"));
  }
}

TEST(bench_test, merge_refuses_a_missing_repeated_foreign_or_cut_shard) {
  testutil::TempDir t;
  auto shard = [&](const std::string& extra, const std::string& k, const std::string& name) {
    auto r = testutil::run(acobench() + sweep_instances() + kSweep + extra + " --shard " + k + " --out " + shell_quote(t / name));
    ASSERT_EQ(r.code, 0) << r.err;
  };
  shard("", "0/3", "p0.csv");
  shard("", "1/3", "p1.csv");
  shard("", "2/3", "p2.csv");
  shard(" --rho 0.3", "2/3", "other.csv");  // another sweep's shard
  const std::string p2 = slurp(t / "p2.csv");
  testutil::spit(t / "cut.csv", p2.substr(0, p2.rfind('\n', p2.size() - 2) + 1));  // its last run lost
  const std::string p0 = shell_quote(t / "p0.csv"), p1 = shell_quote(t / "p1.csv");
  struct Case {
    std::string parts, says;
  };
  for (const Case& c : {Case{p0 + " " + p1, "shard 2/3 of sweep"},
                        Case{p0 + " " + p1 + " " + p1 + " " + shell_quote(t / "p2.csv"), "is given twice"},
                        Case{p0 + " " + p1 + " " + shell_quote(t / "other.csv"), "a shard of another sweep"},
                        Case{p0 + " " + p1 + " " + shell_quote(t / "cut.csv"), "cut short"},
                        Case{p0 + " " + shell_quote(testutil::source_dir() + "/docs/bench/gap-runs.csv"), "not a runs CSV"}}) {
    auto r = testutil::run(acobench() + " merge " + c.parts + " --out " + shell_quote(t / "all.csv"));
    EXPECT_EQ(r.code, 2) << c.parts << ": " << r.err;
    EXPECT_EQ(testutil::count_lines(r.err), 1) << r.err;
    EXPECT_THAT(r.err, ::testing::HasSubstr(c.says));
    EXPECT_FALSE(std::filesystem::exists(t / "all.csv"));
  }
  for (const char* bad : {"4/4", "1/0", "x", "1/2/3"}) {
    auto r = testutil::run(acobench() + sweep_instances() + kSweep + " --shard " + bad + " --out " + shell_quote(t / "x.csv"));
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_THAT(r.err, ::testing::HasSubstr("--shard must be K/N"));
  }
}

// The batch scripts `acobench slurm` writes, run as Slurm runs them (its
// #SBATCH lines are comments to bash): the array's tasks one by one, then the
// merge. scripts/slurm-test runs them on a real one-node Slurm.
TEST(bench_test, slurm_scripts_run_the_shards_and_the_merge) {
  testutil::TempDir t;
  auto w = testutil::run("cd " + shell_quote(t.path()) + " && " + acobench() + " slurm" + sweep_instances() + kSweep +
                         " --shards 4 --out all.csv --summary summary.csv --partition debug --time 0:10:00");
  ASSERT_EQ(w.code, 0) << w.err;
  const std::string array = slurp(t / "acobench-all.sbatch"), merge = slurp(t / "acobench-all-merge.sbatch");
  EXPECT_THAT(array, ::testing::HasSubstr("#SBATCH --array=0-3\n"));
  EXPECT_THAT(array, ::testing::HasSubstr("#SBATCH --partition=debug\n"));
  EXPECT_THAT(array, ::testing::HasSubstr("#SBATCH --time=0:10:00\n"));
  EXPECT_THAT(array, ::testing::HasSubstr("#SBATCH --cpus-per-task=1\n"));
  EXPECT_THAT(array, ::testing::HasSubstr("--shard \"${SLURM_ARRAY_TASK_ID}/4\""));
  EXPECT_THAT(w.out, ::testing::HasSubstr("sbatch --dependency=afterok:"));
  for (int k = 0; k < 4; ++k) {
    auto r = testutil::run("cd / && SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " SLURM_CPUS_PER_TASK=1 bash " +
                           shell_quote(t / "acobench-all.sbatch"));
    ASSERT_EQ(r.code, 0) << r.err;
  }
  auto m = testutil::run("cd / && bash " + shell_quote(t / "acobench-all-merge.sbatch"));
  ASSERT_EQ(m.code, 0) << m.err;
  auto one = testutil::run(acobench() + sweep_instances() + kSweep + " --out " + shell_quote(t / "one.csv"));
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(without_times(slurp(t / "all.csv")), without_times(slurp(t / "one.csv")));
  EXPECT_TRUE(std::filesystem::exists(t / "summary.csv"));
}
