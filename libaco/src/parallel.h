#pragma once
// The one parallel scaffold of the solver (the colony's iterations, and the
// candidate lists' rows and ascent): a team of OpenMP workers that stays up
// for the whole solve (Team). Each round the workers take slots
// [0, count) one at a time (body(k, worker) writes only slot k and worker's
// own scratch); the worker that finishes the round's last slot then runs
// between(), the barrier-synced part, which says whether to go on.
//
// Why not `omp parallel for` per round: a focused round lasts a few hundred
// microseconds, and libgomp's barrier spins for up to a few milliseconds
// before it sleeps. On a busy workstation a spinning worker burns the time
// slice its partner needs, and two threads ran 3x slower than one (measured,
// pcb1173, two busy processes beside; see the commit). Here a waiter spins
// for a fraction of a round (Signal), then sleeps and gives the core away.
// Slots are handed out one at a time, and a round ends when its slots are
// done, not when every worker has looked in: a worker the kernel has put
// aside holds up at most the slot it is in.
//
// Exceptions may not leave an OpenMP region: the first one (by slot, for
// determinism) is kept and rethrown once the team has stopped.
#include "omp_compat.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace aco::detail {

// Something a thread waits for: spin a while, then sleep. A round's serial
// part is tens of microseconds, but a worker also waits for its partner's
// last ant, and on pcb1173 a quarter of those waits passed 100 us: each such
// sleeper cost tens of microseconds more to wake, on this VM's CPUs. With
// 300 us, 1 round in 20 sleeps, and two threads came to 0.909 of what the
// two CPUs allow (focused, 2000 iterations, median of 7 seeds, run beside
// the other build) against 0.901 with 100 us; with two busy processes
// beside, 1.23-1.37x one thread against 1.26-1.39x.
class Signal {
 public:
  // Tells the core this is a spin-wait: it lets the writer's cache line go sooner.
  static void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  template <class Ready>
  void wait_until(Ready&& ready) {
    const auto give_up = std::chrono::steady_clock::now() + kSpin;
    for (unsigned spins = 1; !ready(); ++spins) {
      cpu_relax();
      if (spins % 64 == 0 && std::chrono::steady_clock::now() > give_up) {
        sleepers_.fetch_add(1);
        {
          std::unique_lock<std::mutex> lock(mutex_);
          woken_.wait(lock, ready);
        }
        sleepers_.fetch_sub(1);
        return;
      }
    }
  }
  // Call after making `ready` true (with a sequentially consistent store): a
  // waiter either sees it before it sleeps, or is counted here and woken.
  void notify() {
    if (sleepers_.load() == 0) return;
    { std::lock_guard<std::mutex> lock(mutex_); }
    woken_.notify_all();
  }

 private:
  static constexpr std::chrono::microseconds kSpin{300};
  std::atomic<int> sleepers_{0};
  std::mutex mutex_;
  std::condition_variable woken_;
};

// A team of threads kept for a whole solve: the calling thread runs the
// solve and calls rounds(); the others wait for rounds to help with, and join
// those under way. A region per stage (the candidate rows, the ascent, the
// iterations) waited at its end for every worker, and on this VM the first
// one often took 10-13 ms to start a worker whose CPU had been idle:
// pcb1173's two-thread start took 45-52 ms in most runs against 33-35 on
// one. Here the master goes on alone, and a late worker helps from when it
// comes.
//
// The workers' OpenMP region is entered by a launcher thread, not by the
// master: libgomp's master spins at the region's start until every new
// thread has docked (GOMP_SPINCOUNT, 300 000 turns by default), and on this
// VM that spin kept the one new worker from running for 3-4 ms in most
// two-thread runs of pcb1173 (0.1 ms with GOMP_SPINCOUNT=0), all of it before
// the solve began. The launcher is the region's thread 0 and a worker
// itself; whatever it waits for there, nobody waits for it. (pcb1173, 200
// iterations on two threads, seeds 1-15 in pairs: 166.3 ms on average before,
// 162.8 after, faster in 14 pairs. The worker itself still comes up 0.15-3.3
// ms after the launch, as its CPU wakes; the master works meanwhile.)
class Team {
 public:
  // Runs main(team) on this thread, with threads - 1 workers beside it.
  template <class Main>
  static void run(int threads, Main&& main) {
    Team team(std::max(1, threads));
    if (team.threads_ == 1) {
      main(team);
      return;
    }
    // Without a launcher (no thread to be had) the master does every slot itself.
    std::thread launcher;
    try {
      launcher = std::thread([&team] {
#pragma omp parallel num_threads(team.threads_ - 1)
        team.serve(omp_get_thread_num() + 1);
      });
    } catch (const std::system_error&) {
    }
    std::exception_ptr error;
    try {
      main(team);
    } catch (...) {
      error = std::current_exception();
    }
    team.closed_.store(true);
    team.posted_.notify();
    if (launcher.joinable()) launcher.join();
    if (error) std::rethrow_exception(error);
  }

  int threads() const { return threads_; }

  // body(begin, end, worker) over [0, count) in chunks of `chunk`: one round.
  template <class Body>
  void chunks(std::size_t count, std::size_t chunk, Body&& body) {
    std::vector<double> busy;
    rounds(
        static_cast<int>((count + chunk - 1) / chunk), busy,
        [&](int c, int worker) {
          const std::size_t begin = static_cast<std::size_t>(c) * chunk;
          body(begin, std::min(count, begin + chunk), worker);
        },
        [] { return false; });
  }

  // Rounds of slots [0, count) until between() says stop (see the top). Only
  // from the thread that runs main.
  template <class Body, class Between>
  void rounds(int count, std::vector<double>& busy_s, Body&& body, Between&& between) {
    if (busy_s.size() < static_cast<std::size_t>(threads_)) busy_s.resize(static_cast<std::size_t>(threads_), 0.0);
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
    std::exception_ptr between_error;
    auto run_slot = [&](int k, int worker, double& busy) {
      const double t0 = omp_get_wtime();
      try {
        body(k, worker);
      } catch (...) {
        errors[static_cast<std::size_t>(k)] = std::current_exception();
      }
      busy += omp_get_wtime() - t0;
    };
    auto failed = [&] {
      for (auto& e : errors) {
        if (e) return true;
      }
      return false;
    };
    auto go_on = [&] {
      if (failed()) return false;
      try {
        return static_cast<bool>(between());
      } catch (...) {
        between_error = std::current_exception();
        return false;
      }
    };
    if (threads_ <= 1 || count <= 0) {
      double busy = 0.0;
      do {
        for (int k = 0; k < count; ++k) run_slot(k, 0, busy);
      } while (go_on());
      busy_s[0] += busy;
    } else {
      std::atomic<int> next_slot{0};  // the next slot of the round to hand out
      std::atomic<int> done{0};       // the round's slots finished
      std::atomic<unsigned> round{0};
      std::atomic<bool> stop{false};
      Signal next_round;
      auto work = [&](int me) {
        double busy = 0.0;
        while (!stop.load()) {
          const unsigned seen = round.load();
          for (int k = next_slot.fetch_add(1); k < count; k = next_slot.fetch_add(1)) {
            run_slot(k, me, busy);
            if (done.fetch_add(1) + 1 < count) continue;
            // Whoever finishes the round's last slot runs the serial part
            // itself, and then hands out the next round's slots. A worker that
            // has taken no slot of a round is not waited for: one the kernel
            // has put aside, or that sleeps, joins when it wakes.
            const bool more = go_on();
            done.store(0);
            stop.store(!more);
            if (more) next_slot.store(0);
            round.fetch_add(1);  // not seen + 1: this worker may have gone on into later rounds
            next_round.notify();
          }
          // Also on stop: the last round may have ended between reading stop and round.
          next_round.wait_until([&] { return round.load() != seen || stop.load(); });
        }
        busy_s[static_cast<std::size_t>(me)] += busy;
      };
      const Job job = work;
      job_.store(&job);
      posted_jobs_.fetch_add(1);
      posted_.notify();
      work(0);
      // No worker may be in `work` once this returns: one that counted itself
      // in before the job was taken down is waited for; one after it sees none.
      job_.store(nullptr);
      while (inside_.load() != 0) Signal::cpu_relax();
    }
    for (auto& e : errors) {
      if (e) std::rethrow_exception(e);
    }
    if (between_error) std::rethrow_exception(between_error);
  }

 private:
  using Job = std::function<void(int)>;  // a worker's part in rounds(), given its number
  explicit Team(int threads) : threads_(threads) {}
  void serve(int me) {
    unsigned seen = 0;
    for (;;) {
      posted_.wait_until([&] { return closed_.load() || posted_jobs_.load() != seen; });
      if (closed_.load()) return;
      seen = posted_jobs_.load();
      // Counted in before looking: see the end of rounds(). A job already
      // under way is joined; one that has stopped returns at once.
      inside_.fetch_add(1);
      const Job* job = job_.load();
      if (job != nullptr) (*job)(me);
      inside_.fetch_sub(1);
    }
  }
  int threads_;
  std::atomic<const Job*> job_{nullptr};
  std::atomic<unsigned> posted_jobs_{0};
  std::atomic<int> inside_{0};
  std::atomic<bool> closed_{false};
  Signal posted_;
};

}  // namespace aco::detail
