#include "io/json_fields.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vibro {

Fields::Fields(const nlohmann::json& json, std::string path) : json_(json), path_(std::move(path)) {
  if (!json_.is_object()) {
    throw FieldException(path_.empty() ? "scene" : path_, "must be a JSON object");
  }
  read_.reserve(16);
}

std::string Fields::path(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  std::string p;
  p.reserve(path_.size() + 1 + key.size());
  return p.append(path_).append(1, '.').append(key);
}

const nlohmann::json* Fields::value(std::string_view key) {
  if (std::find(read_.begin(), read_.end(), key) == read_.end()) read_.emplace_back(key);
  auto it = json_.find(key);
  if (it == json_.end() || it->is_null()) return nullptr;
  return &*it;
}

namespace {

// Why `v` is not a finite number, or null when it is one: the field's path is spelled out only
// for an error.
const char* not_a_number(const nlohmann::json& v) {
  if (!v.is_number()) return "must be a number";
  if (!std::isfinite(v.get<double>())) return "must be a finite number";
  return nullptr;
}

}  // namespace

double as_number(const nlohmann::json& v, const std::string& field) {
  if (const char* why = not_a_number(v)) throw FieldException(field, why);
  return v.get<double>();
}

long as_integer(const nlohmann::json& v, const std::string& field) {
  // Beyond ±1e9 in either sign: callers narrow to int, which would wrap -4294967232 to 64.
  if (v.is_number_unsigned()) {
    if (v.get<unsigned long long>() > 1000000000ULL) throw FieldException(field, "is out of range");
    return v.get<long>();
  }
  if (v.is_number_integer()) {
    const long i = v.get<long>();
    if (i < -1000000000L || i > 1000000000L) throw FieldException(field, "is out of range");
    return i;
  }
  if (v.is_number_float()) {
    const double x = v.get<double>();
    if (std::isfinite(x) && x == std::floor(x) && std::abs(x) <= 1e9) return static_cast<long>(x);
  }
  throw FieldException(field, "must be an integer");
}

std::optional<double> Fields::number(std::string_view key) {
  const nlohmann::json* v = value(key);
  if (!v) return std::nullopt;
  if (const char* why = not_a_number(*v)) throw FieldException(path(key), why);
  return v->get<double>();
}

double Fields::number(std::string_view key, double fallback) {
  return number(key).value_or(fallback);
}

double Fields::required_number(std::string_view key) {
  auto x = number(key);
  if (!x) throw FieldException(path(key), "is required (a number)");
  return *x;
}

std::optional<long> Fields::integer(std::string_view key) {
  const nlohmann::json* v = value(key);
  if (!v) return std::nullopt;
  return as_integer(*v, path(key));
}

bool Fields::boolean(std::string_view key, bool fallback) {
  const nlohmann::json* v = value(key);
  if (!v) return fallback;
  if (!v->is_boolean()) throw FieldException(path(key), "must be true or false");
  return v->get<bool>();
}

std::optional<std::string> Fields::string(std::string_view key, std::size_t max_length) {
  const nlohmann::json* v = value(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) throw FieldException(path(key), "must be a string");
  std::string s = v->get<std::string>();
  if (s.size() > max_length) {
    throw FieldException(path(key), "must be at most " + std::to_string(max_length) + " bytes");
  }
  return s;
}

const nlohmann::json* Fields::array(std::string_view key, std::size_t max_items) {
  const nlohmann::json* v = value(key);
  if (!v) return nullptr;
  if (!v->is_array()) throw FieldException(path(key), "must be an array");
  if (v->size() > max_items) {
    throw FieldException(path(key), "must have at most " + std::to_string(max_items) + " items");
  }
  return v;
}

namespace {

// Edit distance, to suggest the field a typo meant.
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

void Fields::done() const {
  for (auto it = json_.begin(); it != json_.end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) != read_.end()) continue;
    std::string message = "is not a known field here";
    std::string best;
    std::size_t best_distance = 3;  // suggest only close matches, the first in sorted order
    for (const std::string& known : read_) {
      const std::size_t d = distance(it.key(), known);
      if (d < best_distance || (d == best_distance && !best.empty() && known < best)) {
        best_distance = d;
        best = known;
      }
    }
    if (!best.empty()) message += " (did you mean \"" + best + "\"?)";
    throw FieldException(path(key_name(it.key())), message);
  }
}

std::string item(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

int index_in(const nlohmann::json& v, const std::string& field, int count, const char* what) {
  const long i = as_integer(v, field);
  if (i < 0 || i >= count) {
    throw FieldException(field, std::string("must be a ") + what + " index in 0.." +
                                    std::to_string(count - 1) + ", got " + std::to_string(i));
  }
  return static_cast<int>(i);
}

}  // namespace vibro
