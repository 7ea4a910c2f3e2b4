// `vibro serve` flags: each sets one field of ServerConfig (docs/SERVER.md lists them).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/validate.h"
#include "server/config.h"

namespace vibro::server {

using ConfigOrError = std::variant<ServerConfig, FieldError>;

// Reads flags like "--port 8081 --max-t-end 100 --quiet"; an unknown flag, a missing value or
// one out of range is an error naming the flag.
ConfigOrError config_from_flags(const std::vector<std::string>& args);

// One line per flag, for `vibro serve --help`.
std::string flags_help();

}  // namespace vibro::server
