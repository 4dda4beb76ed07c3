#include "structure/static_solver.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <fmt/format.h>

namespace valsalva::structure {

namespace {

using Vec = Eigen::VectorXd;

// Direct sparse solves through Eigen: solid problems here are at most ~1e5 dofs and thin
// (0.15 mm) shells make the stiffness badly conditioned, which defeats AMG/Krylov methods, while
// a fill-reducing direct factorisation of these quasi-2D meshes is cheap; it also keeps
// structure/ free of MPI and hypre. SimplicialLDLT (symmetric, indefinite allowed, half the work)
// when the tangent is symmetric; SparseLU when follower pressure makes it non-symmetric.
class LinearSolver {
 public:
  explicit LinearSolver(bool symmetric) : symmetric_(symmetric) {}
  const char* name() const { return symmetric_ ? "Eigen::SimplicialLDLT" : "Eigen::SparseLU"; }
  bool factor(const Eigen::SparseMatrix<double>& K) {
    if (symmetric_) {
      if (!analysed_) ldlt_.analyzePattern(K);
      ldlt_.factorize(K);
      analysed_ = true;
      return ldlt_.info() == Eigen::Success;
    }
    if (!analysed_) lu_.analyzePattern(K);
    lu_.factorize(K);
    analysed_ = true;
    return lu_.info() == Eigen::Success;
  }
  Vec solve(const Vec& b) { return symmetric_ ? Vec(ldlt_.solve(b)) : Vec(lu_.solve(b)); }

 private:
  bool symmetric_, analysed_ = false;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
};

class Newton {
 public:
  Newton(const StaticProblem& p, const NewtonOptions& o) : p_(p), o_(o), mesh_(p.forces->mesh()) {
    const int n = mesh_.num_nodes();
    fixed_.assign(3 * n, false);
    prescribed_ = Eigen::Matrix3Xd::Zero(3, n);
    for (const Dirichlet& d : p.dirichlet)
      for (int node : d.nodes)
        for (int k = 0; k < 3; ++k)
          if (d.components[k]) {
            fixed_[3 * node + k] = true;
            if (d.displacement) prescribed_(k, node) = d.displacement(mesh_.X.col(node))[k];
          }
    dead_ = Eigen::Matrix3Xd::Zero(3, n);
    if (p.body_force.squaredNorm() > 0) add_body_force(mesh_, p.body_force, dead_);
    for (const TractionLoad& t : p.tractions) add_dead_traction(mesh_, t.faces, t.traction, dead_);
    f_.resize(3, n);
  }

  // Residual r = f_int + lambda f_ext on free dofs (zero on fixed ones); returns |r| / scale.
  double residual(const Eigen::Matrix3Xd& x, double lambda, Eigen::SparseMatrix<double>* K, Vec& r,
                  double& minJ) {
    minJ = K ? p_.forces->assemble(x, f_, *K) : p_.forces->internal_forces(x, f_);
    const double fint_norm = f_.norm();
    g_ = lambda * dead_;
    for (const PressureLoad& pl : p_.pressures)
      add_follower_pressure(mesh_, pl.faces, lambda * pl.pressure, x, g_, K);
    const double ext_norm = g_.norm();
    f_ += g_;
    r = Eigen::Map<const Vec>(f_.data(), f_.size());
    double react = 0;
    for (int i = 0; i < r.size(); ++i)
      if (fixed_[i]) {
        react += r[i] * r[i];
        r[i] = 0;
      }
    // Scale: external load, reactions, or the internal forces themselves (pure Dirichlet).
    scale_ = std::max({ext_norm, std::sqrt(react), 1e-3 * fint_norm, 1e-300});
    return std::isfinite(r.squaredNorm()) ? r.norm() / scale_ : INFINITY;
  }

  void constrain(Eigen::SparseMatrix<double>& K) const {
    for (int c = 0; c < K.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it)
        if (fixed_[it.row()] || fixed_[it.col()]) it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
  }

  NewtonResult run(const Eigen::Matrix3Xd* initial) {
    NewtonResult res;
    const bool symmetric = p_.pressures.empty();
    LinearSolver solver(symmetric);
    res.solver = solver.name();
    Eigen::Matrix3Xd x = initial ? *initial : mesh_.X, x_prev = x;
    Eigen::SparseMatrix<double> K;
    double lambda = 0, dl = 1.0 / std::max(1, o_.load_steps), dl_prev = 0;
    int cuts = 0;
    while (lambda < 1 - 1e-12) {
      const double target = std::min(1.0, lambda + dl);
      Eigen::Matrix3Xd xt = x;
      // Predictor: extrapolate the free dofs from the last increment, set the supports.
      if (dl_prev > 0) xt += (target - lambda) / dl_prev * (x - x_prev);
      for (int i = 0; i < 3 * mesh_.num_nodes(); ++i)
        if (fixed_[i]) xt(i % 3, i / 3) = mesh_.X(i % 3, i / 3) + target * prescribed_(i % 3, i / 3);
      std::string why;
      const bool ok = increment(xt, target, solver, K, res, why);
      if (ok) {
        x_prev = x;
        x = xt;
        dl_prev = target - lambda;
        lambda = target;
        ++res.steps;
        cuts = 0;
        dl = std::min(1.0 / std::max(1, o_.load_steps), 2 * dl);
        if (o_.verbose) fmt::print("  load factor {:.4f} converged ({} steps)\n", lambda, res.steps);
        continue;
      }
      if (++cuts > o_.max_cuts) {
        res.diagnosis = fmt::format(
            "Newton solver did not converge: stuck at load factor {:.6g} after {} successive cuts of the "
            "increment (last tried {:.3g}); {}", lambda, o_.max_cuts, dl, why);
        break;
      }
      ++res.cuts;
      dl *= 0.5;
      dl_prev = 0;  // no extrapolation after a failure
      if (o_.verbose) fmt::print("  cut increment to {:.4g}: {}\n", dl, why);
    }
    res.converged = lambda >= 1 - 1e-12;
    res.load_factor = lambda;
    res.x = x;
    return res;
  }

 private:
  bool increment(Eigen::Matrix3Xd& x, double lambda, LinearSolver& solver, Eigen::SparseMatrix<double>& K,
                 NewtonResult& res, std::string& why) {
    Vec r, r_trial;
    double minJ = 0;
    res.last_residuals.clear();
    double rel = residual(x, lambda, &K, r, minJ);
    const double L = (mesh_.X.rowwise().maxCoeff() - mesh_.X.rowwise().minCoeff()).norm();
    for (int it = 0; it < o_.max_iterations; ++it) {
      res.last_residuals.push_back(rel);
      if (!(minJ > 0)) {
        const auto [e, d] = p_.forces->worst_element(x);
        why = fmt::format("element {} inverted (det F = {:.3e}) at iteration {}", e, d, it);
        return false;
      }
      if (!std::isfinite(rel)) {
        why = fmt::format("non-finite residual at iteration {}", it);
        return false;
      }
      if (rel <= o_.rtol) return true;
      ++res.iterations;
      constrain(K);
      if (!solver.factor(K)) {
        why = fmt::format("singular tangent at iteration {} (supports do not remove the rigid-body motion, "
                          "or the structure lost stability)", it);
        return false;
      }
      const Vec du = solver.solve(r);
      const Eigen::Map<const Eigen::Matrix3Xd> dU(du.data(), 3, mesh_.num_nodes());
      double alpha = 1, rel_trial = 0;
      Eigen::Matrix3Xd xt;
      for (int ls = 0; ls < (o_.line_search ? 10 : 1); ++ls, alpha *= 0.5) {
        xt = x + alpha * dU;
        double mj = 0;
        rel_trial = residual(xt, lambda, nullptr, r_trial, mj);
        if (mj > 0 && rel_trial < (1 - 1e-4 * alpha) * rel) break;
      }
      // Round-off floor: a converged update far below the mesh size.
      const double step = alpha * dU.cwiseAbs().maxCoeff();
      x = xt;
      rel = residual(x, lambda, &K, r, minJ);
      if (step <= 1e-13 * L && minJ > 0 && rel < 1e3 * o_.rtol) {
        res.last_residuals.push_back(rel);
        return true;
      }
    }
    const auto& h = res.last_residuals;
    why = fmt::format("{} iterations without reaching {:.1e} (relative residual {:.3e} -> {:.3e}{})",
                      o_.max_iterations, o_.rtol, h.front(), h.back(),
                      h.size() > 3 && h.back() > 0.1 * h[h.size() - 3] ? ", stagnating: load too large for the "
                                                                          "increment or a limit point" : "");
    return false;
  }

  const StaticProblem& p_;
  const NewtonOptions& o_;
  const SolidMesh& mesh_;
  std::vector<bool> fixed_;
  Eigen::Matrix3Xd prescribed_, dead_, f_, g_;
  double scale_ = 1;
};

}  // namespace

NewtonResult solve_static(const StaticProblem& problem, const NewtonOptions& options,
                          const Eigen::Matrix3Xd* initial) {
  if (!problem.forces) throw std::invalid_argument("solve_static: problem has no SolidForces");
  Newton newton(problem, options);
  return newton.run(initial);
}

}  // namespace valsalva::structure
