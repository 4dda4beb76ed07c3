// Comte-Bellot & Corrsin (1971) grid-turbulence energy spectra, J. Fluid Mech. 48, 273-337,
// Table 3: E(k) at tU0/M = 42, 98, 171 (M = 5.08 cm, U0 = 10 m/s).
//
// Reads the transcription that refdata/cbc_decaying_turbulence/SOURCE.txt names as the best
// (PHiLiP_cbc_experiment_table3.txt: columns k [cm^-1], E at the three stations [cm^3 s^-2],
// '-' where the table has no entry, two header lines). Missing entries are left out, never read
// as zero; the other transcriptions encode them as padding values that are not measurements.
// Values are returned in SI: k [1/m], E [m^3/s^2].
#pragma once

#include <array>
#include <string>
#include <vector>

#include "les/spectrum_table.hpp"

namespace valsalva::les {

inline constexpr double cbc_mesh_size = 0.0508;                    // M [m]
inline constexpr double cbc_u0 = 10.0;                             // U0 [m/s]
inline constexpr std::array<int, 3> cbc_stations = {42, 98, 171};  // tU0/M

struct CbcStation {
  int t_u0_over_m = 0;
  std::vector<double> k;  // [1/m], increasing
  std::vector<double> E;  // [m^3/s^2]
  SpectrumTable table(Extrapolation extrapolation) const;
};

struct CbcSpectra {
  std::string source;
  std::array<CbcStation, 3> stations;
  const CbcStation& at(int t_u0_over_m) const;  // throws std::out_of_range naming the stations
};

// Throws std::runtime_error naming file and line for unreadable or malformed input.
CbcSpectra read_cbc_table3(const std::string& path);

}  // namespace valsalva::les
