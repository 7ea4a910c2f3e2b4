#include "core/model/parameter.h"

#include <string_view>

namespace vibro {
namespace {

// "pellets[12].F0" after the prefix: the index 12 and the field "F0", or nothing.
bool split_indexed(std::string_view rest, std::string_view list, std::size_t& index,
                   std::string_view& field) {
  if (!rest.starts_with(list) || rest.size() <= list.size() || rest[list.size()] != '[')
    return false;
  rest.remove_prefix(list.size() + 1);
  const std::size_t close = rest.find(']');
  if (close == 0 || close == std::string_view::npos || close + 1 >= rest.size() ||
      rest[close + 1] != '.')
    return false;
  index = 0;
  for (char c : rest.substr(0, close)) {
    if (c < '0' || c > '9' || index > 1000000) return false;
    index = index * 10 + static_cast<std::size_t>(c - '0');
  }
  field = rest.substr(close + 2);
  return true;
}

// The field the path names, or null; `why` says what is wrong with a path that names none.
double* field_of(Model& model, const std::string& path, std::string& why) {
  constexpr std::string_view prefix = "model.";
  std::string_view rest = path;
  if (!rest.starts_with(prefix)) {
    why = "must name a field of the model, as \"model.pellets[0].F0\"";
    return nullptr;
  }
  rest.remove_prefix(prefix.size());
  if (rest == "g") return &model.g;
  if (rest == "R") return &model.R;
  if (rest == "alpha0") return &model.alpha0;
  if (rest == "k_c") return &model.k_c;
  if (rest == "mu_s") {
    if (!model.mu_s) model.mu_s = model.mu();
    return &*model.mu_s;
  }
  std::size_t i = 0;
  std::string_view field;
  if (split_indexed(rest, "pellets", i, field)) {
    if (i >= model.pellets.size()) {
      why = "names pellet index " + std::to_string(i) + ", but the model has " +
            std::to_string(model.pellets.size()) + " pellets";
      return nullptr;
    }
    Pellet& p = model.pellets[i];
    if (field == "m") return &p.m;
    if (field == "phi0") return &p.phi0;
    if (field == "dphi0") return &p.dphi0;
    if (field == "F0") return &p.force.F0;
    if (field == "Omega") return &p.force.Omega;
    if (field == "psi") return &p.force.psi;
    if (field == "c") return &p.c;
  } else if (split_indexed(rest, "limiters", i, field)) {
    if (i >= model.limiters.size()) {
      why = "names limiter index " + std::to_string(i) + ", but the model has " +
            std::to_string(model.limiters.size()) + " limiters";
      return nullptr;
    }
    Limiter& l = model.limiters[i];
    if (field == "angle") return &l.angle;
    if (field == "k") return &l.k;
  }
  why =
      "names no numeric field of the model (g, R, alpha0, k_c, mu_s, "
      "pellets[i].m/phi0/dphi0/F0/Omega/psi/c, limiters[j].angle/k)";
  return nullptr;
}

}  // namespace

std::optional<std::string> set_parameter(Model& model, const std::string& path, double value) {
  std::string why;
  double* field = field_of(model, path, why);
  if (!field) return why;
  *field = value;
  return std::nullopt;
}

double* parameter_field(Model& model, const std::string& path) {
  std::string why;
  return field_of(model, path, why);
}

std::optional<double> get_parameter(const Model& model, const std::string& path) {
  Model copy = model;
  std::string why;
  const double* field = field_of(copy, path, why);
  if (!field) return std::nullopt;
  return *field;
}

}  // namespace vibro
