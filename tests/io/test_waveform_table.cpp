// Inlet waveform tables through the strict table reader: header recognised, not guessed from a
// failed parse; errors name FILE:LINE:COLUMN.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/numeric_table.hpp"
#include "io/waveform_table.hpp"

using namespace valsalva;

TEST_CASE("waveform table: header, separators, errors naming file, line and column") {
  const auto dir = std::filesystem::temp_directory_path();
  const auto stem = "valsalva_waveform_" + std::to_string(getpid());  // NP 2 runs it twice at once
  const auto good = dir / (stem + "_good.csv");
  std::ofstream(good) << "# comment\nt,Q\n0.0, 1.0\n0.5; 3.0\n1.0 1.0\n";
  const auto w = io::read_waveform_table(good);
  CHECK(w.t.size() == 3);
  CHECK(w.period == 1.0);
  CHECK(w.mean == doctest::Approx(2.0));
  const auto bad = dir / (stem + "_bad.csv");
  std::ofstream(bad) << "t,Q\n0.0,1.0\n0.5\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad),
                       doctest::Contains("_bad.csv:3:1: 1 values, expected 2"), core::TableError);
  std::ofstream(bad) << "0.0,1.0\n0.5,2.0\n0.5,3.0\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad),
                       doctest::Contains("_bad.csv:3:1: time 0.5 is not after"), core::TableError);
  // A typo in the first data row is not taken for a header (that halved the period).
  std::ofstream(bad) << "0.0,1.0x\n0.5,2.0\n1.0,1.0\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad),
                       doctest::Contains("_bad.csv:1:5: '1.0x' is not a finite number"),
                       core::TableError);
  std::ofstream(bad) << "t,Q\n0.0,1.0\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad), doctest::Contains("found 1"),
                       core::TableError);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

TEST_CASE("waveform table: a table that is not one period must cover the run") {
  const auto ramp = flow::table_waveform({0.0, 0.1, 0.2}, {0.0, -5.0, -5.0});  // ramp, then hold
  CHECK_NOTHROW(io::check_table_wrap(ramp, 0.2, "ramp.csv"));                  // never wraps
  // Beyond t = 0.2 s the ramp would restart: -5 jumps back to 0.
  CHECK_THROWS_WITH_AS(io::check_table_wrap(ramp, 0.3, "ramp.csv"),
                       doctest::Contains("'ramp.csv' is not one period (its last value -5 at t = "
                                         "0.2 s differs from its first, 0 at t = 0 s)"),
                       core::TableError);
  // A table starting after t = 0 wraps before its first row too.
  const auto late = flow::table_waveform({0.05, 0.2}, {0.0, -5.0});
  CHECK_THROWS_AS(io::check_table_wrap(late, 0.1, "late.csv"), core::TableError);
  // One period (last value = first, to round-off) repeats without a jump, however long the run.
  const auto period = flow::table_waveform({0.0, 0.5, 1.0}, {1e-4, 3e-4, 1e-4 * (1 + 1e-12)});
  CHECK_NOTHROW(io::check_table_wrap(period, 24.0, "cycle.csv"));
}
