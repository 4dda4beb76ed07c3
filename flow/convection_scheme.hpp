// The convective term div(u u) of the momentum equation as an exchangeable component, chosen by
// name from the scene (flow.scheme):
//   central2  2nd-order centred, kinetic-energy conserving (flow::convection)
//   central4  4th-order edge-based centred scheme on translation-invariant meshes
//             (flow/convection_central4.hpp)
// A scheme owns its scratch arrays: apply() does not allocate once the fields have their size.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "flow/local_mesh.hpp"
#include "flow/operators.hpp"

namespace valsalva::flow {

class ConvectionScheme {
 public:
  virtual ~ConvectionScheme() = default;
  // conv_j = div(u u) per unit volume at every local node (owned and ghost values valid on
  // return); u must have valid ghost values.
  virtual void apply(const VectorField& u, VectorField& conv) = 0;
  virtual std::string name() const = 0;
};

// The accepted names, in the order of the scene documentation.
const std::vector<std::string>& convection_scheme_names();

// Throws std::invalid_argument naming the scheme and the accepted names for an unknown one, and
// the scheme's own error when the mesh cannot carry it (central4: fewer than 2 ghost layers).
std::unique_ptr<ConvectionScheme> make_convection_scheme(const std::string& name,
                                                         const LocalMesh& mesh);

}  // namespace valsalva::flow
