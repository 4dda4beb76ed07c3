// Turek–Hron CSM1/CSM2 (Turek & Hron 2006, doi:10.1007/3-540-34596-5_15): the elastic bar
// behind the cylinder, St Venant–Kirchhoff, loaded by gravity g = 2 m/s^2, steady. Plane strain:
// one layer of Q2 hexahedra with every node fixed in z. The clamped end follows the cylinder arc.
// Reference: tip displacement of point A = (0.6, 0.2), FeatFlow level 5+1 values
// (../shared/refdata/turek_hron_fsi). Metrics: |u_A - ref| <= 1% of |ref| on the finest mesh.
#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <stdexcept>

#include "structure/mesh_generators.hpp"
#include "structure/static_solver.hpp"
#include "validation/case.hpp"
#include "validation/turek_hron_fsi/turek_hron_data.hpp"

namespace valsalva::validation {

namespace {

using namespace valsalva::structure;

struct CsmParams {
  double rho = 0, nu = 0, E = 0, g = 0;
  double ux_ref = 0, uy_ref = 0;
};

CsmParams read_params(const std::filesystem::path& dir, const std::string& name) {
  const auto t = read_turek_hron_parameters(dir, name);
  return {t.rho_s,
          t.nu_s,
          t.E_s,
          t.g,
          read_turek_hron_reference(dir, name, "ux_A", "FF-page").mean,
          read_turek_hron_reference(dir, name, "uy_A", "FF-page").mean};
}

// The bar [cylinder arc, 0.6] x [0.19, 0.21], clamped on the arc x = 0.2 + sqrt(r^2 - (y-0.2)^2).
SolidMesh bar_mesh(int nx, int ny) {
  SolidMesh m = structured_block(HexOrder::q2, {nx, ny, 1}, [](const Vec3& s) {
    const double y = 0.19 + 0.02 * s[1];
    const double x0 = 0.2 + std::sqrt(0.05 * 0.05 - (y - 0.2) * (y - 0.2));
    return Vec3(x0 + s[0] * (0.6 - x0), y, 0.01 * s[2]);
  });
  m.source = fmt::format("<Turek-Hron bar {}x{}>", nx, ny);
  return m;
}

struct Result {
  double ux, uy;
  int iterations;
};

Result solve_csm(const CsmParams& p, int nx, int ny) {
  const SolidMesh m = bar_mesh(nx, ny);
  const auto mat = make_st_venant_kirchhoff(p.E, p.nu);
  SolidForces forces(m, *mat);
  StaticProblem prob;
  prob.forces = &forces;
  prob.dirichlet.push_back({m.node_set("u0"), {true, true, true}, {}});
  std::vector<int> all(m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i) all[i] = i;
  prob.dirichlet.push_back({all, {false, false, true}, {}});  // plane strain
  prob.body_force = Vec3(0, -p.rho * p.g, 0);
  NewtonOptions o;
  o.load_steps = 4;
  o.rtol = 1e-10;
  const NewtonResult r = solve_static(prob, o);
  if (!r.converged) throw std::runtime_error("turek_hron_csm: " + r.diagnosis);
  int A = -1;
  for (int n : m.node_set("u1"))
    if (std::abs(m.X(1, n) - 0.2) < 1e-12 && m.X(2, n) == 0) A = n;
  if (A < 0) throw std::logic_error("turek_hron_csm: no node at point A");
  return {r.x(0, A) - m.X(0, A), r.x(1, A) - m.X(1, A), r.iterations};
}

void run(const Context& ctx, Report& report) {
  const auto dir = ctx.refdata_dir / "turek_hron_fsi";
  std::vector<std::array<int, 2>> meshes = {{8, 1}, {16, 2}, {32, 4}};  // quick: 32x4 is the finest
  if (!ctx.quick) meshes.push_back({64, 8});
  auto out = fmt::output_file((ctx.out_dir / "convergence.csv").string());
  out.print("case,nx,ny,dofs,ux_A,uy_A,ux_ref,uy_ref,err_ux_rel,err_uy_rel,newton_iterations\n");
  for (const std::string name : {"CSM1", "CSM2"}) {
    const CsmParams p = read_params(dir, name);
    Result fine{};
    for (const auto& [nx, ny] : meshes) {
      fine = solve_csm(p, nx, ny);
      out.print("{},{},{},{},{:.8e},{:.8e},{:.8e},{:.8e},{:.3e},{:.3e},{}\n", name, nx, ny,
                3 * (2 * nx + 1) * (2 * ny + 1) * 3, fine.ux, fine.uy, p.ux_ref, p.uy_ref,
                std::abs(fine.ux / p.ux_ref - 1), std::abs(fine.uy / p.uy_ref - 1),
                fine.iterations);
    }
    const int nx = meshes.back()[0], ny = meshes.back()[1];
    report.add(fmt::format("{} ux_A [m], Q2 {}x{}", name, nx, ny), fine.ux, p.ux_ref,
               0.01 * std::abs(p.ux_ref));
    report.add(fmt::format("{} uy_A [m], Q2 {}x{}", name, nx, ny), fine.uy, p.uy_ref,
               0.01 * std::abs(p.uy_ref));
  }
}

}  // namespace

Case turek_hron_csm_case() {
  return {
      "turek_hron_csm",
      "Turek-Hron CSM1/CSM2 gravity-loaded St Venant-Kirchhoff bar: tip displacement vs FeatFlow",
      run};
}

}  // namespace valsalva::validation
