// Strict reading of JSON objects: every value is checked for type, and keys that nobody read
// are reported, so a typo ("alpah0") is an error, not a silent default. Errors carry the
// field's path as the scene spells it ("model.pellets[1].m").
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace vibro {

// Thrown inside io/ only; the public functions turn it into a FieldError value.
struct FieldException : std::runtime_error {
  FieldException(std::string field, const std::string& message)
      : std::runtime_error(message), field(std::move(field)) {}
  std::string field;
};

class Fields {
 public:
  // `json` must be an object, else FieldException naming `path`.
  Fields(const nlohmann::json& json, std::string path);

  std::optional<double> number(std::string_view key);
  double number(std::string_view key, double fallback);
  double required_number(std::string_view key);
  std::optional<long> integer(std::string_view key);
  bool boolean(std::string_view key, bool fallback);
  std::optional<std::string> string(std::string_view key, std::size_t max_length = 200);
  // The value under key if present (any type), marked as read.
  const nlohmann::json* value(std::string_view key);
  // An array under key, with at most max_items items.
  const nlohmann::json* array(std::string_view key, std::size_t max_items);

  std::string path(std::string_view key) const;
  // Throws for the first key that was never read.
  void done() const;

 private:
  const nlohmann::json& json_;
  std::string path_;
  // The keys asked for, in the order asked: a few to a few dozen, short (each within its
  // std::string, no allocation), so one reserved vector searched in turn costs less than a set.
  std::vector<std::string> read_;
};

// A key as a field path spells it: the empty key is `""`, so that a refusal still names a field.
inline std::string key_name(const std::string& key) { return key.empty() ? "\"\"" : key; }

// A number from a JSON value, naming `field` if it is not one.
double as_number(const nlohmann::json& v, const std::string& field);
long as_integer(const nlohmann::json& v, const std::string& field);

// "path[i]": the field path of an array's item.
std::string item(const std::string& path, std::size_t i);

// An index into a list of `count` (pellets, limiters) from a JSON value, naming `field` and
// `what` if it is not one.
int index_in(const nlohmann::json& v, const std::string& field, int count, const char* what);

}  // namespace vibro
