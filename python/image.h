// Drawn figures handed to Python: vibro.Image (python/vibro/__init__.py), the bytes of a PNG, SVG
// or PDF that a notebook shows (_repr_png_, _repr_svg_).
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "render/figure.h"

namespace vibro::python {

namespace py = pybind11;

// The format a `format` argument names ("png", "svg" or "pdf"); raises SceneError naming "format".
ImageFormat image_format(const std::string& name);

// The figure as a vibro.Image; raises SceneError with the figure's error.
py::object image_of(const RenderResult& drawn, ImageFormat format);

}  // namespace vibro::python
