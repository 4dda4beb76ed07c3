// Small helpers shared by the benchmark executables: process CPU time and the machine line
// every benchmark prints with its figures (their command lines: bench_cli.hpp).
#pragma once

#include <sched.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <string>

namespace valsalva::bench {

// CPU seconds of this process (all its threads): robust on a machine shared with others.
inline double cpu_seconds() {
  timespec c;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c);
  return c.tv_sec + 1e-9 * c.tv_nsec;
}

// "<n> CPUs online (<m> in this process's affinity mask), <model name>": mpiexec binds ranks, so
// the mask alone would hide the machine's size.
inline std::string machine() {
  cpu_set_t set;
  const int bound = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : 0;
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  std::ifstream in("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  return std::to_string(online) + " CPUs online (" + std::to_string(bound) +
         " in this process's affinity mask), " + model;
}

}  // namespace valsalva::bench
