// PIV readers: a CSV and a Tecplot file with two phases, masked and NaN points read back value by
// value; 17 malformed files each fail with the file, the line and the problem named.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "io/piv_data.hpp"

using namespace valsalva;

namespace {
const std::filesystem::path dir = std::filesystem::path(VALSALVA_SOURCE_DIR) / "tests/data/piv";
}

TEST_CASE("PIV CSV: phases, RMS, masked and NaN points") {
  const auto d = io::read_piv(dir / "good.csv");
  CHECK(d.frame_key == "phase");
  CHECK(d.has_rms);
  REQUIRE(d.frames.size() == 2);
  CHECK(d.frames[0].phase == 0.25);
  CHECK(d.frames[0].label == "phase=0.25");
  CHECK(d.frames[0].size() == 3);
  CHECK(d.frames[0].valid_count() == 2);  // valid = 0
  CHECK(d.frames[0].u[1] == 1.1);
  CHECK(d.frames[0].v_rms[2] == 0.05);
  CHECK(d.frames[1].phase == 0.75);
  CHECK(d.frames[1].valid_count() == 1);  // NaN and empty u
  CHECK(std::isnan(d.frames[1].u[2]));
  CHECK(d.frames[1].x[1] == 0.001);
}

TEST_CASE("PIV Tecplot: zones, SOLUTIONTIME, continuation line, masks") {
  const auto d = io::read_piv(dir / "good.dat");
  CHECK_FALSE(d.has_rms);
  REQUIRE(d.frames.size() == 2);
  const auto& f = d.frames[0];
  CHECK(f.label == "phase 0.1");
  CHECK(f.phase == 0.1);
  CHECK(f.ni == 3);
  CHECK(f.nj == 2);
  CHECK(f.size() == 6);
  CHECK(f.valid_count() == 4);  // one valid = 0, one NaN
  CHECK(f.u[1] == 1.5);
  CHECK(f.v[5] == 2.5);
  CHECK(d.frames[1].phase == 0.6);
  CHECK(d.frames[1].valid_count() == 6);
  CHECK(d.frames[1].u[4] == -2);
}

TEST_CASE("PIV readers: malformed files name file, line and problem") {
  struct Bad {
    const char* file;
    const char* message;
  };
  const Bad cases[] = {
      {"empty.csv", "empty.csv': empty (no header line)"},
      {"missing_column.csv", "line 1: missing column 'v'"},
      {"non_numeric.csv", "line 3: column 'u': 'abc' is not a number"},
      {"wrong_count.csv", "line 4: 3 values, the header has 4"},
      {"unknown_column.csv", "line 1: unknown column 'w'"},
      {"duplicate_column.csv", "line 1: 'u' appears twice"},
      {"nan_position.csv", "line 2: x and y must be finite numbers"},
      {"bad_valid.csv", "line 2: valid = 3 must be 0 or 1"},
      {"tecplot_no_variables.dat", "line 2: ZONE before the VARIABLES line"},
      {"tecplot_unknown_variable.dat", "line 1: unknown variable 'speed'"},
      {"tecplot_short_zone.dat",
       "line 8: zone 'phase 1' (line 2) declares I*J = 6 points, found 5"},
      {"tecplot_missing_j.dat", "line 2: zone 'p0' without J"},
      {"tecplot_block.dat", "line 2: datapacking=BLOCK is not supported (only POINT)"},
      {"tecplot_bad_value.dat", "line 4: column 'u': '1.0e' is not a number"},
      {"tecplot_data_before_zone.dat", "line 2: data before the first ZONE line"},
      {"tecplot_long_zone.dat",
       "line 5: zone 'p0' (line 2) declares I*J = 2 points, this is one more"},
      {"tecplot_wrong_values.dat", "line 3: 3 values, VARIABLES names 4"},
      // A zone with no points followed by a complete one (issue 23, item 10).
      {"tecplot_empty_zone.dat", "line 2: zone 'phase 1' has no data (the next ZONE is on line 3)"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.file);
    CHECK_THROWS_WITH(io::read_piv(dir / c.file), doctest::Contains(c.message));
    CHECK_THROWS_WITH(io::read_piv(dir / c.file), doctest::Contains(c.file));
  }
  CHECK_THROWS_WITH(io::read_piv(dir / "none.csv"), doctest::Contains("cannot open"));
  CHECK_THROWS_WITH(io::read_piv(dir / "good.xyz"), doctest::Contains("extension '.xyz'"));
}
