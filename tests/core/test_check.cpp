#include <doctest/doctest.h>

#include <string>

#include "core/check.hpp"

using valsalva::core::InternalError;

TEST_CASE("VALSALVA_CHECK passes a true condition and names a false one") {
  CHECK_NOTHROW(VALSALVA_CHECK(1 + 1 == 2));
  try {
    VALSALVA_CHECK(1 + 1 == 3, "arithmetic");
    FAIL("no throw");
  } catch (const InternalError& e) {
    const std::string what = e.what();
    CHECK(what.find("1 + 1 == 3") != std::string::npos);
    CHECK(what.find("test_check.cpp:") != std::string::npos);
    CHECK(what.find(": arithmetic") != std::string::npos);
  }
}

TEST_CASE("VALSALVA_DEBUG_CHECK evaluates its condition only without NDEBUG") {
  int evaluated = 0;
  VALSALVA_DEBUG_CHECK(++evaluated > 0);
#ifdef NDEBUG
  CHECK(evaluated == 0);
#else
  CHECK(evaluated == 1);
  CHECK_THROWS_AS(VALSALVA_DEBUG_CHECK(evaluated == 0), InternalError);
#endif
}
