// The list of validation cases: one declaration and one entry per validation/<case>/ folder.
#include <algorithm>

#include "validation/case.hpp"

namespace valsalva::validation {

Case mesh_metrics_case();
Case taylor_green_case();
Case turek_hron_csm_case();
Case strip_bending_case();
Case leaflet_closure_case();
Case valve_closure_case();
Case membrane_relaxation_case();
Case tgv_inviscid_case();
Case stability_case();
Case dfg_cylinder_case();
Case cbc_decay_case();
Case cavity_case();
Case womersley_statistics_case();
Case poiseuille_wss_case();
Case tgv_les_case();
Case womersley_case();
Case womersley_periodic_case();
Case ib_leakage_case();
Case turek_hron_fsi_case();
Case contact_patch_case();
Case hertz_contact_case();
Case time_order_case();

const std::vector<Case>& all_cases() {
  // clang-format off
  static const std::vector<Case> cases = {
      mesh_metrics_case(),
      taylor_green_case(),
      turek_hron_csm_case(),
      strip_bending_case(),
      leaflet_closure_case(),
      valve_closure_case(),
      membrane_relaxation_case(),
      tgv_inviscid_case(),
      stability_case(),
      dfg_cylinder_case(),
      cbc_decay_case(),
      cavity_case(),
      womersley_statistics_case(),
      poiseuille_wss_case(),
      tgv_les_case(),
      womersley_case(),
      womersley_periodic_case(),
      ib_leakage_case(),
      turek_hron_fsi_case(),
      contact_patch_case(),
      hertz_contact_case(),
      time_order_case(),
  };
  // clang-format on
  return cases;
}

const Case* find_case(const std::string& name) {
  const auto& cases = all_cases();
  auto it = std::find_if(cases.begin(), cases.end(), [&](const Case& c) { return c.name == name; });
  return it == cases.end() ? nullptr : &*it;
}

}  // namespace valsalva::validation
