// Benchmark (not a test): cost of one pointwise subgrid kernel call (les/sgs_kernels.hpp) on
// Gaussian velocity gradients (entries N(0, 100^2) 1/s), without the array loop or the flow
// solver around it. For instruction counts, run it under callgrind and subtract a 0-repeat run:
//   valgrind --tool=callgrind bench_sgs_kernel --model sigma --gradients 20000 --repeats 10
//   (minus the same with --repeats 0)
//   bench_sgs_kernel [--model sigma|wale|smagorinsky] [--gradients 100000] [--repeats 10]
#include <fmt/format.h>

#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "core/thread_cpu_time.hpp"
#include "les/sgs_kernels.hpp"
#include "les/sgs_model.hpp"
#include "validation/bench/bench_cli.hpp"

int main(int argc, char** argv) {
  using namespace valsalva::les;
  std::string model = "sigma";
  int n = 100000, repeats = 10;
  valsalva::bench::App app{"bench_sgs_kernel",
                           "Cost of one pointwise subgrid kernel call on Gaussian velocity "
                           "gradients (thread CPU time; or instructions under callgrind)"};
  app.add_option("--model", model, "Subgrid kernel")
      ->check(CLI::IsMember({"sigma", "wale", "smagorinsky"}));
  app.add_option("--gradients", n, "Velocity gradients per repeat")
      ->check(valsalva::bench::non_negative);
  app.add_option("--repeats", repeats, "Passes over the gradients (0: set-up only)")
      ->check(valsalva::bench::non_negative);
  if (const auto code = valsalva::bench::parse(app, argc, argv)) return *code;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> normal(0.0, 100.0);
  std::vector<Eigen::Matrix3d> grad(static_cast<std::size_t>(n));
  for (auto& g : grad)
    for (int i = 0; i < 9; ++i) g.data()[i] = normal(rng);
  const double delta = 1e-3;
  double sum = 0;                // printed, so that the calls cannot be optimised away
  auto run = [&](auto kernel) {  // one loop per model: no dispatch inside
    for (int r = 0; r < repeats; ++r)
      for (const auto& g : grad) sum += kernel(g);
  };
  const double t0 = valsalva::core::thread_cpu_seconds();
  if (model == "sigma")
    run([&](const Eigen::Matrix3d& g) { return sigma_nu(g, delta, default_c_sigma); });
  else if (model == "wale")
    run([&](const Eigen::Matrix3d& g) { return wale_nu(g, delta, default_c_wale); });
  else
    run([&](const Eigen::Matrix3d& g) { return smagorinsky_nu(g, delta, default_c_smagorinsky); });
  const double calls = static_cast<double>(n) * repeats;
  fmt::print("bench_sgs_kernel {}: {} calls, {:.1f} ns per call (thread CPU), checksum {:.17g}\n",
             model, calls,
             calls > 0 ? 1e9 * (valsalva::core::thread_cpu_seconds() - t0) / calls : 0.0, sum);
  return 0;
}
