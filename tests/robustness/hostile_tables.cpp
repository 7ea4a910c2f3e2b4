// The hand-written hostile classes: values out of range, nesting, long strings, duplicate
// keys, unicode, and bodies that are not a scene at all.
#include <string>
#include <vector>

#include "tests/robustness/hostile_cases.h"
#include "tests/robustness/hostile_full_scene.h"

namespace vibro::robustness {

using nlohmann::json;

namespace {

HostileCase set(const std::string& pointer, const std::string& raw, const std::string& field) {
  return {pointer + " = " + raw.substr(0, 40),
          with_raw(full_scene(), json::json_pointer(pointer), raw), field};
}

std::string repeat(const std::string& s, std::size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (std::size_t i = 0; i < n; ++i) out += s;
  return out;
}

// A small valid scene with `model_extra` spliced into the model object.
std::string with_model_key(const std::string& model_extra) {
  return R"({"model": {"R": 0.5, "pellets": [{"m": 1, "phi0": 0}], )" + model_extra +
         R"(}, "t_end": 1})";
}

}  // namespace

std::vector<HostileCase> out_of_range_cases() {
  return {
      set("/model/R", "0", "model.R"),
      set("/model/R", "-0.5", "model.R"),
      set("/model/R", "-0.0", "model.R"),
      set("/model/R", "1e7", "model.R"),
      set("/model/R", "1e-999", "model.R"),  // underflows to 0
      set("/model/g", "-9.81", "model.g"),
      set("/model/g", "1e5", "model.g"),
      set("/model/alpha0", "-0.1", "model.alpha0"),
      set("/model/alpha0", "1.5707963267948966", "model.alpha0"),  // π/2: mu infinite
      set("/model/mu_s", "0.01", "model.mu_s"),                    // below mu
      set("/model/k_c", "-0.1", "model.k_c"),
      set("/model/k_c", "1.5", "model.k_c"),
      set("/model/pellets/0/m", "0", "model.pellets[0].m"),
      set("/model/pellets/0/m", "-1", "model.pellets[0].m"),
      set("/model/pellets/0/m", "1e13", "model.pellets[0].m"),
      set("/model/pellets/0/phi0", "1e5", "model.pellets[0].phi0"),
      set("/model/pellets/0/dphi0", "-1e8", "model.pellets[0].dphi0"),
      set("/model/pellets/0/F0", "1e13", "model.pellets[0].F0"),
      set("/model/pellets/0/Omega", "2e9", "model.pellets[0].Omega"),
      set("/model/pellets/0/psi", "-1e5", "model.pellets[0].psi"),
      set("/model/pellets/0/c", "-0.1", "model.pellets[0].c"),
      set("/model/pellets/0/c", "2e6", "model.pellets[0].c"),
      set("/model/pellets/1/phi0", "6.383185307179586", "model.pellets[1].phi0"),  // = pellet 0
      set("/model/pellets", "[" + repeat(R"({"m": 1, "phi0": 0.1},)", 8) + "{}]", "model.pellets"),
      set("/model/limiters/0/k", "-0.1", "model.limiters[0].k"),
      set("/model/limiters/0/k", "1.1", "model.limiters[0].k"),
      set("/model/limiters/0/angle", "1e5", "model.limiters[0].angle"),
      set("/model/limiters/0/rearm_by", "0", "model.limiters[0].rearm_by"),  // itself
      set("/model/limiters/0/rearm_by", "2", "model.limiters[0].rearm_by"),
      set("/model/limiters/0/rearm_by", "-1", "model.limiters[0].rearm_by"),
      set("/model/limiters/0/rearm_by", "-4294967295", "model.limiters[0].rearm_by"),  // wraps to 1
      set("/model/limiters/1/rearm_by", "0", "model.limiters[1].rearm_by"),            // not mobile
      set("/model/limiters/0/pellets", "[5]", "model.limiters[0].pellets[0]"),
      set("/model/limiters/0/pellets", "[-1]", "model.limiters[0].pellets[0]"),
      set("/model/limiters/0/pellets", "[0, 0]", "model.limiters[0].pellets[1]"),
      set("/model/limiters", "[" + repeat(R"({"angle": 1, "k": 1},)", 16) + "{}]",
          "model.limiters"),
      set("/t_end", "0", "t_end"),
      set("/t_end", "-1", "t_end"),
      set("/t_end", "1e7", "t_end"),
      set("/solver/rtol", "0", "solver.rtol"),
      set("/solver/rtol", "1", "solver.rtol"),
      set("/solver/atol", "-1", "solver.atol"),
      set("/solver/atol", "2", "solver.atol"),
      set("/plots/0/pellet", "2", "plots[0].pellet"),
      set("/plots/0/pellet", "-1", "plots[0].pellet"),
      set("/plots/0/pellet", "-4294967296", "plots[0].pellet"),
      set("/plots/0/pellet", "18446744073709551615", "plots[0].pellet"),
      set("/plots/0/pellet", "1e300", "plots[0].pellet"),
      set("/plots/0/branches", "[0]", "plots[0].branches[0]"),
      set("/plots/0/branches", "[-3]", "plots[0].branches[0]"),
      set("/plots/0/t_from", "-1", "plots[0].t_from"),
      set("/plots/0/t_to", "0", "plots[0].t_to"),
      set("/plots/1/pellets", "[]", "plots[1].pellets"),
      set("/plots/1/pellets", "[2]", "plots[1].pellets[0]"),
      set("/plots/2/camera/elevation", "90", "plots[2].camera.elevation"),
      set("/plots/2/camera/distance", "1", "plots[2].camera.distance"),
      set("/plots/2/camera/distance", "51", "plots[2].camera.distance"),
      set("/plots", "[" + repeat(R"({"kind": "phase"},)", 8) + "{}]", "plots"),
      set("/width", "0", "width"),
      set("/width", "-1", "width"),
      set("/width", "63", "width"),
      set("/width", "4097", "width"),
      set("/width", "-4294967232", "width"),  // wraps to 64
      set("/width", "4294967360", "width"),
      set("/height", "100000", "height"),
  };
}

std::vector<HostileCase> deep_nesting_cases() {
  std::vector<HostileCase> cases;
  for (std::size_t depth : {17, 1000, 100000, 1000000}) {
    const std::string n = std::to_string(depth);
    cases.push_back({"arrays " + n + " deep", repeat("[", depth) + repeat("]", depth), "scene"});
    cases.push_back(
        {"objects " + n + " deep", repeat(R"({"a":)", depth) + "1" + repeat("}", depth), "scene"});
    cases.push_back({"model.pellets " + n + " deep",
                     with_raw(full_scene(), json::json_pointer("/model/pellets"),
                              repeat("[", depth) + repeat("]", depth)),
                     "scene"});
    cases.push_back({"unclosed arrays " + n + " deep", repeat("[", depth), "scene"});
  }
  return cases;
}

std::vector<HostileCase> long_string_cases() {
  const std::string mb = repeat("x", 1 << 20);
  const std::string q = "\"";
  return {
      set("/name", q + repeat("x", 65) + q, "name"),
      set("/name", q + mb + q, "name"),
      set("/description", q + repeat("x", 2001) + q, "description"),
      set("/assumptions/0", q + repeat("x", 2001) + q, "assumptions[0]"),
      set("/plots/0/title", q + repeat("x", 201) + q, "plots[0].title"),
      set("/plots/0/title", q + repeat("\\u00e9", 1 << 17) + q, "plots[0].title"),
      set("/model/friction", q + repeat("x", 33) + q, "model.friction"),
      set("/model/friction", q + mb + q, "model.friction"),
      set("/solver/method", q + mb + q, "solver.method"),
      set("/plots/0/kind", q + mb + q, "plots[0].kind"),
      {"a 1 MB unknown key", with_model_key(q + mb + q + ": 1"), "model." + mb},
  };
}

std::vector<HostileCase> duplicate_key_cases() {
  return {
      {"R twice, the last negative", with_model_key(R"("R": -1)"), "model.R"},
      {"t_end twice, the last a string",
       R"({"model": {"R": 1, "pellets": [{"m": 1, "phi0": 0}]}, "t_end": 1, "t_end": "2"})",
       "t_end"},
      {"model twice, the last without pellets",
       R"({"model": {"R": 1, "pellets": [{"m": 1, "phi0": 0}]}, "model": {"R": 1}, "t_end": 1})",
       "model"},
      {"an unknown key twice", with_model_key(R"("zz": 1, "zz": 2)"), "model.zz"},
      {"kind twice, the last unknown",
       R"({"model": {"R": 1, "pellets": [{"m": 1, "phi0": 0}]}, "t_end": 1,
           "plots": [{"kind": "phase", "kind": "pie"}]})",
       "plots[0].kind"},
  };
}

std::vector<HostileCase> unicode_key_cases() {
  std::vector<HostileCase> cases;
  // Unknown keys in many scripts: named back exactly, in valid UTF-8.
  const std::string nul("R\0", 2);
  for (const std::string& key :
       {std::string("φ"), std::string("Ｒ"), std::string("R\u200b"), std::string("\u202eR"),
        std::string("🎯"), std::string("m\u0301"), std::string("ℝ"), nul}) {
    const std::string escaped = json(key).dump();
    cases.push_back({"key " + escaped, with_model_key(escaped + ": 1"), "model." + key});
  }
  cases.push_back({"the empty key", R"({"": 1, "model": {"R": 1, "pellets": [{"m": 1, "phi0": 0}]},
                                       "t_end": 1})",
                   "\"\""});
  cases.push_back({"the empty key in the model", with_model_key(R"("": 1)"), "model.\"\""});
  cases.push_back({"an escaped surrogate pair", with_model_key(R"("\ud83c\udfaf": 1)"), "model.🎯"});
  cases.push_back(
      {"a look-alike value", with_model_key(R"("friction": "p\u0430per")"), "model.friction"});
  // Not UTF-8, or not well-formed: not JSON at all.
  cases.push_back({"a lone surrogate", with_model_key(R"("\ud800": 1)"), "scene"});
  cases.push_back({"a raw 0xFF byte", with_model_key("\"R\xff\": 1"), "scene"});
  cases.push_back({"an overlong '/'", with_model_key("\"\xc0\xaf\": 1"), "scene"});
  cases.push_back({"a truncated sequence", with_model_key("\"\xe2\x82\": 1"), "scene"});
  return cases;
}

std::vector<HostileCase> empty_body_cases() {
  const std::string full = full_scene().dump();
  return {
      {"empty", "", "scene"},
      {"spaces", " \n\t ", "scene"},
      {"a NUL byte", std::string(1, '\0'), "scene"},
      {"a byte-order mark only", "\xef\xbb\xbf", "scene"},
      {"null", "null", "scene"},
      {"a number", "0", "scene"},
      {"an array", "[]", "scene"},
      {"a string", "\"scene\"", "scene"},
      {"true", "true", "scene"},
      {"an empty object", "{}", "model"},
      {"a comment", "/* c */" + full, "scene"},
      {"trailing data", full + " {}", "scene"},
      {"truncated by half", full.substr(0, full.size() / 2), "scene"},
      {"truncated by one byte", full.substr(0, full.size() - 1), "scene"},
  };
}

}  // namespace vibro::robustness
