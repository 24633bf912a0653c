#pragma once
/**
 * The one entry to the colony: pure, no I/O, no globals. The same problem,
 * params and seed give the same order whatever the thread count, unless a
 * time limit stops the run.
 *
 * **Example**:
 *   aco::Params params;  params.seed = 7;
 *   aco::Solution s = aco::solve(problem, params);
 */
#include <memory>

#include "aco/params.h"
#include "aco/problem.h"
#include "aco/solution.h"

namespace aco {

Solution solve(const Problem& problem, const Params& params);

/**
 * The same solve in slices, for a front end that must have control back
 * between iterations (a browser's worker sees no message while C++ runs):
 *
 *   aco::ColonyRun run(problem, params);
 *   while (!run.advance(50)) show(run.best_length());  // 50 iterations a slice
 *   aco::Solution s = run.finish();
 *
 * Ended by its iteration count (or a stall), any slicing gives what solve()
 * gives with the same problem, params and seed. The first advance() also
 * builds the candidate lists, which on 10^5 holes takes seconds. A time
 * limit counts from construction, slices and the pauses between them alike.
 */
class ColonyRun {
 public:
  ColonyRun(const Problem& problem, const Params& params);  // checks both; throws InputError
  ~ColonyRun();
  ColonyRun(ColonyRun&&) noexcept;
  ColonyRun& operator=(ColonyRun&&) noexcept;

  // Runs until the run ends (true) or `max_iterations` more iterations (0:
  // no bound) or `max_seconds` more (0: none) have passed (false).
  bool advance(int max_iterations = 0, double max_seconds = 0.0);
  bool ended() const;
  // Whether advance() has set the colony up (its candidate lists and first route).
  bool begun() const;
  int iterations() const;  // run so far
  // The best route so far (empty until begun()), to draw while it runs.
  Order best_order() const;
  // The best route so far; the run ends here if it had not (stop_reason
  // "stopped"). Call once.
  Solution finish();
  // With defaults resolved.
  const Params& params() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Params with every default filled in for a problem of n points.
Params resolve(const Params& params, std::size_t n);

}  // namespace aco
