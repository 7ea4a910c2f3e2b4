// Bad usage as every `vibro` command reports it: {"error", "field"} as JSON on stderr, exit code 2,
// the field naming the option (or the scene field) at fault. The grammar itself is CLI11's; this
// turns its errors into that contract, and gives the value checks that fail with our messages.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "core/run/validate.h"

namespace vibro {

// Prints {"error": message, "field": field} as one line of JSON on stderr.
void print_error(const std::string& field, const std::string& message);

// The option a CLI11 parse error is about, and what was wrong with it: a value that failed a check
// below, or one that is missing ("needs a value").
FieldError field_error(const CLI::ParseError& error);

// A value for which `fits` holds, else `message`: the text as given, not converted.
CLI::Validator accepted_if(std::function<bool(const std::string&)> fits, std::string message);

// A finite number written whole (no trailing text, as std::from_chars reads it), for which `fits`
// holds; else `message`.
CLI::Validator number_where(std::function<bool(double)> fits, std::string message);

// A number in [lo, hi]: "must be a number in [lo, hi]" otherwise.
CLI::Validator number_in(double lo, double hi);

// A whole number in [lo, hi]: "must be an integer in [lo, hi]" otherwise. Rewrites the text as
// the integer ("8080.0", "1e3") so that an integer option converts it; use it with transform().
CLI::Validator integer_in(double lo, double hi);

}  // namespace vibro
