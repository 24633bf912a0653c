#pragma once
// The one parallel scaffold: run body(k) for k in [0, count) on `threads`
// OpenMP workers, each k writing only its own slot. Exceptions may not leave
// an OpenMP region, so the first one (by index, for determinism) is captured
// and rethrown after the barrier. Busy time is added up per worker.
#include <omp.h>

#include <exception>
#include <vector>

namespace aco::detail {

template <class Body>
void parallel_slots(int count, int threads, std::vector<double>& busy_s, Body&& body) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
  if (busy_s.size() < static_cast<std::size_t>(threads)) busy_s.resize(static_cast<std::size_t>(threads), 0.0);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int k = 0; k < count; ++k) {
    const double t0 = omp_get_wtime();
    try {
      body(k);
    } catch (...) {
      errors[static_cast<std::size_t>(k)] = std::current_exception();
    }
    busy_s[static_cast<std::size_t>(omp_get_thread_num())] += omp_get_wtime() - t0;
  }
  for (auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace aco::detail
