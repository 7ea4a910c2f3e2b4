#include "python/json_values.h"

#include <string>

#include "python/scene_error.h"

namespace vibro::python {
namespace {

using nlohmann::json;

// Where a value is, as the scene's field paths spell it: "model.pellets[0].m".
std::string member_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

json integer_json(py::handle value, const std::string& path) {
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
    raise_scene_error({path.empty() ? "scene" : path, "is an integer beyond a double's range"});
  }
  return json(d);
}

json convert(py::handle value, const std::string& path, int depth, int max_depth) {
  if (value.is_none()) return json(nullptr);
  if (PyBool_Check(value.ptr())) return json(value.ptr() == Py_True);
  if (PyLong_Check(value.ptr())) return integer_json(value, path);
  if (PyFloat_Check(value.ptr())) return json(PyFloat_AS_DOUBLE(value.ptr()));
  if (PyUnicode_Check(value.ptr())) return json(value.cast<std::string>());
  const bool dict = PyDict_Check(value.ptr());
  if (dict || PyList_Check(value.ptr()) || PyTuple_Check(value.ptr())) {
    if (depth + 1 > max_depth)
      raise_scene_error({"scene", "nests deeper than " + std::to_string(max_depth) + " levels"});
    if (!dict) {
      json list = json::array();
      std::size_t i = 0;
      for (py::handle item : value)
        list.push_back(convert(item, path + "[" + std::to_string(i++) + "]", depth + 1, max_depth));
      return list;
    }
    json object = json::object();
    for (auto [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!PyUnicode_Check(key.ptr()))
        raise_scene_error({path.empty() ? "scene" : path,
                           "has a key that is not a string: " + py::repr(key).cast<std::string>()});
      const std::string name = key.cast<std::string>();
      object[name] = convert(item, member_path(path, name), depth + 1, max_depth);
    }
    return object;
  }
  // numpy's scalars and arrays say what they hold as Python values.
  if (py::hasattr(value, "tolist") && py::hasattr(value, "dtype"))
    return convert(value.attr("tolist")(), path, depth, max_depth);
  raise_scene_error({path.empty() ? "scene" : path,
                     "is a Python " +
                         py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>() +
                         ", which a JSON scene cannot hold"});
}

}  // namespace

json json_from_python(py::handle value, int max_depth) { return convert(value, "", 0, max_depth); }

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
