// The communicator wrapper's collectives (core/comm.hpp): every rank contributes a piece whose
// length and values depend on its rank, so a wrong count, offset, root or operation shows.
#include <doctest/doctest.h>

#include <numeric>
#include <string>
#include <vector>

#include "core/comm.hpp"

using valsalva::core::Comm;

namespace {
// Rank r holds r + 1 values r * 10 + k, k = 0..r.
std::vector<double> piece(int rank) {
  std::vector<double> v(static_cast<std::size_t>(rank + 1));
  for (int k = 0; k <= rank; ++k) v[k] = rank * 10.0 + k;
  return v;
}
}  // namespace

TEST_CASE("element-wise reductions give the same exact result on every rank") {
  const Comm comm;
  const int r = comm.rank(), n = comm.size();
  std::vector<double> sum{1.0 * r, 2.0}, hi{1.0 * r, -1.0 * r}, lo = hi;
  comm.sum_in_place(sum);
  comm.max_in_place(hi);
  comm.min_in_place(lo);
  CHECK(sum[0] == n * (n - 1) / 2.0);
  CHECK(sum[1] == 2.0 * n);
  CHECK(hi[0] == n - 1.0);
  CHECK(hi[1] == 0.0);
  CHECK(lo[0] == 0.0);
  CHECK(lo[1] == -(n - 1.0));
  CHECK(comm.any(r == n - 1));
  CHECK_FALSE(comm.any(false));
}

TEST_CASE("gather_to_root concatenates pieces of different lengths in rank order on rank 0") {
  const Comm comm;
  const auto all = comm.gather_to_root(piece(comm.rank()));
  if (!comm.root()) {
    CHECK(all.empty());
    return;
  }
  std::vector<double> expected;
  for (int r = 0; r < comm.size(); ++r) {
    const auto p = piece(r);
    expected.insert(expected.end(), p.begin(), p.end());
  }
  CHECK(all == expected);
}

TEST_CASE("all_gather gives every rank the concatenation in rank order") {
  const Comm comm;
  std::vector<std::int64_t> mine(static_cast<std::size_t>(comm.rank()), comm.rank());
  const auto all = comm.all_gather(mine);
  std::vector<std::int64_t> expected;
  for (int r = 0; r < comm.size(); ++r) expected.insert(expected.end(), r, r);
  CHECK(all == expected);
}

TEST_CASE("broadcast copies the root's values, strings and vectors to every rank") {
  const Comm comm;
  const int root = comm.size() - 1;  // not rank 0, so a root ignored shows
  const bool is_root = comm.rank() == root;
  double x = is_root ? 2.5 : -1.0;
  int i = is_root ? 7 : 0;
  std::string text = is_root ? "from the last rank" : "x";
  std::vector<double> v = is_root ? std::vector<double>{1, 2, 3, 4} : std::vector<double>{9};
  std::vector<int> fixed(3, is_root ? 5 : 0);
  comm.broadcast(x, root);
  comm.broadcast(i, root);
  comm.broadcast(text, root);
  comm.broadcast(v, root);
  comm.broadcast(std::span<int>(fixed), root);
  CHECK(x == 2.5);
  CHECK(i == 7);
  CHECK(text == "from the last rank");
  CHECK(v == std::vector<double>{1, 2, 3, 4});
  CHECK(fixed == std::vector<int>(3, 5));
  std::string empty = is_root ? "" : "stale";
  comm.broadcast(empty, root);
  CHECK(empty.empty());
}
