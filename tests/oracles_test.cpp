// The oracles themselves (tests/oracles.h): what makes them trustworthy when
// the suite runs them in parallel.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "oracles.h"
#include "test_util.h"

namespace {

// A program that changes to each of `tools` and drills one hole with each.
std::string program_with_tools(const std::vector<int>& tools) {
  std::string p = "G21 G90 G17\n";
  for (int n : tools) {
    p += "T" + std::to_string(n) + " M6\nG00 Z5.\nG00 X" + std::to_string(n) + ". Y1.\nG01 Z-1. F100.\nG00 Z5.\n";
  }
  return p + "M30\n";
}

}  // namespace

// Issue 85: LinuxCNC 2.9's rs274 maps its tool data into $HOME/.tool.mmap,
// shared by every rs274 of the user; two runs at once with different tool
// tables then read each other's ("Requested tool 7 not found in the tool
// table"). The oracle gives each run a HOME of its own (testutil::rs274_in):
// 50 pairs at once, each reads its own tools. Without that HOME, 30 of 30
// pairs failed when measured.
TEST(oracles_test, rs274_runs_at_once_each_read_their_own_tool_table) {
  ASSERT_EQ(std::system("command -v rs274 >/dev/null 2>&1"), 0) << "rs274 missing: scripts/test installs linuxcnc-uspace";
  testutil::TempDir t;
  const std::vector<int> tools_a = {1, 2, 3}, tools_b = {7, 8, 9};
  testutil::spit(t / "a.nc", program_with_tools(tools_a));
  testutil::spit(t / "b.nc", program_with_tools(tools_b));
  constexpr int kPairs = 50;
  std::vector<std::vector<int>> read_a(kPairs), read_b(kPairs);
  for (int k = 0; k < kPairs; ++k) {
    std::thread other([&] { read_b[k] = oracles::run_rs274(t / "b.nc").tools; });
    read_a[k] = oracles::run_rs274(t / "a.nc").tools;
    other.join();
  }
  for (int k = 0; k < kPairs; ++k) {
    EXPECT_EQ(read_a[k], tools_a) << "pair " << k;
    EXPECT_EQ(read_b[k], tools_b) << "pair " << k;
  }
}
