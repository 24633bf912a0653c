// The colony's one parallel scaffold (libaco/src/parallel.h): each round's
// slots run exactly once, between() runs after all of them and before any of
// the next round's, and failures stop the team, on any number of workers; a
// team kept for a whole solve does so job after job, the solve on the
// calling thread and each worker on a thread of its own.
// scripts/tsan runs these under ThreadSanitizer too.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel.h"

namespace {

template <class Body, class Between>
void rounds_on_a_team_of_their_own(int count, int threads, std::vector<double>& busy_s, Body&& body, Between&& between) {
  aco::detail::Team::run(threads, [&](aco::detail::Team& team) { team.rounds(count, busy_s, body, between); });
}

TEST(parallel_test, every_slot_runs_once_a_round_and_between_runs_after_them_all) {
  for (const int threads : {1, 2, 3, 5}) {
    const int count = 7, rounds = 3000;
    int round = 0;                             // written by between() only
    std::vector<int> ran_in(count, -1);        // the round each slot last ran in
    std::atomic<int> wrong{0};
    std::vector<double> busy;
    rounds_on_a_team_of_their_own(
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
      rounds_on_a_team_of_their_own(
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
    EXPECT_THROW(rounds_on_a_team_of_their_own(
                     4, threads, busy, [](int, int) {},
                     [&]() -> bool {
                       if (++round == 3) throw std::logic_error("between");
                       return true;
                     }),
                 std::logic_error);
    EXPECT_EQ(round, 3);
  }
}

// Many short jobs in a row, as a solve posts them (rows, the ascent's steps,
// the iterations): a worker that looks in late must join the job under way
// or none, never one that has ended (its state is gone: the sanitizer runs
// catch that).
TEST(parallel_test, a_team_runs_job_after_job_each_round_whole_and_each_chunk_once) {
  for (const int threads : {1, 2, 3, 5}) {
    std::atomic<int> wrong{0};
    int jobs_done = 0;
    aco::detail::Team::run(threads, [&](aco::detail::Team& team) {
      EXPECT_EQ(team.threads(), threads);
      for (int job = 0; job < 400; ++job) {
        const int count = 1 + job % 9, rounds = 1 + job % 4;
        int round = 0;
        auto ran_in = std::make_unique<std::vector<int>>(count, -1);  // on the heap, so a stale reader is seen
        std::vector<double> busy;
        team.rounds(
            count, busy,
            [&](int k, int worker) {
              if ((*ran_in)[static_cast<std::size_t>(k)] != round - 1 || worker < 0 || worker >= threads) ++wrong;
              (*ran_in)[static_cast<std::size_t>(k)] = round;
            },
            [&] {
              for (int r : *ran_in) {
                if (r != round) ++wrong;
              }
              return ++round < rounds;
            });
        if (round != rounds) ++wrong;
        const std::size_t size = static_cast<std::size_t>(job) * 7;
        auto hits = std::make_unique<std::vector<std::atomic<int>>>(size);
        team.chunks(size, 64, [&](std::size_t begin, std::size_t end, int) {
          if (begin >= end || end > size || end - begin > 64) ++wrong;
          for (std::size_t i = begin; i < end; ++i) ++(*hits)[i];
        });
        for (const auto& h : *hits) {
          if (h.load() != 1) ++wrong;
        }
        ++jobs_done;
      }
    });
    EXPECT_EQ(wrong.load(), 0) << threads << " threads";
    EXPECT_EQ(jobs_done, 400);
  }
}

TEST(parallel_test, the_solve_runs_on_the_calling_thread_and_each_worker_on_a_thread_of_its_own) {
  for (const int threads : {2, 3, 5}) {
    const std::thread::id caller = std::this_thread::get_id();
    std::mutex mutex;
    std::vector<std::thread::id> thread_of(static_cast<std::size_t>(threads));
    std::vector<double> busy;
    aco::detail::Team::run(threads, [&](aco::detail::Team& team) {
      EXPECT_EQ(std::this_thread::get_id(), caller);
      // Every slot waits until each has been taken, so each worker holds
      // one: the workers come up beside the solve, or this waits 10 s and fails.
      std::atomic<int> arrived{0};
      team.rounds(
          threads, busy,
          [&](int, int worker) {
            {
              std::lock_guard<std::mutex> lock(mutex);
              thread_of[static_cast<std::size_t>(worker)] = std::this_thread::get_id();
            }
            ++arrived;
            const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
            while (arrived.load() < threads && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
          },
          [] { return false; });
    });
    EXPECT_EQ(thread_of[0], caller) << threads << " threads";
    for (int a = 0; a < threads; ++a) {
      EXPECT_NE(thread_of[static_cast<std::size_t>(a)], std::thread::id()) << "worker " << a << " of " << threads << " never came";
      for (int b = 0; b < a; ++b) EXPECT_NE(thread_of[static_cast<std::size_t>(a)], thread_of[static_cast<std::size_t>(b)]);
    }
  }
}

TEST(parallel_test, a_team_goes_on_after_a_failed_job_and_a_failing_solve_is_rethrown) {
  for (const int threads : {1, 2, 3}) {
    int after = 0;
    EXPECT_THROW(aco::detail::Team::run(threads,
                                        [&](aco::detail::Team& team) {
                                          std::vector<double> busy;
                                          EXPECT_THROW(team.rounds(
                                                           6, busy, [](int k, int) {
                                                             if (k == 2) throw std::runtime_error("slot");
                                                           },
                                                           [] { return true; }),
                                                       std::runtime_error);
                                          team.rounds(
                                              6, busy, [](int, int) {}, [&] { return ++after < 50; });
                                          throw std::logic_error("solve");
                                        }),
                 std::logic_error);
    EXPECT_EQ(after, 50) << threads << " threads";
  }
}

}  // namespace
