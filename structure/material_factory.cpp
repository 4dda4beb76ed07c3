#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "structure/material.hpp"

namespace valsalva::structure {

namespace {

// Reads the parameters of one law, rejecting unknown and missing keys and non-positive moduli.
class ParamReader {
 public:
  ParamReader(const std::string& type, const std::map<std::string, double>& p,
              const std::string& where, std::set<std::string> allowed)
      : type_(type), p_(p), where_(where) {
    for (const auto& [k, v] : p)
      if (!allowed.count(k)) {
        std::string list;
        for (const auto& a : allowed) list += " " + a;
        throw std::invalid_argument(
            fmt::format("{}: unknown parameter '{}' = {} for material '{}' (expected:{})", where, k,
                        v, type, list));
      }
  }
  double get(const std::string& key, double lo, bool lo_open, double hi = INFINITY) const {
    auto it = p_.find(key);
    if (it == p_.end())
      throw std::invalid_argument(
          fmt::format("{}: material '{}' needs parameter '{}'", where_, type_, key));
    const double v = it->second;
    const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v < hi;
    if (!ok)
      throw std::invalid_argument(
          fmt::format("{}: material '{}' parameter '{}' = {} is out of range ({}{}, {})", where_,
                      type_, key, v, lo_open ? "(" : "[", lo, hi));
    return v;
  }

 private:
  std::string type_;
  const std::map<std::string, double>& p_;
  std::string where_;
};

}  // namespace

const std::vector<std::string>& material_law_names() {
  static const std::vector<std::string> names{"neo_hookean", "mooney_rivlin", "hgo",
                                              "st_venant_kirchhoff", "linear_elastic"};
  return names;
}

// structure/ stands on Eigen and fmt only, so not on core/enum_names.hpp.
std::string to_string(MaterialLaw law) {
  return material_law_names().at(static_cast<std::size_t>(law));
}

MaterialLaw parse_material_law(std::string_view name) {
  const auto& names = material_law_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw std::invalid_argument(
        fmt::format("unknown material type '{}' (expected {})", name, fmt::join(names, ", ")));
  return static_cast<MaterialLaw>(it - names.begin());
}

std::unique_ptr<Material> make_material(MaterialLaw law, const std::map<std::string, double>& p,
                                        const std::string& where) {
  const std::string type = to_string(law);
  switch (law) {
    case MaterialLaw::neo_hookean: {
      ParamReader r(type, p, where, {"G", "K"});
      return make_neo_hookean(r.get("G", 0, true), r.get("K", 0, true));
    }
    case MaterialLaw::mooney_rivlin: {
      ParamReader r(type, p, where, {"C10", "C01", "C11", "K"});
      return make_mooney_rivlin(r.get("C10", 0, false), r.get("C01", 0, false),
                                r.get("C11", -INFINITY, false), r.get("K", 0, true));
    }
    case MaterialLaw::hgo: {
      ParamReader r(type, p, where, {"mu", "K", "k1", "k2", "kappa", "gamma"});
      HgoParameters h;
      h.mu = r.get("mu", 0, true);
      h.K = r.get("K", 0, true);
      h.k1 = r.get("k1", 0, false);
      h.k2 = r.get("k2", 0, true);
      h.kappa = r.get("kappa", 0, false, 1.0 / 3.0 + 1e-15);
      h.gamma = r.get("gamma", -M_PI, false, M_PI);
      return make_hgo(h);
    }
    case MaterialLaw::st_venant_kirchhoff:
    case MaterialLaw::linear_elastic: {
      ParamReader r(type, p, where, {"E", "nu"});
      const double E = r.get("E", 0, true), nu = r.get("nu", -1, true, 0.5);
      return law == MaterialLaw::linear_elastic ? make_linear_elastic(E, nu)
                                                : make_st_venant_kirchhoff(E, nu);
    }
  }
  throw std::logic_error("structure::make_material: unknown material law");
}

}  // namespace valsalva::structure
