#include "core/run/result.h"

namespace vibro {

std::string_view pellet_state_name(PelletState state) {
  switch (state) {
    case PelletState::sliding:
      return "sliding";
    case PelletState::stuck:
      return "stuck";
    case PelletState::resting_at_limiter:
      return "resting_at_limiter";
  }
  return "?";
}

std::string_view termination_name(Termination t) {
  switch (t) {
    case Termination::completed:
      return "completed";
    case Termination::event_limit:
      return "event_limit";
    case Termination::step_limit:
      return "step_limit";
    case Termination::deadline:
      return "deadline";
    case Termination::numerical_failure:
      return "numerical_failure";
    case Termination::cancelled:
      return "cancelled";
  }
  return "?";
}

}  // namespace vibro
