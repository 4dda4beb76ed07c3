// Internal nodal forces of a hexahedral solid, F_a = -int_V0 P(F) grad_X N_a dV (total
// Lagrangian; Bonet & Wood, Nonlinear Continuum Mechanics for FEA, 2nd ed. 2008, ch. 9), and the
// consistent stiffness K = -dF/dx, K_ab,ik = int grad N_a,J A_iJkL grad N_b,L dV.
//
// Explicit mode (what the immersed boundary calls each time step): positions in, forces out, no
// matrix, no allocation, cost linear in the number of elements. Per Gauss point we keep the
// reference Jacobian inverse dxi/dX and w det(dX/dxi) (10 doubles) instead of the 3 x nen
// reference gradients: grad_X N_a = (dxi/dX)^T dN_a/dxi with the reference-element derivatives
// shared by all elements. That is the same arithmetic but 8x less memory traffic for Q2 (about
// 3 MB instead of 27 MB for 1536 elements). For Q2 with a tensor Gauss rule (3x3x3, 3x3x2) the
// reference gradients and the force accumulation are sum-factorised and vectorised across packs
// of elements (solid_forces_sumfact.cpp); for the neo-Hookean law that kernel keeps, per Gauss
// point, Jinv Jinv^T, det Jinv and w det(dX/dxi) in pack layout (8 doubles: another 2.7 MB for
// 1536 elements with 3x3x3) and evaluates P inline. 1536 elements, one core: 1.5 ms per
// evaluation with 3x3x3, 1.15 ms with 3x3x2 (validation/bench/structure_forces.cpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

#include "structure/material.hpp"
#include "structure/solid_mesh.hpp"

namespace valsalva::structure {

class SolidForces {
 public:
  // `mesh` and `material` must outlive this object. gauss: points per reference direction.
  SolidForces(const SolidMesh& mesh, const Material& material, std::array<int, 3> gauss);
  SolidForces(const SolidMesh& mesh, const Material& material)
      : SolidForces(mesh, material, default_gauss(mesh.order)) {}
  // One material per element (an anisotropic law with each element's own fibre axes, e.g.
  // valve/leaflet_fibres.hpp); the materials must outlive this object. Uses the generic
  // per-Gauss-point material call (no inline neo-Hookean pack kernel).
  SolidForces(const SolidMesh& mesh, std::vector<const Material*> element_materials,
              std::array<int, 3> gauss);
  SolidForces(const SolidMesh& mesh, std::vector<const Material*> element_materials)
      : SolidForces(mesh, std::move(element_materials), default_gauss(mesh.order)) {}

  const SolidMesh& mesh() const { return mesh_; }
  // The material of element 0 (of every element unless one per element was given).
  const Material& material() const { return material_; }
  const Material& material(int element) const {
    return element_materials_.empty() ? material_ : *element_materials_[element];
  }
  int gauss_points_per_element() const { return ngp_; }

  // f (3 x nodes, resized by the caller) = internal forces at positions x. Returns the smallest
  // det F over all Gauss points (<= 0 means an inverted element; the forces are then not finite).
  double internal_forces(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                         Eigen::Ref<Eigen::Matrix3Xd> f) const;
  // The same with the direct per-Gauss-point loop (no sum factorisation), the reference the fast
  // Q2 kernel is tested against.
  double internal_forces_direct(const Eigen::Ref<const Eigen::Matrix3Xd>& x,
                                Eigen::Ref<Eigen::Matrix3Xd> f) const;
  // Whether internal_forces uses the sum-factorised, element-pack Q2 kernel (Q2 with a 3x3x3 or
  // 3x3x2 rule).
  bool sum_factorised() const { return sumfact_ != nullptr; }

  // Forces and stiffness K = -df/dx in dof numbering 3*node + component. The sparsity pattern
  // is built on the first call and reused; K keeps it.
  double assemble(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& f,
                  Eigen::SparseMatrix<double>& K) const;

  // Deformation gradient at reference point xi of element e (for stress output and tests).
  Mat3 deformation_gradient(const Eigen::Matrix3Xd& x, int e, const Vec3& xi) const;
  // Element with the smallest det F and that value, for diagnostics.
  std::pair<int, double> worst_element(const Eigen::Matrix3Xd& x) const;

  // Empty stiffness with the mesh's node-to-node sparsity pattern (3x3 blocks).
  Eigen::SparseMatrix<double> stiffness_pattern() const;

 private:
  template <int NEN>
  double forces_kernel(const double* x, double* f) const;
  template <int NX, int NY, int NZ>
  double sumfact_kernel(const double* x, double* f) const;
  void setup(std::array<int, 3> gauss);
  void setup_sumfact(const QuadratureRule& q, std::array<int, 3> gauss);

  struct SumFact;  // solid_forces_sumfact.cpp
  std::shared_ptr<const SumFact> sumfact_;
  std::array<int, 3> gauss_{};

  const SolidMesh& mesh_;
  const Material& material_;
  std::vector<const Material*> element_materials_;  // empty: material_ everywhere
  int nen_, ngp_;
  std::vector<double> weights_;  // reference rule weights (ngp)
  std::vector<double> dNxi_;     // [g][k][a]: dN_a/dxi_k, shared by all elements
  std::vector<double> jinv_;     // [e][g][9]: dxi/dX, row-major (k, J)
  std::vector<double> wdetj_;    // [e][g]: w_g det(dX/dxi)
};

}  // namespace valsalva::structure
