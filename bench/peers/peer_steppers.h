// Peer integrators behind vibro's Stepper interface, so vibro's own event search and event
// instants drive them: a run then finds the same events, and only the integrator differs.
// Bench-only: built when Boost.Odeint or SUNDIALS CVODE is installed (bench/CMakeLists.txt).
#pragma once

#include <memory>

#include "core/integrators/stepper.h"

namespace vibro::bench {

// Boost.Odeint's runge_kutta_dopri5 in its controlled, dense-output form (the same Dormand–
// Prince pair and 4th-order interpolant as vibro's dopri5; odeint's max-norm error control).
// Restarts keep the previous segment's step size as the first one, as vibro's steppers do.
std::unique_ptr<Stepper> make_odeint_dopri5(const StepperOptions& options);

enum class CvodeMethod { adams, bdf };

// SUNDIALS CVODE in CV_ONE_STEP mode with a stop time at each step's limit, its Nordsieck
// history (CVodeGetDky) as the dense output, and CVodeReInit at each restart. Adams uses the
// fixed-point iteration (no Jacobian), BDF Newton with a dense solver and the exact Jacobian.
std::unique_ptr<Stepper> make_cvode(CvodeMethod method, const StepperOptions& options);

}  // namespace vibro::bench
