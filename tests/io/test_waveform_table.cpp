// Inlet waveform tables through the strict table reader: header recognised, not guessed from a
// failed parse; errors name FILE:LINE:COLUMN.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/numeric_table.hpp"
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
                       doctest::Contains("_bad.csv:3:1: 1 values, expected 2"), io::TableError);
  std::ofstream(bad) << "0.0,1.0\n0.5,2.0\n0.5,3.0\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad),
                       doctest::Contains("_bad.csv:3:1: time 0.5 is not after"), io::TableError);
  // A typo in the first data row is not taken for a header (that halved the period).
  std::ofstream(bad) << "0.0,1.0x\n0.5,2.0\n1.0,1.0\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad),
                       doctest::Contains("_bad.csv:1:5: '1.0x' is not a finite number"),
                       io::TableError);
  std::ofstream(bad) << "t,Q\n0.0,1.0\n";
  CHECK_THROWS_WITH_AS(io::read_waveform_table(bad), doctest::Contains("found 1"), io::TableError);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}
