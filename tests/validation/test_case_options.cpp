// Case options (`valsalva validate CASE --set key=value`, validation/case.hpp): values are checked
// against the declared kind and range when the command line is read, and read back typed.
#include <doctest/doctest.h>

#include <stdexcept>

#include "validation/case.hpp"

using namespace valsalva::validation;

namespace {

Case example() {
  Case c;
  c.name = "example";
  c.options = {CaseOption::real("t_end", "end time", 0.01, 10),
               CaseOption::integer("level", "mesh level", 0, 2),
               CaseOption::choice("part", "which part", {"a", "b"})};
  return c;
}

Context with(const std::vector<std::string>& settings) {
  Context ctx;
  ctx.options = parse_case_options(example(), settings);
  return ctx;
}

}  // namespace

TEST_CASE("case options are read back typed, with their fallbacks when not set") {
  const auto ctx = with({"t_end=2.5", "level=2", "part=b"});
  CHECK(ctx.option_real("t_end", 1.0) == 2.5);
  CHECK(ctx.option_int("level", 0) == 2);
  CHECK(ctx.option("part", "a") == "b");
  const auto unset = with({});
  CHECK(unset.option_real("t_end", 1.5) == 1.5);
  CHECK(unset.option_int("level", -1) == -1);
  CHECK(unset.option("part") == "");
  CHECK(with({"t_end=1e-2"}).option_real("t_end", 0) == 0.01);  // the range is inclusive
}

TEST_CASE("case options outside their kind or range are refused, naming what is accepted") {
  const auto refused = [](const std::vector<std::string>& s, const std::string& message) {
    try {
      parse_case_options(example(), s);
      FAIL("accepted " << s.front());
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()) == message);
    }
  };
  refused({"t_end=20"},
          "validate: --set t_end=20 is not accepted (expected a number in [0.01, 10])");
  refused({"t_end=2s"},
          "validate: --set t_end=2s is not accepted (expected a number in [0.01, 10])");
  refused({"t_end=nan"},
          "validate: --set t_end=nan is not accepted (expected a number in [0.01, 10])");
  refused({"level=1.5"},
          "validate: --set level=1.5 is not accepted (expected an integer in [0, 2])");
  refused({"level=3"}, "validate: --set level=3 is not accepted (expected an integer in [0, 2])");
  refused({"part=c"}, "validate: --set part=c is not accepted (expected one of a, b)");
  refused({"size=1"},
          "validate: case 'example' has no option 'size' (its options: t_end, level, part)");
  refused({"level"}, "validate: --set 'level' is not of the form key=value");
  refused({"=1"}, "validate: --set '=1' is not of the form key=value");
  refused({"level=1", "level=2"}, "validate: option 'level' is set twice");
}

TEST_CASE("every registered case option declares a range or words, and a help text") {
  for (const auto& c : all_cases())
    for (const auto& o : c.options) {
      CHECK_MESSAGE(!o.help.empty(), c.name << ": " << o.key);
      if (o.kind == CaseOption::Kind::choice)
        CHECK_MESSAGE(!o.choices.empty(), c.name << ": " << o.key);
      else
        CHECK_MESSAGE(o.lo <= o.hi, c.name << ": " << o.key);
    }
}
