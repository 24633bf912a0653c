#pragma once
// OpenMP where the compiler has it; where it has none (the browser build of
// issue 65: Emscripten has no OpenMP) one core, the pragmas ignored and the
// team's master doing every slot itself.
#ifdef _OPENMP
#include <omp.h>
#else
#include <chrono>
inline int omp_get_num_procs() { return 1; }
inline int omp_get_thread_num() { return 0; }
inline double omp_get_wtime() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
#endif
