// Reader of the Turek & Hron (2006) benchmark tables in validation/refdata/turek_hron_fsi
// (turek_hron_parameters.csv, turek_hron_reference_values.csv; SOURCE.txt says where they come
// from). Shared by the CSM and FSI cases. Errors name the file, line and field.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace valsalva::validation {

// One row of turek_hron_parameters.csv (SI units); rho_s is NaN for the rigid CFD rows.
struct TurekHronParameters {
  double rho_s = 0, nu_s = 0, mu_s = 0, E_s = 0, rho_f = 0, nu_f = 0, U_bar = 0, g = 0;
};
TurekHronParameters read_turek_hron_parameters(const std::filesystem::path& dir,
                                               const std::string& case_name);

// One row of turek_hron_reference_values.csv: mean (steady value) and, for periodic
// quantities, amplitude and frequency (NaN when the row has none).
struct TurekHronReference {
  double mean = 0, amplitude = 0, frequency = 0;
};
// The row (case, quantity, set); throws when it is missing.
TurekHronReference read_turek_hron_reference(const std::filesystem::path& dir,
                                             const std::string& case_name,
                                             const std::string& quantity, const std::string& set);

}  // namespace valsalva::validation
