// Columns of a table as numpy arrays, one value per row: what the module's results hold where the
// CSV exports have a column (API.md, "Exports").
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

#include "python/code_points.h"

namespace vibro::python {

namespace py = pybind11;

// A new one-dimensional array of n items of `type`, uninitialised: numpy's own constructor,
// without the shape and strides vectors py::array's constructors allocate first.
inline py::array empty_column(py::dtype type, std::size_t n) {
  auto& api = py::detail::npy_api::get();
  const Py_intptr_t shape[1] = {static_cast<Py_intptr_t>(n)};
  PyObject* a = api.PyArray_NewFromDescr_(api.PyArray_Type_, type.release().ptr(), 1, shape,
                                          nullptr, nullptr, 0, nullptr);  // takes `type`
  if (a == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::array>(a);
}

// The n values get(0) … get(n − 1) as a numpy array of T (double, std::int64_t or bool).
template <class T, class Get>
py::array_t<T> column(std::size_t n, const Get& get) {
  auto a = py::reinterpret_steal<py::array_t<T>>(empty_column(py::dtype::of<T>(), n).release());
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
  py::array a = empty_column(py::dtype("<U" + std::to_string(width)), n);
  auto* data = static_cast<char32_t*>(a.mutable_data());
  for (std::size_t k = 0; k < n; ++k) {
    char32_t* row = data + k * width;
    std::fill(write_code_points(get(k), row), row + width, U'\0');
  }
  return a;
}

}  // namespace vibro::python
