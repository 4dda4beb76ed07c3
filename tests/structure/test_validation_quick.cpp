// Quick versions of the structure validation cases (label validation): each must pass all of its
// metrics (Turek–Hron CSM tip displacement within 1%, strip bending within 2% of beam theory and
// the elastica, leaflet closure converging and closing, contact patch pressure within 1 % of the
// applied traction, Hertz half-width within 8 % and peak pressure within 2 % on the coarsest mesh).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <filesystem>

#include "validation/case.hpp"

namespace {
void run_quick(const std::string& name) {
  using namespace valsalva::validation;
  const Case* c = find_case(name);
  REQUIRE(c != nullptr);
  Context ctx;
  ctx.quick = true;
  ctx.case_dir = std::filesystem::path(VALSALVA_SOURCE_DIR) / "validation" / name;
  ctx.refdata_dir = std::filesystem::path(VALSALVA_SOURCE_DIR) / "validation" / "refdata";
  ctx.out_dir = std::filesystem::temp_directory_path() / ("valsalva_quick_" + name);
  std::filesystem::create_directories(ctx.out_dir);
  Report report;
  c->run(ctx, report);
  for (const auto& m : report.metrics())
    MESSAGE(fmt::format("{}: {} = {:.6g} (reference {:.6g}, tolerance {:.3g}) {}", name, m.name,
                        m.value, m.reference, m.tolerance, m.pass() ? "pass" : "FAIL"));
  CHECK(report.all_pass());
}
}  // namespace

TEST_CASE("turek_hron_csm --quick") {
  run_quick("turek_hron_csm");
}
TEST_CASE("strip_bending --quick") {
  run_quick("strip_bending");
}
TEST_CASE("leaflet_closure --quick") {
  run_quick("leaflet_closure");
}
TEST_CASE("contact_patch --quick") {
  run_quick("contact_patch");
}
TEST_CASE("hertz_contact --quick") {
  run_quick("hertz_contact");
}
