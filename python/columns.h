// Columns of a table as numpy arrays, one value per row: what the module's results hold where the
// CSV exports have a column (API.md, "Exports").
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>

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

// numpy's functions the columns of one table are made with, looked up once for the table (an
// import is not free).
struct Numpy {
  Numpy() : module(py::module_::import("numpy")) {}
  py::module_ module;
  py::object array = module.attr("array");
  py::object empty = module.attr("empty");
};

// The n strings get(0) … as a numpy array of str.
template <class Get>
py::array string_column(const Numpy& np, std::size_t n, const Get& get) {
  py::list list(n);
  for (std::size_t k = 0; k < n; ++k) list[k] = py::str(std::string(get(k)));
  return np.array(list, py::arg("dtype") = "str");
}

// The n Python objects get(0) … as a numpy array of dtype object: what a column holds whose
// entries are lists (an event's pellets, its speeds), one tuple each.
template <class Get>
py::array object_column(const Numpy& np, std::size_t n, const Get& get) {
  py::array a = np.empty(n, py::arg("dtype") = "object");  // n references to None
  // Stored through the array's own pointers: an item assignment from C++ goes through Python's
  // indexing machinery, which costs more than the value it stores.
  auto** items = static_cast<PyObject**>(a.mutable_data());
  for (std::size_t k = 0; k < n; ++k) {
    PyObject* none = items[k];
    items[k] = py::object(get(k)).release().ptr();
    Py_XDECREF(none);
  }
  return a;
}

// A tuple of the items of a vector.
template <class T>
py::tuple tuple_of(const std::vector<T>& items) {
  py::tuple t(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) t[k] = py::cast(items[k]);
  return t;
}

}  // namespace vibro::python
