// Columns of a table as numpy arrays, one value per row: what the module's results hold where the
// CSV exports have a column (API.md, "Exports").
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "python/code_points.h"

namespace vibro::python {

namespace py = pybind11;

// The n values get(0) … get(n − 1) as a numpy array of T (double, std::int64_t or bool).
template <class T, class Get>
py::array_t<T> column(std::size_t n, const Get& get) {
  py::array_t<T> a(static_cast<py::ssize_t>(n));
  T* data = a.mutable_data();
  for (std::size_t k = 0; k < n; ++k) data[k] = static_cast<T>(get(k));
  return a;
}

// The n strings get(0) … as a numpy array of str ('<U' of the longest), decoded straight into
// the array (a list of Python strings handed to numpy.array would cost more than the run's events
// themselves): get(k) is called twice, to size the array and to fill it.
template <class Get>
py::array string_column(std::size_t n, const Get& get) {
  std::size_t width = 1;  // numpy's narrowest str
  for (std::size_t k = 0; k < n; ++k) width = std::max(width, code_point_count(get(k)));
  py::array a(py::dtype("<U" + std::to_string(width)),
              std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)});
  auto* data = static_cast<char32_t*>(a.mutable_data());
  for (std::size_t k = 0; k < n; ++k) {
    char32_t* row = data + k * width;
    std::fill(write_code_points(get(k), row), row + width, U'\0');
  }
  return a;
}

}  // namespace vibro::python
