// The quick version of the membrane_relaxation validation case (its scene with 16^3 fluid
// hexahedra, 6 x 6 Q2 elements per cube face of the shell, 0.5 s): every metric of its report
// within tolerance, the case's data files and the run's Lagrangian output written.
#include <doctest/doctest.h>
#include <mpi.h>

#include <filesystem>

#include "validation/case.hpp"

using namespace valsalva;

TEST_CASE("membrane_relaxation quick case passes its metrics") {
  const auto* c = validation::find_case("membrane_relaxation");
  REQUIRE(c != nullptr);
  validation::Context ctx;
  ctx.quick = true;
  ctx.out_dir = std::filesystem::path("validation-results") / "membrane_relaxation_quick";
  std::filesystem::create_directories(ctx.out_dir);
  validation::Report report;
  c->run(ctx, report);
  for (const auto& m : report.metrics()) {
    MESSAGE(m.name << ": " << m.value << " (reference " << m.reference << ", tolerance "
                   << m.tolerance << ")");
    CHECK(m.pass());
  }
  CHECK(std::filesystem::file_size(ctx.out_dir / "relaxation.csv") > 0);
  CHECK(std::filesystem::file_size(ctx.out_dir / "equator.csv") > 0);
  CHECK(std::filesystem::exists(ctx.out_dir / "run" / "structures" / "membrane.xmf"));
}
