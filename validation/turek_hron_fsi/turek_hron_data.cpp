// Turek–Hron reference tables; see turek_hron_data.hpp.
#include "validation/turek_hron_fsi/turek_hron_data.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

namespace valsalva::validation {

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else
      cur += c;
  }
  out.push_back(cur);
  return out;
}

// A number, NaN for an empty field (or "rigid") when `optional`.
double parse(const std::vector<std::string>& f, std::size_t i, const std::filesystem::path& file,
             int line, const std::string& what, bool optional = false) {
  const std::string s = i < f.size() ? f[i] : "";
  if (optional && (s.empty() || s == "rigid")) return std::numeric_limits<double>::quiet_NaN();
  try {
    std::size_t pos = 0;
    const double v = std::stod(s, &pos);
    if (pos == s.size()) return v;
  } catch (const std::exception&) {
  }
  throw std::runtime_error(
      fmt::format("{}:{}: cannot read {} from '{}'", file.string(), line, what, s));
}

// Calls row(fields, line) for every data row whose first field is `case_name`.
template <class Row>
void for_rows(const std::filesystem::path& file, const std::string& case_name, Row row) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(fmt::format("cannot open {}", file.string()));
  std::string line;
  for (int ln = 1; std::getline(in, line); ++ln) {
    if (line.empty() || line[0] == '#') continue;
    const auto f = split_csv(line);
    if (f[0] == case_name) row(f, ln);
  }
}

}  // namespace

TurekHronParameters read_turek_hron_parameters(const std::filesystem::path& dir,
                                               const std::string& case_name) {
  const auto file = dir / "turek_hron_parameters.csv";
  std::optional<TurekHronParameters> found;
  // case,rho_s,nu_s,mu_s,E_s,rho_f,nu_f,Ubar,Re,g,type
  for_rows(file, case_name, [&](const std::vector<std::string>& f, int ln) {
    TurekHronParameters p;
    p.rho_s = parse(f, 1, file, ln, "rho_s", true);
    p.nu_s = parse(f, 2, file, ln, "nu_s", true);
    p.mu_s = parse(f, 3, file, ln, "mu_s", true);
    p.E_s = parse(f, 4, file, ln, "E_s", true);
    p.rho_f = parse(f, 5, file, ln, "rho_f");
    p.nu_f = parse(f, 6, file, ln, "nu_f");
    p.U_bar = parse(f, 7, file, ln, "Ubar");
    p.g = parse(f, 9, file, ln, "g");
    found = p;
  });
  if (!found)
    throw std::runtime_error(fmt::format("{}: no row for case {}", file.string(), case_name));
  return *found;
}

TurekHronReference read_turek_hron_reference(const std::filesystem::path& dir,
                                             const std::string& case_name,
                                             const std::string& quantity, const std::string& set) {
  const auto file = dir / "turek_hron_reference_values.csv";
  std::optional<TurekHronReference> found;
  // case,quantity,mean,amplitude,frequency_Hz,set,note
  for_rows(file, case_name, [&](const std::vector<std::string>& f, int ln) {
    if (f.size() < 6 || f[1] != quantity || f[5] != set) return;
    found =
        TurekHronReference{parse(f, 2, file, ln, "mean"), parse(f, 3, file, ln, "amplitude", true),
                           parse(f, 4, file, ln, "frequency_Hz", true)};
  });
  if (!found)
    throw std::runtime_error(fmt::format("{}: no row for case {}, quantity {}, set {}",
                                         file.string(), case_name, quantity, set));
  return *found;
}

}  // namespace valsalva::validation
