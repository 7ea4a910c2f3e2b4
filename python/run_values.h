// A run's summary, stats, warnings and Lyapunov exponents as the Python values of their JSON
// (io/result_json.cpp, API.md): the same keys in the same (sorted) order, numbers as float or
// int as the JSON writes them, None where it writes null. Made straight from the run, not through
// a JSON tree: the tree's maps and strings cost more than the values themselves.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro::python {

namespace py = pybind11;

// `answer` is answer_sentence(run, model), passed in as the caller keeps it.
py::dict summary_values(const RunResult& run, const std::string& answer);
py::dict stats_values(const RunResult& run);
py::list warning_values(const std::vector<Warning>& warnings);
// None when the run computed none.
py::object lyapunov_values(const std::optional<LyapunovSpectrum>& lyapunov);

}  // namespace vibro::python
