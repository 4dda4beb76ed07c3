// PIV readers: a CSV and a Tecplot file with two phases, masked and NaN points read back value by
// value; 23 malformed files each fail with FILE:LINE:COLUMN and the problem named.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "analysis/piv_data.hpp"

using namespace valsalva;

namespace {
const std::filesystem::path dir = std::filesystem::path(VALSALVA_SOURCE_DIR) / "tests/data/piv";
}

TEST_CASE("PIV CSV: phases, RMS, masked and NaN points") {
  const auto d = analysis::read_piv(dir / "good.csv");
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
  const auto d = analysis::read_piv(dir / "good.dat");
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
      {"missing_column.csv", "missing_column.csv:1:1: missing column 'v'"},
      {"non_numeric.csv", "non_numeric.csv:3:7: 'abc' (column 'u') is not a finite number"},
      {"wrong_count.csv", "wrong_count.csv:4:1: 3 values, expected 4 (the header's columns)"},
      {"unknown_column.csv", "unknown_column.csv:1:9: unknown column 'w'"},
      {"duplicate_column.csv",
       "duplicate_column.csv:1:7: column 'u' appears twice (columns 3 and 4)"},
      {"nan_position.csv", "nan_position.csv:2:1: 'nan' (column 'x') is not a finite number"},
      {"bad_valid.csv", "bad_valid.csv:2:9: valid = 3 must be 0 or 1"},
      {"tecplot_no_variables.dat", "tecplot_no_variables.dat:2:1: ZONE before the VARIABLES line"},
      {"tecplot_unknown_variable.dat",
       "tecplot_unknown_variable.dat:1:29: unknown variable 'speed'"},
      {"tecplot_short_zone.dat",
       "tecplot_short_zone.dat:2:1: zone 'phase 1' declares I*J = 6 points, found 5 (up to line "
       "8)"},
      {"tecplot_missing_j.dat", "tecplot_missing_j.dat:2:1: zone 'p0' without J"},
      {"tecplot_block.dat",
       "tecplot_block.dat:2:36: datapacking=BLOCK is not supported (only POINT)"},
      {"tecplot_bad_value.dat",
       "tecplot_bad_value.dat:4:5: '1.0e' (column 'u') is not a finite number"},
      {"tecplot_data_before_zone.dat",
       "tecplot_data_before_zone.dat:2:1: data before the first ZONE line"},
      {"tecplot_long_zone.dat",
       "tecplot_long_zone.dat:5:1: zone 'p0' (line 2) declares I*J = 2 points, this is one more"},
      {"tecplot_wrong_values.dat", "tecplot_wrong_values.dat:3:1: 3 values, expected 4"},
      // A zone with no points followed by a complete one (issue 23, item 10).
      {"tecplot_empty_zone.dat",
       "tecplot_empty_zone.dat:2:1: zone 'phase 1' has no data (the next ZONE is on line 3)"},
      // Through the shared strict reader (core/numeric_table.hpp): inf and overflow are not masked
      // vectors (they were, silently), names are unique case-insensitively, a zone's size is
      // checked at the end of the file too, and I*J stays a sane integer.
      {"inf_velocity.csv", "inf_velocity.csv:4:9: 'inf' (column 'u') is not a finite number"},
      {"tecplot_overflow_velocity.dat",
       "tecplot_overflow_velocity.dat:4:5: '1e999' (column 'u') is not a finite number"},
      {"duplicate_column_case.csv",
       "duplicate_column_case.csv:1:9: column 'U' appears twice (columns 3 and 5)"},
      {"tecplot_short_last_zone.dat",
       "tecplot_short_last_zone.dat:2:1: zone 'p0' declares I*J = 3 points, found 2"},
      {"tecplot_huge_zone.dat",
       "tecplot_huge_zone.dat:2:16: i = 20000000000 must be a positive integer (<= 1e9)"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.file);
    CHECK_THROWS_WITH(analysis::read_piv(dir / c.file), doctest::Contains(c.message));
    CHECK_THROWS_WITH(analysis::read_piv(dir / c.file), doctest::Contains(c.file));
  }
  CHECK_THROWS_WITH(analysis::read_piv(dir / "none.csv"), doctest::Contains("cannot open"));
  CHECK_THROWS_WITH(analysis::read_piv(dir / "good.xyz"), doctest::Contains("extension '.xyz'"));
}
