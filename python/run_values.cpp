#include "python/run_values.h"

#include <cmath>
#include <string_view>

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

// d[key] = value. Keys are set in the sorted order the JSON's keys have.
void put(py::dict& d, const char* key, const py::object& value) {
  if (PyDict_SetItemString(d.ptr(), key, value.ptr()) != 0) throw py::error_already_set();
}

py::dict final_state(const FinalState& f) {
  py::dict d;
  put(d, "dphi", finite(f.dphi));
  if (f.limiter >= 0) put(d, "limiter", integer(f.limiter));
  put(d, "phi", finite(f.phi));
  put(d, "phi_wrapped", finite(wrap_angle(f.phi)));
  put(d, "state", text(pellet_state_name(f.state)));
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
  put(d, "answer", text(answer));
  put(d, "chatter_sequences", integer(sm.chatter_sequences));
  put(d, "collisions", integer(sm.collisions));
  put(d, "ends_vibro_impact", boolean(sm.ends_vibro_impact));
  put(d, "final", finals);
  put(d, "impacts_by_limiter", by_limiter);
  if (sm.last_impact.index > 0) {
    py::dict last;
    put(last, "index", integer(sm.last_impact.index));
    put(last, "t", finite(sm.last_impact.t));
    put(d, "last_impact", last);
  } else {
    put(d, "last_impact", py::none());
  }
  put(d, "limiter_impacts", integer(sm.limiter_impacts));
  return d;
}

py::dict stats_values(const RunResult& run) {
  const Stats& st = run.stats;
  py::dict d;
  put(d, "atol", number(st.atol));
  put(d, "check", boolean(st.check));
  if (!st.check_method.empty()) put(d, "check_method", text(st.check_method));
  put(d, "check_wall_ms", finite(st.check_wall_ms));
  put(d, "energy_defect", finite(st.energy_defect));
  put(d, "error_estimate", finite(st.error_estimate));
  put(d, "event_time_error", finite(st.event_time_error));
  put(d, "events", integer(static_cast<long long>(run.events.size())));
  put(d, "first_integral_residual", finite(st.first_integral_residual));
  put(d, "jac_evals", integer(st.jac_evals));
  put(d, "lu_decomps", integer(st.lu_decomps));
  if (!st.message.empty()) put(d, "message", text(st.message));
  put(d, "method", text(st.method));
  put(d, "rejected", integer(st.rejected));
  put(d, "rhs_evals", integer(st.rhs_evals));
  put(d, "rtol", number(st.rtol));
  put(d, "state_error", finite(st.state_error));
  put(d, "steps", integer(st.steps));
  put(d, "stiff_switches", integer(st.stiff_switches));
  put(d, "t_reached", finite(st.t_reached));
  put(d, "termination", text(termination_name(st.termination)));
  put(d, "trusted_until", finite(st.trusted_until));
  put(d, "wall_ms", finite(st.wall_ms));
  return d;
}

py::list warning_values(const std::vector<Warning>& warnings) {
  py::list list(warnings.size());
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    const Warning& w = warnings[i];
    py::dict d;
    put(d, "code", text(w.code));
    put(d, "message", text(w.message));
    put(d, "pellet", integer(w.pellet));
    put(d, "t_begin", finite(w.t_begin));
    put(d, "t_end", finite(w.t_end));
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
  put(d, "exponents", exponents);
  put(d, "span", finite(lyapunov->span));
  if (!lyapunov->unsupported.empty()) put(d, "unsupported", text(lyapunov->unsupported));
  return d;
}

}  // namespace vibro::python
