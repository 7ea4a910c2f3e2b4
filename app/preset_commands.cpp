// `vibro presets`: the named scenes with a sentence each, the paper's first. `vibro preset NAME`:
// one of them as JSON, a scene to edit and run.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/usage.h"
#include "io/presets.h"

namespace vibro {

Command add_presets_command(CLI::App& vibro) {
  CLI::App* command =
      vibro.add_subcommand("presets", "List the named scenes as JSON, with a sentence each");
  return {command, [] {
            nlohmann::json list = nlohmann::json::array();
            for (const PresetText& p : presets()) {
              const nlohmann::json j = nlohmann::json::parse(p.json);
              list.push_back({{"name", p.name}, {"description", j.value("description", "")}});
            }
            std::cout << list.dump(2) << "\n";
            return 0;
          }};
}

Command add_preset_command(CLI::App& vibro) {
  auto name = std::make_shared<std::string>();
  CLI::App* command = vibro.add_subcommand("preset", "Print a named scene as JSON");
  command->add_option("NAME", *name, "the preset (`vibro presets` lists them)");
  return {command, [name] {
            if (name->empty()) {
              print_error("preset", "usage: vibro preset NAME");
              return 2;
            }
            const auto text = preset_json(*name);
            if (!text) {
              print_error("preset", "no preset named \"" + *name + "\" (see `vibro presets`)");
              return 2;
            }
            std::cout << *text;
            return 0;
          }};
}

}  // namespace vibro
