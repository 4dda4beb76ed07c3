// h5::File, the HDF5 layer under XdmfWriter: scattered rows written in any order by any rank
// come back exactly by id, serially and in parallel (where rows travel to their block's rank),
// gaps keep the fill value 0, and bad calls fail on every rank with the file and dataset named.
#include <doctest/doctest.h>
#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>

#include "io/hdf5_file.hpp"

using namespace valsalva::io;
namespace fs = std::filesystem;

namespace {

int world_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int world_size() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path("test_output") / ("hdf5_np" + std::to_string(world_size()));
  if (world_rank() == 0) fs::create_directories(dir);
  MPI_Barrier(MPI_COMM_WORLD);
  return dir / name;
}

double value(std::int64_t row, int col) {
  return 1.0 / (3.0 + row) + 0.25 * col;
}

}  // namespace

TEST_CASE("serial h5::File: scattered rows, gaps at zero, rows read back in any order") {
  // Each rank writes a private file of its own.
  const fs::path path = scratch("serial_rank" + std::to_string(world_rank()) + ".h5");
  std::vector<std::int64_t> rows = {17, 3, 4, 5, 40, 9, 38};  // gaps, runs, any order
  std::vector<double> data;
  for (std::int64_t r : rows)
    for (int c = 0; c < 3; ++c) data.push_back(value(r, c));
  std::vector<std::int64_t> labels(rows.begin(), rows.end());
  {
    h5::File file(path, h5::Mode::create);
    file.write_rows<double>("xyz", 50, 3, rows, data);
    file.write_rows<std::int64_t>("label", 50, 0, rows, labels);
    file.write_attribute("time", 0.125);
    file.close();
  }
  const h5::File file(path, h5::Mode::read);
  CHECK(file.dims("xyz") == std::vector<std::int64_t>{50, 3});
  CHECK(file.dims("label") == std::vector<std::int64_t>{50});
  CHECK(file.read_attribute("time") == 0.125);
  const std::vector<double> all = file.read_all<double>("xyz");
  const std::vector<std::int64_t> all_labels = file.read_all<std::int64_t>("label");
  REQUIRE(all.size() == 150);
  for (std::int64_t r = 0; r < 50; ++r) {
    const bool written = std::find(rows.begin(), rows.end(), r) != rows.end();
    CHECK(all_labels[r] == (written ? r : 0));
    for (int c = 0; c < 3; ++c) CHECK(all[3 * r + c] == (written ? value(r, c) : 0.0));
  }
  const std::vector<std::int64_t> ask = {40, 0, 40, 4, 49};  // duplicates and unwritten rows
  const std::vector<double> some = file.read_rows<double>("xyz", ask);
  REQUIRE(some.size() == 15);
  for (std::size_t i = 0; i < ask.size(); ++i) CHECK(some[3 * i + 1] == all[3 * ask[i] + 1]);

  CHECK_THROWS_WITH(file.read_rows<double>("xyz", std::vector<std::int64_t>{50}),
                    doctest::Contains("outside [0, 50)"));
  CHECK_THROWS_WITH(file.read_attribute("dt"), doctest::Contains("'dt': no such attribute"));
  CHECK_THROWS_WITH(h5::File(path.string() + ".none", h5::Mode::read),
                    doctest::Contains("no such file"));
}

TEST_CASE("parallel h5::File: a global permutation of rows split over ranks round-trips") {
  const int rank = world_rank(), size = world_size();
  const fs::path path = scratch("parallel.h5");
  constexpr std::int64_t n = 1000;
  std::vector<std::int64_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(7));  // same on every rank
  // Rank 0 owns nothing when there are several ranks: it still takes part in the collectives.
  std::vector<std::int64_t> mine;
  for (std::int64_t i = 0; i < n; ++i)
    if (size == 1 || 1 + i % (size - 1) == rank) mine.push_back(perm[i]);
  std::vector<double> data;
  for (std::int64_t r : mine)
    for (int c = 0; c < 3; ++c) data.push_back(value(r, c));
  {
    h5::File file(MPI_COMM_WORLD, path, h5::Mode::create);
    file.write_rows<double>("xyz", n, 3, mine, data);
    file.close();
  }
  // Read back by another distribution: rank r asks for every size-th row, from the end.
  std::vector<std::int64_t> ask;
  for (std::int64_t row = n - 1 - rank; row >= 0; row -= size) ask.push_back(row);
  const h5::File file(MPI_COMM_WORLD, path, h5::Mode::read);
  const std::vector<double> got = file.read_rows<double>("xyz", ask);
  REQUIRE(got.size() == 3 * ask.size());
  int wrong = 0;
  for (std::size_t i = 0; i < ask.size(); ++i)
    for (int c = 0; c < 3; ++c) wrong += got[3 * i + c] != value(ask[i], c);
  CHECK(wrong == 0);
}

// Sorted rows that are exactly a rank's block are written in place (no copy); with gaps they
// go through the zero-filled block: both must give the same file.
TEST_CASE("parallel h5::File: sorted rows, whole blocks and with gaps, round-trip") {
  const int rank = world_rank(), size = world_size();
  const fs::path path = scratch("sorted.h5");
  constexpr std::int64_t n = 101;
  std::vector<std::int64_t> block, even;
  for (std::int64_t row = n * rank / size; row < n * (rank + 1) / size; ++row) {
    block.push_back(row);
    if (row % 2 == 0) even.push_back(row);
  }
  auto values = [](const std::vector<std::int64_t>& rows) {
    std::vector<double> v;
    for (std::int64_t r : rows) v.insert(v.end(), {value(r, 0), value(r, 1)});
    return v;
  };
  {
    h5::File file(MPI_COMM_WORLD, path, h5::Mode::create);
    file.write_rows<double>("whole", n, 2, block, values(block));
    file.write_rows<double>("gaps", n, 2, even, values(even));
    file.close();
  }
  std::vector<std::int64_t> all(n);
  std::iota(all.begin(), all.end(), 0);
  const h5::File file(MPI_COMM_WORLD, path, h5::Mode::read);
  const auto whole = file.read_rows<double>("whole", all),
             gaps = file.read_rows<double>("gaps", all);
  int wrong = 0;
  for (std::int64_t r = 0; r < n; ++r)
    for (int c = 0; c < 2; ++c) {
      wrong += whole[2 * r + c] != value(r, c);
      wrong += gaps[2 * r + c] != (r % 2 == 0 ? value(r, c) : 0.0);
    }
  CHECK(wrong == 0);
}

TEST_CASE("parallel h5::File: bad calls fail on every rank, naming file and dataset") {
  const int rank = world_rank(), size = world_size();
  h5::File file(MPI_COMM_WORLD, scratch("bad.h5"), h5::Mode::create);
  const std::vector<std::int64_t> row = {rank};
  const std::vector<double> one = {1.0};

  // Only rank 0 passes a row out of range: every rank must throw, none may hang.
  const std::vector<std::int64_t> far = {rank == 0 ? 99 : rank};
  CHECK_THROWS_WITH(
      file.write_rows<double>("a", size, 0, far, one),
      doctest::Contains(rank == 0 ? "dataset 'a': row id 99 outside" : "another rank"));
  const std::vector<std::int64_t> twice = {rank, rank};
  const std::vector<double> two = {1.0, 2.0};
  CHECK_THROWS_WITH(file.write_rows<double>("b", size, 0, twice, two),
                    doctest::Contains("given twice"));
  if (size > 1) {
    CHECK_THROWS_WITH(file.write_rows<double>("c", size + rank, 0, row, one),
                      doctest::Contains("ranks disagree on the shape"));
    // Every rank writes row 0; rank 0 holds that row's block and finds the clash.
    const std::vector<std::int64_t> zero = {0};
    CHECK_THROWS_WITH(
        file.write_rows<double>("d", size, 0, zero, one),
        doctest::Contains(rank == 0 ? "row id 0 given by two ranks" : "another rank"));
  }
  file.write_rows<double>("e", size, 0, row, one);
  CHECK_THROWS_WITH(file.write_rows<double>("e", size, 0, row, one),
                    doctest::Contains("HDF5 error in H5Dcreate2"));
  CHECK_THROWS_WITH(file.dims("nothing"), doctest::Contains("bad.h5', dataset 'nothing'"));
}
