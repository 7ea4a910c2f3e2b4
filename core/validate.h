// Checks a model and options before any work: every field for finiteness and range.
// A failure names the field the way the scene JSON spells it ("model.pellets[1].m").
#pragma once

#include <optional>
#include <string>

#include "core/model.h"
#include "core/sim_options.h"

namespace vibro {

struct FieldError {
  std::string field;
  std::string message;  // what was expected
};

// The shortest text that reads back as x, for messages: a value just past a bound shows how far.
std::string shortest_text(double x);

std::optional<FieldError> validate_model(const Model& model, const SimLimits& limits = {});
std::optional<FieldError> validate_options(const SimOptions& options, int pellets,
                                           const SimLimits& limits = {});

}  // namespace vibro
