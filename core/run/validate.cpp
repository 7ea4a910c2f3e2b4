#include "core/run/validate.h"

#include <charconv>
#include <cmath>
#include <numbers>

namespace vibro {
namespace {

// The shortest text that reads back as x: a value just past a bound shows how far (t_end
// 1000.0000001, not "1000").
std::string fmt(double x) {
  char text[32];
  return {text, std::to_chars(text, text + sizeof text, x).ptr};
}

// Checks lo <= x <= hi (or lo < x when open_lo) and finiteness; returns the error if any. The
// field's name is made only for an error: a sweep checks the model at every one of its values.
template <class Name>
std::optional<FieldError> check_range(const Name& field, double x, double lo, double hi,
                                      bool open_lo = false, bool open_hi = false) {
  if (!std::isfinite(x)) return FieldError{std::string(field), "must be a finite number"};
  const bool low = open_lo ? x <= lo : x < lo;
  const bool high = open_hi ? x >= hi : x > hi;
  if (low || high) {
    return FieldError{std::string(field), "must be in " + std::string(open_lo ? "(" : "[") +
                                              fmt(lo) + ", " + fmt(hi) + (open_hi ? ")" : "]") +
                                              ", got " + fmt(x)};
  }
  return std::nullopt;
}

// "model.pellets[i].name", spelled out when it is read as a string.
struct ItemField {
  const char* list;
  int i;
  const char* name;
  operator std::string() const {
    return std::string("model.") + list + "[" + std::to_string(i) + "]." + name;
  }
};

ItemField pellet_field(int i, const char* name) { return {"pellets", i, name}; }
ItemField limiter_field(int i, const char* name) { return {"limiters", i, name}; }

}  // namespace

std::string shortest_text(double x) { return fmt(x); }

std::optional<FieldError> validate_state(const std::string& field, double phi, double dphi) {
  if (auto e = check_range(field + ".phi", phi, -kMaxStartAngle, kMaxStartAngle)) return e;
  return check_range(field + ".dphi", dphi, -kMaxStartSpeed, kMaxStartSpeed);
}

namespace {

// The model's own constants: gravity, radius, tilt, friction, the collisions' restitution.
std::optional<FieldError> check_constants(const Model& m) {
  if (auto e = check_range("model.g", m.g, 0.0, 1e4)) return e;
  if (auto e = check_range("model.R", m.R, 0.0, 1e6, true)) return e;
  if (auto e = check_range("model.alpha0", m.alpha0, 0.0, std::numbers::pi / 2, false, true))
    return e;
  if (m.mu_s) {
    if (auto e = check_range("model.mu_s", *m.mu_s, 0.0, 1e6)) return e;
    if (*m.mu_s < m.mu()) {
      return FieldError{"model.mu_s", "must be ≥ mu = tan(alpha0) = " + fmt(m.mu()) +
                                          " (a smaller one leaves states that can neither "
                                          "stick nor slide), got " +
                                          fmt(*m.mu_s)};
    }
  }
  return check_range("model.k_c", m.k_c, 0.0, 1.0);
}

// The pellets' count against limits.pellets, then each pellet's fields, and their starts apart.
std::optional<FieldError> check_pellets(const Model& m, const Limits& limits) {
  const int n = m.size();
  if (n < 1 || n > limits.pellets) {
    return FieldError{"model.pellets", "must list 1 to " + std::to_string(limits.pellets) +
                                           " pellets, got " + std::to_string(n)};
  }
  for (int i = 0; i < n; ++i) {
    const Pellet& p = m.pellets[i];
    if (auto e = check_range(pellet_field(i, "m"), p.m, 0.0, 1e12, true)) return e;
    if (auto e = check_range(pellet_field(i, "phi0"), p.phi0, -kMaxStartAngle, kMaxStartAngle))
      return e;
    if (auto e = check_range(pellet_field(i, "dphi0"), p.dphi0, -kMaxStartSpeed, kMaxStartSpeed))
      return e;
    if (auto e = check_range(pellet_field(i, "F0"), p.force.F0, -1e12, 1e12)) return e;
    if (auto e = check_range(pellet_field(i, "Omega"), p.force.Omega, -1e9, 1e9)) return e;
    if (auto e = check_range(pellet_field(i, "psi"), p.force.psi, -1e4, 1e4)) return e;
    if (auto e = check_range(pellet_field(i, "c"), p.c, 0.0, kMaxDamping)) return e;
    for (int j = 0; j < i; ++j) {
      if (std::abs(wrap_angle(p.phi0 - m.pellets[j].phi0)) < 1e-9) {
        return FieldError{pellet_field(i, "phi0"),
                          "coincides with pellet " + std::to_string(j + 1) + " (model.pellets[" +
                              std::to_string(j) +
                              "]) mod 2π; pellets are point masses and must start apart"};
      }
    }
  }
  return std::nullopt;
}

// Limiter i's re-arming: a mobile one names another limiter, a fixed one none (and is armed).
std::optional<FieldError> check_rearm(const Model& m, int i) {
  const Limiter& l = m.limiters[i];
  const int nl = static_cast<int>(m.limiters.size());
  if (l.mobile) {
    if (l.rearm_by < 0 || l.rearm_by >= nl || l.rearm_by == i) {
      return FieldError{limiter_field(i, "rearm_by"),
                        "a mobile limiter needs the index of another limiter (0.." +
                            std::to_string(nl - 1) + ", not " + std::to_string(i) +
                            ") whose impacts re-arm it"};
    }
  } else if (l.rearm_by != -1) {
    return FieldError{limiter_field(i, "rearm_by"), "applies only to a mobile limiter"};
  } else if (!l.armed) {
    return FieldError{limiter_field(i, "armed"),
                      "only a mobile limiter may start disarmed: a fixed one is always armed"};
  }
  return std::nullopt;
}

// Limiter i's pellets: each an index of the model's, none twice.
std::optional<FieldError> check_limiter_pellets(const Model& m, int i) {
  const Limiter& l = m.limiters[i];
  const int n = m.size();
  for (std::size_t j = 0; j < l.pellets.size(); ++j) {
    const int p = l.pellets[j];
    const std::string field =
        "model.limiters[" + std::to_string(i) + "].pellets[" + std::to_string(j) + "]";
    if (p < 0 || p >= n) {
      return FieldError{field, "must be a pellet index in 0.." + std::to_string(n - 1) +
                                   " (indices count from 0: pellet 1 is 0), got " +
                                   std::to_string(p)};
    }
    for (std::size_t q = 0; q < j; ++q) {
      if (l.pellets[q] == p)
        return FieldError{field, "lists pellet " + std::to_string(p + 1) + " (index " +
                                     std::to_string(p) + ") twice"};
    }
  }
  return std::nullopt;
}

// Two limiters at one angle that stop the same pellet: which one it strikes (its k, its
// re-arming) would be decided by their order in the list.
std::optional<FieldError> check_limiter_apart(const Model& m, int i) {
  const Limiter& l = m.limiters[i];
  for (int j = 0; j < i; ++j) {
    const Limiter& o = m.limiters[j];
    if (std::abs(wrap_angle(l.angle - o.angle)) >= 1e-9) continue;
    for (int p = 0; p < m.size(); ++p)
      if (o.acts_on(p) && l.acts_on(p))
        return FieldError{limiter_field(i, "angle"),
                          "coincides with limiter " + std::to_string(j + 1) + " (model.limiters[" +
                              std::to_string(j) + "]) mod 2π, and both stop pellet " +
                              std::to_string(p + 1) + ": merge them, or list different pellets"};
  }
  return std::nullopt;
}

// The limiters' count against limits.limiters, then each limiter in turn.
std::optional<FieldError> check_limiters(const Model& m, const Limits& limits) {
  const int nl = static_cast<int>(m.limiters.size());
  if (nl > limits.limiters) {
    return FieldError{"model.limiters", "at most " + std::to_string(limits.limiters) +
                                            " limiters, got " + std::to_string(nl)};
  }
  for (int i = 0; i < nl; ++i) {
    const Limiter& l = m.limiters[i];
    if (auto e = check_range(limiter_field(i, "angle"), l.angle, -1e4, 1e4)) return e;
    if (auto e = check_range(limiter_field(i, "k"), l.k, 0.0, 1.0)) return e;
    if (auto e = check_rearm(m, i)) return e;
    if (auto e = check_limiter_pellets(m, i)) return e;
    if (auto e = check_limiter_apart(m, i)) return e;
  }
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_model(const Model& m, const Limits& limits) {
  if (auto e = check_constants(m)) return e;
  if (auto e = check_pellets(m, limits)) return e;
  return check_limiters(m, limits);
}

std::optional<FieldError> validate_options(const SimOptions& o, int pellets, const Limits& limits) {
  if (auto e = check_range("t_end", o.t_end, 0.0, limits.t_end, true)) return e;
  if (auto e = check_range("solver.rtol", o.rtol, 1e-14, 0.1)) return e;
  if (auto e = check_range("solver.atol", o.atol, 1e-16, 1.0)) return e;
  if (!o.record.empty() && static_cast<int>(o.record.size()) != pellets) {
    return FieldError{"record", "must flag each pellet"};
  }
  if (o.samples_per_step < 0 || o.samples_per_step > 64) {
    return FieldError{"samples_per_step", "must be in [0, 64]"};
  }
  if (o.max_events < 1 || o.max_steps < 1) return FieldError{"limits", "must be positive"};
  return std::nullopt;
}

}  // namespace vibro
