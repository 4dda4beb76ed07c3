// The list of validation cases, generated from their registrations in validation/CMakeLists.txt
// (validation/cases.cmake): a case is registered in one place.
#include <algorithm>

#include "validation/case.hpp"

namespace valsalva::validation {

#define VALSALVA_CASE_DECLARATIONS
#include "validation/registry_cases.inc"
#undef VALSALVA_CASE_DECLARATIONS

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases = {
#include "validation/registry_cases.inc"
  };
  return cases;
}

const Case* find_case(const std::string& name) {
  const auto& cases = all_cases();
  auto it = std::find_if(cases.begin(), cases.end(), [&](const Case& c) { return c.name == name; });
  return it == cases.end() ? nullptr : &*it;
}

}  // namespace valsalva::validation
