// Names of the initial states; see initial_condition.hpp.
#include "flow/initial_condition.hpp"

#include "core/enum_names.hpp"

namespace valsalva::flow {

constexpr core::EnumNames<InitialType, 6> kTypes{
    {"rest", "taylor_green", "taylor_green_3d", "cyclic_sines", "womersley", "plane_poiseuille"},
    "flow: initial type"};

VALSALVA_ENUM_NAMES(InitialType, kTypes, initial_type_names, to_string, parse_initial_type)

}  // namespace valsalva::flow
