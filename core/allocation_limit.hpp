// Allocations sized from input (a mesh header's node count, statistics bins) checked before they
// are made: beyond the machine's physical memory they can only end in a bare std::bad_alloc or
// the kernel's OOM killer, neither of which names the input that asked for them.
#pragma once

#include <string>

namespace valsalva::core {

// Physical memory of this machine, bytes (sysconf).
double physical_memory_bytes();

// "12.3 GB", "456 MB", "789 bytes".
std::string byte_size(double bytes);

// "<what>: <count> x <bytes_each> bytes = <total>, more than this machine's <physical> of
// physical memory" when count * bytes_each exceeds physical memory, else "".
std::string allocation_problem(const std::string& what, double count, double bytes_each);
// Throws std::runtime_error with allocation_problem's text when there is one.
void check_allocation(const std::string& what, double count, double bytes_each);

}  // namespace valsalva::core
