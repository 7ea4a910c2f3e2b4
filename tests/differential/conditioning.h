// How close an event is to not happening, or to happening otherwise: the numbers that tell a
// genuine miss of one method from an ill-conditioned scene whose event sequence legitimately
// depends on tiny differences. All are dimensionless, in the scene's scales T0 = sqrt(R/g)
// and g/R; small means ill-conditioned.
#pragma once

#include <string>
#include <string_view>

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro::differential {

// Below these an event is ill-conditioned. Two runs at rtol ≤ 1e-11 differ in angle by about
// δ ≤ 1e3·rtol ≈ 1e-8 rad (TimeTolerance): that decides a grazing impact when its speed is
// below sqrt(2δ) ≈ 1.4e-4 (v² = 2aδ in scene units), and a stick test whose margin is below
// δ (the free acceleration moves by (g/R)·δ). The bounds leave a factor of ten or more.
inline constexpr double kGrazingSpeed = 1e-3;
inline constexpr double kStickMargin = 1e-6;
inline constexpr double kReleaseRate = 1e-4;
inline constexpr double kRoundOffSpeed = 1e-12;  // an "impact" at this speed is round-off
inline constexpr double kSimultaneous = 1e-6;    // events closer than this (in T0) interact

struct Margin {
  double value = 0.0;      // dimensionless; infinity when the event has no such threshold
  std::string what;        // "impact speed", "stick margin", "release rate", ...
  bool ill = false;        // below its kind's bound above
  bool round_off = false;  // an impact or approach speed at round-off
  bool is_speed = false;   // an impact or approach speed
};

// The event's own margin:
// - limiter impact, chatter: the impact speed |dphi⁻|·T0 (a grazing impact has a small one);
// - collision: the approach speed |dphi_i⁻ − dphi_j⁻|·T0;
// - reversal, stick: the stick test's margin | |a_free| − capacity | / (g/R) at the event
//   (a small one flips stick against slide on);
// - release under forcing: |dF/dt|·T0/(M g), how fast the free acceleration crosses the
//   threshold (a small one is a tangency); infinity for a release by separation.
Margin event_margin(const Model& model, const Event& e);

// The time to the nearest event of `run` at another instant, over T0 (near-simultaneous
// events have a small one). Events within 1e-12·(1 + t) s are one instant.
double isolation(const Model& model, const RunResult& run, std::size_t index);

// The likely cause of a mismatch between two runs, from the conditioning around it.
enum class Cause {
  round_off_impact,  // an impact at round-off speed, listed by one run only: an artefact
  grazing,           // an impact at a small speed
  stick_threshold,   // a stick test near its threshold
  tangent_release,   // a release where the forcing barely crosses the threshold
  simultaneous,      // events nearly at one instant
  regrouped,         // one impact instant, but a different set of touching pellets in it
  amplified,         // an earlier ill-conditioned event magnified the difference
  unexplained,       // well-conditioned: a candidate miss of one method
};
std::string_view cause_name(Cause c);

struct MismatchContext {
  Margin a, b;               // the first differing events' margins (infinite where one is missing)
  double isolation = 0.0;    // the smaller isolation of the two
  bool earlier_ill = false;  // an earlier event of either run was ill-conditioned
  double slowest = 0.0;      // the smallest impact or approach speed among these and earlier events
  double excess = 0.0;       // a time mismatch's |Δt| over its tolerance; 0 for a sequence
  bool regrouped = false;    // both are collisions at one time, of different pellets
};
// An impact at speed v turns a difference δφ of the state into one of its time of about
// δφ/v (in scene units): a time mismatch that exceeds its tolerance by less than 1/slowest
// is put down to that amplification.
Cause likely_cause(const MismatchContext& c);

}  // namespace vibro::differential
