// The command-line options bench_cbc_study and bench_les_cost share (bench_cli.hpp): cells per
// side of the box, subgrid model, convective scheme and when nu_sgs is updated.
#pragma once

#include "flow/convection_scheme.hpp"
#include "validation/bench/bench_cli.hpp"
#include "validation/cbc_decay/cbc_run.hpp"

namespace valsalva::bench {

inline void add_cbc_options(CLI::App& app, validation::CbcSpec& spec) {
  app.add_option("--n", spec.n, "Cells per side of the periodic box")->check(positive);
  app.add_option("--model", spec.model, "Subgrid model")
      ->check(CLI::IsMember({"sigma", "wale", "smagorinsky", "none"}));
  app.add_option("--scheme", spec.scheme, "Convective scheme")
      ->check(CLI::IsMember(flow::convection_scheme_names()));
  app.add_option("--update", spec.update, "nu_sgs once per time step or at every RK stage")
      ->check(CLI::IsMember({"step", "stage"}));
}

}  // namespace valsalva::bench
