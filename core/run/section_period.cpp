#include "core/run/section_period.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/model/model.h"

namespace vibro {

namespace {

// Each pellet's tolerances for the period test, scaled to the states' spread.
struct Tolerances {
  std::vector<double> phi, dphi;
};

Tolerances tolerances(std::span<const StateAt> stops, double speed_scale, double floor) {
  const std::size_t n = stops.front().pellets.size();
  Tolerances tol{std::vector<double>(n), std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    double lo = 1e300, hi = -1e300, vlo = 1e300, vhi = -1e300;
    for (const StateAt& s : stops) {
      const double w = wrap_angle(s.pellets[i].phi);
      lo = std::min(lo, w);
      hi = std::max(hi, w);
      vlo = std::min(vlo, s.pellets[i].dphi);
      vhi = std::max(vhi, s.pellets[i].dphi);
    }
    tol.phi[i] = 1e-5 * (floor + (hi - lo));
    tol.dphi[i] = 1e-5 * (floor * speed_scale + (vhi - vlo));
  }
  return tol;
}

// How far state k + p is from state k, in units of the tolerances: at most 1 where they agree.
double gap(std::span<const StateAt> stops, const Tolerances& tol, int k, int p) {
  double g = 0.0;
  for (std::size_t i = 0; i < tol.phi.size(); ++i) {
    const FinalState& a = stops[k].pellets[i];
    const FinalState& b = stops[k + p].pellets[i];
    g = std::max({g, std::abs(std::remainder(b.phi - a.phi, kTwoPi)) / tol.phi[i],
                  std::abs(b.dphi - a.dphi) / tol.dphi[i]});
  }
  return g;
}

int period_within(std::span<const StateAt> stops, const Tolerances& tol) {
  const int K = static_cast<int>(stops.size()) - 1;
  for (int p = 1; 2 * p <= K; ++p) {
    bool repeats = true;
    for (int k = 0; repeats && k + p <= K; ++k) repeats = gap(stops, tol, k, p) <= 1.0;
    if (repeats) return p;
  }
  return 0;
}

}  // namespace

int section_period(std::span<const StateAt> stops, double speed_scale, double floor) {
  if (stops.size() < 3) return 0;
  return period_within(stops, tolerances(stops, speed_scale, floor));
}

bool section_settled(std::span<const StateAt> stops, double speed_scale) {
  if (stops.size() < 3) return false;
  const Tolerances tol = tolerances(stops, speed_scale, kSettleFloor);
  const int p = period_within(stops, tol);
  if (p == 0) return false;
  // A period-1 motion approached along a spiral of a quarter turn a period repeats every 4
  // periods long before it does every period: the window's later half must show the same period.
  const std::span<const StateAt> later = stops.last(stops.size() / 2 + 1);
  if (period_within(later, tolerances(later, speed_scale, kSettleFloor)) != p) return false;
  // The gaps k → k + p, the window's first half against its second.
  const int m = static_cast<int>(stops.size()) - p;  // gaps k = 0 … m − 1
  const int h = m / 2;
  double early = 0.0, late = 0.0;
  for (int k = 0; k < m; ++k) {
    double& half = k < m - h ? early : late;
    half = std::max(half, gap(stops, tol, k, p));
  }
  // At the integration's round-off the gaps stop shrinking: settled.
  if (late <= kSettledGap) return true;
  if (early <= 0.0 || late >= early) return false;
  // A geometric approach by rho per gap: what is left to go, sum of late·rho^j.
  const double rho = std::pow(late / early, 1.0 / std::max(h, 1));
  return late * rho / (1.0 - rho) <= 1.0;
}

}  // namespace vibro
