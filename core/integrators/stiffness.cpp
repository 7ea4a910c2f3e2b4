#include "core/integrators/stiffness.h"

#include "core/integrators/auto_switch.h"
#include "core/integrators/dop853.h"
#include "core/integrators/dopri5.h"
#include "core/integrators/radau5.h"

namespace vibro::integrators {

bool stiffness_detected(const Stepper& stepper) {
  if (const auto* s = dynamic_cast<const Dopri5*>(&stepper)) return s->stiffness_detected();
  if (const auto* s = dynamic_cast<const Dop853*>(&stepper)) return s->stiffness_detected();
  if (const auto* s = dynamic_cast<const AutoSwitch*>(&stepper)) return s->stiff();
  if (const auto* s = dynamic_cast<const Radau5*>(&stepper)) {
    return s->stiffness_ratio() > AutoSwitch::kNonStiffBound;
  }
  return false;
}

}  // namespace vibro::integrators
