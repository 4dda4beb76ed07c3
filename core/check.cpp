#include "core/check.hpp"

#include <fmt/format.h>

namespace valsalva::core {

void check_failed(const char* expression, const char* file, int line, const std::string& message) {
  throw InternalError(
      fmt::format("internal error (a bug in valsalva, please report it): {}:{}: "
                  "check `{}` failed{}{}",
                  file, line, expression, message.empty() ? "" : ": ", message));
}

}  // namespace valsalva::core
