// Convection scheme factory; see convection_scheme.hpp.
#include "flow/convection_scheme.hpp"

#include <stdexcept>

#include "core/enum_names.hpp"
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

constexpr core::EnumNames<ConvectionKind, 2> kKinds{{"central2", "central4"},
                                                    "flow: convective scheme"};

VALSALVA_ENUM_NAMES(ConvectionKind, kKinds, convection_scheme_names, to_string,
                    parse_convection_kind)

std::unique_ptr<ConvectionScheme> make_convection_scheme(ConvectionKind kind,
                                                         const mesh::LocalMesh& mesh) {
  switch (kind) {
    case ConvectionKind::central2:
      return std::make_unique<ConvectionCentral2>(mesh);
    case ConvectionKind::central4:
      return std::make_unique<ConvectionCentral4>(mesh);
  }
  throw std::logic_error("flow::make_convection_scheme: unknown convective scheme");
}

}  // namespace valsalva::flow
