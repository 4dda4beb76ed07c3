#include "structure/static_solver.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

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
    // Contact couples new node pairs as it spreads: the pattern then grows.
    if (K.nonZeros() != nnz_) analysed_ = false;
    nnz_ = K.nonZeros();
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
  Eigen::Index nnz_ = -1;
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
    if (!p.contact.empty() || !p.obstacles.empty())
      contact_ = std::make_unique<Contact>(mesh_, p.forces->material(), p.contact, p.obstacles,
                                           p.contact_options);
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
    if (contact_) {
      triplets_.clear();
      contact_->add_forces(x, f_, K ? &triplets_ : nullptr);
      if (K && !triplets_.empty()) {
        Eigen::SparseMatrix<double> Kc(K->rows(), K->cols());
        Kc.setFromTriplets(triplets_.begin(), triplets_.end());
        *K = *K + Kc;  // pattern union: SolidForces::assemble reuses a superset pattern
      }
    }
    r = Eigen::Map<const Vec>(f_.data(), f_.size());
    double react = 0;
    for (int i = 0; i < r.size(); ++i)
      if (fixed_[i]) {
        react += r[i] * r[i];
        r[i] = 0;
      }
    // Scale: external load, reactions, or the internal forces themselves (pure Dirichlet).
    scale_ = std::max({ext_norm, std::sqrt(react), 1e-3 * fint_norm, 1e-300});
    if (d_ > 0) {
      for (int i = 0; i < r.size(); ++i)
        if (!fixed_[i]) r[i] -= d_ * (x(i % 3, i / 3) - x0_(i % 3, i / 3));
      if (K)
        for (int i = 0; i < K->rows(); ++i) K->coeffRef(i, i) += d_;
    }
    return std::isfinite(r.squaredNorm()) ? r.norm() / scale_ : INFINITY;
  }

  void constrain(Eigen::SparseMatrix<double>& K) const {
    for (int c = 0; c < K.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it)
        if (fixed_[it.row()] || fixed_[it.col()]) it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
  }

  NewtonResult run(const Eigen::Matrix3Xd* initial) {
    NewtonResult res;
    const bool symmetric = p_.pressures.empty() && !contact_;
    LinearSolver solver(symmetric);
    res.solver = solver.name();
    Eigen::Matrix3Xd x = initial ? *initial : mesh_.X, x_prev = x;
    Eigen::SparseMatrix<double> K;
    if (o_.damping > 0) {
      Eigen::Matrix3Xd f;
      p_.forces->assemble(mesh_.X, f, K);
      d_ = o_.damping * K.diagonal().mean();
    }
    double lambda = 0, dl = 1.0 / std::max(1, o_.load_steps), dl_prev = 0;
    int cuts = 0;
    while (lambda < 1 - 1e-12) {
      const double target = std::min(1.0, lambda + dl);
      Eigen::Matrix3Xd xt = x;
      // Predictor: extrapolate the free dofs from the last increment, set the supports.
      if (dl_prev > 0) xt += (target - lambda) / dl_prev * (x - x_prev);
      for (int i = 0; i < 3 * mesh_.num_nodes(); ++i)
        if (fixed_[i])
          xt(i % 3, i / 3) = mesh_.X(i % 3, i / 3) + target * prescribed_(i % 3, i / 3);
      if (o_.admissible && !o_.admissible(xt)) xt = x;  // the extrapolation crossed: start at x
      std::string why;
      x0_ = x;
      const bool ok = increment(xt, target, solver, K, res, why);
      if (ok) {
        x_prev = x;
        x = xt;
        dl_prev = target - lambda;
        lambda = target;
        ++res.steps;
        cuts = 0;
        dl = std::min(1.0 / std::max(1, o_.load_steps), 2 * dl);
        if (o_.verbose)
          fmt::print("  load factor {:.4f} converged ({} steps)\n", lambda, res.steps);
        continue;
      }
      if (++cuts > o_.max_cuts) {
        res.diagnosis = fmt::format(
            "Newton solver did not converge: stuck at load factor {:.6g} after {} successive cuts "
            "of the "
            "increment (last tried {:.3g}); {}",
            lambda, o_.max_cuts, dl, why);
        break;
      }
      ++res.cuts;
      dl *= 0.5;
      dl_prev = 0;  // no extrapolation after a failure
      if (o_.verbose) fmt::print("  cut increment to {:.4g}: {}\n", dl, why);
    }
    res.converged = lambda >= 1 - 1e-12;
    if (res.converged && d_ > 0) res.converged = relax(x, solver, K, res);
    res.load_factor = lambda;
    res.x = x;
    if (contact_) {
      Eigen::Matrix3Xd unused = Eigen::Matrix3Xd::Zero(3, mesh_.num_nodes());
      res.contact = contact_->add_forces(x, unused);
    }
    return res;
  }

 private:
  // Damped relaxation at full load until the undamped residual converges.
  bool relax(Eigen::Matrix3Xd& x, LinearSolver& solver, Eigen::SparseMatrix<double>& K,
             NewtonResult& res) {
    const double d_start = d_;
    for (int k = 0; k < o_.max_relaxation_steps; ++k) {
      Vec r;
      double minJ = 0;
      const double d = d_;
      d_ = 0;
      const double rel = residual(x, 1.0, nullptr, r, minJ);
      d_ = d;
      if (o_.verbose)
        fmt::print("  relaxation {}: damping {:.3e}, undamped residual {:.3e}\n", k, d_, rel);
      if (rel <= o_.rtol || d_ < 1e-12 * d_start) {
        res.last_residuals.push_back(rel);
        if (rel <= 1e3 * o_.rtol) return true;
      }
      Eigen::Matrix3Xd xt = x;
      x0_ = x;
      std::string why;
      if (increment(xt, 1.0, solver, K, res, why)) {
        x = xt;
        d_ *= 0.25;
      } else {
        d_ *= 4;
        ++res.cuts;
      }
    }
    res.diagnosis =
        fmt::format("Newton solver: damped relaxation at full load did not converge in {} steps",
                    o_.max_relaxation_steps);
    return false;
  }

  bool increment(Eigen::Matrix3Xd& x, double lambda, LinearSolver& solver,
                 Eigen::SparseMatrix<double>& K, NewtonResult& res, std::string& why) {
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
        why = fmt::format(
            "singular tangent at iteration {} (supports do not remove the rigid-body motion, "
            "or the structure lost stability)",
            it);
        return false;
      }
      Vec du = solver.solve(r);
      // One step of iterative refinement: thin shells make K ill-conditioned (membrane vs
      // bending stiffness ~ (L/t)^2), and the refined step lowers the residual floor.
      du += solver.solve(r - K * du);
      const Eigen::Map<const Eigen::Matrix3Xd> dU(du.data(), 3, mesh_.num_nodes());
      // Line search on the energy-like product s(alpha) = du . r(x + alpha du) (Crisfield,
      // Non-linear FEA of Solids and Structures, vol. 1, sec. 9.3), used as a safeguard: the Newton
      // step is kept unless it inverts an element (halve) or overshoots badly, |s(1)| > 4 |s(0)|
      // (secant step). Tighter criteria, or backtracking on |r|, slowed thin-strip solves down:
      // their residual norm jumps through membrane forces while Newton is on its way.
      const double s0 = du.dot(r);
      double alpha = 1;
      Eigen::Matrix3Xd xt;
      for (int ls = 0; ls < (o_.line_search ? 8 : 1); ++ls) {
        xt = x + alpha * dU;
        double mj = 0;
        const double rel_trial = residual(xt, lambda, nullptr, r_trial, mj);
        if (!(mj > 0) || !std::isfinite(rel_trial) || (o_.admissible && !o_.admissible(xt))) {
          alpha *= 0.5;
          continue;
        }
        const double s1 = du.dot(r_trial);
        if (std::abs(s1) <= 4 * std::abs(s0) || s0 == s1) break;
        alpha = std::clamp(alpha * s0 / (s0 - s1), 0.1 * alpha, 4.0 * alpha);
      }
      // Round-off floor: the update is negligible against the displacement (1e-10) and the
      // residual is small; further iterations cannot improve on round-off.
      if (o_.admissible && !o_.admissible(xt)) {
        why = fmt::format("iteration {}: every step the line search tried was inadmissible", it);
        return false;
      }
      const double step = alpha * dU.cwiseAbs().maxCoeff();
      const double umax = std::max((xt - mesh_.X).cwiseAbs().maxCoeff(), 1e-9 * L);
      x = xt;
      rel = residual(x, lambda, &K, r, minJ);
      if (o_.verbose)
        fmt::print(
            "    iteration {}: step {:.3e} (alpha {:.3g}, |u| {:.3e}), relative residual {:.3e}\n",
            it, step, alpha, umax, rel);
      if (step <= 1e-10 * umax && minJ > 0 && rel < 1e-4) {
        res.last_residuals.push_back(rel);
        return true;
      }
    }
    const auto& h = res.last_residuals;
    why = fmt::format(
        "{} iterations without reaching {:.1e} (relative residual {:.3e} -> {:.3e}{})",
        o_.max_iterations, o_.rtol, h.front(), h.back(),
        h.size() > 3 && h.back() > 0.1 * h[h.size() - 3] ? ", stagnating: load too large for the "
                                                           "increment or a limit point"
                                                         : "");
    return false;
  }

  const StaticProblem& p_;
  const NewtonOptions& o_;
  const SolidMesh& mesh_;
  std::vector<bool> fixed_;
  Eigen::Matrix3Xd prescribed_, dead_, f_, g_, x0_;
  double d_ = 0;
  double scale_ = 1;
  std::unique_ptr<Contact> contact_;
  std::vector<Eigen::Triplet<double>> triplets_;
};

}  // namespace

NewtonResult solve_static(const StaticProblem& problem, const NewtonOptions& options,
                          const Eigen::Matrix3Xd* initial) {
  if (!problem.forces) throw std::invalid_argument("solve_static: problem has no SolidForces");
  Newton newton(problem, options);
  return newton.run(initial);
}

}  // namespace valsalva::structure
