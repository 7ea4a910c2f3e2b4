// Hostile scenes, by class: each is refused with a FieldError that names the field (or
// "scene" for the document as a whole), never a crash, and the error itself can be sent as
// JSON. The counts per class go to docs/ROBUSTNESS.md; each test prints its own.
#include <gtest/gtest.h>

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/scene_json.h"
#include "tests/robustness/hostile_cases.h"

namespace vibro::robustness {
namespace {

using nlohmann::json;

// Reads every case and checks the field it names; prints the class's count.
void expect_refused(const std::string& name, const std::vector<HostileCase>& cases) {
  for (const HostileCase& c : cases) {
    SCOPED_TRACE(name + ": " + c.what);
    const SceneOrError r = scene_from_text(c.text);
    const FieldError* e = std::get_if<FieldError>(&r);
    if (!e) {
      ADD_FAILURE() << "accepted";
      continue;
    }
    EXPECT_EQ(e->field, c.field) << e->message;
    EXPECT_FALSE(e->message.empty());
    // What the server would answer: it must serialize (valid UTF-8), and never be much
    // larger than the request.
    std::string body;
    EXPECT_NO_THROW(body = json({{"error", e->message}, {"field", e->field}}).dump());
    EXPECT_LE(body.size(), c.text.size() + 512);
  }
  std::cout << "[ class    ] " << name << ": " << cases.size() << " cases\n";
}

TEST(HostileScenes, WrongJsonTypeForEveryField) {
  expect_refused("wrong JSON type for every field", wrong_type_cases());
}
TEST(HostileScenes, NanAndInfinitySpelledEveryWay) {
  expect_refused("NaN and infinity", non_finite_cases());
}
TEST(HostileScenes, NegativeZeroAndOutOfRangeSizes) {
  expect_refused("negative, zero, out-of-range", out_of_range_cases());
}
TEST(HostileScenes, MillionElementArrays) {
  expect_refused("10^6-element arrays", huge_array_cases());
}
TEST(HostileScenes, DeeplyNestedJson) { expect_refused("deep nesting", deep_nesting_cases()); }
TEST(HostileScenes, VeryLongStrings) { expect_refused("long strings", long_string_cases()); }
TEST(HostileScenes, DuplicateKeys) { expect_refused("duplicate keys", duplicate_key_cases()); }
TEST(HostileScenes, UnicodeInKeys) { expect_refused("unicode in keys", unicode_key_cases()); }
TEST(HostileScenes, EmptyAndNonObjectBodies) {
  expect_refused("empty and non-object bodies", empty_body_cases());
}

// A key given twice is refused, even when both values are good: JSON would keep the last
// silently, and a script that sets "R" twice means one of them.
TEST(HostileScenes, DuplicateKeysAreRefusedEvenWithGoodValues) {
  const SceneOrError r = scene_from_text(
      R"({"model": {"R": 0.5, "R": 0.25, "pellets": [{"m": 1, "phi0": 0}]}, "t_end": 1})");
  ASSERT_TRUE(std::holds_alternative<FieldError>(r));
  EXPECT_EQ(std::get<FieldError>(r).field, "model.R");
  EXPECT_EQ(std::get<FieldError>(r).message, "appears twice");
}

}  // namespace
}  // namespace vibro::robustness
