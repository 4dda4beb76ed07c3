// Decaying isotropic turbulence against Comte-Bellot & Corrsin 1971 (issue 4, verification 3):
// periodic box L = 11 M, hexahedra 32^3 and 64^3, 2nd-order centred scheme, initialised from the
// tU0/M = 42 spectrum, run to 98 and 171 with sigma, WALE, Smagorinsky and no model; E(k) and
// the resolved energy against the measured spectra filtered to the mesh's shells (see
// cbc_run.hpp). Target: resolved energy within 10% at both stations at 64^3 with sigma.
// Quick version: 32^3, sigma only. CSV: spectra.csv, energy.csv, decay.csv, runs.csv.
//
// Initial field: random phases rescaled to the 42 spectrum after every step of a spin-up
// (les/spectrum_rescale.hpp), so that the cascade exists at 42. Its length is the one free
// parameter of the initialisation: a quarter of the large-eddy turnover L11 / u' of the 42
// spectrum (les::large_scales: L11 2.38 cm, u' 22.8 cm/s, 20.6 tU0/M; so 5.1 tU0/M).
//
// Why a quarter: the random phases carry no triple correlations; one step of rescaled flow
// gives the resolved derivative skewness its developed value (-0.24..-0.26 after 2 tU0/M, no
// further growth; les/derivative_skewness.hpp, printed by bench_cbc_study), so the small-scale
// cascade is there after a few tU0/M. Continuing to rescale is a forcing: every step puts the
// energy the large shells lost back into them, and over a whole turnover it turns the large
// eddies into a forced-stationary state whose transfer outruns the measured decaying flow.
//
// Tolerances: 10 % for sigma at 64^3 (the target), 35 % for the other models and at 32^3,
// 100 % for the model-free run. Sigma as in Nicoud et al. 2011: (C Delta)^2 s3 (s1 - s2)(s2 - s3)
// / s1^2, C = 1.35, Delta = V^(1/3).
// Measured numbers, their run conditions and what they show: README.md in this folder.
#include <fmt/format.h>
#include <fmt/os.h>

#include <memory>

#include "validation/case.hpp"
#include "validation/cbc_decay/cbc_run.hpp"

namespace valsalva::validation {

namespace {

// 64^3 sigma: how the stations depend on the spin-up length (the initialisation's one free
// parameter), and the 98 -> 171 decay from the measured 98 spectrum itself (spinup.csv).
void spinup_study(const Context& ctx, Report& report, int rank) {
  std::unique_ptr<fmt::ostream> csv;
  if (rank == 0) {
    csv = std::make_unique<fmt::ostream>(fmt::output_file((ctx.out_dir / "spinup.csv").string()));
    csv->print("start,spinup_turnovers,spinup_u0_over_m,station,ratio\n");
  }
  struct Variant {
    int start;
    double turnovers;
  };
  for (const Variant v :
       {Variant{42, 0.0}, Variant{42, 0.5}, Variant{42, 1.0}, Variant{98, 0.25}}) {
    CbcSpec spec;
    spec.n = 64;
    spec.start_station = v.start;
    spec.stations = v.start == 98 ? std::vector<int>{171} : std::vector<int>{98, 171};
    spec.spinup_turnovers = v.turnovers;
    spec.table = ctx.refdata_dir / "cbc_decaying_turbulence" / "PHiLiP_cbc_experiment_table3.txt";
    const auto r = run_cbc(spec, ctx.comm);
    for (const auto& s : r.stations) {
      const double ratio = s.resolved / s.resolved_exp;
      if (rank == 0) {
        csv->print("{},{},{:.3f},{},{:.6f}\n", v.start, v.turnovers, r.spinup_u0_over_m,
                   s.t_u0_over_m, ratio);
        fmt::print(
            "cbc_decay 64^3 sigma from {} (spin-up {} turnovers = {:.2f} tU0/M): E_res({}) "
            "/ E_exp = {:.3f}\n",
            v.start, v.turnovers, r.spinup_u0_over_m, s.t_u0_over_m, ratio);
      }
      // From the measured 98 spectrum the decay to 171 is the solver's and model's alone.
      if (v.start == 98)
        report.add("64^3 sigma from the measured 98 spectrum: E_res(171) / E_exp(171)", ratio, 1.0,
                   0.10);
    }
  }
}

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
  if (!ctx.quick) spinup_study(ctx, report, rank);
}

}  // namespace

Case cbc_decay_case() {
  return {"cbc_decay",
          "Decaying isotropic turbulence vs Comte-Bellot & Corrsin 1971: E(k) and resolved energy "
          "at tU0/M 98, 171 for sigma, WALE, Smagorinsky, no model (32^3, 64^3)",
          run};
}

}  // namespace valsalva::validation
