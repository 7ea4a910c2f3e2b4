// The method registry of core/integrators/stepper.h.
#include "core/integrators/stepper.h"

#include "core/integrators/auto_switch.h"
#include "core/integrators/dop853.h"
#include "core/integrators/dopri5.h"
#include "core/integrators/radau5.h"
#include "core/integrators/taylor.h"

namespace vibro {

std::string_view method_name(Method m) {
  switch (m) {
    case Method::dopri5:
      return "dopri5";
    case Method::dop853:
      return "dop853";
    case Method::radau5:
      return "radau5";
    case Method::automatic:
      return "auto";
    case Method::taylor:
      return "taylor";
  }
  return "unknown";
}

AutoExplicit auto_explicit_for(double rtol, AutoExplicit choice) {
  if (choice != AutoExplicit::by_tolerance) return choice;
  return rtol > kAutoTaylorRtol ? AutoExplicit::dopri5 : AutoExplicit::taylor;
}

bool auto_weighs_explicit(double rtol, AutoExplicit choice) {
  return choice == AutoExplicit::by_tolerance && rtol > kAutoTaylorRtol && rtol <= 5e-6;
}

std::unique_ptr<Stepper> make_stepper(Method method, const StepperOptions& options) {
  switch (method) {
    case Method::dopri5:
      return std::make_unique<integrators::Dopri5>(options);
    case Method::dop853:
      return std::make_unique<integrators::Dop853>(options);
    case Method::radau5:
      return std::make_unique<integrators::Radau5>(options);
    case Method::automatic:
      return std::make_unique<integrators::AutoSwitch>(options);
    case Method::taylor:
      return std::make_unique<integrators::Taylor>(options);
  }
  return nullptr;
}

}  // namespace vibro
