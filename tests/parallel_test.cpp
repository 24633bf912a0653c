// The colony's one parallel scaffold (libaco/src/parallel.h): each round's
// slots run exactly once, between() runs after all of them and before any of
// the next round's, and failures stop the team, on any number of workers.
// scripts/tsan runs these under ThreadSanitizer too.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "parallel.h"

namespace {

TEST(parallel_test, every_slot_runs_once_a_round_and_between_runs_after_them_all) {
  for (const int threads : {1, 2, 3, 5}) {
    const int count = 7, rounds = 3000;
    int round = 0;                             // written by between() only
    std::vector<int> ran_in(count, -1);        // the round each slot last ran in
    std::atomic<int> wrong{0};
    std::vector<double> busy;
    aco::detail::parallel_rounds(
        count, threads, busy,
        [&](int k, int worker) {
          // Reads what between() wrote: it must have finished before this round began.
          if (ran_in[static_cast<std::size_t>(k)] != round - 1 || worker < 0 || worker >= threads) ++wrong;
          ran_in[static_cast<std::size_t>(k)] = round;
        },
        [&] {
          for (int r : ran_in) {
            if (r != round) ++wrong;
          }
          return ++round < rounds;
        });
    EXPECT_EQ(wrong.load(), 0) << threads << " threads";
    EXPECT_EQ(round, rounds) << threads << " threads";
    EXPECT_EQ(busy.size(), static_cast<std::size_t>(threads));
  }
}

TEST(parallel_test, a_failing_slot_stops_the_team_and_the_first_failure_by_slot_is_rethrown) {
  for (const int threads : {1, 2, 3}) {
    int round = 0;
    std::vector<double> busy;
    try {
      aco::detail::parallel_rounds(
          10, threads, busy,
          [&](int k, int) {
            if (round == 4 && (k == 3 || k == 8)) throw std::runtime_error("slot " + std::to_string(k));
          },
          [&] { return ++round < 100; });
      ADD_FAILURE() << "no exception, " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "slot 3") << threads << " threads";
    }
    EXPECT_EQ(round, 4) << "between() ran after the failing round, " << threads << " threads";
  }
}

TEST(parallel_test, a_failing_between_stops_the_team_and_is_rethrown) {
  for (const int threads : {1, 2}) {
    int round = 0;
    std::vector<double> busy;
    EXPECT_THROW(aco::detail::parallel_rounds(
                     4, threads, busy, [](int, int) {},
                     [&]() -> bool {
                       if (++round == 3) throw std::logic_error("between");
                       return true;
                     }),
                 std::logic_error);
    EXPECT_EQ(round, 3);
  }
}

}  // namespace
