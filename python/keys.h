// Dict keys made once: a result's dicts (a run's summary, stats, events...) set their entries by
// str objects created and interned on first use and kept for the module's life, so that filling
// a dict neither makes a str nor hashes one per entry. They are constants, shared by every call
// and thread alike, like the interpreter's own interned names; never released (a Python object
// must not be freed after the interpreter is gone, as a static's destructor would).
#pragma once

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <new>

namespace vibro::python {

namespace py = pybind11;

// A string literal as a template argument: put<"atol">(d, value).
template <std::size_t N>
struct KeyText {
  char text[N];
  constexpr KeyText(const char (&s)[N]) { std::copy_n(s, N, text); }  // NOLINT: implicit by design
};

// The interned str of K. Call with the GIL held.
template <KeyText K>
PyObject* key() {
  static PyObject* const object = PyUnicode_InternFromString(K.text);
  if (object == nullptr) throw std::bad_alloc();
  return object;
}

// d[K] = value.
template <KeyText K>
void put(py::dict& d, const py::handle& value) {
  if (PyDict_SetItem(d.ptr(), key<K>(), value.ptr()) != 0) throw py::error_already_set();
}

}  // namespace vibro::python
