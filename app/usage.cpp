#include "app/usage.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

namespace vibro {
namespace {

std::optional<double> parse_number(std::string_view text) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) return {};
  return x;
}

std::string text_of(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  return text;
}

std::string range_of(double lo, double hi) { return "[" + text_of(lo) + ", " + text_of(hi) + "]"; }

}  // namespace

void print_error(const std::string& field, const std::string& message) {
  std::cerr << nlohmann::json{{"error", message}, {"field", field}}.dump() << "\n";
}

FieldError field_error(const CLI::ParseError& error) {
  // CLI11 2.1 carries no option in its exceptions, only in their text (its Error.hpp): a failed
  // check and a missing value read "--name: what", a value a flag cannot take
  // "Could not convert: --name = value".
  const std::string what = error.what();
  const std::string unconverted = "Could not convert: ";
  if (what.starts_with(unconverted)) {
    const std::size_t equals = what.find(" = ", unconverted.size());
    if (equals != std::string::npos) {
      return {what.substr(unconverted.size(), equals - unconverted.size()),
              "cannot take the value \"" + what.substr(equals + 3) + "\""};
    }
  }
  const std::size_t colon = what.find(": ");
  if (what.starts_with("-") && colon != std::string::npos) {
    const std::string option = what.substr(0, colon);
    if (error.get_name() == "ArgumentMismatch") return {option, "needs a value"};
    return {option, what.substr(colon + 2)};
  }
  return {"command line", what};
}

CLI::Validator accepted_if(std::function<bool(const std::string&)> fits, std::string message) {
  return CLI::Validator([fits = std::move(fits), message = std::move(message)](
                            std::string& text) { return fits(text) ? std::string() : message; },
                        "");
}

CLI::Validator number_where(std::function<bool(double)> fits, std::string message) {
  return accepted_if(
      [fits = std::move(fits)](const std::string& text) {
        const auto x = parse_number(text);
        return x && fits(*x);
      },
      std::move(message));
}

CLI::Validator number_in(double lo, double hi) {
  return number_where([=](double x) { return x >= lo && x <= hi; },
                      "must be a number in " + range_of(lo, hi));
}

CLI::Validator integer_in(double lo, double hi) {
  const std::string message = "must be an integer in " + range_of(lo, hi);
  return CLI::Validator(
      [=](std::string& text) {
        const auto x = parse_number(text);
        if (!x || *x < lo || *x > hi || *x != std::floor(*x)) return message;
        text = text_of(*x);
        return std::string();
      },
      "");
}

}  // namespace vibro
