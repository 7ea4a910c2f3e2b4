#include "solvers.h"

#if defined(VIBRO_BENCH_ODEINT) || defined(VIBRO_BENCH_CVODE)
#include "peers/peer_steppers.h"
#endif

namespace vibro::bench {

std::vector<Solver> solvers() {
  std::vector<Solver> list;
  for (Method m : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    list.push_back(
        {std::string(method_name(m)), [m](const StepperOptions& o) { return make_stepper(m, o); }});
  }
#ifdef VIBRO_BENCH_ODEINT
  list.push_back({"odeint-dopri5", [](const StepperOptions& o) { return make_odeint_dopri5(o); }});
#endif
#ifdef VIBRO_BENCH_CVODE
  list.push_back(
      {"cvode-adams", [](const StepperOptions& o) { return make_cvode(CvodeMethod::adams, o); }});
  list.push_back(
      {"cvode-bdf", [](const StepperOptions& o) { return make_cvode(CvodeMethod::bdf, o); }});
#endif
  return list;
}

}  // namespace vibro::bench
