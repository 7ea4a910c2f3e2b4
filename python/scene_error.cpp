#include "python/scene_error.h"

#include "python/bindings.h"

namespace vibro::python {
namespace {

// The exception type, made once when the module is imported. Never released: a Python object
// must not be freed after the interpreter is gone, as a static's destructor would.
PyObject* scene_error_type = nullptr;

}  // namespace

void add_scene_error(py::module_& m) {
  scene_error_type = PyErr_NewExceptionWithDoc(
      "vibro.SceneError",
      "A scene the engine refuses: .field names the field as the JSON scene spells it, .message "
      "says what was expected (the HTTP 400 answer's message).",
      PyExc_ValueError, nullptr);
  if (scene_error_type == nullptr) throw py::error_already_set();
  m.add_object("SceneError", py::handle(scene_error_type).inc_ref());
}

void raise_scene_error(const FieldError& error) {
  py::object type = py::reinterpret_borrow<py::object>(scene_error_type);
  py::object e = type(error.field + ": " + error.message);
  e.attr("field") = error.field;
  e.attr("message") = error.message;
  PyErr_SetObject(scene_error_type, e.ptr());
  throw py::error_already_set();
}

}  // namespace vibro::python
