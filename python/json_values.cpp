#include "python/json_values.h"

#include <string>

#include "python/scene_error.h"

namespace vibro::python {
namespace {

using nlohmann::json;

// Where a value is in the scene: a chain from the top, spelled out only for an error as the
// scene's field paths are ("model.pellets[0].m"), since most values are never named.
struct Where {
  const Where* parent = nullptr;
  const std::string* key = nullptr;  // a dict's member: its key; else a list's item
  std::size_t index = 0;
};

std::string path_of(const Where* w) {
  if (w == nullptr) return "";
  const std::string above = path_of(w->parent);
  if (w->key) return above.empty() ? *w->key : above + "." + *w->key;
  return above + "[" + std::to_string(w->index) + "]";
}

// The field an error names: the value's path, "scene" for the scene itself.
std::string field_of(const Where* w) { return w == nullptr ? "scene" : path_of(w); }

json integer_json(py::handle value, const Where* where) {
  int overflow = 0;
  const long long x = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (overflow == 0) {
    if (x == -1 && PyErr_Occurred()) throw py::error_already_set();
    return json(static_cast<std::int64_t>(x));
  }
  if (overflow > 0) {
    const unsigned long long u = PyLong_AsUnsignedLongLong(value.ptr());
    if (!PyErr_Occurred()) return json(static_cast<std::uint64_t>(u));
    PyErr_Clear();
  }
  const double d = PyLong_AsDouble(value.ptr());
  if (d == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    raise_scene_error({field_of(where), "is an integer beyond a double's range"});
  }
  return json(d);
}

// A str's text as UTF-8, read in place (Python keeps a str's UTF-8 once made). Raises SceneError
// naming the str's place (a key: its dict's) for a str UTF-8 cannot hold (a lone surrogate).
std::string utf8_of(PyObject* str, const Where* where) {
  Py_ssize_t size = 0;
  const char* text = PyUnicode_AsUTF8AndSize(str, &size);
  if (text == nullptr) {
    PyErr_Clear();
    raise_scene_error({field_of(where), "is a string that is not Unicode text (a lone surrogate)"});
  }
  return std::string(text, static_cast<std::size_t>(size));
}

void convert_items(PyObject* v, nlohmann::json& out, const Where* where, int depth, int max_depth);
void convert_members(PyObject* v, nlohmann::json& out, const Where* where, int depth,
                     int max_depth);

// Converts `value` into `out` (null before), in place: a container's items are made where they
// stay, not built apart and moved in.
void convert(py::handle value, json& out, const Where* where, int depth, int max_depth) {
  PyObject* const v = value.ptr();
  if (v == Py_None) return;
  if (PyBool_Check(v)) {
    out = v == Py_True;
  } else if (PyLong_Check(v)) {
    out = integer_json(value, where);
  } else if (PyFloat_Check(v)) {
    out = PyFloat_AS_DOUBLE(v);
  } else if (PyUnicode_Check(v)) {
    out = utf8_of(v, where);
  } else if (PyDict_Check(v) || PyList_Check(v) || PyTuple_Check(v)) {
    if (depth + 1 > max_depth)
      raise_scene_error({"scene", "nests deeper than " + std::to_string(max_depth) + " levels"});
    if (PyDict_Check(v))
      convert_members(v, out, where, depth, max_depth);
    else
      convert_items(v, out, where, depth, max_depth);
  } else if (py::hasattr(value, "tolist") && py::hasattr(value, "dtype")) {
    // numpy's scalars and arrays say what they hold as Python values.
    convert(value.attr("tolist")(), out, where, depth, max_depth);
  } else {
    raise_scene_error(
        {field_of(where),
         "is a Python " + py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>() +
             ", which a JSON scene cannot hold"});
  }
}

// A list's or a tuple's items, read in place, each held while it is converted; the size read
// again after each, as converting a value (numpy's tolist) may run code that changes the list.
void convert_items(PyObject* v, json& out, const Where* where, int depth, int max_depth) {
  const bool list = PyList_Check(v);
  const auto size = [&] { return list ? PyList_GET_SIZE(v) : PyTuple_GET_SIZE(v); };
  out = json::array();
  auto& items = out.get_ref<json::array_t&>();
  items.reserve(static_cast<std::size_t>(size()));
  for (Py_ssize_t i = 0; i < size(); ++i) {
    const auto item =
        py::reinterpret_borrow<py::object>(list ? PyList_GET_ITEM(v, i) : PyTuple_GET_ITEM(v, i));
    const Where item_at{where, nullptr, static_cast<std::size_t>(i)};
    items.emplace_back();
    convert(item, items.back(), &item_at, depth + 1, max_depth);
  }
}

// A dict's members, each key and value held while the value is converted.
void convert_members(PyObject* v, json& out, const Where* where, int depth, int max_depth) {
  out = json::object();
  auto& members = out.get_ref<json::object_t&>();
  PyObject *key = nullptr, *value_at = nullptr;
  for (Py_ssize_t at = 0; PyDict_Next(v, &at, &key, &value_at);) {
    const auto held_key = py::reinterpret_borrow<py::object>(key);
    const auto item = py::reinterpret_borrow<py::object>(value_at);
    if (!PyUnicode_Check(key))
      raise_scene_error({field_of(where),
                         "has a key that is not a string: " + py::repr(key).cast<std::string>()});
    auto [member, fresh] = members.try_emplace(utf8_of(key, where));
    if (!fresh) member->second = nullptr;  // two keys of one text: the last one's value, as before
    const Where member_at{where, &member->first};
    convert(item, member->second, &member_at, depth + 1, max_depth);
  }
}

}  // namespace

json json_from_python(py::handle value, int max_depth) {
  json out;
  convert(value, out, nullptr, 0, max_depth);
  return out;
}

py::object python_from_json(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return py::none();
    case json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case json::value_t::number_float:
      return py::float_(j.get<double>());
    case json::value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case json::value_t::array: {
      py::list list(j.size());
      for (std::size_t i = 0; i < j.size(); ++i) list[i] = python_from_json(j[i]);
      return list;
    }
    case json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : j.items()) dict[py::str(key)] = python_from_json(item);
      return dict;
    }
    default:  // binary and discarded values: the engine's JSON has none
      return py::none();
  }
}

}  // namespace vibro::python
