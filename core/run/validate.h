// Checks a model and options before any work: every field for finiteness and range, and the
// counts and the time span against a Limits (core/run/limits.h). A failure names the field the
// way the scene JSON spells it ("model.pellets[1].m").
#pragma once

#include <optional>
#include <string>

#include "core/model/model.h"
#include "core/run/limits.h"
#include "core/run/sim_options.h"

namespace vibro {

struct FieldError {
  std::string field;
  std::string message;  // what was expected
};

// The shortest text that reads back as x, for messages: a value just past a bound shows how far.
std::string shortest_text(double x);

// The largest angle (rad) and angular speed (rad/s) a pellet may start with: phi0 and dphi0, and
// every state a search starts from or steps to. Past them an angle keeps too few digits below the
// turn for its motion to mean anything (2π at 1e4 rad is resolved to 1e-12 rad).
constexpr double kMaxStartAngle = 1e4;
constexpr double kMaxStartSpeed = 1e7;
// Viscous damping, 1/s: a pellet stops within 1 µs at most.
constexpr double kMaxDamping = 1e6;

// A pellet's state {phi, dphi} checked against those bounds; the error names `field`.phi or .dphi.
std::optional<FieldError> validate_state(const std::string& field, double phi, double dphi);

std::optional<FieldError> validate_model(const Model& model, const Limits& limits = {});
std::optional<FieldError> validate_options(const SimOptions& options, int pellets,
                                           const Limits& limits = {});

}  // namespace vibro
