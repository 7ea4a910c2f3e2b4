// A model's numeric fields named by path, as a sweep varies them: "model.R",
// "model.pellets[0].F0", "model.limiters[1].angle" (the spelling of the scene's JSON and of its
// error messages).
#pragma once

#include <optional>
#include <string>

#include "core/model/model.h"

namespace vibro {

// Sets the field at `path` to `value`. Returns why not when the path names no numeric field of
// this model (an unknown name, or an index past the pellets or limiters).
std::optional<std::string> set_parameter(Model& model, const std::string& path, double value);

// The field at `path` in `model`, or null when the path names none: for setting it many times
// (a sweep checking each of its values). Valid while the model's lists keep their sizes.
double* parameter_field(Model& model, const std::string& path);

// The field's value, if the path names one.
std::optional<double> get_parameter(const Model& model, const std::string& path);

}  // namespace vibro
