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

// A new column of n values of T (double, std::int64_t or bool) to fill row by row, for tables
// whose columns are best filled together in one pass over the rows.
template <class T>
class Column {
 public:
  explicit Column(std::size_t n)
      : array_(empty_column(py::dtype::of<T>(), n)),
        data_(static_cast<T*>(array_.mutable_data())) {}
  T& operator[](std::size_t row) { return data_[row]; }
  const py::array& array() const { return array_; }

 private:
  py::array array_;
  T* data_;
};

// A column of str whose rows repeat a few names (an enum's names from a static table), filled
// row by row: note() every name first (the width is the longest, numpy's '<U' of it, as
// string_column makes it), then allocate(n), then set() each row. Each distinct name, known by
// its text's address, is decoded once and copied to its other rows; past kDistinct names the
// others are decoded row by row. A name's text must stay in place until the column is made.
class NameColumn {
 public:
  void note(std::string_view name) {
    const Seen* s = seen(name);
    width_ = std::max(width_, s ? s->code_points : code_point_count(name));
  }
  void allocate(std::size_t n) {
    array_ = empty_column(py::dtype("<U" + std::to_string(width_)), n);
    data_ = static_cast<char32_t*>(array_.mutable_data());
  }
  void set(std::size_t row, std::string_view name) {
    char32_t* out = data_ + row * width_;
    Seen* s = seen(name);
    if (s && s->row != kNone) {
      std::copy_n(data_ + s->row * width_, width_, out);
      return;
    }
    std::fill(write_code_points(name, out), out + width_, U'\0');
    if (s) s->row = row;
  }
  const py::array& array() const { return array_; }

 private:
  static constexpr std::size_t kDistinct = 16;
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Seen {
    const char* text;
    std::size_t size, code_points, row;  // row: the first row set to it, kNone before
  };
  // The name's entry, made on first sight; null when the table is full.
  Seen* seen(std::string_view name) {
    for (std::size_t i = 0; i < count_; ++i)
      if (seen_[i].text == name.data() && seen_[i].size == name.size()) return &seen_[i];
    if (count_ == kDistinct) return nullptr;
    seen_[count_] = {name.data(), name.size(), code_point_count(name), kNone};
    return &seen_[count_++];
  }

  Seen seen_[kDistinct];
  std::size_t count_ = 0;
  std::size_t width_ = 1;  // numpy's narrowest str
  py::array array_;
  char32_t* data_ = nullptr;
};

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
