// The physical system of MODEL.md: pellets on a rough circle in a vertical plane, with limiters.
// Units: SI (m, kg, s, N); angles in rad, measured from the lowest point, positive toward the
// paper's right-hand limiter delta_1. Angles are unwrapped; positions match modulo 2π.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace vibro {

inline constexpr double kTwoPi = 6.283185307179586476925286766559;

enum class FrictionLaw {
  paper,      // the paper's equation as printed: friction mu·(g cos phi + R dphi²), sign kept
  bilateral,  // a pellet threaded on a wire: friction mu·|g cos phi + R dphi²|
};

// Tangential force F(t) = F0 cos(Omega t + psi) on one pellet, N.
struct Forcing {
  double F0 = 0.0;
  double Omega = 0.0;
  double psi = 0.0;
  double at(double t) const { return F0 != 0.0 ? F0 * std::cos(Omega * t + psi) : 0.0; }
  double rate(double t) const { return -F0 * Omega * std::sin(Omega * t + psi); }  // dF/dt
  bool active() const { return F0 != 0.0; }
};

struct Pellet {
  double m = 0.0;      // kg, > 0
  double phi0 = 0.0;   // rad
  double dphi0 = 0.0;  // rad/s
  Forcing force;
  double c = 0.0;  // viscous damping, 1/s, ≥ 0: adds −c·dphi to the pellet's acceleration
};

struct Limiter {
  double angle = 0.0;        // rad; acts at every angle ≡ this (mod 2π)
  double k = 1.0;            // restitution in [0, 1]
  bool mobile = false;       // disarmed by the impact it takes, re-armed by an impact on `rearm_by`
  int rearm_by = -1;         // index of the limiter whose impacts re-arm this one (mobile only)
  std::vector<int> pellets;  // pellets it acts on; empty: all
  // Armed at t = 0. Only a mobile limiter may start disarmed (a run started on a periodic motion
  // whose section finds it so); a fixed one is always armed.
  bool armed = true;
  bool acts_on(int pellet) const;
};

struct Model {
  double g = 9.81;
  double R = 0.5;
  double alpha0 = 0.0;
  std::optional<double> mu_s;  // static coefficient for the stick test; default: mu
  FrictionLaw friction = FrictionLaw::paper;
  std::vector<Pellet> pellets;
  std::vector<Limiter> limiters;
  double k_c = 1.0;  // restitution of pellet-pellet collisions

  double mu() const { return std::tan(alpha0); }
  double mu_static() const { return mu_s.value_or(mu()); }
  int size() const { return static_cast<int>(pellets.size()); }
  // Whether any pellet is damped (then the unforced motion has no first integral).
  bool damped() const;
};

// Free tangential acceleration of pellet i at rest: forcing and gravity, no friction (rad/s²).
double free_acceleration(const Model& model, int i, double t, double phi);
// Static friction capacity per unit mass and radius at angle phi: mu_s·(g/R)·|cos phi| (rad/s²).
double stick_capacity(const Model& model, double phi);
// Kinetic + potential energy of pellet i, J: ½ m R² dphi² − m g R cos phi.
double energy(const Model& model, int i, double phi, double dphi);
// The scene's unit of time, s: gravity's sqrt(R/g), unless gravity is a thousand times slower
// than the rest of the motion (g = 0 included); then the longest time of that motion: a start's
// speed 1/|dphi0|, a force's push sqrt(m·R/|F0|) and its period 2π/|Omega|. 1 s if nothing moves.
double time_scale(const Model& model);
// Whether that unit is gravity's; where it is not, neither are the scene's energies (2mgR).
bool gravity_sets_time_scale(const Model& model);
// The scene's unit of angular speed, rad/s: sqrt(g/R), or 1/time_scale where gravity does not
// set the time.
double speed_scale(const Model& model);
// phi reduced to (−π, π].
double wrap_angle(double phi);

}  // namespace vibro
