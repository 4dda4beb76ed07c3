#include "core/allocation_limit.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <stdexcept>

namespace valsalva::core {

double physical_memory_bytes() {
  return static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

std::string byte_size(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.3g} GB", bytes / 1e9);
  if (bytes >= 1e6) return fmt::format("{:.3g} MB", bytes / 1e6);
  return fmt::format("{:.0f} bytes", bytes);
}

std::string allocation_problem(const std::string& what, double count, double bytes_each) {
  const double total = count * bytes_each, physical = physical_memory_bytes();
  if (!(total > physical)) return "";
  return fmt::format("{}: {:.4g} x {:g} bytes = {}, more than this machine's {} of physical memory",
                     what, count, bytes_each, byte_size(total), byte_size(physical));
}

void check_allocation(const std::string& what, double count, double bytes_each) {
  if (auto problem = allocation_problem(what, count, bytes_each); !problem.empty())
    throw std::runtime_error(problem);
}

}  // namespace valsalva::core
