// White-box tests of the Hilbert-curve numbering (libaco/src/hilbert.h) the
// solver gives the holes of large jobs: the curve visits every cell once,
// each next to the last, so holes near in the numbering are near on the plate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>

#include "hilbert.h"

namespace {

using aco::HoleIndex;
using aco::Point2;

TEST(Hilbert, FirstCellsOfTheCurveFillACornerEachNextToTheLast) {
  // The curve fills the grid quadrant by quadrant: its first 4^6 cells are
  // the 64 x 64 corner at the origin.
  constexpr std::uint32_t side = 64;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cell_at(side * side, {UINT32_MAX, UINT32_MAX});
  for (std::uint32_t x = 0; x < side; ++x) {
    for (std::uint32_t y = 0; y < side; ++y) {
      const std::uint64_t d = aco::detail::hilbert_index(x, y);
      ASSERT_LT(d, side * side) << x << "," << y;
      ASSERT_EQ(cell_at[d].first, UINT32_MAX) << "two cells at " << d;
      cell_at[d] = {x, y};
    }
  }
  EXPECT_EQ(cell_at[0], (std::pair<std::uint32_t, std::uint32_t>{0, 0}));
  for (std::size_t d = 1; d < cell_at.size(); ++d) {
    const auto [x0, y0] = cell_at[d - 1];
    const auto [x1, y1] = cell_at[d];
    const std::uint32_t steps = (x0 > x1 ? x0 - x1 : x1 - x0) + (y0 > y1 ? y0 - y1 : y1 - y0);
    EXPECT_EQ(steps, 1u) << "cells " << d - 1 << " and " << d;
  }
}

double path_length(const std::vector<Point2>& points, const std::vector<HoleIndex>& order) {
  double len = 0.0;
  for (std::size_t i = 1; i < order.size(); ++i) {
    len += std::hypot(points[order[i]].x - points[order[i - 1]].x, points[order[i]].y - points[order[i - 1]].y);
  }
  return len;
}

TEST(Hilbert, OrderOfAShuffledGridIsAShortPathThroughEveryPoint) {
  // 128 x 128 holes at 2.54 mm, given in random order.
  std::vector<Point2> points;
  for (int x = 0; x < 128; ++x) {
    for (int y = 0; y < 128; ++y) points.push_back({10.0 + 2.54 * x, 5.0 + 2.54 * y});
  }
  std::shuffle(points.begin(), points.end(), std::mt19937(5));
  const std::vector<HoleIndex> order = aco::detail::hilbert_order(points);
  ASSERT_EQ(order.size(), points.size());
  EXPECT_EQ(std::set<HoleIndex>(order.begin(), order.end()).size(), points.size());
  std::vector<HoleIndex> given(points.size());
  std::iota(given.begin(), given.end(), HoleIndex{0});
  const double shortest = 2.54 * static_cast<double>(points.size() - 1);
  EXPECT_GT(path_length(points, given), 20 * shortest);  // the input order jumps about
  EXPECT_LT(path_length(points, order), 1.05 * shortest);
}

TEST(Hilbert, StretchTellsAnOrderThatFollowsThePlateFromOneThatJumpsAbout) {
  std::vector<Point2> rows;  // 128 rows of 128 holes, row by row
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 128; ++x) rows.push_back({2.54 * x, 2.54 * y});
  }
  const double in_rows = aco::detail::order_stretch(rows, aco::detail::hilbert_order(rows));
  EXPECT_GT(in_rows, 1.0);  // each row's end jumps back across the plate
  EXPECT_LT(in_rows, 2.0);
  std::vector<Point2> shuffled = rows;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(9));
  EXPECT_GT(aco::detail::order_stretch(shuffled, aco::detail::hilbert_order(shuffled)), 20.0);
}

TEST(Hilbert, PointsInOneCellKeepTheirInputOrder) {
  const std::vector<Point2> same(5, Point2{3.0, 4.0});
  EXPECT_EQ(aco::detail::hilbert_order(same), (std::vector<HoleIndex>{0, 1, 2, 3, 4}));
  const std::vector<Point2> line = {{2, 0}, {0, 0}, {2, 0}, {1, 0}};
  const std::vector<HoleIndex> order = aco::detail::hilbert_order(line);
  EXPECT_EQ(order.size(), 4u);
  // Holes 0 and 2 share a cell: 0 comes first, and nothing comes between.
  const auto at = [&](HoleIndex h) { return std::find(order.begin(), order.end(), h) - order.begin(); };
  EXPECT_EQ(at(2), at(0) + 1);
  EXPECT_TRUE(aco::detail::hilbert_order({}).empty());
}

}  // namespace
