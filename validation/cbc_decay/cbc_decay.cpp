// Decaying isotropic turbulence against Comte-Bellot & Corrsin 1971 (issue 4, verification 3):
// periodic box L = 11 M, hexahedra 32^3 and 64^3, 2nd-order centred scheme, initialised from the
// tU0/M = 42 spectrum, run to 98 and 171 with sigma, WALE, Smagorinsky and no model; E(k) and
// the resolved energy against the measured spectra filtered to the mesh's shells (see
// cbc_run.hpp). Target: resolved energy within 10% at both stations at 64^3 with sigma.
// Quick version: 32^3, sigma only. CSV: spectra.csv, energy.csv, decay.csv, runs.csv.
// Initial field: random phases rescaled to the 42 spectrum after every step of a spin-up of
// 20 tU0/M (les/spectrum_rescale.hpp), so that the cascade exists at 42.
// Tolerances: 10% for sigma at 64^3 (the target). At 32^3 the cut-off (1.7 1/cm) lies in
// the energy-containing range and every model keeps too much resolved energy (measured ratios
// 1.13-1.25 at np 1); 35% separates them from the model-free run (1.67 at 98, 1.87 at 171), which
// is only loosely bounded.
// The 64^3 sigma miss at 171 (issue 4, measured with bench_cbc_study; ratios resolved /
// experiment at 98 and 171): default 1.014, 0.889. Time step 1/2, 1/4 (stability 0.35, 0.175):
// 1.016/0.882, 1.015/0.880 (converged in dt). Seeds 1-4: 171 at 0.876-0.895. central4: 1.043,
// 0.881. Spin-up 40: 1.011, 0.877; none: 1.130, 1.029 (no transfer at first, so more energy
// everywhere). No model: 1.350, 1.133. Box 22 M at the 32^3 spacing: 1.240/1.148 against
// 1.220/1.122 in 11 M (box size: 2 % at 171). Reference definition: the exact shell integral
// int_{k0/2}^{(n/2 - 1/2) k0} E dk instead of the midpoint sum changes E_exp(171) by +0.04 %, the
// integral to pi / h by +0.5 % (both make the miss larger). Sigma as in Nicoud et al. 2011:
// (C Delta)^2 s3 (s1 - s2)(s2 - s3) / s1^2 with C = 1.35 and Delta = V^(1/3), as implemented.
// Where: at 171 the shells 3-8 (0.34-0.90 1/cm, around the spectral peak) hold 0.65-0.90 of the
// measured E(k), the shells above 0.87-1.13. Every set-up loses 8-16 % against the measurement
// from 98 to 171, with and without a model: the energy-containing scales decay faster than
// measured, which the subgrid model does not set. Not fixed; reported.
#include <fmt/format.h>
#include <fmt/os.h>

#include <memory>

#include "validation/case.hpp"
#include "validation/cbc_decay/cbc_run.hpp"

namespace valsalva::validation {

namespace {

void run(const Context& ctx, Report& report) {
  int rank = 0;
  MPI_Comm_rank(ctx.comm, &rank);
  std::unique_ptr<fmt::ostream> spectra, energy, decay, runs;
  if (rank == 0) {
    auto open = [&](const char* name, const char* header) {
      auto f = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / name).string()));
      f->print("{}\n", header);
      return f;
    };
    spectra = open("spectra.csv", "n,model,station,k,E,E_exp");
    energy = open("energy.csv", "n,model,station,resolved,resolved_exp,ratio,max_nu_sgs_over_nu");
    decay = open("decay.csv", "n,model,t_u0_over_m,energy");
    runs = open("runs.csv", "n,model,nodes,steps,wall_seconds,step_seconds,sgs_seconds");
  }
  const std::vector<int> meshes = ctx.quick ? std::vector<int>{32} : std::vector<int>{32, 64};
  const std::vector<std::string> models =
      ctx.quick ? std::vector<std::string>{"sigma"}
                : std::vector<std::string>{"sigma", "wale", "smagorinsky", "none"};
  for (int n : meshes)
    for (const auto& model : models) {
      CbcSpec spec;
      spec.n = n;
      spec.model = model;
      spec.spinup = 20;  // about one large-eddy turnover (L11 / u' ~ 0.1 s at tU0/M = 42)
      spec.table = ctx.refdata_dir / "cbc_decaying_turbulence" / "PHiLiP_cbc_experiment_table3.txt";
      const auto r = run_cbc(spec, ctx.comm);
      if (rank == 0) {
        fmt::print("cbc_decay {}^3 {}: {} steps, {:.1f} s (steps {:.1f} s, subgrid {:.2f} s)\n", n,
                   model, r.steps, r.wall_seconds, r.step_seconds, r.sgs_seconds);
        runs->print("{},{},{},{},{:.3f},{:.3f},{:.3f}\n", n, model, r.nodes, r.steps,
                    r.wall_seconds, r.step_seconds, r.sgs_seconds);
        for (std::size_t i = 0; i < r.energy.size(); ++i)
          decay->print("{},{},{:.6f},{:.9e}\n", n, model, r.time_u0_over_m[i], r.energy[i]);
        auto stations = r.stations;
        stations.insert(stations.begin(), r.initial);
        for (const auto& s : stations) {
          energy->print("{},{},{},{:.9e},{:.9e},{:.6f},{:.4g}\n", n, model, s.t_u0_over_m,
                        s.resolved, s.resolved_exp, s.resolved / s.resolved_exp,
                        s.max_nu_sgs_over_nu);
          for (std::size_t i = 0; i < s.k.size(); ++i)
            spectra->print("{},{},{},{:.6e},{:.6e},{:.6e}\n", n, model, s.t_u0_over_m, s.k[i],
                           s.E[i], s.E_exp[i]);
          fmt::print(
              "  tU0/M {:>3}: resolved energy {:.4e} m2/s2, experiment {:.4e} (ratio {:.3f})\n",
              s.t_u0_over_m, s.resolved, s.resolved_exp, s.resolved / s.resolved_exp);
        }
      }
      // The initial field carries the filtered 42 spectrum exactly (fixed-amplitude modes).
      report.add(fmt::format("{}^3 {}: E_res(42) / E_exp(42)", n, model),
                 r.initial.resolved / r.initial.resolved_exp, 1.0, 1e-10);
      for (const auto& s : r.stations) {
        const double ratio = s.resolved / s.resolved_exp;
        const auto name =
            fmt::format("{}^3 {}: E_res({}) / E_exp({})", n, model, s.t_u0_over_m, s.t_u0_over_m);
        if (n == 64 && model == "sigma")
          report.add(name, ratio, 1.0, 0.10);  // the target
        else if (model != "none")
          report.add(name, ratio, 1.0, 0.35);  // see "Tolerances" above
        else
          report.add(name, ratio, 1.0, 1.0);  // no model: reported, loosely bounded
      }
    }
}

}  // namespace

Case cbc_decay_case() {
  return {"cbc_decay",
          "Decaying isotropic turbulence vs Comte-Bellot & Corrsin 1971: E(k) and resolved energy "
          "at tU0/M 98, 171 for sigma, WALE, Smagorinsky, no model (32^3, 64^3)",
          run};
}

}  // namespace valsalva::validation
