// The convective term div(u u) of the momentum equation as an exchangeable component, chosen by
// name from the scene (flow.scheme):
//   central2  2nd-order centred
//   central4  4th-order edge-based centred scheme on translation-invariant meshes
//             (flow/convection_central4.hpp)
// The solver uses the skew-symmetric form carried by the projected face flux F
// (flow/face_flux.hpp), apply(u, flux, conv):
//   V_j conv_j = K(u)_j + B_j u_j / 2,   K = (C_F - C_F^*) / 2,   B_j = sum_faces u_j . A_j,
// with C_F(u)_j = sum_k F_jk u_jk the flux-form transport of u by F (u_jk the scheme's face
// value) and C_F^* its adjoint in the volume-weighted inner product. For any F,
// sum_j u_j . K(u)_j = 0 to round-off, so the convective term adds exactly the kinetic-energy
// flux through the boundary faces, sum_j B_j |u_j|^2 / 2, to dE/dt (zero on periodic boxes and
// at walls): the symmetry-preserving discretisation of Verstappen & Veldman, J. Comput. Phys.
// 187, 343-368 (2003), on unstructured collocated meshes as in Trias, Lehmkuhl, Oliva,
// Perez-Segarra & Verstappen, J. Comput. Phys. 258, 246-267 (2014). Where sum_k F_jk + B_j = 0
// (the projected flux), the skew form equals the flux form: it is consistent with div(u u).
// central2: V_j conv_j = (1/2) [sum_k F_jk u_k + B_j u_j].
// apply(u, conv) is the divergence form with the nodal-average flux S.(u_j + u_k)/2 (the form
// the truncation-error tests measure); it conserves kinetic energy only where that nodal
// flux is divergence-free, which the approximate projection does not give.
// A scheme owns its scratch arrays: apply() does not allocate once the fields have their size.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "flow/face_flux.hpp"
#include "flow/operators.hpp"
#include "mesh/local_mesh.hpp"

namespace valsalva::flow {

class ConvectionScheme {
 public:
  virtual ~ConvectionScheme() = default;
  // conv_j = div(u u) per unit volume at every local node (owned and ghost values valid on
  // return); u must have valid ghost values.
  virtual void apply(const VectorField& u, VectorField& conv) = 0;
  // The skew-symmetric form carried by `flux` (valid on every local edge), per unit volume, owned
  // and ghost values valid on return.
  virtual void apply(const VectorField& u, const EdgeField& flux, VectorField& conv) = 0;
  virtual std::string name() const = 0;
};

// The convective scheme of the scene key flow.scheme (ProjectionOptions::scheme).
enum class ConvectionKind { central2, central4 };

// The accepted names, in the order of the scene documentation: "central2", "central4".
const std::vector<std::string>& convection_scheme_names();
std::string to_string(ConvectionKind kind);
// std::invalid_argument naming the scheme and the accepted names for an unknown name.
ConvectionKind parse_convection_kind(std::string_view name);

// Throws the scheme's own error when the mesh cannot carry it (central4: fewer than 2 ghost
// layers).
std::unique_ptr<ConvectionScheme> make_convection_scheme(ConvectionKind kind,
                                                         const mesh::LocalMesh& mesh);

}  // namespace valsalva::flow
