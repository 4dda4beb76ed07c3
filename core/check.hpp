// Internal invariants: what must hold whatever the input, so that a failure is a bug in valsalva,
// not a user error (user input gets its own messages naming file, key and value).
// VALSALVA_CHECK is always on; VALSALVA_DEBUG_CHECK only in builds without NDEBUG (hot loops,
// collective checks that cost a reduction). Both throw core::InternalError naming the expression,
// the file and line and an optional message, so that the front end reports it and MPI aborts
// cleanly instead of a rank dying on an assert.
#pragma once

#include <stdexcept>
#include <string>

namespace valsalva::core {

class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] void check_failed(const char* expression, const char* file, int line,
                               const std::string& message);

}  // namespace valsalva::core

#define VALSALVA_CHECK(condition, ...)                                                          \
  do {                                                                                          \
    if (!(condition))                                                                           \
      ::valsalva::core::check_failed(#condition, __FILE__, __LINE__, std::string{__VA_ARGS__}); \
  } while (false)

#ifdef NDEBUG
#define VALSALVA_DEBUG_CHECK(condition, ...) \
  do {                                       \
  } while (false)
#else
#define VALSALVA_DEBUG_CHECK(condition, ...) VALSALVA_CHECK(condition, __VA_ARGS__)
#endif
