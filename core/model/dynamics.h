// The equations of motion of one segment (MODEL.md, "Sliding motion"), as an OdeSystem.
// Every member of a body gets the body's acceleration, so members stay together exactly.
#pragma once

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "core/integrators/ode.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

// Normal force per unit mass, g cos phi + R dphi² (m/s²); negative means the paper law's
// friction pushes the pellet along.
double normal_per_mass(const Model& model, double phi, double dphi);

// Total force and mass of a body at time t.
double body_force(const Model& model, const Body& body, double t);
double body_mass(const Model& model, const Body& body);

// Free acceleration of a body at rest at phi: forcing and gravity, no friction.
double body_free_acceleration(const Model& model, const Body& body, double t, double phi);

// The longest step an integrator may take on this model, s: a radian of the slowest swing or
// of a forcing (sqrt(R/g), 1/Ω).
double longest_step(const Model& model);

// The viscous damping of a body, 1/s: its pellet's c alone, or the mass-weighted mean
// Σ m_i c_i / M of its members (the dampers' forces −m_i R c_i dphi over the body's mass).
double body_damping(const Model& model, const Body& body);

// What drives a sliding body besides gravity and friction: its total force F (N), its mass M
// (kg) and its damping C (1/s, body_damping).
struct BodyLoad {
  double F, M, C;
};
// body_force, body_mass and body_damping, to the bit, in one pass over the members (asked for at
// every sample the crossing finder takes of a speed's rate).
BodyLoad body_load(const Model& model, const Body& body, double t);

// The acceleration of a sliding body under the model's friction law, with the model's constants
// computed once: the right-hand side calls it for every body at every evaluation.
struct SlidingLaw {
  explicit SlidingLaw(const Model& model)
      : paper(model.friction == FrictionLaw::paper),
        R(model.R),
        gR(model.g / model.R),
        mu(model.mu()) {}
  // A body under `load` at phi (its cosine and sine given), moving at dphi in direction s:
  // forcing, gravity, kinetic friction and damping.
  double acceleration(const BodyLoad& load, double cos_phi, double sin_phi, double dphi,
                      int s) const {
    return acceleration(load, cos_phi, sin_phi, dphi, s,
                        dphi * dphi + gR * cos_phi >= 0.0 ? 1 : -1);
  }
  // The same with the bilateral law's normal force taken on one side of its zero (side ±1), not
  // by its magnitude: a motion interval keeps one side, so its equations stay smooth where the
  // force changes sign (the normal watch ends the interval there). An integrator stepping over
  // the kink of |N| errs by the kink, whatever its error estimate says.
  // The damping is subtracted last, and only when there is some, so an undamped body's
  // acceleration is that of the law alone, to the bit and at its cost (the hot loop of a run).
  double acceleration(const BodyLoad& load, double cos_phi, double sin_phi, double dphi, int s,
                      int side) const {
    const double F = load.F, M = load.M;
    const double a =
        paper ? F / (M * R) - s * mu * dphi * dphi - gR * (sin_phi + s * mu * cos_phi)
              : F / (M * R) - gR * sin_phi - s * mu * side * (dphi * dphi + gR * cos_phi);
    return load.C == 0.0 ? a : a - load.C * dphi;
  }
  // Its partial derivatives in phi and dphi, which depend on the place and speed alone (and on
  // the body's damping C, 1/s).
  struct Slopes {
    double phi, dphi;
  };
  Slopes slopes(double C, double cos_phi, double sin_phi, double dphi, int s, int side) const {
    return paper ? Slopes{-gR * (cos_phi - s * mu * sin_phi), -2.0 * s * mu * dphi - C}
                 : Slopes{-gR * cos_phi + s * mu * side * gR * sin_phi,
                          -2.0 * s * mu * side * dphi - C};
  }
  bool paper;
  double R;   // m
  double gR;  // g / R, 1/s²
  double mu;  // tan(alpha0)
};

class SegmentDynamics final : public OdeSystem {
 public:
  // The bilateral law's normal force of each sliding body is taken on the side it has at y.
  SegmentDynamics(const Model& model, const std::vector<Body>& bodies, const Vec& y);
  // The equations of the bodies now in the vector it reads (a new interval's), the bilateral
  // law's sides again from y; its storage kept.
  void reset(const Vec& y);
  // Sets a body's side of the normal force's zero (±1): one starting on the zero takes the side
  // it moves to.
  void set_normal_side(int body, int side) { terms_[body].normal_side = side; }
  int normal_side(int body) const { return terms_[body].normal_side; }
  int dimension() const override { return 3 * model_.size(); }
  void rhs(double t, const Vec& y, Vec& dydt) const override { evaluate(t, y, dydt, nullptr); }
  void jacobian(double t, const Vec& y, Mat& dfdy, Vec& dfdt) const override;
  // rhs, and J = ∂(dphi, ddphi)/∂(phi, dphi) of every pellet (2N × 2N, rows and columns 2i,
  // 2i + 1 for pellet i): the variational equations' matrix, without the forcing's and the
  // work's terms, from the same sines and cosines.
  void rhs_and_motion_jacobian(double t, const Vec& y, Vec& dydt, Mat& J) const;
  double period(int component) const override {
    return component == phi_index(component / 3) ? 2.0 * std::numbers::pi : 0.0;
  }
  // The jets of these equations (core/model/dynamics_jets.cpp): a sliding body's sine, cosine
  // and square of its speed by their recursions, its forcing in closed form; a held body's
  // state constant.
  bool taylor_coefficients(double t0, const Vec& y0, int order,
                           std::span<double> out) const override;
  bool has_taylor_coefficients() const override { return true; }
  // The fastest decay of a sliding body's speed disturbance, c + 2μ|φ̇| (the acceleration's
  // derivative in φ̇ under either friction law), over the pendulum's own rate sqrt(g/R).
  double stiffness_hint(double t, const Vec& y) const override;

 private:
  void evaluate(double t, const Vec& y, Vec& dydt, Mat* J) const;
  template <bool kDamped>
  void evaluate(double t, const Vec& y, Vec& dydt, Mat* J) const;
  void body_jets(std::size_t b, double t0, int order, std::span<double> out) const;
  const Model& model_;
  const std::vector<Body>& bodies_;
  // What the equations read of one body, fixed for the interval.
  struct BodyTerms {
    double mass = 0.0;
    double damping = 0.0;  // 1/s
    int normal_side = 1;   // the sign of the bilateral law's normal force
  };
  std::vector<BodyTerms> terms_;  // per body
  bool damped_ = false;           // some body's damping is not zero
  SlidingLaw law_;
  mutable std::vector<double> jet_scratch_;  // the series of a body's jets, reused
  // Every pellet's forcing series factors F0·Ωᵏ/k!, (force_order_ + 1) each: taken on the first
  // jets of an interval (reset() drops them), so that a step computes only the phase's sine and
  // cosine.
  mutable std::vector<double> force_factors_;
  mutable int force_order_ = -1;
};

}  // namespace vibro
