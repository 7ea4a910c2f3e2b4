// An array of many objects is refused by its size at a cost linear in its length: the parse
// that once looked back through an array after each of its objects took 5 s for 2·10^5 of them.
// The test bounds the time generously (a hang, not a speed target) and compares two lengths,
// where a quadratic cost grows 16-fold and a linear one 4-fold.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>

#include "io/scene_json.h"
#include "tests/robustness/hostile_full_scene.h"

namespace vibro::robustness {
namespace {

using nlohmann::json;

// The full scene with the array at `pointer` replaced by `count` copies of `item`.
std::string with_objects(const std::string& pointer, const std::string& item, int count) {
  std::string array = "[" + item;
  array.reserve((item.size() + 1) * count + 2);
  for (int i = 1; i < count; ++i) array += "," + item;
  return with_raw(full_scene(), json::json_pointer(pointer), array + "]");
}

// The shortest of three reads of `text`, s; each must be refused naming `field`.
double refusal_seconds(const std::string& text, const std::string& field) {
  double best = 1e9;
  for (int k = 0; k < 3; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const SceneOrError read = scene_from_text(text);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    const auto* e = std::get_if<FieldError>(&read);
    EXPECT_TRUE(e && e->field == field) << (e ? e->field + ": " + e->message : "accepted");
    best = std::min(best, took.count());
  }
  return best;
}

TEST(LongArrays, ArraysOfObjectsAreRefusedInLinearTime) {
  const struct {
    const char* pointer;
    const char* field;
    const char* item;
  } arrays[] = {
      {"/model/pellets", "model.pellets", R"({"m":1,"phi0":0.5})"},
      {"/model/limiters", "model.limiters", R"({"angle":1,"k":0.5})"},
      {"/plots", "plots", R"({"kind":"phase","pellet":0})"},
  };
  for (const auto& a : arrays) {
    SCOPED_TRACE(a.field);
    const double small = refusal_seconds(with_objects(a.pointer, a.item, 50000), a.field);
    const double large = refusal_seconds(with_objects(a.pointer, a.item, 200000), a.field);
    EXPECT_LT(large, 5.0);  // generous: sanitizer builds on a busy machine
    // Four times the items: about four times the time when linear, sixteen when quadratic.
    EXPECT_LT(large, 9.0 * std::max(small, 1e-3)) << small << " s, then " << large << " s";
  }
}

}  // namespace
}  // namespace vibro::robustness
