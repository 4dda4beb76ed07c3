// Turek–Hron reference tables; see turek_hron_data.hpp.
#include "validation/turek_hron_fsi/turek_hron_data.hpp"

#include <fmt/format.h>

#include <limits>
#include <stdexcept>
#include <vector>

#include "core/numeric_table.hpp"

namespace valsalva::validation {

namespace {

// A number of field i of a row; NaN for an empty field (or "rigid") when `optional`. Errors name
// FILE:LINE:COLUMN and the column (core/numeric_table.hpp).
double parse(const core::TableLines& lines, const std::vector<core::TableField>& f, std::size_t i,
             const std::string& what, bool optional = false) {
  if (i >= f.size())
    throw lines.error(1, fmt::format("{} fields, no column {} ({})", f.size(), i + 1, what));
  if (optional && (f[i].text.empty() || f[i].text == "rigid"))
    return std::numeric_limits<double>::quiet_NaN();
  return lines.number(f[i], what);
}

// Calls row(lines, fields) for every data row whose first field is `case_name`, after a header
// line of unique column names.
template <class Row>
void for_rows(const std::filesystem::path& file, const std::string& case_name, Row row) {
  core::TableFormat format;
  format.quoted = true;
  core::TableLines lines(file, format);
  if (!lines.next()) throw std::runtime_error(fmt::format("{}: no header line", file.string()));
  const auto width = lines.header(lines.fields()).size();
  while (lines.next()) {
    const auto f = lines.fields();
    if (f.size() != width)
      throw lines.error(1, fmt::format("{} fields, the header has {}", f.size(), width));
    if (f[0].text == case_name) row(lines, f);
  }
}

}  // namespace

TurekHronParameters read_turek_hron_parameters(const std::filesystem::path& dir,
                                               const std::string& case_name) {
  const auto file = dir / "turek_hron_parameters.csv";
  std::optional<TurekHronParameters> found;
  // case,rho_s,nu_s,mu_s,E_s,rho_f,nu_f,Ubar,Re,g,type
  for_rows(file, case_name, [&](const core::TableLines& l, const std::vector<core::TableField>& f) {
    TurekHronParameters p;
    p.rho_s = parse(l, f, 1, "rho_s", true);
    p.nu_s = parse(l, f, 2, "nu_s", true);
    p.mu_s = parse(l, f, 3, "mu_s", true);
    p.E_s = parse(l, f, 4, "E_s", true);
    p.rho_f = parse(l, f, 5, "rho_f");
    p.nu_f = parse(l, f, 6, "nu_f");
    p.U_bar = parse(l, f, 7, "Ubar");
    p.g = parse(l, f, 9, "g");
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
  for_rows(file, case_name, [&](const core::TableLines& l, const std::vector<core::TableField>& f) {
    if (f[1].text != quantity || f[5].text != set) return;
    found = TurekHronReference{parse(l, f, 2, "mean"), parse(l, f, 3, "amplitude", true),
                               parse(l, f, 4, "frequency_Hz", true)};
  });
  if (!found)
    throw std::runtime_error(fmt::format("{}: no row for case {}, quantity {}, set {}",
                                         file.string(), case_name, quantity, set));
  return *found;
}

}  // namespace valsalva::validation
