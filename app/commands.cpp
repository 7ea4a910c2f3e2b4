#include "app/commands.h"

#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/simulate.h"
#include "io/presets.h"
#include "io/result_json.h"
#include "io/run_csv.h"
#include "io/scene_json.h"

namespace vibro {
namespace {

using nlohmann::json;

std::optional<std::string> read_source(const std::string& source) {
  if (source == "-") {
    return std::string(std::istreambuf_iterator<char>(std::cin), {});
  }
  std::ifstream in(source, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

void print_error(const std::string& field, const std::string& message) {
  std::cerr << json{{"error", message}, {"field", field}}.dump() << "\n";
}

std::optional<Scene> load_scene(const Args& args, std::size_t& next) {
  std::optional<std::string> text;
  std::string origin;
  json overrides = json::object();
  double deadline_ms = 0.0;
  for (next = 0; next < args.size(); ++next) {
    const std::string& a = args[next];
    auto value = [&]() -> std::optional<std::string> {
      if (next + 1 >= args.size()) {
        print_error(a, "needs a value");
        return std::nullopt;
      }
      return args[++next];
    };
    if (a == "--preset") {
      auto name = value();
      if (!name) return std::nullopt;
      auto preset = preset_json(*name);
      if (!preset) {
        print_error("preset", "no preset named \"" + *name + "\" (see `vibro presets`)");
        return std::nullopt;
      }
      text = std::string(*preset);
      origin = *name;
    } else if (a == "--t-end" || a == "--method" || a == "--rtol" || a == "--atol") {
      auto v = value();
      if (!v) return std::nullopt;
      try {
        if (a == "--method") overrides["solver"]["method"] = *v;
        else if (a == "--t-end") overrides["t_end"] = std::stod(*v);
        else overrides["solver"][a.substr(2)] = std::stod(*v);
      } catch (const std::exception&) {
        print_error(a, "must be a number");
        return std::nullopt;
      }
    } else if (a == "--deadline-ms") {
      auto v = value();
      if (!v) return std::nullopt;
      try {
        deadline_ms = std::stod(*v);
      } catch (const std::exception&) {
        deadline_ms = -1.0;
      }
      if (!(deadline_ms > 0.0)) {
        print_error(a, "must be a positive number of milliseconds");
        return std::nullopt;
      }
    } else if (a == "--trajectories") {
      overrides["trajectories"] = true;
    } else if (a == "--no-check") {
      overrides["solver"]["check"] = false;
    } else if (!a.starts_with("--") || a == "-") {
      if (text) break;  // a later positional argument belongs to the command
      text = read_source(a);
      if (!text) {
        print_error("scene", "cannot read the file \"" + a + "\"");
        return std::nullopt;
      }
      origin = a == "-" ? "the standard input" : a;
    } else {
      break;  // an option of the command itself
    }
  }
  if (!text) {
    print_error("scene", "name a scene file, - for stdin, or --preset NAME");
    return std::nullopt;
  }
  auto parsed_text = parse_scene_text(*text);
  if (auto* e = std::get_if<FieldError>(&parsed_text)) {
    print_error(e->field, e->field == "scene" ? origin + " " + e->message : e->message);
    return std::nullopt;
  }
  json j = std::get<json>(std::move(parsed_text));
  if (j.is_object()) j.merge_patch(overrides);
  SceneOrError parsed = scene_from_json(j);
  if (auto* e = std::get_if<FieldError>(&parsed)) {
    print_error(e->field, e->message);
    return std::nullopt;
  }
  Scene scene = std::get<Scene>(std::move(parsed));
  if (deadline_ms > 0.0) scene.sim.deadline_ms = deadline_ms;
  return scene;
}

std::optional<SceneAndOutput> scene_and_output(const Args& args, const std::string& command) {
  std::size_t next = 0;
  auto scene = load_scene(args, next);
  if (!scene) return std::nullopt;
  SceneAndOutput job{std::move(*scene), ""};
  for (; next < args.size(); ++next) {
    if ((args[next] == "-o" || args[next] == "--output") && next + 1 < args.size()) {
      job.out = args[++next];
    } else {
      print_error(args[next], "is not an option of `vibro " + command + "`");
      return std::nullopt;
    }
  }
  return job;
}

int simulate_command(const Args& args) {
  std::size_t next = 0;
  auto scene = load_scene(args, next);
  if (!scene) return 2;
  std::string out;
  std::optional<RunTable> table;
  for (; next < args.size(); ++next) {
    if ((args[next] == "-o" || args[next] == "--output") && next + 1 < args.size()) {
      out = args[++next];
    } else if (args[next] == "--what" && next + 1 < args.size()) {
      table = run_table_named(args[++next]);
      if (!table) {
        print_error("--what", "must be \"events\" or \"trajectory\"");
        return 2;
      }
    } else {
      print_error(args[next], "is not an option of `vibro simulate`");
      return 2;
    }
  }
  const bool csv = out.ends_with(".csv");
  if (!out.empty() && !csv && !out.ends_with(".json")) {
    print_error("-o", "name the output OUT.json or OUT.csv");
    return 2;
  }
  if (table && !csv) {
    print_error("--what", "applies to a CSV output (-o OUT.csv)");
    return 2;
  }
  if (csv && !table) table = RunTable::events;
  SimOptions options = scene->sim;
  options.record.assign(scene->model.size(),
                        table ? *table == RunTable::trajectory : scene->trajectories);
  const RunResult run = simulate(scene->model, options);
  const std::string text =
      table ? run_csv(run, *table) : result_to_json(run, scene->model).dump(2) + "\n";
  if (out.empty()) {
    std::cout << text;
  } else if (!(std::ofstream(out, std::ios::binary) << text)) {
    print_error("-o", "cannot write " + out);
    return 1;
  }
  return run.stats.termination == Termination::completed ? 0 : 1;
}

int presets_command(const Args& args) {
  if (!args.empty()) {
    print_error(args[0], "`vibro presets` takes no arguments");
    return 2;
  }
  json list = json::array();
  for (const PresetText& p : presets()) {
    const json j = json::parse(p.json);
    list.push_back({{"name", p.name}, {"description", j.value("description", "")}});
  }
  std::cout << list.dump(2) << "\n";
  return 0;
}

int preset_command(const Args& args) {
  if (args.size() != 1) {
    print_error("preset", "usage: vibro preset NAME");
    return 2;
  }
  auto text = preset_json(args[0]);
  if (!text) {
    print_error("preset", "no preset named \"" + args[0] + "\" (see `vibro presets`)");
    return 2;
  }
  std::cout << *text;
  return 0;
}

}  // namespace vibro
