#include "io/scene_json.h"

#include <cmath>
#include <set>

#include "io/figure_json.h"
#include "io/json_fields.h"
#include "io/orbit_json.h"
#include "io/plot_json.h"
#include "io/sweep_json.h"
#include "render/figure_size.h"

namespace vibro {
namespace {

using nlohmann::json;

Pellet read_pellet(const json& j, const std::string& path) {
  Fields f(j, path);
  Pellet p;
  p.m = f.required_number("m");
  p.phi0 = f.required_number("phi0");
  p.dphi0 = f.number("dphi0", 0.0);
  p.c = f.number("c", 0.0);
  p.force.F0 = f.number("F0", 0.0);
  p.force.Omega = f.number("Omega", 0.0);
  p.force.psi = f.number("psi", 0.0);
  f.done();
  return p;
}

Limiter read_limiter(const json& j, const std::string& path, int pellets) {
  Fields f(j, path);
  Limiter l;
  l.angle = f.required_number("angle");
  l.k = f.required_number("k");
  l.mobile = f.boolean("mobile", false);
  if (auto r = f.integer("rearm_by")) l.rearm_by = static_cast<int>(*r);
  l.armed = f.boolean("armed", true);
  if (const json* list = f.array("pellets", 64)) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      l.pellets.push_back(index_in((*list)[i], item(f.path("pellets"), i), pellets, "pellet"));
    }
  }
  f.done();
  return l;
}

Model read_model(const json& j, const Limits& limits) {
  Fields f(j, "model");
  Model m;
  m.g = f.number("g", 9.81);
  m.R = f.required_number("R");
  m.alpha0 = f.number("alpha0", 0.0);
  m.mu_s = f.number("mu_s");
  m.k_c = f.number("k_c", 1.0);
  if (auto law = f.string("friction", 32)) {
    if (*law == "paper")
      m.friction = FrictionLaw::paper;
    else if (*law == "bilateral")
      m.friction = FrictionLaw::bilateral;
    else
      throw FieldException("model.friction",
                           "must be \"paper\" or \"bilateral\", got \"" + *law + "\"");
  }
  const json* pellets = f.array("pellets", limits.pellets);
  if (!pellets || pellets->empty()) {
    throw FieldException("model.pellets",
                         "must list 1 to " + std::to_string(limits.pellets) + " pellets");
  }
  for (std::size_t i = 0; i < pellets->size(); ++i) {
    m.pellets.push_back(read_pellet((*pellets)[i], item("model.pellets", i)));
  }
  if (const json* limiters = f.array("limiters", limits.limiters)) {
    for (std::size_t i = 0; i < limiters->size(); ++i) {
      m.limiters.push_back(read_limiter((*limiters)[i], item("model.limiters", i), m.size()));
    }
  }
  f.done();
  return m;
}

Method read_method(const std::string& name) {
  if (name == "dopri5") return Method::dopri5;
  if (name == "dop853") return Method::dop853;
  if (name == "radau5") return Method::radau5;
  if (name == "auto") return Method::automatic;
  if (name == "taylor") return Method::taylor;
  throw FieldException(
      "solver.method",
      "must be one of \"auto\", \"dopri5\", \"dop853\", \"radau5\", \"taylor\", got \"" + name +
          "\"");
}

void read_solver(const json& j, SimOptions& o) {
  Fields f(j, "solver");
  if (auto name = f.string("method", 32)) o.method = read_method(*name);
  o.rtol = f.number("rtol", o.rtol);
  o.atol = f.number("atol", o.atol);
  o.check = f.boolean("check", o.check);
  f.done();
}

// The deepest nesting of arrays and objects in JSON text, strings skipped. A loop over the
// text, not a recursion over the parsed tree: a body of 10^6 '[' overflowed the stack.
int text_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;  // the escaped character cannot end the string
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

SceneOrError scene_from_json(const json& j, const Limits& limits) {
  try {
    Fields f(j, "");
    Scene s;
    if (auto name = f.string("name", 64)) s.name = *name;
    if (auto d = f.string("description", 2000)) s.description = *d;
    if (const json* list = f.array("assumptions", 16)) {
      for (std::size_t i = 0; i < list->size(); ++i) {
        if (!(*list)[i].is_string() || (*list)[i].get<std::string>().size() > 2000)
          throw FieldException(item("assumptions", i), "must be a string of at most 2000 bytes");
        s.assumptions.push_back((*list)[i].get<std::string>());
      }
    }
    const json* model = f.value("model");
    if (!model) throw FieldException("model", "is required");
    s.model = read_model(*model, limits);
    const auto t_end = f.number("t_end");
    if (!t_end) throw FieldException("t_end", "is required (s)");
    s.sim.t_end = *t_end;
    if (const json* solver = f.value("solver")) read_solver(*solver, s.sim);
    s.trajectories = f.boolean("trajectories", false);
    s.sim.lyapunov = f.boolean("lyapunov", false);
    if (const json* plots = f.array("plots", limits.plots)) {
      for (std::size_t i = 0; i < plots->size(); ++i)
        s.figure.plots.push_back(plot_from_json((*plots)[i], item("plots", i), limits));
    }
    if (auto w = f.integer("width")) s.figure.width = static_cast<int>(*w);
    if (auto h = f.integer("height")) s.figure.height = static_cast<int>(*h);
    // A print size sets the pixels, over width and height (checked by validate_scene first).
    if (const json* print = f.value("figure")) s.figure.print = read_print_size(*print);
    if (const json* sweep = f.value("sweep")) s.sweep = read_sweep(*sweep);
    if (const json* orbit = f.value("periodic_orbit"))
      s.periodic_orbit = read_orbit_request(*orbit, limits.pellets, limits.limiters);
    f.done();
    if (auto e = validate_scene(s, limits)) return *e;
    apply_print_size(s.figure);
    return s;
  } catch (const FieldException& e) {
    return FieldError{e.field, e.what()};
  }
}

namespace {

// A pass of the parser's events over the text (nlohmann's SAX interface, building nothing) that
// refuses a key given twice in one object (JSON would silently keep the last value: a script
// that sets "R" twice means one of them), naming it by its path. A pass of its own rather than
// a callback of the parse that builds the tree: that parser looks through an array's items for
// a discarded one after each object, quadratic in an array of objects (2·10^5 of them: 5 s).
class DuplicateKeys {
 public:
  bool null() { return element_done(); }
  bool boolean(bool) { return element_done(); }
  bool number_integer(json::number_integer_t) { return element_done(); }
  bool number_unsigned(json::number_unsigned_t) { return element_done(); }
  bool number_float(json::number_float_t, const json::string_t&) { return element_done(); }
  bool string(json::string_t&) { return element_done(); }
  bool binary(json::binary_t&) { return element_done(); }
  bool start_object(std::size_t) { return start(true); }
  bool start_array(std::size_t) { return start(false); }
  bool end_object() { return end(); }
  bool end_array() { return end(); }
  bool key(json::string_t& key) {
    Frame& f = frames_.back();
    if (!f.keys.insert(key).second) throw FieldException(path() + key_name(key), "appears twice");
    f.key = key;
    return true;
  }
  // Not JSON: the parse that builds the tree says where and why.
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
    return false;
  }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;    // object: the key being read
    std::size_t index;  // array: the element being read
  };

  bool start(bool object) {
    frames_.push_back({object, {}, {}, 0});
    return true;
  }
  bool end() {
    frames_.pop_back();
    return element_done();
  }
  bool element_done() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }

  // The path of the innermost object, ready for a key to be appended ("model.pellets[1].").
  std::string path() const {
    std::string p;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.object)
        p += (p.empty() ? "" : ".") + key_name(f.key);
      else
        p += "[" + std::to_string(f.index) + "]";
    }
    return p.empty() ? p : p + ".";
  }

  std::vector<Frame> frames_;
};

}  // namespace

std::variant<json, FieldError> parse_scene_text(std::string_view text, const Limits& limits) {
  // Checked before parsing, so a deep document costs no tree (and no deep recursion).
  if (text_depth(text) > limits.depth) {
    return FieldError{"scene", "nests deeper than " + std::to_string(limits.depth) + " levels"};
  }
  // The parser's message may quote the bytes it read: keep it printable ASCII, so that the
  // error itself is valid JSON text.
  auto printable = [](std::string why) {
    for (char& c : why)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return why;
  };
  try {
    DuplicateKeys duplicates;
    json::sax_parse(text, &duplicates);
    return json::parse(text);
  } catch (const FieldException& e) {
    return FieldError{e.field, e.what()};
  } catch (const json::parse_error& e) {
    // Where it breaks helps a person find the typo: "at byte 57: ...".
    const std::string why = printable(e.what());
    const auto colon = why.find("syntax error");
    return FieldError{"scene", "is not valid JSON (at byte " + std::to_string(e.byte) + ": " +
                                   (colon == std::string::npos ? why : why.substr(colon)) + ")"};
  } catch (const json::exception& e) {  // a number beyond double's range (1e999), say
    const std::string why = printable(e.what());
    const auto end = why.find("] ");
    return FieldError{"scene", "is not valid JSON (" +
                                   (end == std::string::npos ? why : why.substr(end + 2)) + ")"};
  }
}

SceneOrError scene_from_text(std::string_view text, const Limits& limits) {
  auto parsed = parse_scene_text(text, limits);
  if (auto* e = std::get_if<FieldError>(&parsed)) return *e;
  return scene_from_json(std::get<json>(parsed), limits);
}

json scene_to_json(const Scene& s) {
  json model = {{"g", s.model.g},
                {"R", s.model.R},
                {"alpha0", s.model.alpha0},
                {"friction", s.model.friction == FrictionLaw::paper ? "paper" : "bilateral"},
                {"k_c", s.model.k_c}};
  if (s.model.mu_s) model["mu_s"] = *s.model.mu_s;
  json pellets = json::array();
  for (const Pellet& p : s.model.pellets) {
    pellets.push_back({{"m", p.m},
                       {"phi0", p.phi0},
                       {"dphi0", p.dphi0},
                       {"F0", p.force.F0},
                       {"Omega", p.force.Omega},
                       {"psi", p.force.psi}});
    if (p.c != 0.0) pellets.back()["c"] = p.c;  // undamped scenes read back as before
  }
  model["pellets"] = pellets;
  json limiters = json::array();
  for (const Limiter& l : s.model.limiters) {
    json lj = {{"angle", l.angle}, {"k", l.k}, {"mobile", l.mobile}};
    if (l.mobile) lj["rearm_by"] = l.rearm_by;
    if (!l.armed) lj["armed"] = false;  // scenes that start armed read back as before
    if (!l.pellets.empty()) lj["pellets"] = l.pellets;
    limiters.push_back(lj);
  }
  model["limiters"] = limiters;

  json plots = json::array();
  for (const PlotSpec& p : s.figure.plots) plots.push_back(plot_to_json(p));
  json j;
  if (!s.name.empty()) j["name"] = s.name;
  if (!s.description.empty()) j["description"] = s.description;
  if (!s.assumptions.empty()) j["assumptions"] = s.assumptions;
  j["model"] = model;
  j["t_end"] = s.sim.t_end;
  j["solver"] = {{"method", method_name(s.sim.method)},
                 {"rtol", s.sim.rtol},
                 {"atol", s.sim.atol},
                 {"check", s.sim.check}};
  if (s.trajectories) j["trajectories"] = true;
  if (s.sim.lyapunov) j["lyapunov"] = true;
  j["plots"] = plots;
  j["width"] = s.figure.width;
  j["height"] = s.figure.height;
  if (s.figure.print) j["figure"] = print_size_to_json(*s.figure.print);
  if (s.sweep) j["sweep"] = sweep_to_json(*s.sweep);
  if (s.periodic_orbit) j["periodic_orbit"] = orbit_request_to_json(*s.periodic_orbit);
  return j;
}

}  // namespace vibro
