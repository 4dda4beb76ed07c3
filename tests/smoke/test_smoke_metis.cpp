// METIS smoke test: METIS_PartGraphKway splits the 16 x 16 grid graph (256 vertices, 480 edges)
// into 4 parts. Bounds: each part within METIS's default k-way imbalance 1.03 of 64 (<= 66
// vertices); the edge cut is at least 32 (four 8 x 8 quadrants: a part of 64 grid vertices has an
// edge boundary of at least 16 unless it touches the border, and the optimum is the quadrants)
// and at most 48, the cut of four 4 x 16 strips, which any decent partitioner must match.
// The cut METIS reports is recomputed from the partition.
#include <doctest/doctest.h>
#include <metis.h>

#include <algorithm>
#include <vector>

TEST_CASE("METIS: k-way partition of a grid graph is balanced with a small edge cut") {
  constexpr idx_t side = 16, n = side * side;
  std::vector<idx_t> xadj{0}, adjncy;
  for (idx_t j = 0; j < side; ++j)
    for (idx_t i = 0; i < side; ++i) {
      if (i > 0) adjncy.push_back(j * side + i - 1);
      if (i < side - 1) adjncy.push_back(j * side + i + 1);
      if (j > 0) adjncy.push_back((j - 1) * side + i);
      if (j < side - 1) adjncy.push_back((j + 1) * side + i);
      xadj.push_back(static_cast<idx_t>(adjncy.size()));
    }
  REQUIRE(adjncy.size() == 2 * 480);
  idx_t vertices = n, constraints = 1, parts = 4, cut = -1;
  std::vector<idx_t> part(n, -1);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  const int status =
      METIS_PartGraphKway(&vertices, &constraints, xadj.data(), adjncy.data(), nullptr, nullptr,
                          nullptr, &parts, nullptr, nullptr, options, &cut, part.data());
  REQUIRE(status == METIS_OK);

  std::vector<int> count(parts, 0);
  for (idx_t p : part) {
    REQUIRE(p >= 0);
    REQUIRE(p < parts);
    ++count[p];
  }
  idx_t recount = 0;
  for (idx_t v = 0; v < n; ++v)
    for (idx_t e = xadj[v]; e < xadj[v + 1]; ++e) recount += part[v] != part[adjncy[e]];
  MESSAGE("METIS: cut ", cut, ", parts ", count[0], " ", count[1], " ", count[2], " ", count[3]);
  CHECK(recount / 2 == cut);
  CHECK(cut >= 32);
  CHECK(cut <= 48);
  CHECK(*std::max_element(count.begin(), count.end()) <= 66);
  CHECK(*std::min_element(count.begin(), count.end()) > 0);
}
