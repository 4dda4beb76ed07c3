// Convection scheme factory; see convection_scheme.hpp.
#include "flow/convection_scheme.hpp"

#include <stdexcept>

#include "flow/convection_central4.hpp"

namespace valsalva::flow {

namespace {

class ConvectionCentral2 final : public ConvectionScheme {
 public:
  explicit ConvectionCentral2(const mesh::LocalMesh& mesh) : mesh_(mesh) {}
  void apply(const VectorField& u, VectorField& conv) override { convection(mesh_, u, u, conv); }
  void apply(const VectorField& u, const EdgeField& flux, VectorField& conv) override {
    skew_convection(mesh_, u, flux, conv);
  }
  std::string name() const override { return "central2"; }

 private:
  const mesh::LocalMesh& mesh_;
};

}  // namespace

const std::vector<std::string>& convection_scheme_names() {
  static const std::vector<std::string> names = {"central2", "central4"};
  return names;
}

std::unique_ptr<ConvectionScheme> make_convection_scheme(const std::string& name,
                                                         const mesh::LocalMesh& mesh) {
  if (name == "central2") return std::make_unique<ConvectionCentral2>(mesh);
  if (name == "central4") return std::make_unique<ConvectionCentral4>(mesh);
  std::string accepted;
  for (const auto& n : convection_scheme_names()) accepted += (accepted.empty() ? "" : ", ") + n;
  throw std::invalid_argument("flow: convective scheme '" + name + "' is not one of " + accepted);
}

}  // namespace valsalva::flow
