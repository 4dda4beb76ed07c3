// Linearly implicit marker update; see implicit_markers.hpp.
#include "ibm/implicit_markers.hpp"

#include <fmt/format.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <span>
#include <stdexcept>
#include <vector>

namespace valsalva::ibm {
class ImplicitMarkerOperator;
}

// Eigen's matrix-free pattern (Eigen docs, "Matrix-free solvers"): the operator I + c A K acts
// on flat 3 x markers vectors.
namespace Eigen::internal {
template <>
struct traits<valsalva::ibm::ImplicitMarkerOperator> : public traits<Eigen::SparseMatrix<double>> {
};
}  // namespace Eigen::internal

namespace valsalva::ibm {

class ImplicitMarkerOperator : public Eigen::EigenBase<ImplicitMarkerOperator> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };

  ImplicitMarkerOperator(
      DiracTransfer& transfer,
      const std::function<void(const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&)>& apply_stiffness,
      double c, const Projector* project)
      : transfer_(transfer),
        apply_stiffness_(apply_stiffness),
        project_(project),
        c_(c),
        n_(transfer.num_markers()),
        v_(3, n_),
        kv_(3, n_),
        av_(3, n_),
        density_(static_cast<std::size_t>(transfer.mesh().num_local())) {}

  Eigen::Index rows() const { return 3 * n_; }
  Eigen::Index cols() const { return 3 * n_; }

  template <typename Rhs>
  Eigen::Product<ImplicitMarkerOperator, Rhs, Eigen::AliasFreeProduct> operator*(
      const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<ImplicitMarkerOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

  // y = x + c A K x (flat vectors of 3 n), A = Interp (P) Spread. Collective.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    v_ = Eigen::Map<const Eigen::Matrix3Xd>(x.data(), 3, n_);
    apply_stiffness_(v_, kv_);
    transfer_.spread(std::span<const Eigen::Vector3d>(
                         reinterpret_cast<const Eigen::Vector3d*>(kv_.data()), std::size_t(n_)),
                     density_);
    if (project_ && *project_) {
      potential_.resize(density_.size(), 0.0);
      (*project_)(density_, potential_);
    }
    transfer_.interpolate(std::span<Eigen::Vector3d>(density_),
                          std::span<Eigen::Vector3d>(reinterpret_cast<Eigen::Vector3d*>(av_.data()),
                                                     std::size_t(n_)));
    y = x + c_ * Eigen::Map<const Eigen::VectorXd>(av_.data(), 3 * n_);
  }

 private:
  DiracTransfer& transfer_;
  const std::function<void(const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&)>& apply_stiffness_;
  const Projector* project_;
  double c_;
  int n_;
  mutable Eigen::Matrix3Xd v_, kv_, av_;
  mutable std::vector<Eigen::Vector3d> density_;
  mutable std::vector<double> potential_;  // warm start of the projections
};

}  // namespace valsalva::ibm

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<valsalva::ibm::ImplicitMarkerOperator, Rhs, SparseShape, DenseShape,
                            GemvProduct>
    : generic_product_impl_base<valsalva::ibm::ImplicitMarkerOperator, Rhs,
                                generic_product_impl<valsalva::ibm::ImplicitMarkerOperator, Rhs>> {
  using Scalar = typename Product<valsalva::ibm::ImplicitMarkerOperator, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const valsalva::ibm::ImplicitMarkerOperator& lhs,
                            const Rhs& rhs, const Scalar& alpha) {
    Eigen::VectorXd y;
    lhs.apply(Eigen::VectorXd(rhs), y);
    dst.noalias() += alpha * y;
  }
};
}  // namespace Eigen::internal

namespace valsalva::ibm {

ImplicitSolve implicit_marker_displacement(
    DiracTransfer& transfer,
    const std::function<void(const Eigen::Matrix3Xd&, Eigen::Matrix3Xd&)>& apply_stiffness,
    const Eigen::Matrix3Xd& b, double c, double tolerance, int max_iterations,
    const Projector* project, const Eigen::Matrix3Xd* guess) {
  const int n = transfer.num_markers();
  if (b.cols() != n)
    throw std::invalid_argument(fmt::format(
        "ibm::implicit_marker_displacement: {} right-hand sides for {} markers", b.cols(), n));
  ImplicitSolve out;
  out.displacement = Eigen::Matrix3Xd::Zero(3, n);
  const Eigen::Map<const Eigen::VectorXd> rhs(b.data(), 3 * n);
  if (n == 0 || rhs.norm() == 0) return out;
  ImplicitMarkerOperator op(transfer, apply_stiffness, c, project);
  Eigen::BiCGSTAB<ImplicitMarkerOperator, Eigen::IdentityPreconditioner> solver;
  solver.setTolerance(tolerance);
  solver.setMaxIterations(max_iterations);
  solver.compute(op);
  // The initial guess b (the explicit displacement): exact where A K vanishes.
  const Eigen::VectorXd x =
      guess ? solver.solveWithGuess(rhs, Eigen::Map<const Eigen::VectorXd>(guess->data(), 3 * n))
            : solver.solveWithGuess(rhs, rhs);
  out.iterations = static_cast<int>(solver.iterations());
  out.residual = solver.error();
  if (solver.info() != Eigen::Success || !x.allFinite())
    throw std::runtime_error(fmt::format(
        "ibm: the implicit marker update did not converge ({} BiCGSTAB iterations, relative "
        "residual {:.3e} against {:.1e}); the solid's tangent may be indefinite (buckling) at a "
        "time step this large: lower time.cfl or time.dt",
        out.iterations, out.residual, tolerance));
  out.displacement = Eigen::Map<const Eigen::Matrix3Xd>(x.data(), 3, n);
  return out;
}

}  // namespace valsalva::ibm
