// STREAM-like triad a = b + s c (McCalpin, "Memory Bandwidth and Machine Balance in Current
// High Performance Computers", IEEE TCCA Newsletter, 1995): the sustainable memory bandwidth of
// one core, against which the flow solver's edge loops are bounded (bench_tgv_re1600 prints it).
// Bytes are counted as STREAM does, 24 per element (two loads, one store; the write-allocate
// read of `a` is not counted), best of `repeats` passes over arrays far larger than any cache.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <limits>
#include <vector>

namespace valsalva::bench {

struct TriadResult {
  double bytes_per_second = 0;  // best pass
  double checksum = 0;          // keeps the compiler from dropping the passes
};

inline TriadResult stream_triad(std::size_t elements = std::size_t(1) << 23, int repeats = 10) {
  std::vector<double> a(elements, 0.0), b(elements, 1.0), c(elements, 2.0);
  const double s = 3.0;
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    double* __restrict pa = a.data();
    const double* __restrict pb = b.data();
    const double* __restrict pc = c.data();
    for (std::size_t i = 0; i < elements; ++i) pa[i] = pb[i] + s * pc[i];
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, t);
    b[r % elements] = a[(r * 7919) % elements];  // each pass depends on the one before
  }
  TriadResult result;
  result.bytes_per_second = 24.0 * double(elements) / best;
  for (std::size_t i = 0; i < elements; i += 4096) result.checksum += a[i];
  return result;
}

}  // namespace valsalva::bench
