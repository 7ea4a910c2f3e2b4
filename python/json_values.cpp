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

json convert(py::handle value, const Where* where, int depth, int max_depth) {
  if (value.is_none()) return json(nullptr);
  if (PyBool_Check(value.ptr())) return json(value.ptr() == Py_True);
  if (PyLong_Check(value.ptr())) return integer_json(value, where);
  if (PyFloat_Check(value.ptr())) return json(PyFloat_AS_DOUBLE(value.ptr()));
  if (PyUnicode_Check(value.ptr())) return json(value.cast<std::string>());
  const bool dict = PyDict_Check(value.ptr());
  if (dict || PyList_Check(value.ptr()) || PyTuple_Check(value.ptr())) {
    if (depth + 1 > max_depth)
      raise_scene_error({"scene", "nests deeper than " + std::to_string(max_depth) + " levels"});
    if (!dict) {
      json list = json::array();
      Where item_at{where, nullptr, 0};
      for (py::handle item : value) {
        list.push_back(convert(item, &item_at, depth + 1, max_depth));
        ++item_at.index;
      }
      return list;
    }
    json object = json::object();
    for (auto [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!PyUnicode_Check(key.ptr()))
        raise_scene_error({field_of(where),
                           "has a key that is not a string: " + py::repr(key).cast<std::string>()});
      const std::string name = key.cast<std::string>();
      const Where member{where, &name};
      object[name] = convert(item, &member, depth + 1, max_depth);
    }
    return object;
  }
  // numpy's scalars and arrays say what they hold as Python values.
  if (py::hasattr(value, "tolist") && py::hasattr(value, "dtype"))
    return convert(value.attr("tolist")(), where, depth, max_depth);
  raise_scene_error({field_of(where),
                     "is a Python " +
                         py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>() +
                         ", which a JSON scene cannot hold"});
}

}  // namespace

json json_from_python(py::handle value, int max_depth) {
  return convert(value, nullptr, 0, max_depth);
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
