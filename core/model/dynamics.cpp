#include "core/model/dynamics.h"

#include <algorithm>
#include <cmath>

namespace vibro {
namespace {

// The power a pellet's damper takes at speed dphi, m R² c dphi², W.
double damper_power(const Pellet& p, double R, double dphi) {
  return p.m * R * R * p.c * dphi * dphi;
}

}  // namespace

double normal_per_mass(const Model& model, double phi, double dphi) {
  return model.g * std::cos(phi) + model.R * dphi * dphi;
}

double body_force(const Model& model, const Body& body, double t) {
  double F = 0.0;
  for (int i : body.members) F += model.pellets[i].force.at(t);
  return F;
}

double body_mass(const Model& model, const Body& body) {
  double M = 0.0;
  for (int i : body.members) M += model.pellets[i].m;
  return M;
}

double body_damping(const Model& model, const Body& body) {
  if (body.members.size() == 1) return model.pellets[body.leader()].c;
  double mc = 0.0;
  for (int i : body.members) mc += model.pellets[i].m * model.pellets[i].c;
  return mc / body_mass(model, body);
}

BodyLoad body_load(const Model& model, const Body& body, double t) {
  BodyLoad load{0.0, 0.0, 0.0};
  double mc = 0.0;
  for (int i : body.members) {
    const Pellet& p = model.pellets[i];
    load.F += p.force.at(t);
    load.M += p.m;
    mc += p.m * p.c;
  }
  load.C = body.members.size() == 1 ? model.pellets[body.leader()].c : mc / load.M;
  return load;
}

double body_free_acceleration(const Model& model, const Body& body, double t, double phi) {
  return body_force(model, body, t) / (body_mass(model, body) * model.R) -
         model.g / model.R * std::sin(phi);
}

// No step spans more than a radian of the slowest swing or of a forcing: sqrt(R/g) and 1/Ω.
// Longer steps leave the range where the embedded error estimates hold, and one that takes a
// quarter swing at once can be accepted on an estimate far below its true error (evidence:
// tests/differential/corpus/dop853-takes-a-quarter-swing-in-one-step.json).
double longest_step(const Model& model) {
  double h = std::sqrt(model.R / model.g);
  for (const Pellet& p : model.pellets)
    if (p.force.active() && p.force.Omega > 0.0) h = std::min(h, 1.0 / p.force.Omega);
  return h;
}

SegmentDynamics::SegmentDynamics(const Model& model, const std::vector<Body>& bodies, const Vec& y)
    : model_(model), bodies_(bodies), law_(model) {
  reset(y);
}

void SegmentDynamics::reset(const Vec& y) {
  force_order_ = -1;
  terms_.clear();
  terms_.reserve(bodies_.size());
  damped_ = false;
  for (const Body& b : bodies_) {
    const int L = b.leader();
    const int side = normal_per_mass(model_, y[phi_index(L)], y[dphi_index(L)]) >= 0.0 ? 1 : -1;
    terms_.push_back({body_mass(model_, b), body_damping(model_, b), side});
    damped_ = damped_ || terms_.back().damping != 0.0;
  }
}

double SegmentDynamics::stiffness_hint(double, const Vec& y) const {
  double fastest = 0.0;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].mode == Mode::sliding)
      fastest = std::max(fastest, terms_[b].damping +
                                      2.0 * law_.mu * std::abs(y[dphi_index(bodies_[b].leader())]));
  return fastest / std::sqrt(law_.gR);
}

void SegmentDynamics::evaluate(double t, const Vec& y, Vec& dydt, Mat* J) const {
  if (damped_)
    evaluate<true>(t, y, dydt, J);
  else
    evaluate<false>(t, y, dydt, J);
}

// The hot loop of every run: each transcendental function is computed once per body. Undamped
// (no body of the interval damped), the dampers' terms are not compiled in.
template <bool kDamped>
void SegmentDynamics::evaluate(double t, const Vec& y, Vec& dydt, Mat* J) const {
  if (J) J->setZero();
  const double R = model_.R;
  const bool paper = model_.friction == FrictionLaw::paper;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    if (body.mode != Mode::sliding) {
      for (int i : body.members) {
        dydt[phi_index(i)] = 0.0;
        dydt[dphi_index(i)] = 0.0;
        dydt[work_index(i)] = 0.0;
      }
      continue;
    }
    const int L = body.leader();
    const double phi = y[phi_index(L)], dphi = y[dphi_index(L)];
    const double c = std::cos(phi), sn = std::sin(phi);
    const int s = body.s;
    const bool alone = body.members.size() == 1;
    auto force = [&](int i) {
      const Forcing& f = model_.pellets[i].force;
      return f.active() ? f.at(t) : 0.0;
    };
    double F = alone ? force(L) : 0.0;
    if (!alone)
      for (int i : body.members) F += force(i);
    const double q = dphi * dphi + law_.gR * c;  // normal force per unit mass, over R
    const int side = terms_[b].normal_side;
    const double C = terms_[b].damping;  // zero exactly when no member is damped (c ≥ 0)
    const double acc = law_.acceleration({F, terms_[b].mass, 0.0}, c, sn, dphi, s, side);
    const double n = R * (paper ? q : side * q);  // g cos phi + R dphi², or its magnitude
    for (int i : body.members) {
      const double m = model_.pellets[i].m;
      const double Fi = alone ? F : force(i);
      dydt[phi_index(i)] = y[dphi_index(i)];
      dydt[dphi_index(i)] = acc;
      dydt[work_index(i)] = R * dphi * (Fi - m * s * law_.mu * n);  // the force's and friction's
    }
    // The dampers, in a loop of their own, as SlidingLaw::acceleration subtracts them: the
    // undamped loop above stays as lean as the hot path needs (no register spilled).
    if (kDamped && C != 0.0)
      for (int i : body.members) {
        dydt[dphi_index(i)] = acc - C * dphi;
        dydt[work_index(i)] -= damper_power(model_.pellets[i], R, dphi);
      }
    if (!J) continue;
    const SlidingLaw::Slopes dacc = law_.slopes(C, c, sn, dphi, s, side);
    for (int i : body.members) {
      (*J)(2 * i, 2 * i + 1) = 1.0;
      (*J)(2 * i + 1, 2 * L) = dacc.phi;
      (*J)(2 * i + 1, 2 * L + 1) = dacc.dphi;
    }
  }
}

void SegmentDynamics::rhs_and_motion_jacobian(double t, const Vec& y, Vec& dydt, Mat& J) const {
  evaluate(t, y, dydt, &J);
}

void SegmentDynamics::jacobian(double t, const Vec& y, Mat& dfdy, Vec& dfdt) const {
  dfdy.setZero();
  dfdt.setZero();
  const double R = model_.R, g = model_.g;
  const double mu = law_.mu;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    if (body.mode != Mode::sliding) continue;
    const int L = body.leader();
    const int s = body.s;
    const double phi = y[phi_index(L)], dphi = y[dphi_index(L)];
    const double c = std::cos(phi), sn = std::sin(phi);
    double F = 0.0, dF = 0.0;
    for (int i : body.members) {
      F += model_.pellets[i].force.at(t);
      dF += model_.pellets[i].force.rate(t);
    }
    // acc and the normal force per mass n, with their partial derivatives.
    const SlidingLaw::Slopes dacc =
        law_.slopes(terms_[b].damping, c, sn, dphi, s, terms_[b].normal_side);
    const double sq = model_.friction == FrictionLaw::paper ? 1.0 : terms_[b].normal_side;
    const double n = sq * (g * c + R * dphi * dphi);
    const double dn_dphi = -sq * g * sn, dn_ddphi = sq * 2.0 * R * dphi;
    const double dacc_dt = dF / (terms_[b].mass * R);
    for (int i : body.members) {
      const double m = model_.pellets[i].m;
      const double Fi = model_.pellets[i].force.at(t);
      dfdy(phi_index(i), dphi_index(i)) = 1.0;
      dfdy(dphi_index(i), phi_index(L)) = dacc.phi;
      dfdy(dphi_index(i), dphi_index(L)) = dacc.dphi;
      dfdt[dphi_index(i)] = dacc_dt;
      const int w = work_index(i);
      dfdy(w, phi_index(L)) += R * dphi * (-m * s * mu * dn_dphi);
      dfdy(w, dphi_index(L)) += R * (Fi - m * s * mu * n) + R * dphi * (-m * s * mu * dn_ddphi) -
                                2.0 * m * R * R * model_.pellets[i].c * dphi;
      dfdt[w] = R * dphi * model_.pellets[i].force.rate(t);
    }
  }
}

}  // namespace vibro
