#include "app/scene_options.h"

#include <cstdio>
#include <iostream>
#include <iterator>
#include <variant>

#include "app/usage.h"
#include "io/presets.h"
#include "io/scene_json.h"
#include "io/whole_file.h"

namespace vibro {
namespace {

using nlohmann::json;

// The scene's text from a file or, for "-", the standard input; else why it cannot be read.
std::variant<std::string, FileProblem> read_source(const std::string& source) {
  if (source != "-") return read_whole_file(source);
  std::string text(std::istreambuf_iterator<char>(std::cin), {});
  if (std::cin.bad() || std::ferror(stdin)) return FileProblem{"the standard input cannot be read"};
  return text;
}

// An option whose number goes into the scene's JSON at `path` (checked there with the rest of
// the scene, so its range errors name the scene's field).
void add_number_override(CLI::App& command, const std::string& name, const std::string& help,
                         SceneSource& source, json::json_pointer path) {
  command
      .add_option_function<double>(
          name, [&source, path](double x) { source.overrides[path] = x; }, help)
      ->check(number_where([](double) { return true; }, "must be a number"))
      ->type_name("X");
}

// The SCENE positional and the options of SceneSource, bound to `source`.
void add_scene_options(CLI::App& command, SceneSource& source) {
  command.add_option("SCENE", source.file, "the scene as JSON (API.md): a file, or - for stdin")
      ->type_name("FILE|-");
  command
      .add_option("--preset", source.preset, "a named scene instead (`vibro presets` lists them)")
      ->type_name("NAME");
  add_number_override(command, "--t-end", "simulated time span, s (the scene's t_end)", source,
                      json::json_pointer("/t_end"));
  command
      .add_option_function<std::string>(
          "--method", [&source](const std::string& m) { source.overrides["solver"]["method"] = m; },
          "integrator: auto, dopri5, dop853, radau5 or taylor")
      ->type_name("M");
  add_number_override(command, "--rtol", "relative tolerance", source,
                      json::json_pointer("/solver/rtol"));
  add_number_override(command, "--atol", "absolute tolerance", source,
                      json::json_pointer("/solver/atol"));
  command.add_option("--deadline-ms", source.deadline_ms, "wall clock allowed for the run, ms")
      ->check(number_where([](double x) { return x > 0.0; },
                           "must be a positive number of milliseconds"))
      ->type_name("MS");
  command.add_flag_callback(
      "--no-check", [&source] { source.overrides["solver"]["check"] = false; },
      "skip the shadow run at a tighter tolerance (no error estimate; about 2x faster)");
  command.add_flag_callback(
      "--trajectories", [&source] { source.overrides["trajectories"] = true; },
      "record every pellet's trajectory");
}

}  // namespace

CLI::App* add_scene_command(CLI::App& vibro, const std::string& name,
                            const std::string& description, const std::string& output_help,
                            SceneOutput& job) {
  CLI::App* command = vibro.add_subcommand(name, description);
  add_scene_options(*command, job.scene);
  command->add_option("-o,--output", job.outs, output_help + " (repeat -o for several)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->expected(1)
      ->type_name("OUT");
  return command;
}

std::optional<Scene> load_scene(const SceneSource& source) {
  if (source.file.empty() == source.preset.empty()) {
    print_error("scene", source.file.empty()
                             ? "name a scene file, - for stdin, or --preset NAME"
                             : "name one scene: a file, - for stdin, or --preset NAME");
    return std::nullopt;
  }
  std::optional<std::string> text;
  std::string origin;
  if (!source.preset.empty()) {
    const auto preset = preset_json(source.preset);
    if (!preset) {
      print_error("preset", "no preset named \"" + source.preset + "\" (see `vibro presets`)");
      return std::nullopt;
    }
    text = std::string(*preset);
    origin = source.preset;
  } else {
    auto read = read_source(source.file);
    if (auto* problem = std::get_if<FileProblem>(&read)) {
      print_error("scene", problem->message);
      return std::nullopt;
    }
    text = std::get<std::string>(std::move(read));
    origin = source.file == "-" ? "the standard input" : source.file;
  }
  auto parsed_text = parse_scene_text(*text);
  if (auto* e = std::get_if<FieldError>(&parsed_text)) {
    print_error(e->field, e->field == "scene" ? origin + " " + e->message : e->message);
    return std::nullopt;
  }
  json j = std::get<json>(std::move(parsed_text));
  if (j.is_object()) j.merge_patch(source.overrides);
  SceneOrError parsed = scene_from_json(j);
  if (auto* e = std::get_if<FieldError>(&parsed)) {
    print_error(e->field, e->message);
    return std::nullopt;
  }
  Scene scene = std::get<Scene>(std::move(parsed));
  if (source.deadline_ms > 0.0) scene.sim.deadline_ms = source.deadline_ms;
  return scene;
}

bool outputs_named(const std::vector<std::string>& outs, std::initializer_list<const char*> endings,
                   const std::string& names) {
  for (const std::string& out : outs) {
    bool named = false;
    for (const char* ending : endings) named = named || out.ends_with(ending);
    if (!named) {
      print_error("-o", "name the output " + names + ", not \"" + out + "\"");
      return false;
    }
  }
  return true;
}

bool write_output(const std::string& out, std::string_view bytes) {
  const auto problem = write_whole_file(out, bytes);
  if (problem) print_error("-o", problem->message);
  return !problem;
}

std::optional<std::string> drawn_bytes(const RenderResult& image) {
  if (!image.ok()) {
    print_error(image.error->field, image.error->message);
    return std::nullopt;
  }
  return std::string(image.bytes.begin(), image.bytes.end());
}

}  // namespace vibro
