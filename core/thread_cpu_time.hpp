// CPU time of the calling thread, in seconds: on a shared machine the wall clock also counts the
// time the process waits for a core, so costs are measured with this.
#pragma once

#include <ctime>

namespace valsalva::core {

inline double thread_cpu_seconds() {
  timespec c;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &c);
  return static_cast<double>(c.tv_sec) + 1e-9 * static_cast<double>(c.tv_nsec);
}

}  // namespace valsalva::core
