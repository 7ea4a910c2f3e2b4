// vibro.presets() and vibro.preset(name): the named scenes, as `vibro presets` and `vibro preset
// NAME` print them (app/preset_commands.cpp).
#include <nlohmann/json.hpp>

#include "io/presets.h"
#include "python/bindings.h"
#include "python/json_values.h"
#include "python/scene_error.h"

namespace vibro::python {

void add_presets(py::module_& m) {
  m.def(
      "presets",
      [] {
        py::list list;
        for (const PresetText& p : presets()) {
          const nlohmann::json j = nlohmann::json::parse(p.json);
          py::dict entry;
          entry["name"] = std::string(p.name);
          entry["description"] = j.value("description", "");
          list.append(entry);
        }
        return list;
      },
      "The named scenes, the paper's first: a list of {\"name\", \"description\"}.");
  m.def(
      "preset",
      [](const std::string& name) {
        const auto text = preset_json(name);
        if (!text)
          raise_scene_error({"preset", "no preset named \"" + name + "\" (see vibro.presets())"});
        return python_from_json(nlohmann::json::parse(*text));
      },
      py::arg("name"), "A named scene as a dict, to edit and run.");
}

}  // namespace vibro::python
