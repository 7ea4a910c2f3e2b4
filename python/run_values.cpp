#include "python/run_values.h"

#include <cmath>
#include <string_view>

#include "python/keys.h"

namespace vibro::python {
namespace {

// A new reference as an object, raising the Python error when there is none.
py::object owned(PyObject* value) {
  if (value == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(value);
}

py::object number(double x) { return owned(PyFloat_FromDouble(x)); }
// io/result_json.cpp's finite_number: null where JSON has no number.
py::object finite(double x) { return std::isfinite(x) ? number(x) : py::none(); }
py::object integer(long long x) { return owned(PyLong_FromLongLong(x)); }
py::object text(std::string_view s) {
  return owned(PyUnicode_FromStringAndSize(s.data(), static_cast<py::ssize_t>(s.size())));
}
py::object boolean(bool b) { return py::bool_(b); }

// Each dict's keys are set in the sorted order the JSON's keys have.

py::dict final_state(const FinalState& f) {
  py::dict d;
  put<"dphi">(d, finite(f.dphi));
  if (f.limiter >= 0) put<"limiter">(d, integer(f.limiter));
  put<"phi">(d, finite(f.phi));
  put<"phi_wrapped">(d, finite(wrap_angle(f.phi)));
  put<"state">(d, text(pellet_state_name(f.state)));
  return d;
}

}  // namespace

py::dict summary_values(const RunResult& run, const std::string& answer) {
  const Summary& sm = run.summary;
  py::list finals(sm.final.size());
  for (std::size_t i = 0; i < sm.final.size(); ++i) finals[i] = final_state(sm.final[i]);
  py::list by_limiter(sm.impacts_by_limiter.size());
  for (std::size_t l = 0; l < sm.impacts_by_limiter.size(); ++l) {
    const std::vector<int>& counts = sm.impacts_by_limiter[l];
    py::list row(counts.size());
    for (std::size_t p = 0; p < counts.size(); ++p) row[p] = integer(counts[p]);
    by_limiter[l] = row;
  }
  py::dict d;
  put<"answer">(d, text(answer));
  put<"chatter_sequences">(d, integer(sm.chatter_sequences));
  put<"collisions">(d, integer(sm.collisions));
  put<"ends_vibro_impact">(d, boolean(sm.ends_vibro_impact));
  put<"final">(d, finals);
  put<"impacts_by_limiter">(d, by_limiter);
  if (sm.last_impact.index > 0) {
    py::dict last;
    put<"index">(last, integer(sm.last_impact.index));
    put<"t">(last, finite(sm.last_impact.t));
    put<"last_impact">(d, last);
  } else {
    put<"last_impact">(d, py::none());
  }
  put<"limiter_impacts">(d, integer(sm.limiter_impacts));
  return d;
}

py::dict stats_values(const RunResult& run) {
  const Stats& st = run.stats;
  py::dict d;
  put<"atol">(d, number(st.atol));
  put<"check">(d, boolean(st.check));
  if (!st.check_method.empty()) put<"check_method">(d, text(st.check_method));
  put<"check_wall_ms">(d, finite(st.check_wall_ms));
  put<"energy_defect">(d, finite(st.energy_defect));
  put<"error_estimate">(d, finite(st.error_estimate));
  put<"event_time_error">(d, finite(st.event_time_error));
  put<"events">(d, integer(static_cast<long long>(run.events.size())));
  put<"first_integral_residual">(d, finite(st.first_integral_residual));
  put<"jac_evals">(d, integer(st.jac_evals));
  put<"lu_decomps">(d, integer(st.lu_decomps));
  if (!st.message.empty()) put<"message">(d, text(st.message));
  put<"method">(d, text(st.method));
  put<"rejected">(d, integer(st.rejected));
  put<"rhs_evals">(d, integer(st.rhs_evals));
  put<"rtol">(d, number(st.rtol));
  put<"state_error">(d, finite(st.state_error));
  put<"steps">(d, integer(st.steps));
  put<"stiff_switches">(d, integer(st.stiff_switches));
  put<"t_reached">(d, finite(st.t_reached));
  put<"termination">(d, text(termination_name(st.termination)));
  put<"trusted_until">(d, finite(st.trusted_until));
  put<"wall_ms">(d, finite(st.wall_ms));
  return d;
}

py::list warning_values(const std::vector<Warning>& warnings) {
  py::list list(warnings.size());
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    const Warning& w = warnings[i];
    py::dict d;
    put<"code">(d, text(w.code));
    put<"message">(d, text(w.message));
    put<"pellet">(d, integer(w.pellet));
    put<"t_begin">(d, finite(w.t_begin));
    put<"t_end">(d, finite(w.t_end));
    list[i] = d;
  }
  return list;
}

py::object lyapunov_values(const std::optional<LyapunovSpectrum>& lyapunov) {
  if (!lyapunov) return py::none();
  py::list exponents(lyapunov->exponents.size());
  for (std::size_t i = 0; i < lyapunov->exponents.size(); ++i)
    exponents[i] = finite(lyapunov->exponents[i]);
  py::dict d;
  put<"exponents">(d, exponents);
  put<"span">(d, finite(lyapunov->span));
  if (!lyapunov->unsupported.empty()) put<"unsupported">(d, text(lyapunov->unsupported));
  return d;
}

}  // namespace vibro::python
