// A method-independent query of the steppers' stiffness diagnostics, for the simulator (which
// holds a Stepper&).
#pragma once

#include "core/integrators/stepper.h"

namespace vibro::integrators {

// True when the stepper judges the current problem stiff: DOPRI5's or DOP853's stiffness detection
// has fired (h·ρ beyond the stability boundary in 15 steps), "auto" runs RADAU5 (or switches to it
// at the next step), or RADAU5's last step had h·‖J‖∞ above AutoSwitch::kNonStiffBound.
bool stiffness_detected(const Stepper& stepper);

}  // namespace vibro::integrators
