// The one-pellet system both event-locating peers integrate, and what happens at its events
// (MODEL.md: sliding motion, limiter impacts, reversals).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "core/model/model.h"

namespace vibro::bench {

class ForcedPellet {
 public:
  explicit ForcedPellet(const Model& model)
      : p_(model.pellets.at(0)),
        R_(model.R),
        gR_(model.g / model.R),
        mu_(model.mu()),
        mu_s_(model.mu_static()),
        lower_(std::min(model.limiters.at(0).angle, model.limiters.at(1).angle)),
        upper_(std::max(model.limiters.at(0).angle, model.limiters.at(1).angle)),
        k_lower_(model.limiters[0].angle < model.limiters[1].angle ? model.limiters[0].k
                                                                   : model.limiters[1].k),
        k_upper_(model.limiters[0].angle < model.limiters[1].angle ? model.limiters[1].k
                                                                   : model.limiters[0].k),
        s_(p_.dphi0 < 0.0 ? -1 : 1) {}

  static constexpr int kEvents = 3;

  int direction() const {
    return s_;
  }  // the sliding direction s of the current segment  // reversal, upper limiter, lower limiter

  double ddphi(double t, double phi, double dphi) const {
    return p_.force.at(t) / (p_.m * R_) - s_ * mu_ * dphi * dphi -
           gR_ * (std::sin(phi) + s_ * mu_ * std::cos(phi));
  }

  // Positive while nothing happens.
  void events(double phi, double dphi, double g[kEvents]) const {
    g[0] = s_ * dphi;
    g[1] = upper_ - phi;
    g[2] = phi - lower_;
  }

  // Applies event `which` at t to (phi, dphi); returns an error text if the pellet would stick.
  std::string apply(int which, double t, double& phi, double& dphi) {
    if (which == 0) {
      dphi = 0.0;
      const double a_free = p_.force.at(t) / (p_.m * R_) - gR_ * std::sin(phi);
      if (std::abs(a_free) <= mu_s_ * gR_ * std::abs(std::cos(phi))) return "the pellet sticks";
      s_ = a_free > 0.0 ? 1 : -1;
      return {};
    }
    phi = which == 1 ? upper_ : lower_;
    dphi = -(which == 1 ? k_upper_ : k_lower_) * dphi;
    s_ = dphi < 0.0 ? -1 : 1;
    return {};
  }

 private:
  Pellet p_;
  double R_, gR_, mu_, mu_s_;
  double lower_, upper_, k_lower_, k_upper_;
  int s_;
};

}  // namespace vibro::bench
