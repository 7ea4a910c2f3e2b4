// Every threshold the trust check (core/analysis/trust.h) uses, with its reason: the check's
// counterpart of EventTolerances (core/events/event_tolerances.h), which decides the events
// themselves. Times are relative to the time scale and the time run where a formula says so.
#pragma once

#include <cstddef>

namespace vibro {

struct TrustPolicy {
  // The shadow runs at rtol and atol over this: its own error must be well below the run's,
  // whatever the methods' error constants and whatever luck the run has.
  double shadow_tolerance_ratio = 100.0;
  // The shadow's longest step as a share of the run's: where the longest step holds both, a
  // shadow held alike takes the same steps and shares their error
  // (Trust.AShadowDoesNotShareTheRunsCappedSteps).
  double shadow_step_share = 0.5;
  // The shadow's start is moved by this many ulps (check_model), so that where run and shadow
  // take the same steps they do not round alike through a chain that amplifies round-off.
  double start_ulps = 64.0;
  // The round-off a run carries in its angles, in ulps, as the chain amplifies it; a few, since
  // pellets at one place moved alike keep their gaps.
  double carried_ulps = 4.0;
  // The tolerance of the variational equations that find the start's shifts: the estimate needs
  // a tenth of a shift, and this puts the shifts within 1 % of their value.
  double shift_rtol = 1e-4;
  // The shifts are found over the shadow's first instants up to this many (about 20 MB of path):
  // past them the shadow is taken as it is.
  std::size_t shift_instants = 20000;
  // Events this close (relative to 1 + |t|) are at one instant, as runs are compared.
  double same_instant = 1e-12;
  // Times that differ by more than this share of the time to the neighbouring events leave the
  // events' order and spacing unresolved.
  double unresolved_share = 0.1;
  // A time difference that the tolerance explains: this many rtol over the time scale and time
  // run (sensitive dynamics amplify a run's error by that much and still resolve the events).
  double explained_rtols = 1e3;
  // The round-off of event times, in ulps of the time scale and the time run: errors a run and
  // its shadow share, which the shadow cannot see.
  double time_round_off_ulps = 1e3;
  // The round-off of an impact's time, in ulps of the angle it is found at over the speed of
  // approach (pellets that meet slowly collide at times round-off alone moves).
  double placement_round_off_ulps = 1e2;
  // A run vouches for no less than this share of what its tolerance asks, rtol·(T0 + t): a run
  // and its shadow of one method that agree far better than asked may share their error.
  double asked_share = 1e-2;
  // A collision that leaves a pellet at a speed within this many of its errors (the run's speed
  // against its shadow's) of zero leaves whether and when the pellet turns unresolved (a limiter
  // sets the sign of the speed an impact on it leaves, whatever its error): a run and
  // its shadow that both left it slowly backwards listed no turn where the truth turned 2.6e-7 s
  // later (ctest trust_scene.a_shadow_started_with_the_run_shared_its_chaotic_error).
  double turn_speed_errors = 10.0;
  // The round-off of the speeds an instant leaves, in ulps of the largest speed it meets or
  // leaves: differences below it are what the runs cannot resolve, not an error.
  double speed_round_off_ulps = 1e3;
  // Trust ends this many errors before the first events the runs do not list alike (the bound the
  // estimate keeps).
  double margin_errors = 10.0;
  // A grazing contact is decided by a position error of this many times what the tolerance holds
  // an angle to (grazing_window).
  double grazing_tolerances = 10.0;
};

inline constexpr TrustPolicy kTrustPolicy{};

}  // namespace vibro
