#include "tests/fuzz/render_scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <type_traits>
#include <variant>

#include "core/run/validate.h"
#include "render/figure.h"
#include "server/config.h"
#include "tests/differential/scene_gen.h"

namespace vibro::fuzz {
namespace {

using std::numbers::pi;

// splitmix64: the stretching's own stream, the same on every platform (std:: distributions are
// not specified bit for bit).
class Draw {
 public:
  Draw(std::uint64_t seed, long i) : state_(seed * 0xD1B54A32D192ED03ull + std::uint64_t(i)) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double unit() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  int between(int lo, int hi) { return lo + below(hi - lo + 1); }  // [lo, hi]
  bool chance(double p) { return unit() < p; }

 private:
  std::uint64_t state_;
};

const server::Limits kServer;  // the server's default limits

Pellet extra_pellet(const Model& m, Draw& d) {
  Pellet p;
  p.m = d.log_uniform(0.01, 10.0);
  p.phi0 = d.uniform(-pi, pi);
  if (d.chance(0.6))
    p.dphi0 = (d.chance(0.5) ? 1 : -1) * d.log_uniform(0.03, 10.0) * std::sqrt(m.g / m.R);
  if (d.chance(0.3)) {
    p.force.F0 = p.m * m.g * d.uniform(0.0, 3.0);
    p.force.Omega = d.log_uniform(0.1, 100.0);
    p.force.psi = d.uniform(0.0, 2.0 * pi);
  }
  return p;
}

// More pellets, up to 8 in all, each clear of the others; dropped again if the model would not
// validate with them.
void add_pellets(Model& m, Draw& d) {
  if (d.chance(0.4)) return;
  const int target = std::max(m.size(), d.between(2, kServer.pellets));
  const Model before = m;
  while (m.size() < target) {
    Pellet p = extra_pellet(m, d);
    for (const Pellet& q : m.pellets)
      if (std::abs(wrap_angle(p.phi0 - q.phi0)) < 1e-6) p.phi0 += 1e-3;
    m.pellets.push_back(p);
  }
  if (validate_model(m)) m = before;
}

// A time window inside [0, t_end], or beyond its end, or one of a nanosecond.
void window(TimeWindow& p, double t_end, Draw& d) {
  if (d.chance(0.7)) return;
  p.t_from = d.chance(0.3) ? 0.0 : d.uniform(0.0, t_end);
  p.t_to = p.t_from + (d.chance(0.2) ? 1e-9 : d.log_uniform(1e-3, 2.0 * t_end));
}

// Axis limits of any span from 1e-9 to 1e4, anywhere near the data or far from it.
AxisLimits limits(Draw& d) {
  const double lo = d.chance(0.2) ? d.uniform(-1e4, 1e4) : d.uniform(-10.0, 10.0);
  return {lo, lo + d.log_uniform(1e-9, 1e4)};
}

template <class Plot>
void ranges(Plot& p, Draw& d) {
  if (d.chance(0.15)) p.phi_range = limits(d);
  if (d.chance(0.15)) p.dphi_range = limits(d);
}

std::string long_title(Draw& d) {
  std::string title;
  while (title.size() < 180) title += d.chance(0.5) ? "φ̇ impact \u2014 " : "WWWWWWWW ";
  return title;
}

PhasePlot phase_plot(int pellets, double t_end, Draw& d) {
  PhasePlot p;
  p.pellet = d.below(pellets);
  window(p, t_end, d);
  ranges(p, d);
  p.wrap = d.chance(0.3);
  p.friction_zone = d.chance(0.2);
  p.branch_labels = d.chance(0.8);
  if (d.chance(0.15))
    for (int k = d.between(1, 4); k > 0; --k) p.branches.push_back(d.between(1, 60));
  if (d.chance(0.15)) p.first_integral_through = PhasePoint{d.uniform(-pi, pi), d.uniform(-20, 20)};
  return p;
}

TimePlot time_plot(int pellets, double t_end, Draw& d) {
  TimePlot p;
  // Every pellet, or a few, repeats included.
  const int listed = d.chance(0.5) ? pellets : d.between(1, pellets + 1);
  for (int k = 0; k < listed; ++k) p.pellets.push_back(listed == pellets ? k : d.below(pellets));
  p.show_dphi = d.chance(0.4);
  window(p, t_end, d);
  ranges(p, d);
  return p;
}

MechanismPlot mechanism_plot(double t_end, Draw& d) {
  MechanismPlot p;
  p.t = d.chance(0.2) ? (d.chance(0.5) ? 0.0 : t_end) : d.uniform(0.0, t_end);
  return p;
}

CylinderPlot cylinder_plot(int pellets, double t_end, Draw& d) {
  CylinderPlot p;
  p.pellet = d.below(pellets);
  window(p, t_end, d);
  p.camera = Camera{d.uniform(-180, 180), d.uniform(-89, 89), d.uniform(1.5, 50)};
  return p;
}

// A panel of any kind a scene can ask for; cylinders rarely (3-D panels are slow to draw).
PlotSpec any_plot(int pellets, double t_end, Draw& d) {
  const int kind = d.below(20);
  PlotSpec p;
  if (kind < 8)
    p = phase_plot(pellets, t_end, d);
  else if (kind < 16)
    p = time_plot(pellets, t_end, d);
  else if (kind < 19 || !cylinder_panels_available())
    p = mechanism_plot(t_end, d);
  else
    p = cylinder_plot(pellets, t_end, d);
  if (d.chance(0.1)) std::visit([&d](auto& plot) { plot.title = long_title(d); }, p);
  return p;
}

// One value the reader or the renderer must refuse, naming its field.
void break_one(Scene& s, Draw& d) {
  PlotSpec& p = s.figure.plots[d.below(static_cast<int>(s.figure.plots.size()))];
  switch (d.below(5)) {
    case 0:  // a pellet past the last
      if (auto* phase = std::get_if<PhasePlot>(&p)) phase->pellet = s.model.size();
      if (auto* cylinder = std::get_if<CylinderPlot>(&p)) cylinder->pellet = s.model.size();
      break;
    case 1:  // an empty window
      std::visit(
          [](auto& plot) {
            if constexpr (std::is_base_of_v<TimeWindow, std::decay_t<decltype(plot)>>)
              plot.t_to = plot.t_from;
          },
          p);
      break;
    case 2:
      p = MechanismPlot{2.0 * s.sim.t_end, {}};
      break;
    case 3:
      s.figure.width = 63;
      break;
    default: {
      CylinderPlot cylinder;
      cylinder.camera.distance = 0.5;
      p = cylinder;
      break;
    }
  }
}

// Sizes from the smallest the reader takes to the server's 4000 px and 8 Mpx, odd ones too.
void size(FigureSpec& f, Draw& d) {
  const int shape = d.below(10);
  if (shape < 7) {
    f.width = d.between(kMinFigureSide, 1600);
    f.height = d.between(kMinFigureSide, 1200);
  } else if (shape < 9) {
    f.width = d.between(kMinFigureSide, 200);
    f.height = d.between(kMinFigureSide, 200);
  } else {
    f.width = d.between(1600, kServer.width);
    f.height = std::min(kServer.height, static_cast<int>(kServer.pixels / f.width));
    f.height = d.between(kMinFigureSide, f.height);
  }
}

}  // namespace

Scene render_scene_at(std::uint64_t seed, long i) {
  const differential::RandomScene random = differential::scene_at(seed, i);
  Draw d(seed, i);
  Scene s;
  s.model = random.model;
  add_pellets(s.model, d);
  s.sim.t_end = d.log_uniform(20.0, 800.0);
  s.sim.check = false;
  const int n = s.model.size();
  const int plots = d.chance(0.85) ? d.between(1, 4) : d.between(5, 8);
  for (int k = 0; k < plots; ++k) s.figure.plots.push_back(any_plot(n, s.sim.t_end, d));
  size(s.figure, d);
  if (d.chance(0.05)) break_one(s, d);
  return s;
}

}  // namespace vibro::fuzz
