// Quick version of validation/cbc_decay: 32^3 hexahedra, sigma model, Comte-Bellot & Corrsin
// decaying turbulence from tU0/M = 42 (after the default spin-up of a quarter large-eddy
// turnover, 5.1 tU0/M) to 98. The initial field must carry the filtered measured energy exactly
// and nu_sgs must be active. Resolved energy at 98 over the filtered measurement: measured 1.243
// at np 1 with nu_sgs per step (1.220 after a full-turnover spin-up; at 32^3 the cut-off lies in
// the energy-containing range and the model under-dissipates; the 10% target is for 64^3, see
// validation/cbc_decay). The window (1.0, 1.35) fails for a model that does nothing (no model:
// 1.67) and for one that over-dissipates.
#include <doctest/doctest.h>
#include <mpi.h>

#include <cmath>

#include "validation/cbc_decay/cbc_run.hpp"

TEST_CASE("Comte-Bellot & Corrsin decay, 32^3 sigma, to tU0/M = 98") {
  valsalva::validation::CbcSpec spec;
  spec.n = 32;
  spec.model = "sigma";
  spec.stations = {98};
  spec.table = std::string(VALSALVA_SOURCE_DIR) +
               "/validation/refdata/cbc_decaying_turbulence/PHiLiP_cbc_experiment_table3.txt";
  const auto r = valsalva::validation::run_cbc(spec, MPI_COMM_WORLD);
  const auto& s = r.stations.at(0);
  MESSAGE("steps " << r.steps << ", E_res(42)/E_exp " << r.initial.resolved / r.initial.resolved_exp
                   << ", E_res(98)/E_exp " << s.resolved / s.resolved_exp << ", max nu_sgs/nu "
                   << s.max_nu_sgs_over_nu << ", wall " << r.wall_seconds << " s");
  CHECK(r.initial.resolved / r.initial.resolved_exp == doctest::Approx(1.0).epsilon(1e-10));
  CHECK(s.resolved / s.resolved_exp > 1.0);
  CHECK(s.resolved / s.resolved_exp < 1.35);
  CHECK(s.max_nu_sgs_over_nu > 1.0);
}
