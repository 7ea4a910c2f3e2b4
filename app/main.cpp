// vibro: phase portraits of vibro-impact dynamics. `vibro --help` lists the subcommands;
// `vibro COMMAND --help` (or `vibro help COMMAND`) lists a subcommand's options.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/usage.h"

namespace {

// What the program wrote to stdout must have reached it (a full disk, a closed pipe, /dev/full
// fail only when the buffer is flushed): a command's exit code, or 1 with a message when not.
int with_stdout_checked(int code) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  if (flushed && std::cout.good() && !std::ferror(stdout)) return code;
  const int error = errno;
  vibro::print_error("stdout", std::string("the output could not be written") +
                                   (error != 0 ? std::string(": ") + std::strerror(error) : ""));
  return 1;
}

int run(int argc, char** argv) {
  using namespace vibro;
  CLI::App app("vibro: phase portraits of vibro-impact dynamics", "vibro");
  // A repeated option's last value counts, as it always has. Arguments nobody declared are left
  // in remaining() rather than thrown, so that they are reported below as JSON naming them.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  // At most one command: a second command's name is an argument of the first.
  app.require_subcommand(0, 1);
  const std::vector<Command> commands = {
      add_simulate_command(app), add_render_command(app),  add_work_precision_command(app),
      add_sweep_command(app),    add_orbit_command(app),   add_plot_command(app),
      add_serve_command(app),    add_presets_command(app), add_preset_command(app),
  };
  std::string topic;
  CLI::App* help =
      app.add_subcommand("help", "List the commands, or with COMMAND that command's options");
  help->add_option("COMMAND", topic, "the command to explain");
  // After the subcommands, which would inherit it.
  app.footer(
      "`vibro COMMAND --help` lists a command's options. Bad usage is reported as JSON, "
      "{\"error\", \"field\"}, on stderr with exit code 2.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const FieldError error = field_error(e);
    print_error(error.field, error.message);
    return 2;
  }
  if (const auto extra = app.remaining(); !extra.empty()) {
    print_error(extra[0], "is not a command or option of `vibro` (see `vibro --help`)");
    return 2;
  }
  for (const CLI::App* command : app.get_subcommands()) {  // the one given
    const std::string name = command->get_name();
    if (const auto extra = command->remaining(); !extra.empty()) {
      print_error(extra[0],
                  "is not an option of `vibro " + name + "` (see `vibro " + name + " --help`)");
      return 2;
    }
    for (const Command& c : commands)
      if (c.app == command) return c.run();
  }
  if (!help->parsed() || topic.empty()) {  // with no command at all, the list as a usage error
    // The program's own help: app.help() would give that of the command given, `help`.
    std::cout << app.get_formatter()->make_help(&app, "vibro", CLI::AppFormatMode::Normal);
    return help->parsed() ? 0 : 2;
  }
  for (const Command& c : commands) {
    if (c.app->get_name() == topic) {
      std::cout << c.app->help("vibro");
      return 0;
    }
  }
  print_error(topic, "is not a command of `vibro` (see `vibro --help`)");
  return 2;
}

}  // namespace

int main(int argc, char** argv) { return with_stdout_checked(run(argc, argv)); }
